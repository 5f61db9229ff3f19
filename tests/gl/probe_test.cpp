// The pixel probe (app/core/probe/probe.hpp) against what the renderer draws: for pixels of every shading
// mode, the probe's 8-bit total must be the rendered pixel. The probe gets its numbers from the CPU
// reference, so this also pins the renderer to the reference at the probed pixels.
//
// Tolerances (per channel, out of 255), the same as the analytic tests':
//   flat, phong  1: GPU and CPU round the same formula differently by a few ulps, which can put a
//                value on either side of an 8-bit rounding boundary;
//   gouraud      2: llvmpipe interpolates the vertex colours with fixed-point weights, not exactly
//                the barycentrics of the pixel centre.
// Flat pixels are compared only where the pixels two to either side see the same triangle: at an
// edge the rasteriser's tie rule and the ray cast may pick different triangles (for gouraud and phong
// the colour is continuous there, but the same rule is used for all three).
#include "core/probe/probe.hpp"
#include "core/geometry/ray_cast.hpp"
#include "core/scene/scene_json.hpp"
#include "gl/gl_test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace shadelab;
using namespace shadelab::test;

namespace {

int maxChannelDifference(const glm::ivec3& a, const glm::ivec3& b) {
    return std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
}

int tolerance(ShadingMode mode) { return mode == ShadingMode::Gouraud ? 2 : 1; }

// A coarse icosphere (320 triangles, so flat facets are large) under threeLightScene()'s lights,
// rotated and scaled unevenly so the normal transform matters.
Scene litIcosphere() {
    Scene s = threeLightScene();
    s.objects[0].mesh = MeshSpec{};
    s.objects[0].mesh.type = MeshSpec::Type::IcoSphere;
    s.objects[0].mesh.subdivisions = 2;
    s.objects[0].material.ke = 24.0f;
    s.objects[0].material.ks = 0.6f;
    s.objects[0].transform.rotationDeg = {20.0f, 35.0f, 0.0f};
    s.objects[0].transform.scale = {1.15f, 0.9f, 1.0f};
    s.layout = Layout::Compare;
    s.width = 3 * 160;
    s.height = 160;
    return s;
}

struct Sweep {
    int checked[3] = {0, 0, 0};  // by ShadingMode
    int worst[3] = {0, 0, 0};
    int background = 0;
};

// Probes every `step`-th pixel of the image and compares it with the render.
Sweep compareGrid(const Rendered& r, int step) {
    const SceneRayCaster caster(r.scene, *r.geometry);
    Sweep sweep;
    for (int y = 2; y < r.scene.height - 2; y += step)
        for (int x = 2; x < r.scene.width - 2; x += step) {
            const ProbeResult p = probePixel(r.scene, *r.geometry, caster, x, y);
            const glm::ivec3 got = quantize(color(r.image, x, y));
            if (p.miss) {
                EXPECT_EQ(got, p.output8) << "background at " << x << "," << y;
                ++sweep.background;
                continue;
            }
            bool interior = true;
            for (const auto& [dx, dy] : {std::pair{-2, 0}, std::pair{2, 0}, std::pair{0, -2}, std::pair{0, 2}}) {
                const ProbeResult n = probePixel(r.scene, *r.geometry, caster, x + dx, y + dy);
                interior = interior && !n.miss && n.pane == p.pane && n.anchor.object == p.anchor.object &&
                           n.anchor.triangle == p.anchor.triangle;
            }
            if (!interior) continue;
            const auto mode = std::size_t(p.modes[0].mode);
            const int d = maxChannelDifference(got, p.output8);
            EXPECT_LE(d, tolerance(p.modes[0].mode)) << toString(p.modes[0].mode) << " pixel " << x << "," << y;
            sweep.worst[mode] = std::max(sweep.worst[mode], d);
            ++sweep.checked[mode];
        }
    return sweep;
}

// The brightest pixel of a pane: on this scene, the key light's highlight.
glm::ivec2 brightestPixel(const Image& image, const Pane& pane) {
    glm::ivec2 best(pane.x, pane.y);
    int bestSum = -1;
    for (int y = pane.y; y < pane.y + pane.height; ++y)
        for (int x = pane.x; x < pane.x + pane.width; ++x) {
            const std::uint8_t* p = image.pixel(x, y);
            if (p[0] + p[1] + p[2] > bestSum) bestSum = p[0] + p[1] + p[2], best = {x, y};
        }
    return best;
}

struct LayoutCase {
    const char* name;
    ReflectionModel reflection;
    OutputEncoding encoding;
};

class ProbeVersusRender : public ::testing::TestWithParam<LayoutCase> {};

}  // namespace

