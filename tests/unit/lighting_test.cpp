// The CPU reference of the lecture's formula, checked against values worked out by hand here.
#include "core/lighting.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>

using namespace shadelab;

namespace {

constexpr float kEps = 1e-5f;

Material plainMaterial() {
    Material m;
    m.color = {0.5f, 0.25f, 1.0f};
    m.specularColor = {1.0f, 1.0f, 1.0f};
    m.ka = 0.1f;
    m.kd = 0.6f;
    m.ks = 0.3f;
    m.ke = 8.0f;
    return m;
}

Light directional(glm::vec3 travel, float intensity = 1.0f) {
    Light l;
    l.type = LightType::Directional;
    l.direction = travel;
    l.intensity = intensity;
    return l;
}

}  // namespace

// Surface at the origin facing +z, eye on +z. Light from 60 degrees off the normal in the y-z plane.
// By hand: N.I = cos 60 = 0.5; R = 2(N.I)N - I = (0, -sin 60, cos 60); V = (0,0,1): R.V = 0.5.
// H = normalize(I + V) is 30 degrees off N: H.N = cos 30.
TEST(Lighting, PhongAndBlinnPhongLobesMatchHandValues) {
    const float a = 60.0f * 3.14159265f / 180.0f;
    const glm::vec3 towardLight(0.0f, std::sin(a), std::cos(a));
    LightingEnvironment env;
    env.ambient = {0.0f, 0.0f, 0.0f};
    env.eyeWorld = {0.0f, 0.0f, 10.0f};
    env.lights = {directional(-towardLight)};
    Material m = plainMaterial();
    m.ka = 0.0f;

    env.model = ReflectionModel::Phong;
    const ShadingTerms phong = shadeTerms(m, env, {0, 0, 0}, {0, 0, 1});
    EXPECT_NEAR(phong.diffuse.x, 0.6f * 0.5f * 0.5f, kEps);
    EXPECT_NEAR(phong.specular.x, 0.3f * std::pow(0.5f, 8.0f), kEps);

    env.model = ReflectionModel::BlinnPhong;
    const ShadingTerms blinn = shadeTerms(m, env, {0, 0, 0}, {0, 0, 1});
    EXPECT_NEAR(blinn.diffuse.x, phong.diffuse.x, kEps);  // the diffuse term does not depend on the model
    EXPECT_NEAR(blinn.specular.x, 0.3f * std::pow(std::cos(a / 2.0f), 8.0f), kEps);
    // At this angle Blinn-Phong's lobe is much wider than Phong's for the same exponent.
    EXPECT_GT(blinn.specular.x, 10.0f * phong.specular.x);
}

TEST(Lighting, AmbientTermIsKaTimesAmbientTimesColor) {
    LightingEnvironment env;
    env.ambient = {0.5f, 1.0f, 0.2f};
    const ShadingTerms t = shadeTerms(plainMaterial(), env, {0, 0, 0}, {0, 0, 1});
    EXPECT_NEAR(t.ambient.x, 0.1f * 0.5f * 0.5f, kEps);
    EXPECT_NEAR(t.ambient.y, 0.1f * 1.0f * 0.25f, kEps);
    EXPECT_NEAR(t.ambient.z, 0.1f * 0.2f * 1.0f, kEps);
    EXPECT_EQ(t.diffuse, glm::vec3(0.0f));
    EXPECT_EQ(t.specular, glm::vec3(0.0f));
}

