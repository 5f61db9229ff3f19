// Multisample anti-aliasing (render/multisample_target.hpp, --msaa): with one sample the image is
// exactly what a frame drawn straight into the context's target is (the golden images' pixels); with
// four, the sphere's silhouette is blended with the background and nothing away from it changes.
// The renderer's own passes must work on a multisampled target too: the diff layout copies its two
// panes out of it, readPixels reads it, progressive frames resolve their sum into it.
#include "core/scene/scene_json.hpp"
#include "gl/gl_test_support.hpp"
#include "headless/headless.hpp"
#include "render/multisample_target.hpp"
#include "render/renderer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

using namespace shadelab;
using namespace shadelab::test;

namespace {

// The three-light sphere in Phong shading on a white background, so a silhouette pixel's blend with
// the background stands out from both. Phong's colour is continuous across the mesh's own edges, so
// only the silhouette can change (flat shading's facet edges are anti-aliased too: 32 levels).
Scene sphereScene() {
    Scene s = threeLightScene();
    s.shading = ShadingMode::Phong;
    s.background = {1.0f, 1.0f, 1.0f};
    s.width = 160, s.height = 120;
    return s;
}

Image render(const Scene& scene, int msaa) {
    auto geometry = std::make_shared<SceneGeometry>(buildSceneGeometry(scene));
    return renderHeadless(scene, geometry, ShaderLibrary(), backendUnderTest(), msaa);
}

int channelDifference(const Image& a, const Image& b, int x, int y) {
    int d = 0;
    for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a.pixel(x, y)[c]) - int(b.pixel(x, y)[c])));
    return d;
}

int maxDifference(const Image& a, const Image& b) {
    int d = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) d = std::max(d, channelDifference(a, b, x, y));
    return d;
}

// Whether a pixel of `image` shows something other than `background` (the clear colour is exact).
bool covered(const Image& image, int x, int y, const glm::ivec3& background) {
    const std::uint8_t* p = image.pixel(x, y);
    return glm::ivec3(p[0], p[1], p[2]) != background;
}

// Whether the square of radius r around (x, y) holds both covered and background pixels.
bool nearEdge(const Image& image, int x, int y, int r, const glm::ivec3& background) {
    const bool here = covered(image, x, y, background);
    for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
            const int u = std::clamp(x + dx, 0, image.width - 1), v = std::clamp(y + dy, 0, image.height - 1);
            if (covered(image, u, v, background) != here) return true;
        }
    return false;
}

// Strictly between the background and the colour `one` in every channel (1 level of slack at the
// ends), and at least 3 levels from both: a blend, not either colour.
bool between(const std::uint8_t* m, const std::uint8_t* one, const glm::ivec3& background) {
    int fromOne = 0, fromBackground = 0;
    for (int c = 0; c < 3; ++c) {
        const int lo = std::min(int(one[c]), background[c]), hi = std::max(int(one[c]), background[c]);
        if (m[c] < lo - 1 || m[c] > hi + 1) return false;
        fromOne = std::max(fromOne, std::abs(int(m[c]) - int(one[c])));
        fromBackground = std::max(fromBackground, std::abs(int(m[c]) - background[c]));
    }
    return fromOne >= 3 && fromBackground >= 3;
}

// Whether pixel (x, y) of `four` blends the background with the surface that `one` shows there or,
// where `one` shows background (the pixel's centre is not covered), at a neighbour.
bool blended(const Image& four, const Image& one, int x, int y, const glm::ivec3& background) {
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int u = std::clamp(x + dx, 0, one.width - 1), v = std::clamp(y + dy, 0, one.height - 1);
            const bool self = dx == 0 && dy == 0;
            if ((self || !covered(one, x, y, background)) && covered(one, u, v, background) &&
                between(four.pixel(x, y), one.pixel(u, v), background))
                return true;
        }
    return false;
}

}  // namespace

TEST(Msaa, OneSampleIsTheImageDrawnStraightIntoTheTarget) {
    const Scene scene = sphereScene();
    auto context = makeHeadlessContext(backendUnderTest(), scene.width, scene.height);
    Renderer renderer(context->getProcAddress());
    renderer.setGeometry(std::make_shared<SceneGeometry>(buildSceneGeometry(scene)));
    renderer.render(scene, context->target());
    const Image straight = readPixels(context->target());
    EXPECT_EQ(maxDifference(render(scene, 1), straight), 0);
    EXPECT_EQ(maxDifference(render(scene, 0), straight), 0);
}

