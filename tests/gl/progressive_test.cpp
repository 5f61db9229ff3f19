// Progressive area-light sampling (Renderer::renderProgressive, the viewer's way to stay interactive
// with an 8x8 area light): once every pass is summed, the image must be the one-pass render's; before
// that, a pass really is a subset of the samples (so these tests can fail).
//
// Tolerance: the passes are summed in 32-bit floats and divided by their count, which can move a
// value by a few ulps from the one-pass sum: 1 of 255 at a rounding boundary, nowhere more.
#include "core/scene/scene_json.hpp"
#include "gl/gl_test_support.hpp"
#include "render/renderer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <utility>

using namespace shadelab;
using namespace shadelab::test;

namespace {

// The shipped 4x4 soft-shadow scene, small.
Scene areaScene(int width = 160, int height = 96) {
    Scene s = loadSceneFile(std::string(SHADELAB_SOURCE_DIR) + "/assets/scenes/shadow_area_4x4.json");
    s.width = width, s.height = height;
    return s;
}

struct Difference {
    int max = 0;
    double mean = 0;  // per channel
};
Difference compare(const Image& a, const Image& b) {
    Difference d;
    for (std::size_t i = 0; i < a.rgba.size(); ++i) {
        if (i % 4 == 3) continue;
        const int delta = std::abs(int(a.rgba[i]) - int(b.rgba[i]));
        d.max = std::max(d.max, delta);
        d.mean += delta;
    }
    d.mean /= double(a.rgba.size()) * 0.75;
    return d;
}

// Renders `scene` in one pass and progressively with `stride`; returns both images, the image after
// the first pass, and the number of passes.
struct Runs {
    Image onePass, firstPass, progressive;
    int passes = 0;
};
Runs renderBoth(const Scene& scene, int stride) {
    Runs r;
    auto context = makeHeadlessContext(backendUnderTest(), scene.width, scene.height);
    Renderer renderer(context->getProcAddress());
    renderer.setGeometry(std::make_shared<SceneGeometry>(buildSceneGeometry(scene)));
    const RenderTarget target = context->target();
    renderer.render(scene, target);
    r.onePass = readPixels(target);
    Renderer::ProgressiveStatus status = renderer.renderProgressive(scene, target, stride, true);
    r.firstPass = readPixels(target);
    while (!status.complete()) status = renderer.renderProgressive(scene, target, stride, false);
    r.passes = status.passCount;
    r.progressive = readPixels(target);
    // A complete image is redrawn, not summed again.
    const Renderer::ProgressiveStatus again = renderer.renderProgressive(scene, target, stride, false);
    EXPECT_EQ(again.passesDone, status.passesDone);
    EXPECT_EQ(compare(readPixels(target), r.progressive).max, 0);
    return r;
}

}  // namespace

TEST(Progressive, PassOrderVisitsEveryFirstSampleOnceSpreadOverTheLight) {
    const std::vector<glm::ivec2> order = progressivePassOrder({4, 4});
    ASSERT_EQ(order.size(), 16u);
    std::set<std::pair<int, int>> seen;
    for (const glm::ivec2& o : order) seen.insert({o.x, o.y});
    EXPECT_EQ(seen.size(), 16u);
    // The first four passes take one sample from each 2x2 quadrant of the 4x4 cell.
    std::set<std::pair<int, int>> quadrants;
    for (int p = 0; p < 4; ++p) quadrants.insert({order[std::size_t(p)].x / 2, order[std::size_t(p)].y / 2});
    EXPECT_EQ(quadrants.size(), 4u);
    EXPECT_EQ(progressivePassOrder({3, 2}).size(), 6u);
}

TEST(Progressive, AllPassesSumToTheOnePassImage) {
    for (int stride : {2, 4}) {
        SCOPED_TRACE(stride);
        const Runs r = renderBoth(areaScene(), stride);
        EXPECT_EQ(r.passes, stride * stride);
        const Difference d = compare(r.onePass, r.progressive);
        EXPECT_LE(d.max, 1);
        EXPECT_LT(d.mean, 0.01);
        // One pass is a quarter (a sixteenth) of the samples: the soft shadow is visibly different.
        EXPECT_GT(compare(r.onePass, r.firstPass).max, 10);
        if (stride == 4) saveForInspection("progressive_first_pass", r.firstPass);
    }
}

// Flat and Gouraud clamp before interpolating, so their passes evaluate all samples; Phong panes split
// them. The compare layout draws all three into one sum; sRGB is encoded after the mean.
TEST(Progressive, CompareLayoutAndSrgbEncodingMatchTheOnePassImage) {
    Scene s = areaScene(240, 80);
    s.layout = Layout::Compare;
    s.outputEncoding = OutputEncoding::Srgb;
    const Runs r = renderBoth(s, 4);
    EXPECT_LE(compare(r.onePass, r.progressive).max, 1);
}

TEST(Progressive, DiffLayoutIsDrawnFromTheResolvedPanes) {
    Scene s = areaScene(240, 80);
    s.layout = Layout::Diff;
    s.diff.factor = 1.0f;  // the pane amplifies differences: at 1 a rounding step stays one step
    const Runs r = renderBoth(s, 2);
    EXPECT_LE(compare(r.onePass, r.progressive).max, 1);
}

// The stride is clamped to the light's grid: a 2x1 light takes two passes at most, a scene without
// area lights one.
TEST(Progressive, StrideIsClampedToTheSampleGrid) {
    Scene s = areaScene(64, 48);
    s.lights[0].samples = {2, 1};
    EXPECT_EQ(renderBoth(s, 8).passes, 2);
    s.lights[0].type = LightType::Point;
    const Runs r = renderBoth(s, 8);
    EXPECT_EQ(r.passes, 1);
    EXPECT_LE(compare(r.onePass, r.progressive).max, 1);
}