// A light just below the horizon: N.I < 0. Blinn-Phong's H.N is still positive there (H lies between
// I and V), so without the cut a highlight would appear on the unlit side.
TEST(Lighting, NoDiffuseOrSpecularWhereNDotIIsNotPositive) {
    const glm::vec3 towardLight = glm::normalize(glm::vec3(0.0f, 1.0f, -0.05f));
    LightingEnvironment env;
    env.ambient = {1, 1, 1};
    env.eyeWorld = {0.0f, 0.2f, 10.0f};
    env.lights = {directional(-towardLight)};
    env.model = ReflectionModel::BlinnPhong;
    const glm::vec3 h = glm::normalize(towardLight + glm::normalize(env.eyeWorld));
    ASSERT_GT(glm::dot(h, glm::vec3(0, 0, 1)), 0.5f);  // the lobe alone would light this point
    const Material m = plainMaterial();
    const ShadingTerms t = shadeTerms(m, env, {0, 0, 0}, {0, 0, 1});
    EXPECT_EQ(t.diffuse, glm::vec3(0.0f));
    EXPECT_EQ(t.specular, glm::vec3(0.0f));
    EXPECT_NEAR(t.total.x, 0.1f * 0.5f, kEps);

    // Exactly at the horizon (N.I = 0) the cut applies too.
    env.lights = {directional(glm::vec3(0.0f, -1.0f, 0.0f))};
    EXPECT_EQ(shadeTerms(m, env, {0, 0, 0}, {0, 0, 1}).specular, glm::vec3(0.0f));
}

TEST(Lighting, InverseSquareAttenuation) {
    Light l;
    l.type = LightType::Point;
    l.position = {0.0f, 0.0f, 2.0f};  // straight above: N.I = 1, r = 2
    l.attenuation = Attenuation::InverseSquare;
    LightingEnvironment env;
    env.ambient = {0, 0, 0};
    env.eyeWorld = {5.0f, 0.0f, 0.0f};
    env.lights = {l};
    Material m = plainMaterial();
    m.ks = 0.0f;
    EXPECT_NEAR(shadeTerms(m, env, {0, 0, 0}, {0, 0, 1}).diffuse.x, 0.6f * 0.5f / 4.0f, kEps);
    env.lights[0].attenuation = Attenuation::None;
    EXPECT_NEAR(shadeTerms(m, env, {0, 0, 0}, {0, 0, 1}).diffuse.x, 0.6f * 0.5f, kEps);
    // Intensity and colour scale L_l linearly.
    env.lights[0].intensity = 0.5f;
    env.lights[0].color = {1.0f, 0.0f, 1.0f};
    const ShadingTerms t = shadeTerms(m, env, {0, 0, 0}, {0, 0, 1});
    EXPECT_NEAR(t.diffuse.x, 0.6f * 0.5f * 0.5f, kEps);
    EXPECT_EQ(t.diffuse.y, 0.0f);
}

TEST(Lighting, ContributionsOfSeveralLightsAdd) {
    LightingEnvironment env;
    env.ambient = {0, 0, 0};
    env.eyeWorld = {0, 0, 10};
    env.lights = {directional({0, 0, -1})};
    const Material m = plainMaterial();
    const ShadingTerms one = shadeTerms(m, env, {0, 0, 0}, {0, 0, 1});
    env.lights.push_back(directional({0, 0, -1}, 0.5f));
    const ShadingTerms two = shadeTerms(m, env, {0, 0, 0}, {0, 0, 1});
    EXPECT_NEAR(two.diffuse.x, 1.5f * one.diffuse.x, kEps);
    EXPECT_NEAR(two.specular.x, 1.5f * one.specular.x, kEps);
}

TEST(Lighting, EachChannelIsClampedSeparately) {
    LightingEnvironment env;
    env.ambient = {0, 0, 0};
    env.eyeWorld = {0, 0, 10};
    env.lights = {directional({0, 0, -1}, 3.0f)};
    Material m = plainMaterial();
    m.color = {1.0f, 0.0f, 0.0f};
    m.specularColor = {0.0f, 0.0f, 0.0f};
    const ShadingTerms t = shadeTerms(m, env, {0, 0, 0}, {0, 0, 1});
    EXPECT_GT(t.diffuse.x, 1.0f);
    EXPECT_EQ(t.total, glm::vec3(1.0f, 0.0f, 0.0f));
}

TEST(Lighting, SrgbEncodingKnownValues) {
    EXPECT_NEAR(encodeSrgb(0.0f), 0.0f, 1e-6f);
    EXPECT_NEAR(encodeSrgb(1.0f), 1.0f, 1e-5f);
    EXPECT_NEAR(encodeSrgb(0.5f), 0.735357f, 1e-4f);
    EXPECT_NEAR(encodeSrgb(0.002f), 0.02584f, 1e-5f);  // linear segment
}