// All three modes at once (compare layout), every third pixel, and each pane's highlight.
TEST_P(ProbeVersusRender, EveryModeMatchesTheRenderedPixel) {
    Scene scene = litIcosphere();
    scene.reflection = GetParam().reflection;
    scene.outputEncoding = GetParam().encoding;
    const Rendered r = renderScene(scene);
    const Sweep sweep = compareGrid(r, 3);
    for (int mode = 0; mode < 3; ++mode) {
        EXPECT_GT(sweep.checked[mode], 250) << toString(ShadingMode(mode));
        RecordProperty(std::string("worst_") + toString(ShadingMode(mode)), sweep.worst[mode]);
    }
    EXPECT_GT(sweep.background, 1000);

    // The highlight: the specular share is most of the pixel there, so a wrong lobe cannot pass.
    const SceneRayCaster caster(r.scene, *r.geometry);
    for (const Pane& pane : layoutPanes(scene.layout, scene.shading, scene.width, scene.height)) {
        const glm::ivec2 at = brightestPixel(r.image, pane);
        const ProbeResult p = probePixel(r.scene, *r.geometry, caster, at.x, at.y);
        ASSERT_FALSE(p.miss) << toString(pane.mode);
        EXPECT_LE(maxChannelDifference(quantize(color(r.image, at.x, at.y)), p.output8), tolerance(pane.mode))
            << toString(pane.mode) << " highlight at " << at.x << "," << at.y;
        float specular = 0.0f;
        for (const ProbeEvaluation& e : p.modes[0].evaluations) specular = std::max(specular, e.terms.specular.g);
        EXPECT_GT(specular, 0.2f) << toString(pane.mode) << ": not a highlight";
    }
    if (HasFailure()) saveForInspection(std::string("probe_") + GetParam().name, r.image);
}

INSTANTIATE_TEST_SUITE_P(Layouts, ProbeVersusRender,
                         ::testing::Values(LayoutCase{"blinn_linear", ReflectionModel::BlinnPhong, OutputEncoding::Linear},
                                           LayoutCase{"phong_srgb", ReflectionModel::Phong, OutputEncoding::Srgb}),
                         [](const auto& p) { return std::string(p.param.name); });

// A spot light whose cone edge crosses the sphere: inside, in the smooth falloff, and outside the
// cone, every mode's pixel is the probe's (its CPU reference has the same falloff).
TEST(ProbeVersusRender, SpotLightConeAndFalloff) {
    Scene scene = litIcosphere();
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {1.5f, 2.5f, 3.0f};
    spot.direction = glm::vec3(0.35f, 0.1f, 0.0f) - spot.position;
    spot.outerConeDeg = 14.0f;
    spot.innerConeDeg = 6.0f;
    spot.intensity = 1.2f;
    scene.lights = {spot, scene.lights[2]};  // and the warm directional light, dim
    const Rendered r = renderScene(scene);
    const Sweep sweep = compareGrid(r, 3);
    for (int mode = 0; mode < 3; ++mode) EXPECT_GT(sweep.checked[mode], 250) << toString(ShadingMode(mode));
    // The cone covers part of the sphere: some visible points are in it, some in its falloff, some outside.
    const SceneRayCaster caster(r.scene, *r.geometry);
    int inside = 0, edge = 0, outside = 0;
    for (int y = 2; y < scene.height; y += 4)
        for (int x = 2 * 160; x < 3 * 160; x += 4) {
            const ProbeResult p = probePixel(r.scene, *r.geometry, caster, x, y);
            if (p.miss) continue;
            const glm::vec3 towardLight = glm::normalize(spot.position - p.posWorld);
            const float f = spotFalloff(spot, towardLight);
            (f >= 1.0f ? inside : f > 0.0f ? edge : outside) += 1;
        }
    EXPECT_GT(inside, 20);
    EXPECT_GT(edge, 20);
    EXPECT_GT(outside, 20);
    if (HasFailure()) saveForInspection("probe_spot", r.image);
}

