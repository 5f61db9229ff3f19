// The CPU reference of the lecture's formula, checked against values worked out by hand here.
#include "core/shading/lighting.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec3.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <initializer_list>
#include <utility>

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

// ---- Issue 5: several lights, falloff windows, area lights, visibility -------------------------

namespace {

Light pointAt(glm::vec3 p, float intensity, Attenuation a = Attenuation::None) {
    Light l;
    l.position = p;
    l.intensity = intensity;
    l.attenuation = a;
    return l;
}

LightingEnvironment envWith(std::vector<Light> lights) {
    LightingEnvironment env;
    env.ambient = {0.2f, 0.2f, 0.2f};
    env.eyeWorld = {0.3f, 4.0f, 2.0f};
    env.lights = std::move(lights);
    return env;
}

}  // namespace

// The lecture's "add their contributions": two lights together are the sum of each alone.
TEST(Lighting, LightsAddUp) {
    Material m = plainMaterial();
    m.ka = 0.0f;
    const Light a = pointAt({1, 2, 1}, 0.3f), b = pointAt({-2, 1, 0.5f}, 4.0f, Attenuation::InverseSquare);
    const glm::vec3 p(0.1f, 0, 0), n(0, 1, 0);
    const ShadingTerms both = shadeTerms(m, envWith({a, b}), p, n);
    const ShadingTerms one = shadeTerms(m, envWith({a}), p, n), two = shadeTerms(m, envWith({b}), p, n);
    EXPECT_NEAR(both.diffuse.x, one.diffuse.x + two.diffuse.x, kEps);
    EXPECT_NEAR(both.specular.y, one.specular.y + two.specular.y, kEps);
}

// Inverse-square with a range: 1/r^2 * (1 - (r/range)^4)^2, zero from the range on.
// A spot light is a point light times glTF's cone falloff: 1 inside the inner cone, 0 outside the
// outer, ((cd - cos outer) / (cos inner - cos outer))^2 between (by hand at 25 degrees off the axis).
TEST(Lighting, SpotLightIsAPointLightTimesItsConeFalloff) {
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {0, 0, 5};
    spot.direction = {0, 0, -1};
    spot.innerConeDeg = 20.0f;
    spot.outerConeDeg = 30.0f;
    const auto toward = [&](float degreesOff) {  // from a point seen degreesOff from the axis, toward the light
        const float a = glm::radians(degreesOff);
        return -glm::vec3(std::sin(a), 0.0f, -std::cos(a));
    };
    EXPECT_FLOAT_EQ(spotFalloff(spot, toward(0.0f)), 1.0f);
    EXPECT_FLOAT_EQ(spotFalloff(spot, toward(19.0f)), 1.0f);
    EXPECT_FLOAT_EQ(spotFalloff(spot, toward(31.0f)), 0.0f);
    const float t = (std::cos(glm::radians(25.0f)) - std::cos(glm::radians(30.0f))) /
                    (std::cos(glm::radians(20.0f)) - std::cos(glm::radians(30.0f)));
    EXPECT_NEAR(spotFalloff(spot, toward(25.0f)), t * t, 1e-5f);
    // In the formula: the point light's terms times the falloff.
    LightingEnvironment env;
    env.eyeWorld = {0, 0, 5};
    Light point = spot;
    point.type = LightType::Point;
    const glm::vec3 p(std::tan(glm::radians(25.0f)) * 5.0f, 0.0f, 0.0f), n(0, 0, 1);
    env.lights = {point};
    const ShadingTerms a = shadeTerms(plainMaterial(), env, p, n);
    env.lights = {spot};
    const ShadingTerms b = shadeTerms(plainMaterial(), env, p, n);
    EXPECT_NEAR(b.diffuse.r, a.diffuse.r * t * t, 1e-5f);
    EXPECT_NEAR(b.specular.g, a.specular.g * t * t, 1e-5f);
}

