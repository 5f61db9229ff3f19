// Where the shadow maps look (render/cpu/shadow_projection.hpp): every object point a light can see lands
// inside the map, cube faces agree with the face the shader picks, and depths increase with distance.
#include "core/shading/lighting.hpp"
#include "render/cpu/shadow_projection.hpp"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

using namespace shadelab;

namespace {

// A sphere's box over a plane's box (the shipped shadow scenes).
const std::vector<Aabb> kObjects = {Aabb{{-4.0f, -1.0f, -4.0f}, {4.0f, -1.0f, 4.0f}},
                                    Aabb{{-0.7f, -0.7f, -0.7f}, {0.7f, 0.7f, 0.7f}}};

std::vector<glm::vec3> probePoints() {
    std::vector<glm::vec3> pts;
    for (int i = 0; i <= 8; ++i)
        for (int k = 0; k <= 8; ++k) pts.push_back({-4.0f + float(i), -1.0f, -4.0f + float(k)});
    for (int i = 0; i < 50; ++i) {
        const float a = float(i) * 2.4f, b = float(i) * 0.7f;
        pts.push_back(0.7f * glm::vec3(std::cos(a) * std::sin(b), std::cos(b), std::sin(a) * std::sin(b)));
    }
    return pts;
}

glm::vec3 ndc(const glm::mat4& m, const glm::vec3& p) {
    const glm::vec4 c = m * glm::vec4(p, 1.0f);
    return glm::vec3(c) / c.w;
}

}  // namespace

TEST(ShadowProjection, PointLightFacesMatchTheShadersFaceChoice) {
    Light l;
    l.position = {1.2f, 2.6f, 0.8f};
    const ShadowSettings s;
    const ShadowProjection sp = shadowProjection(l, kObjects, s);
    ASSERT_EQ(sp.clipFromWorld.size(), 6u);
    EXPECT_EQ(sp.size, s.mapSize);
    EXPECT_GT(sp.tanHalf, 1.0f);
    for (const glm::vec3& p : probePoints()) {
        const glm::vec3 d = p - l.position;
        const int face = cubeFace(d);
        const glm::vec3 c = ndc(sp.clipFromWorld[std::size_t(face)], p);
        // Inside the face, and not in its margin.
        EXPECT_LE(std::fabs(c.x), 1.0f / sp.tanHalf + 1e-5f) << face;
        EXPECT_LE(std::fabs(c.y), 1.0f / sp.tanHalf + 1e-5f) << face;
        EXPECT_GT(c.z, -1.0f);
        EXPECT_LT(c.z, 1.0f);
        // The shader's depth formula gives the same value as the matrix.
        const float ma = std::max({std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)});
        EXPECT_NEAR(sp.depthA - sp.depthB / ma, 0.5f * c.z + 0.5f, 1e-5f);
    }
}

TEST(ShadowProjection, DirectionalMapCoversTheObjects) {
    Light l;
    l.type = LightType::Directional;
    l.direction = {-0.5f, -1.4f, -0.4f};
    const ShadowProjection sp = shadowProjection(l, kObjects, ShadowSettings{});
    ASSERT_EQ(sp.clipFromWorld.size(), 1u);
    float nearer = 2.0f;
    for (const glm::vec3& p : probePoints()) {
        const glm::vec3 c = ndc(sp.clipFromWorld[0], p);
        EXPECT_LT(glm::max(std::fabs(c.x), std::fabs(c.y)), 1.0f);
        EXPECT_GT(c.z, -1.0f);
        EXPECT_LT(c.z, 1.0f);
        // Depth grows along the light's direction.
        const float further = ndc(sp.clipFromWorld[0], p + 0.1f * glm::normalize(l.direction)).z;
        EXPECT_GT(further, c.z);
        nearer = std::min(nearer, c.z);
    }
    // The map is 2 * half world units wide, half = 1 / |first row|: texelWorld is that over its size.
    const glm::mat4& m = sp.clipFromWorld[0];
    const float half = 1.0f / glm::length(glm::vec3(m[0][0], m[1][0], m[2][0]));
    EXPECT_NEAR(sp.texelWorld * float(sp.size), 2.0f * half, 1e-4f);
    EXPECT_LT(nearer, 0.0f);
}