// Layout diff, factor 1: A and B are each within their tolerance of the probe, so the difference
// pane is within the sum of both (2 + 1) of the probe's |A - B|.
TEST(ProbeVersusRender, DifferencePane) {
    Scene scene = litIcosphere();
    scene.layout = Layout::Diff;
    scene.diff = DiffSettings{ShadingMode::Gouraud, ShadingMode::Phong, 1.0f};
    const Rendered r = renderScene(scene);
    const SceneRayCaster caster(r.scene, *r.geometry);
    int checked = 0, nonZero = 0;
    for (int y = 4; y < scene.height; y += 4)
        for (int x = 2 * 160; x < 3 * 160; x += 4) {
            const ProbeResult p = probePixel(r.scene, *r.geometry, caster, x, y);
            if (p.miss) continue;
            ASSERT_EQ(p.modes.size(), 2u);
            EXPECT_LE(maxChannelDifference(quantize(color(r.image, x, y)), p.output8), 3) << "pixel " << x << "," << y;
            nonZero += p.output8 != glm::ivec3(0);
            ++checked;
        }
    EXPECT_GT(checked, 300);
    EXPECT_GT(nonZero, 100);
}

// With shadows the probe's occlusion is a ray cast and the renderer's a shadow map; they agree away
// from shadow edges, where the map's texels, bias and filtering move the edge (tests/gl/shadow_test.cpp:
// by up to ~0.03 world units). Pixels are compared where the probe's visibility is the same for the
// pixels four to either side (~0.1 world units on the plane at this size), in the umbra and in the light.
TEST(ProbeVersusRender, ShadowsAwayFromTheirEdges) {
    for (const char* name : {"shadow_point.json", "shadow_area_4x4.json", "shadow_spot.json"}) {
        SCOPED_TRACE(name);
        Scene scene = loadSceneFile(std::string(SHADELAB_SOURCE_DIR) + "/assets/scenes/" + name);
        scene.width = 240;
        scene.height = 135;
        const Rendered r = renderScene(scene);
        const SceneRayCaster caster(r.scene, *r.geometry);
        auto visibility = [&](int x, int y) {
            const ProbeResult p = probePixel(r.scene, *r.geometry, caster, x, y);
            return p.miss ? -1.0f : p.modes[0].evaluations[0].lights[0].visibility;
        };
        int lit = 0, umbra = 0;
        for (int y = 4; y < scene.height - 4; y += 2)
            for (int x = 4; x < scene.width - 4; x += 2) {
                const ProbeResult p = probePixel(r.scene, *r.geometry, caster, x, y);
                if (p.miss) continue;
                const float v = p.modes[0].evaluations[0].lights[0].visibility;
                if (v != 0.0f && v != 1.0f) continue;  // penumbra
                if (visibility(x - 4, y) != v || visibility(x + 4, y) != v || visibility(x, y - 4) != v ||
                    visibility(x, y + 4) != v)
                    continue;
                EXPECT_LE(maxChannelDifference(quantize(color(r.image, x, y)), p.output8), 1)
                    << "pixel " << x << "," << y << " visibility " << v;
                (v == 0.0f ? umbra : lit) += 1;
            }
        EXPECT_GT(lit, 2000);
        EXPECT_GT(umbra, 25);
        if (HasFailure()) saveForInspection(std::string("probe_shadows_") + name, r.image);
    }
}