TEST(Lighting, RangeWindowReachesZero) {
    Light l = pointAt({0, 0, 0}, 1.0f, Attenuation::InverseSquare);
    EXPECT_NEAR(attenuationFactor(l, 4.0f), 0.25f, 1e-7f);  // no range: plain 1/r^2
    l.range = 4.0f;
    // r = 2: (1 - (1/2)^4)^2 / 4 = (15/16)^2 / 4
    EXPECT_NEAR(attenuationFactor(l, 4.0f), (15.0f / 16.0f) * (15.0f / 16.0f) / 4.0f, 1e-7f);
    EXPECT_NEAR(attenuationFactor(l, 0.01f), 100.0f, 1e-3f);  // near the light the window is ~1
    EXPECT_EQ(attenuationFactor(l, 16.0f), 0.0f);             // r = range
    EXPECT_EQ(attenuationFactor(l, 100.0f), 0.0f);            // beyond it
    l.attenuation = Attenuation::None;
    EXPECT_EQ(attenuationFactor(l, 100.0f), 1.0f);  // a range means nothing without inverse-square
}

// A 1 x 1 area light is a point light at its centre whose intensity is multiplied by the cosine at the
// light, cos = n_light . (p - centre) / |p - centre| - in every term, with either falloff.
TEST(Lighting, OneSampleAreaLightIsAPointLightTimesTheCosine) {
    const Material m = plainMaterial();
    const glm::vec3 p(0.4f, 0.0f, -0.3f), n = glm::normalize(glm::vec3(0.1f, 1.0f, 0.2f));
    for (Attenuation att : {Attenuation::None, Attenuation::InverseSquare}) {
        Light area;
        area.type = LightType::Area;
        area.position = {1.0f, 2.5f, 0.5f};
        area.normal = {-0.3f, -1.0f, 0.1f};
        area.size = {2.0f, 0.7f};
        area.samples = {1, 1};
        area.intensity = 3.0f;
        area.color = {1.0f, 0.8f, 0.6f};
        area.attenuation = att;
        const float cosLight = glm::dot(glm::normalize(area.normal), glm::normalize(p - area.position));
        ASSERT_GT(cosLight, 0.5f);
        Light point = pointAt(area.position, area.intensity * cosLight, att);
        point.color = area.color;
        const ShadingTerms a = shadeTerms(m, envWith({area}), p, n), b = shadeTerms(m, envWith({point}), p, n);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(a.diffuse[c], b.diffuse[c], 1e-6f);
            EXPECT_NEAR(a.specular[c], b.specular[c], 1e-6f);
        }
        EXPECT_GT(a.diffuse.x, 0.01f);
    }
}

// An n x n area light, by hand: the sum over its samples of (1/n^2) * cos at the light * the point
// term; far away (distance >> size) it tends to a point light at the centre.
TEST(Lighting, AreaLightIsTheWeightedSumOfItsSamples) {
    Material m = plainMaterial();
    m.ks = 0.0f;
    Light area;
    area.type = LightType::Area;
    area.position = {0.0f, 2.0f, 0.0f};
    area.size = {1.0f, 2.0f};
    area.samples = {3, 2};
    area.attenuation = Attenuation::InverseSquare;
    const glm::vec3 p(0.5f, 0.0f, 0.2f), n(0, 1, 0);
    float expected = 0.0f;
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 3; ++i) {
            const glm::vec3 s = areaSamplePosition(area, i, j);
            EXPECT_NEAR(s.y, 2.0f, 1e-6f);  // in the light's plane, inside its rectangle
            EXPECT_LE(std::fabs(s.x), 0.5f);
            EXPECT_LE(std::fabs(s.z), 1.0f);
            const glm::vec3 d = s - p;
            const float r2 = glm::dot(d, d);
            const glm::vec3 i_ = d / std::sqrt(r2);
            expected += (1.0f / 6.0f) * (-glm::dot(glm::vec3(0, -1, 0), i_)) / r2 * m.kd * m.color.x * glm::dot(n, i_);
        }
    EXPECT_NEAR(shadeTerms(m, envWith({area}), p, n).diffuse.x, expected, 1e-6f);

    area.position = {0.0f, 200.0f, 0.0f};
    const Light point = pointAt(area.position, 1.0f, Attenuation::InverseSquare);
    const float far = shadeTerms(m, envWith({area}), p, n).diffuse.x;
    EXPECT_NEAR(far / shadeTerms(m, envWith({point}), p, n).diffuse.x, 1.0f, 1e-4f);
}