TEST(Msaa, FourSamplesBlendTheSilhouetteAndChangeNothingElse) {
    const Scene scene = sphereScene();
    const Image one = render(scene, 1), four = render(scene, 4);
    saveForInspection("msaa_1", one);
    saveForInspection("msaa_4", four);
    const glm::ivec3 background = quantize(scene.background);
    // silhouette: the one-sample image's covered pixels with background among their 8 neighbours.
    int silhouette = 0, blendedNearEdge = 0, changedNearEdge = 0, changedFar = 0, worstFar = 0;
    for (int y = 0; y < one.height; ++y)
        for (int x = 0; x < one.width; ++x) {
            const int d = channelDifference(one, four, x, y);
            if (!nearEdge(one, x, y, 2, background)) {
                // Away from the silhouette every sample of a pixel sees the same surface (or none).
                worstFar = std::max(worstFar, d);
                changedFar += d > 2;
                continue;
            }
            changedNearEdge += d > 2;
            blendedNearEdge += blended(four, one, x, y, background);
            silhouette += covered(one, x, y, background) && nearEdge(one, x, y, 1, background);
        }
    EXPECT_EQ(changedFar, 0) << "largest difference away from the silhouette: " << worstFar;
    EXPECT_GT(silhouette, 100);
    EXPECT_GE(blendedNearEdge, silhouette / 2) << blendedNearEdge << " blended pixels along " << silhouette;
    EXPECT_GT(changedNearEdge, silhouette / 2);
}

TEST(Msaa, DiffLayoutSubtractsTheResolvedPanes) {
    Scene scene = sphereScene();
    scene.layout = Layout::Diff;
    scene.width = 240;
    scene.diff.factor = 4.0f;
    for (int msaa : {1, 4}) {
        const Image image = render(scene, msaa);
        const std::vector<Pane> panes = layoutPanes(scene.layout, scene.shading, scene.width, scene.height, scene.diff);
        ASSERT_EQ(panes.size(), 3u);
        int worst = 0, lit = 0;
        for (int y = 0; y < panes[2].height; ++y)
            for (int x = 0; x < panes[2].width; ++x) {
                const std::uint8_t* a = image.pixel(panes[0].x + x, panes[0].y + y);
                const std::uint8_t* b = image.pixel(panes[1].x + x, panes[1].y + y);
                const std::uint8_t* d = image.pixel(panes[2].x + x, panes[2].y + y);
                for (int c = 0; c < 3; ++c) {
                    const int expected = std::min(255, int(4 * std::abs(int(a[c]) - int(b[c]))));
                    worst = std::max(worst, std::abs(int(d[c]) - expected));
                    lit += d[c] > 0;
                }
            }
        EXPECT_LE(worst, 1) << "msaa " << msaa;
        EXPECT_GT(lit, 100) << "msaa " << msaa << ": Gouraud and Phong differ somewhere";
    }
}

TEST(Msaa, ReadPixelsResolvesAMultisampledTarget) {
    const Scene scene = sphereScene();
    auto context = makeHeadlessContext(backendUnderTest(), scene.width, scene.height);
    Renderer renderer(context->getProcAddress());
    renderer.setGeometry(std::make_shared<SceneGeometry>(buildSceneGeometry(scene)));
    MultisampleTarget msaa;
    const RenderTarget view = context->target();
    EXPECT_EQ(msaa.begin(view, 1).framebuffer, view.framebuffer);  // off: draw straight into the view
    EXPECT_FALSE(msaa.active());
    const RenderTarget target = msaa.begin(view, 4);
    ASSERT_TRUE(msaa.active());
    EXPECT_NE(target.framebuffer, view.framebuffer);
    EXPECT_GE(msaa.samples(), 2);
    renderer.render(scene, target);
    const Image direct = readPixels(target);
    msaa.resolveInto(view);
    EXPECT_EQ(maxDifference(direct, readPixels(view)), 0);
    EXPECT_GT(maxDifference(direct, render(scene, 1)), 2);  // it was anti-aliased
}

TEST(Msaa, ProgressiveFramesResolveTheirSumIntoAMultisampledTarget) {
    // The sum of the passes is single-sample: the complete image is the one-sample one, every sample
    // of a pixel the same (so the resolve changes nothing); overlays drawn after it are anti-aliased.
    Scene scene = loadSceneFile(std::string(SHADELAB_SOURCE_DIR) + "/assets/scenes/shadow_area_4x4.json");
    scene.width = 160, scene.height = 96;
    auto context = makeHeadlessContext(backendUnderTest(), scene.width, scene.height);
    Renderer renderer(context->getProcAddress());
    renderer.setGeometry(std::make_shared<SceneGeometry>(buildSceneGeometry(scene)));
    const RenderTarget view = context->target();
    renderer.render(scene, view);
    const Image onePass = readPixels(view);
    MultisampleTarget msaa;
    const RenderTarget target = msaa.begin(view, 4);
    Renderer::ProgressiveStatus status = renderer.renderProgressive(scene, target, 2, true);
    while (!status.complete()) status = renderer.renderProgressive(scene, target, 2, false);
    msaa.resolveInto(view);
    // 1 level: the passes are summed in floats (see progressive_test.cpp).
    EXPECT_LE(maxDifference(readPixels(view), onePass), 1);
}
