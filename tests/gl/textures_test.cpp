// The object texture of the lecture's C (a glTF base colour texture and vertex colours) as the renderer
// draws it in each mode, against the probe's CPU evaluation (core/probe/probe.hpp) and against the
// untextured programs. The model is the project's checker globe (assets/models/make_models.py).
//
// Tolerances (per channel, out of 255) are the probe test's (flat, Phong 1; Gouraud 2). The GPU reads
// smaller mip levels where the texture is minified and the CPU reads the full-size image: they agree
// inside the checker's squares and can differ across their edges, so up to 2% of the pixels may be
// past the tolerance (none are on llvmpipe with this close camera: the worst pixel is 1 off).
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

const std::string kModels = std::string(SHADELAB_SOURCE_DIR) + "/assets/models/";

Scene globeScene(const std::string& model = "checker_globe.gltf") {
    Scene s = loadSceneFile(std::string(SHADELAB_SOURCE_DIR) + "/tests/scenes/textured_globe_compare.json");
    s.objects[0].mesh.path = s.objects[0].mesh.resolvedPath = kModels + model;
    s.camera.eye = {0.4f, 0.5f, 2.3f};  // close: the texture is magnified over most of the sphere
    s.width = 3 * 200;
    s.height = 200;
    return s;
}

int maxChannelDifference(const glm::ivec3& a, const glm::ivec3& b) {
    return std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
}

// How much of the image differs from `b` by more than 8/255 (share of all pixels).
double shareDiffering(const Image& a, const Image& b) {
    return double(compareImages(a, b, 8).differingPixels) / double(a.width * a.height);
}

}  // namespace

// Every mode, every third pixel: the probe's sampled C and its evaluation of the formula give the
// rendered pixel (flat and Gouraud: the per-face / per-vertex parts, combined with the texel per
// fragment as object_color.glsl does).
TEST(Textures, ProbeMatchesTheRenderedPixelInEveryMode) {
    const Rendered r = renderScene(globeScene());
    const SceneRayCaster caster(r.scene, *r.geometry);
    int checked[3] = {0, 0, 0}, over[3] = {0, 0, 0}, worst[3] = {0, 0, 0};
    for (int y = 2; y < r.scene.height - 2; y += 3)
        for (int x = 2; x < r.scene.width - 2; x += 3) {
            const ProbeResult p = probePixel(r.scene, *r.geometry, caster, x, y);
            if (p.miss) continue;
            bool interior = true;  // the same triangle two pixels to each side (see probe_test.cpp)
            for (const auto& [dx, dy] : {std::pair{-2, 0}, std::pair{2, 0}, std::pair{0, -2}, std::pair{0, 2}}) {
                const ProbeResult n = probePixel(r.scene, *r.geometry, caster, x + dx, y + dy);
                interior = interior && !n.miss && n.pane == p.pane && n.anchor.triangle == p.anchor.triangle;
            }
            if (!interior) continue;
            ASSERT_TRUE(p.textured);
            const auto mode = std::size_t(p.modes[0].mode);
            const int d = maxChannelDifference(quantize(color(r.image, x, y)), p.output8);
            const int tolerance = p.modes[0].mode == ShadingMode::Gouraud ? 2 : 1;
            if (d > tolerance) ++over[mode];
            worst[mode] = std::max(worst[mode], d);
            ++checked[mode];
        }
    for (int mode = 0; mode < 3; ++mode) {
        SCOPED_TRACE(toString(ShadingMode(mode)));
        EXPECT_GT(checked[mode], 400);
        EXPECT_LE(over[mode], checked[mode] / 50) << "worst " << worst[mode];
        RecordProperty(std::string("worst_") + toString(ShadingMode(mode)), worst[mode]);
    }
    if (HasFailure()) saveForInspection("textures_probe", r.image);
}

// The probe's C is the base colour times the texel: on a teal square of the checker it is teal.
TEST(Textures, ProbeReportsTheSampledColour) {
    const Rendered r = renderScene(globeScene());
    const SceneRayCaster caster(r.scene, *r.geometry);
    bool sawTeal = false, sawCream = false;
    for (int x = 500; x < 600 && !(sawTeal && sawCream); ++x) {
        const ProbeResult p = probePixel(r.scene, *r.geometry, caster, x, 100);
        if (p.miss) continue;
        EXPECT_EQ(p.baseColor, glm::vec3(1.0f, 0.95f, 0.9f));
        const glm::vec3 c = p.material.color;
        if (c.b > 1.5f * c.r) sawTeal = true;   // teal (40, 120, 130) times a bluish vertex colour
        if (c.r > 0.5f && c.r > c.b) sawCream = true;
    }
    EXPECT_TRUE(sawTeal);
    EXPECT_TRUE(sawCream);
}

// --no-textures ("textures": false) draws the untextured programs with each part's base colour
// factor: the same picture as the scene's own material colour set to that factor.
TEST(Textures, NoTexturesDrawsTheBaseColourFactor) {
    Scene off = globeScene();
    off.textures = false;
    Scene factor = globeScene();
    factor.objects[0].material.color = {1.0f, 0.95f, 0.9f};
    factor.objects[0].material.colorSet = true;
    const Rendered a = renderScene(off), b = renderScene(factor);
    EXPECT_EQ(compareImages(a.image, b.image).differingPixels, 0u);
    // ... and the texture changes a large part of every pane.
    const Rendered textured = renderScene(globeScene());
    for (const Pane& pane : layoutPanes(off.layout, off.shading, off.width, off.height)) {
        int differing = 0, drawn = 0;
        for (int y = pane.y; y < pane.y + pane.height; ++y)
            for (int x = pane.x; x < pane.x + pane.width; ++x) {
                const glm::ivec3 t = quantize(color(textured.image, x, y)), u = quantize(color(a.image, x, y));
                if (u != quantize(off.background)) ++drawn;
                if (maxChannelDifference(t, u) > 30) ++differing;
            }
        EXPECT_GT(differing, drawn / 3) << toString(pane.mode);
    }
}

// KHR_texture_transform: coordinates stored transformed back, with the extension restoring them
// (checker_globe_transform.gltf, its image beside it) draw what the plain coordinates draw.
TEST(Textures, TextureTransformDrawsLikeTheCoordinatesItStandsFor) {
    const Rendered plain = renderScene(globeScene());
    const Rendered transformed = renderScene(globeScene("checker_globe_transform.gltf"));
    EXPECT_LT(shareDiffering(plain.image, transformed.image), 0.0005);
}