// Each sample of an area light sees every object point in front of the light inside its map, and
// its matrix is the centre's minus a * uClip + b * vClip, as the shader computes it.
// A spot light's one view looks down its axis and is as wide as the outer cone (plus the filter's
// margin): the axis lands at the centre, a point on the outer cone just inside the edge.
TEST(ShadowProjection, SpotViewIsItsOuterCone) {
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {1.2f, 3.0f, 0.8f};
    spot.direction = glm::vec3(0.0f, -0.3f, 0.0f) - spot.position;
    spot.outerConeDeg = 30.0f;
    const ShadowSettings settings;
    const ShadowProjection sp = shadowProjection(spot, kObjects, settings);
    ASSERT_EQ(sp.clipFromWorld.size(), 1u);
    EXPECT_EQ(sp.size, settings.mapSize);
    const glm::vec3 axis = glm::normalize(spot.direction);
    const glm::vec3 centre = ndc(sp.clipFromWorld[0], spot.position + 3.0f * axis);
    EXPECT_NEAR(centre.x, 0.0f, 1e-5f);
    EXPECT_NEAR(centre.y, 0.0f, 1e-5f);
    const glm::vec3 side = glm::normalize(glm::cross(axis, glm::vec3(0, 1, 0)));
    const glm::vec3 edge = spot.position + 3.0f * (axis + side * std::tan(glm::radians(30.0f)));
    const glm::vec3 e = ndc(sp.clipFromWorld[0], edge);
    EXPECT_LT(std::max(std::fabs(e.x), std::fabs(e.y)), 1.0f);
    EXPECT_GT(std::max(std::fabs(e.x), std::fabs(e.y)), 0.97f);
    // Everything inside the cone lies between the view's near and far planes.
    int inside = 0;
    for (const glm::vec3& p : probePoints()) {
        const glm::vec4 c = sp.clipFromWorld[0] * glm::vec4(p, 1.0f);
        if (glm::dot(glm::normalize(p - spot.position), axis) < std::cos(glm::radians(30.0f))) continue;
        ++inside;
        EXPECT_GE(c.z / c.w, -1.0f) << p.x << "," << p.y << "," << p.z;
        EXPECT_LE(c.z / c.w, 1.0f) << p.x << "," << p.y << "," << p.z;
    }
    EXPECT_GT(inside, 10);
}

TEST(ShadowProjection, AreaSamplesSeeTheObjectsInFrontOfTheLight) {
    Light l;
    l.type = LightType::Area;
    l.position = {1.2f, 2.6f, 0.8f};
    l.size = {1.6f, 1.6f};
    l.samples = {4, 3};
    const ShadowProjection sp = shadowProjection(l, kObjects, ShadowSettings{});
    ASSERT_EQ(sp.clipFromWorld.size(), 12u);
    EXPECT_EQ(sp.size, ShadowSettings{}.areaMapSize);
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 4; ++i) {
            const glm::vec2 o = areaSampleOffset(i, j, l.samples);
            const glm::mat4& m = sp.clipFromWorld[std::size_t(j * 4 + i)];
            for (const glm::vec3& p : probePoints()) {
                const glm::vec4 shader = sp.centreClipFromWorld * glm::vec4(p, 1.0f) - o.x * sp.uClip - o.y * sp.vClip;
                const glm::vec4 direct = m * glm::vec4(p, 1.0f);
                EXPECT_NEAR(glm::length(shader - direct), 0.0f, 1e-4f);
                const glm::vec3 c = glm::vec3(direct) / direct.w;
                EXPECT_GT(direct.w, 0.0f);
                EXPECT_LT(glm::max(std::fabs(c.x), std::fabs(c.y)), 1.0f);
                EXPECT_GT(c.z, -1.0f);
                EXPECT_LT(c.z, 1.0f);
            }
        }
}

// All lights' layers in two texture arrays (ShadowLayout): each light's layers follow the previous
// light's of the same array, as many as its projection has views.
TEST(ShadowLayout, LightsTakeConsecutiveLayersOfTheirArray) {
    std::vector<Light> lights(5);
    lights[0].type = LightType::Point;
    lights[1].type = LightType::Area, lights[1].samples = {4, 2};
    lights[2].type = LightType::Spot, lights[2].direction = {0.0f, -1.0f, 0.0f};
    lights[3].type = LightType::Directional, lights[3].direction = {0.0f, -1.0f, 0.0f};
    lights[4].type = LightType::Area, lights[4].samples = {2, 3};
    for (Light& l : lights) l.position = {0.5f, 3.0f, 0.5f}, l.normal = {0.0f, -1.0f, 0.0f};
    const ShadowLayout layout = shadowLayout(lights, lights.size());
    EXPECT_EQ(layout.firstLayer, (std::vector<int>{0, 0, 6, 7, 8}));
    EXPECT_EQ(layout.layers, 8);       // point 6 + spot 1 + directional 1
    EXPECT_EQ(layout.areaLayers, 14);  // 4 x 2 + 2 x 3
    for (const Light& l : lights)
        EXPECT_EQ(std::size_t(shadowLayerCount(l)), shadowProjection(l, kObjects, ShadowSettings{}).clipFromWorld.size());
    EXPECT_EQ(shadowLayout(lights, 2).firstLayer, (std::vector<int>{0, 0}));  // only the lights drawn
}
