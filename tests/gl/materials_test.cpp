// What a glTF material adds to the lecture's C, as the renderer draws it (issue 27): alpha MASK
// (cut-outs, and their shadows), alpha BLEND (over what is behind, back to front) and emission E
// (added to the sum). The model is assets/models/material_panels.gltf before a wall
// (tests/scenes/material_panels.json); the references are the probe's CPU evaluation and the same
// scene drawn without the panels.
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

// The panels' scene in `mode`, framed as frameIfNeeded leaves it (sRGB output: a glTF model).
Scene panelsScene(ShadingMode mode, bool shadows = false) {
    Scene s = loadSceneFile(std::string(SHADELAB_SOURCE_DIR) + "/tests/scenes/material_panels.json");
    s.shading = mode;
    s.shadows.enabled = shadows;
    frameIfNeeded(s, buildSceneGeometry(s));
    return s;
}

// The same scene with the panels moved behind the camera: what they are drawn over.
Scene withoutPanels(Scene s) {
    s.objects[1].transform.translation = glm::vec3(0.0f, 0.0f, 100.0f);
    return s;
}

glm::ivec2 pixelOf(const Scene& s, const glm::vec3& world) {
    const Pane pane = layoutPanes(s.layout, s.shading, s.width, s.height, s.diff).front();
    const glm::vec2 p = projectToImage(s, pane, world);
    return glm::ivec2(int(std::floor(p.x)), int(std::floor(p.y)));
}

glm::ivec3 pixel8(const Image& image, const glm::ivec2& p) { return quantize(color(image, p.x, p.y)); }

int maxDifference(const glm::ivec3& a, const glm::ivec3& b) {
    return std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
}

// Centre of square (i, j) of the cut-out's 4 x 4 checker (row 0 at the top); its alpha is 1 where i + j is even.
glm::vec3 checkerSquare(int i, int j) { return {-1.7f + (float(i) + 0.5f) * 0.25f, 0.5f - (float(j) + 0.5f) * 0.25f, 0.0f}; }

class Materials : public ::testing::TestWithParam<ShadingMode> {};

}  // namespace

// MASK: where the texel's alpha is 0 the wall shows through exactly; elsewhere the panel, as the probe
// evaluates it. Fails where alpha is ignored (the checker drawn solid).
TEST_P(Materials, MaskCutsOut) {
    const Scene scene = panelsScene(GetParam());
    const Rendered r = renderScene(scene), wall = renderScene(withoutPanels(scene));
    const SceneRayCaster caster(r.scene, *r.geometry);
    const int tolerance = GetParam() == ShadingMode::Gouraud ? 2 : 1;
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
            SCOPED_TRACE("square " + std::to_string(i) + "," + std::to_string(j));
            const glm::ivec2 p = pixelOf(scene, checkerSquare(i, j));
            if ((i + j) % 2 == 1) {
                EXPECT_EQ(pixel8(r.image, p), pixel8(wall.image, p));
                continue;
            }
            const ProbeResult probe = probePixel(r.scene, *r.geometry, caster, p.x, p.y);
            ASSERT_FALSE(probe.miss);
            EXPECT_EQ(probe.alphaMode, AlphaMode::Mask);
            EXPECT_FLOAT_EQ(probe.alpha, 1.0f);
            EXPECT_LE(maxDifference(pixel8(r.image, p), probe.output8), tolerance);
            EXPECT_GT(maxDifference(pixel8(r.image, p), pixel8(wall.image, p)), 20);
        }
    if (HasFailure()) saveForInspection(std::string("materials_mask_") + toString(GetParam()), r.image);
}

// BLEND: the pane's colour (the probe's, encoded) weighted by its alpha 0.5 over the wall's 8-bit value,
// as GL blends; the wall's depth is kept. Fails where alpha is ignored (an opaque blue pane).
TEST_P(Materials, BlendMixesOverWhatIsBehind) {
    const Scene scene = panelsScene(GetParam());
    const Rendered r = renderScene(scene), wall = renderScene(withoutPanels(scene));
    const SceneRayCaster caster(r.scene, *r.geometry);
    for (const glm::vec3& at : {glm::vec3(-0.3f, -0.3f, 0.0f), glm::vec3(0.0f), glm::vec3(0.3f, 0.2f, 0.0f)}) {
        const glm::ivec2 p = pixelOf(scene, at);
        const ProbeResult probe = probePixel(r.scene, *r.geometry, caster, p.x, p.y);
        ASSERT_FALSE(probe.miss);
        EXPECT_EQ(probe.alphaMode, AlphaMode::Blend);
        EXPECT_FLOAT_EQ(probe.alpha, 0.5f);
        const glm::vec3 expected = 0.5f * probe.modes[0].output * 255.0f + 0.5f * glm::vec3(pixel8(wall.image, p));
        const glm::ivec3 got = pixel8(r.image, p);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(float(got[k]), expected[k], 2.0f) << "channel " << k;
    }
    if (HasFailure()) saveForInspection(std::string("materials_blend_") + toString(GetParam()), r.image);
}