// One-sided lights light nothing behind them; two-sided ones light both sides the same.
TEST(Lighting, AreaLightSides) {
    Material m = plainMaterial();
    Light area;
    area.type = LightType::Area;
    area.position = {0.0f, 1.0f, 0.0f};
    area.normal = {0.0f, 1.0f, 0.0f};  // emits upward: the floor below is behind it
    area.samples = {2, 2};
    const glm::vec3 below(0.2f, 0.0f, 0.0f), above(0.2f, 2.0f, 0.0f);
    EXPECT_EQ(shadeTerms(m, envWith({area}), below, {0, 1, 0}).diffuse, glm::vec3(0.0f));
    area.twoSided = true;
    const float under = shadeTerms(m, envWith({area}), below, {0, 1, 0}).diffuse.x;
    const float over = shadeTerms(m, envWith({area}), above, {0, -1, 0}).diffuse.x;
    EXPECT_GT(under, 0.05f);
    EXPECT_NEAR(under, over, 1e-6f);  // mirror images
}

// The jitter: stratified (each sample in its own cell), fixed (pinned hash values), centred for one
// sample per side.
TEST(Lighting, AreaSampleJitterIsStratifiedAndFixed) {
    EXPECT_EQ(jitterHash(0u), 0u);
    EXPECT_EQ(jitterHash(1u), 0x688990c0u);
    EXPECT_EQ(jitterHash(0x5ade1abu), 0xe74f2785u);
    EXPECT_EQ(areaSampleOffset(0, 0, {1, 1}), glm::vec2(0.0f));
    const glm::ivec2 n(8, 4);
    float spread = 0.0f;
    for (int j = 0; j < n.y; ++j)
        for (int i = 0; i < n.x; ++i) {
            const glm::vec2 o = areaSampleOffset(i, j, n);
            EXPECT_GE(o.x + 0.5f, float(i) / 8.0f);
            EXPECT_LT(o.x + 0.5f, float(i + 1) / 8.0f);
            EXPECT_GE(o.y + 0.5f, float(j) / 4.0f);
            EXPECT_LT(o.y + 0.5f, float(j + 1) / 4.0f);
            spread += std::fabs(o.x + 0.5f - (float(i) + 0.5f) / 8.0f);
        }
    EXPECT_GT(spread, 0.01f) << "not jittered";
    EXPECT_EQ(areaSampleOffset(3, 2, n), areaSampleOffset(3, 2, n));
}

// v(p, I): an occluded light leaves only the ambient term; the visibility sees each sample's ray.
TEST(Lighting, VisibilityScalesEachLightSample) {
    const Material m = plainMaterial();
    Light area;
    area.type = LightType::Area;
    area.position = {0.0f, 3.0f, 0.0f};
    area.samples = {2, 2};
    const LightingEnvironment env = envWith({pointAt({1, 2, 0}, 1.0f), area});
    const glm::vec3 p(0, 0, 0), n(0, 1, 0);
    const ShadingTerms lit = shadeTerms(m, env, p, n);
    const ShadingTerms dark = shadeTerms(m, env, p, n, [](const glm::vec3&, const LightRay&) { return 0.0f; });
    EXPECT_EQ(dark.diffuse, glm::vec3(0.0f));
    EXPECT_EQ(dark.specular, glm::vec3(0.0f));
    EXPECT_EQ(dark.total, lit.ambient);
    int rays = 0;
    const ShadingTerms half = shadeTerms(m, env, p, n, [&](const glm::vec3& at, const LightRay& r) {
        ++rays;
        EXPECT_EQ(at, p);
        EXPECT_NEAR(glm::length(r.towardLight), 1.0f, 1e-6f);
        const glm::vec3 target = r.light == 0 ? glm::vec3(1, 2, 0) : areaSamplePosition(area, r.sample % 2, r.sample / 2);
        EXPECT_NEAR(glm::length(p + r.distance * r.towardLight - target), 0.0f, 1e-5f);
        return r.light == 1 ? 1.0f : 0.0f;  // the point light is hidden, the area light is not
    });
    EXPECT_EQ(rays, 5);
    EXPECT_NEAR(half.diffuse.x, lit.diffuse.x - shadeTerms(m, envWith({pointAt({1, 2, 0}, 1.0f)}), p, n).diffuse.x, 1e-6f);
}

// ---- Beyond the heuristic model (issue 6): Fresnel, Schlick, energy-normalised lobes, term isolation.

namespace {
constexpr double kPiD = 3.14159265358979323846;

// The lecture's forms, written independently of core/shading/lighting.cpp: R_par = tan^2(t1 - t3) / tan^2(t1 + t3),
// R_perp = sin^2(t1 - t3) / sin^2(t1 + t3), with Snell's eta1 sin t1 = eta2 sin t3 (t1 > 0).
void lectureFresnel(double theta1, double eta1, double eta2, double& par, double& perp) {
    const double theta3 = std::asin(eta1 / eta2 * std::sin(theta1));
    par = std::pow(std::tan(theta1 - theta3), 2) / std::pow(std::tan(theta1 + theta3), 2);
    perp = std::pow(std::sin(theta1 - theta3), 2) / std::pow(std::sin(theta1 + theta3), 2);
}
}  // namespace

TEST(Fresnel, NormalIncidenceEqualsR0) {
    const std::initializer_list<std::pair<float, float>> media = {
        {1.0f, 1.5f}, {1.0f, 1.33f}, {1.0f, 2.4f}, {1.5f, 1.0f}, {1.33f, 1.0f}};
    for (const auto& [eta1, eta2] : media) {
        const double r0 = std::pow((eta1 - eta2) / (eta1 + eta2), 2.0);  // by hand, e.g. 0.04 for glass
        const FresnelTerms f = fresnelExact(1.0f, eta1, eta2);
        EXPECT_NEAR(f.parallel, r0, 1e-6) << eta1 << " -> " << eta2;
        EXPECT_NEAR(f.perpendicular, r0, 1e-6);
        EXPECT_NEAR(f.average, r0, 1e-6);
        EXPECT_NEAR(fresnelSchlick(1.0f, eta1, eta2), r0, 1e-6);
        EXPECT_NEAR(fresnelR0(eta1, eta2), r0, 1e-6);
    }
    EXPECT_NEAR(fresnelR0(1.0f, 1.5f), 0.04f, 1e-6);
}

TEST(Fresnel, ExactMatchesTheLecturesTanAndSinForms) {
    for (double deg : {10.0, 30.0, 45.0, 60.0, 75.0, 85.0})
        for (double eta2 : {1.33, 1.5, 2.0}) {
            double par = 0.0, perp = 0.0;
            lectureFresnel(deg * kPiD / 180.0, 1.0, eta2, par, perp);
            const FresnelTerms f = fresnelExact(float(std::cos(deg * kPiD / 180.0)), 1.0f, float(eta2));
            EXPECT_NEAR(f.parallel, par, 2e-5) << deg << " deg, eta2 " << eta2;
            EXPECT_NEAR(f.perpendicular, perp, 2e-5) << deg << " deg, eta2 " << eta2;
            EXPECT_NEAR(f.average, 0.5 * (par + perp), 2e-5);
        }
    // Brewster's angle, tan theta_B = eta2 / eta1: the parallel polarisation is not reflected at all.
    EXPECT_NEAR(fresnelExact(float(std::cos(std::atan(1.5))), 1.0f, 1.5f).parallel, 0.0f, 1e-6);
    // Grazing incidence reflects everything.
    EXPECT_NEAR(fresnelExact(0.0f, 1.0f, 1.5f).average, 1.0f, 1e-6);
}

TEST(Fresnel, TotalInternalReflectionPastTheCriticalAngle) {
    const double critical = std::asin(1.0 / 1.5);  // 41.8 degrees, glass to air
    const FresnelTerms below = fresnelExact(float(std::cos(critical - 0.01)), 1.5f, 1.0f);
    const FresnelTerms above = fresnelExact(float(std::cos(critical + 0.01)), 1.5f, 1.0f);
    EXPECT_FALSE(below.totalInternal);
    EXPECT_LT(below.average, 1.0f);
    EXPECT_TRUE(above.totalInternal);
    EXPECT_EQ(above.average, 1.0f);
}