// E: the lamp's lower half emits (its stripe texture read at TEXCOORD_1) and its pixels are the probe's
// L = E + k_a A C + ...; `show: emissive` draws E alone. Fails without emission (the lamp dark).
TEST_P(Materials, EmissionIsAddedToTheSum) {
    const Scene scene = panelsScene(GetParam());
    ASSERT_TRUE(scene.emissiveModel);
    const Rendered r = renderScene(scene);
    const SceneRayCaster caster(r.scene, *r.geometry);
    const int tolerance = GetParam() == ShadingMode::Gouraud ? 2 : 1;
    const glm::ivec2 lit = pixelOf(scene, {1.2f, -0.25f, 0.0f}), dark = pixelOf(scene, {1.2f, 0.25f, 0.0f});
    for (const glm::ivec2& p : {lit, dark}) {
        const ProbeResult probe = probePixel(r.scene, *r.geometry, caster, p.x, p.y);
        ASSERT_FALSE(probe.miss);
        EXPECT_LE(maxDifference(pixel8(r.image, p), probe.output8), tolerance);
    }
    const ProbeResult probe = probePixel(r.scene, *r.geometry, caster, lit.x, lit.y);
    EXPECT_EQ(probe.material.emissive, glm::vec3(2.0f, 1.0f, 0.5f));  // factor x strength x the white stripe
    EXPECT_EQ(probePixel(r.scene, *r.geometry, caster, dark.x, dark.y).material.emissive, glm::vec3(0.0f));  // the black stripe
    EXPECT_GT(pixel8(r.image, lit).r, pixel8(r.image, dark).r + 60);

    Scene alone = scene;
    alone.show.term = ShowTerm::Emissive;
    const Rendered e = renderScene(alone);
    EXPECT_EQ(pixel8(e.image, lit), glm::ivec3(255, 255, 188));  // clamp(2, 1, 0.5), sRGB-encoded
    EXPECT_EQ(pixel8(e.image, dark), glm::ivec3(0, 0, 0));
    if (HasFailure()) saveForInspection(std::string("materials_emission_") + toString(GetParam()), r.image);
}

INSTANTIATE_TEST_SUITE_P(EveryMode, Materials, ::testing::Values(ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong),
                         [](const ::testing::TestParamInfo<ShadingMode>& i) { return std::string(toString(i.param)); });

// A cut-out casts a cut-out shadow: lit from above and in front, the checker's bottom row falls on the
// wall below the panel, dark under its opaque squares and lit under its holes. Fails where the shadow
// pass ignores alpha (the whole row dark).
TEST(MaterialShadows, CutOutCastsACutOutShadow) {
    Scene scene = panelsScene(ShadingMode::Phong, true);
    scene.lights[0].direction = glm::vec3(0.0f, -1.0f, -1.0f);  // the shadow lands 0.6 below (the wall is 0.6 behind)
    const Rendered r = renderScene(scene), wall = renderScene(withoutPanels(scene));
    for (int i = 0; i < 4; ++i) {
        SCOPED_TRACE("column " + std::to_string(i));
        const glm::ivec2 p = pixelOf(scene, checkerSquare(i, 3) + glm::vec3(0.0f, -0.6f, -0.6f));
        const glm::ivec3 got = pixel8(r.image, p), open = pixel8(wall.image, p);
        if ((i + 3) % 2 == 1) EXPECT_LE(maxDifference(got, open), 2);  // a hole: lit as if the panel were not there
        else EXPECT_GT(maxDifference(got, open), 30);                  // an opaque square: its shadow
    }
    if (HasFailure()) saveForInspection("materials_shadow", r.image);
}