// Schlick's approximation is exact at 0 and 90 degrees; in between, for dielectrics from air with
// 1.33 <= eta <= 2 (water to dense glass), it stays within 0.061 of the exact average (the largest
// gap, found by sampling every 0.01 degree, is 0.0599 for water and 0.0357 for eta = 1.5, near 80 deg).
TEST(Fresnel, SchlickAgreesWithTheExactCurveWithinTheKnownBound) {
    for (float eta : {1.33f, 1.5f, 1.7f, 2.0f}) {
        double worst = 0.0;
        for (int k = 0; k <= 9000; ++k) {
            const float c = float(std::cos(k / 100.0 * kPiD / 180.0));
            worst = std::max(worst, double(std::fabs(fresnelSchlick(c, 1.0f, eta) - fresnelExact(c, 1.0f, eta).average)));
        }
        EXPECT_LT(worst, 0.061) << "eta " << eta;
        if (eta == 1.5f) {
            EXPECT_LT(worst, 0.036);
        }
        EXPECT_NEAR(fresnelSchlick(0.0f, 1.0f, eta), 1.0f, 1e-6);
    }
}

// Numerical integration over the outgoing hemisphere: the energy a lobe reflects for light from
// direction theta_i is the integral of n(k_e) lobe(w_o) cos(theta_o) dw_o (midpoint rule, 360 x 720
// cells; its own error is below 0.2%, 0.5% for k_e = 512). Phong's (k_e + 2) / 2pi makes that exactly 1
// at normal incidence and less elsewhere (the horizon cuts the lobe). Blinn-Phong's (k_e + 8) / 8pi is
// the usual approximation of the exact factor (k_e + 2)(k_e + 4) / (8pi (2^(-k_e/2) + k_e)): it
// overshoots by at most 7.5% (k_e = 8, normal incidence; 2.4% at k_e = 1, 0.4% at 512) and is below 1
// from 30 degrees on; the exact factor stays <= 1 everywhere. Without normalisation the reflected
// energy falls as 2pi / (k_e + 2): the highlight dims as k_e grows, the lecture's "not energy conserving".
TEST(EnergyNormalization, NormalisedLobesIntegrateToAtMostOne) {
    auto integral = [](ReflectionModel model, float ke, double thetaI) {
        const glm::dvec3 n(0, 0, 1), i(std::sin(thetaI), 0, std::cos(thetaI));
        const glm::dvec3 r = 2.0 * glm::dot(n, i) * n - i;
        const int steps = 360;  // theta_o cells; phi_o gets twice as many
        double sum = 0.0;
        for (int a = 0; a < steps; ++a) {
            const double t = (a + 0.5) * (kPiD / 2.0) / steps;
            for (int b = 0; b < 2 * steps; ++b) {
                const double p = (b + 0.5) * (2.0 * kPiD) / (2 * steps);
                const glm::dvec3 o(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
                const double c = model == ReflectionModel::Phong ? glm::dot(r, o) : glm::dot(glm::normalize(i + o), n);
                sum += std::pow(std::max(c, 0.0), double(ke)) * std::cos(t) * std::sin(t);
            }
        }
        return sum * (kPiD / 2.0 / steps) * (2.0 * kPiD / (2 * steps));
    };
    for (float ke : {1.0f, 8.0f, 32.0f, 128.0f, 512.0f})
        for (double deg : {0.0, 30.0, 60.0, 85.0}) {
            const double lobe = integral(ReflectionModel::Phong, ke, deg * kPiD / 180.0);
            EXPECT_LE(lobe * lobeNormalization(ReflectionModel::Phong, ke), 1.005) << "Phong k_e " << ke << " at " << deg;
            EXPECT_GT(lobe * lobeNormalization(ReflectionModel::Phong, ke), 0.0);
            const double blinn = integral(ReflectionModel::BlinnPhong, ke, deg * kPiD / 180.0);
            const double k = double(ke);
            const double exact = (k + 2.0) * (k + 4.0) / (8.0 * kPiD * (std::pow(2.0, -k / 2.0) + k));
            EXPECT_LE(blinn * exact, 1.003) << "Blinn-Phong (exact factor) k_e " << ke << " at " << deg;
            EXPECT_LE(blinn * lobeNormalization(ReflectionModel::BlinnPhong, ke), deg == 0.0 ? 1.076 : 1.0)
                << "Blinn-Phong k_e " << ke << " at " << deg;
        }
    EXPECT_NEAR(integral(ReflectionModel::Phong, 32.0f, 0.0) * lobeNormalization(ReflectionModel::Phong, 32.0f), 1.0, 2e-3);
    EXPECT_NEAR(integral(ReflectionModel::Phong, 512.0f, 0.0) * lobeNormalization(ReflectionModel::Phong, 512.0f), 1.0, 5e-3);
    EXPECT_NEAR(integral(ReflectionModel::Phong, 8.0f, 0.0), 2.0 * kPiD / 10.0, 2e-3);
}

TEST(EnergyNormalization, LooksTheSameAtKe32AndKeepsEnergyElsewhere) {
    EXPECT_FLOAT_EQ(energySpecularScale(ReflectionModel::Phong, 32.0f), 1.0f);
    EXPECT_FLOAT_EQ(energySpecularScale(ReflectionModel::BlinnPhong, 32.0f), 1.0f);
    EXPECT_NEAR(energySpecularScale(ReflectionModel::Phong, 128.0f), 130.0f / 34.0f, 1e-5);
    EXPECT_NEAR(energySpecularScale(ReflectionModel::BlinnPhong, 1.0f), 9.0f / 40.0f, 1e-5);
    EXPECT_NEAR(lobeNormalization(ReflectionModel::Phong, 8.0f), 10.0 / (2.0 * kPiD), 1e-6);
    EXPECT_NEAR(lobeNormalization(ReflectionModel::BlinnPhong, 8.0f), 16.0 / (8.0 * kPiD), 1e-6);

    // In shadeTerms: the diffuse term is unchanged, spec is multiplied by the scale.
    const float a = 40.0f * 3.14159265f / 180.0f;
    const glm::vec3 towardLight(0.0f, std::sin(a), std::cos(a));
    LightingEnvironment env;
    env.eyeWorld = {0.0f, 0.0f, 10.0f};
    env.lights = {directional(-towardLight)};
    Material m = plainMaterial();
    for (ReflectionModel model : {ReflectionModel::Phong, ReflectionModel::BlinnPhong})
        for (float ke : {1.0f, 32.0f, 200.0f}) {
            m.ke = ke;
            env.model = model;
            env.normalization = SpecularNormalization::None;
            const ShadingTerms plain = shadeTerms(m, env, {0, 0, 0}, {0, 0, 1});
            env.normalization = SpecularNormalization::Energy;
            const ShadingTerms energy = shadeTerms(m, env, {0, 0, 0}, {0, 0, 1});
            EXPECT_EQ(energy.diffuse, plain.diffuse);
            const float scale = model == ReflectionModel::Phong ? (ke + 2.0f) / 34.0f : (ke + 8.0f) / 40.0f;
            EXPECT_NEAR(energy.specular.x, plain.specular.x * scale, 1e-6f);
        }
}

// The specular term is weighted by F(V.H): Blinn-Phong, light at 60 degrees, eye on the normal, so
// H is 30 degrees off both and V.H = cos 30.
TEST(Fresnel, WeightsTheSpecularTermAtTheAngleBetweenVAndH) {
    const float a = 60.0f * 3.14159265f / 180.0f;
    LightingEnvironment env;
    env.eyeWorld = {0.0f, 0.0f, 10.0f};
    env.lights = {directional(-glm::vec3(0.0f, std::sin(a), std::cos(a)))};
    const Material m = plainMaterial();
    const ShadingTerms plain = shadeTerms(m, env, {0, 0, 0}, {0, 0, 1});
    const double c = std::cos(a / 2.0f), r0 = 0.04;
    env.ior = 1.5f;
    env.fresnel = FresnelMode::Schlick;
    const ShadingTerms schlick = shadeTerms(m, env, {0, 0, 0}, {0, 0, 1});
    EXPECT_NEAR(schlick.specular.x, plain.specular.x * (r0 + (1.0 - r0) * std::pow(1.0 - c, 5.0)), 1e-6);
    EXPECT_EQ(schlick.diffuse, plain.diffuse);
    env.fresnel = FresnelMode::Exact;
    double par = 0.0, perp = 0.0;
    lectureFresnel(a / 2.0, 1.0, 1.5, par, perp);
    EXPECT_NEAR(shadeTerms(m, env, {0, 0, 0}, {0, 0, 1}).specular.x, plain.specular.x * 0.5 * (par + perp), 1e-6);
}

TEST(TermIsolation, EachTermAloneAndOneLightsShare) {
    LightingEnvironment env;
    env.ambient = {1, 1, 1};
    env.eyeWorld = {0.0f, 0.0f, 10.0f};
    env.lights = {directional({0, 0, -1}, 0.5f), directional(-glm::normalize(glm::vec3(0, 1, 1)), 0.25f)};
    Material m = plainMaterial();
    const ShadingTerms all = shadeTerms(m, env, {0, 0, 0}, {0, 0, 1});
    ASSERT_EQ(all.lights.size(), 2u);
    // Per light, by hand: light 0 head-on (N.I = 1, spec 1), light 1 at 45 degrees.
    EXPECT_NEAR(all.lights[0].diffuse.x, 0.5f * 0.6f * 0.5f, kEps);
    EXPECT_NEAR(all.lights[0].specular.x, 0.5f * 0.3f, kEps);
    EXPECT_NEAR(all.lights[1].diffuse.x, 0.25f * 0.6f * 0.5f * std::sqrt(0.5f), kEps);
    EXPECT_NEAR(all.diffuse.x, all.lights[0].diffuse.x + all.lights[1].diffuse.x, kEps);
    auto shown = [&](ShowTerm term, int light = 0) {
        env.show = TermView{term, light};
        return shadeTerms(m, env, {0, 0, 0}, {0, 0, 1}).total;
    };
    EXPECT_EQ(shown(ShowTerm::All), all.total);
    EXPECT_EQ(shown(ShowTerm::Ambient), glm::clamp(all.ambient, 0.0f, 1.0f));
    EXPECT_EQ(shown(ShowTerm::Diffuse), glm::clamp(all.diffuse, 0.0f, 1.0f));
    EXPECT_EQ(shown(ShowTerm::Specular), glm::clamp(all.specular, 0.0f, 1.0f));
    EXPECT_EQ(shown(ShowTerm::Light, 1), glm::clamp(all.lights[1].diffuse + all.lights[1].specular, 0.0f, 1.0f));
    EXPECT_EQ(shown(ShowTerm::Unlit), m.color);
}

// E, the light a glTF material gives off, is added before the clamp: L = E + k_a A C + sum ..., and
// "show": "emissive" draws it alone; without E the sum is what it always was.
TEST(TermIsolation, EmissionIsAddedToTheSum) {
    LightingEnvironment env;
    env.ambient = {1, 1, 1};
    env.eyeWorld = {0.0f, 0.0f, 10.0f};
    env.lights = {directional({0, 0, -1}, 0.5f)};
    Material m = plainMaterial();
    const ShadingTerms without = shadeTerms(m, env, {0, 0, 0}, {0, 0, 1});
    m.emissive = {0.25f, 0.0f, 2.0f};
    const ShadingTerms with = shadeTerms(m, env, {0, 0, 0}, {0, 0, 1});
    EXPECT_EQ(with.emissive, m.emissive);
    EXPECT_EQ(with.ambient, without.ambient);
    EXPECT_NEAR(with.shown.x, without.shown.x + 0.25f, kEps);
    EXPECT_NEAR(with.shown.y, without.shown.y, kEps);
    EXPECT_EQ(with.total.z, 1.0f);  // clamped
    env.show = TermView{ShowTerm::Emissive, 0};
    EXPECT_EQ(shadeTerms(m, env, {0, 0, 0}, {0, 0, 1}).total, glm::vec3(0.25f, 0.0f, 1.0f));
    env.show = TermView{ShowTerm::Ambient, 0};
    EXPECT_EQ(shadeTerms(m, env, {0, 0, 0}, {0, 0, 1}).total, glm::clamp(without.ambient, 0.0f, 1.0f));
}
