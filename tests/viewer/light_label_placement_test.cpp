// Where light labels go over the view (viewer/light_label_placement.hpp): beside their marker where
// that is clear, off the models, and never touching a box already taken in the pane (issue 31: at a 2x
// content scale the labels of presets 18 and 19 ran into their border arrow's head).
#include "viewer/light_label_placement.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace shadelab {
namespace {

// At a 2x content scale: a 36-unit font, its labels' padding (0.3 of it) and search step (a third).
constexpr float kFont = 36.0f, kPad = 0.3f * kFont, kStep = 0.33f * kFont;
const glm::vec2 kSize(99.0f, 36.0f);  // "0 area"

float apart(const LabelRect& a, const LabelRect& b) {  // the gap between two boxes (negative: they overlap)
    return std::max(std::max(a.lo.x - b.hi.x, b.lo.x - a.hi.x), std::max(a.lo.y - b.hi.y, b.lo.y - a.hi.y));
}

bool insideArea(const LightLabelArea& a, const LabelRect& r) {
    return r.lo.x >= a.lo.x - 1e-3f && r.lo.y >= a.lo.y - 1e-3f && r.hi.x <= a.hi.x + 1e-3f && r.hi.y <= a.hi.y + 1e-3f;
}

TEST(LightLabelPlacement, BesideTheMarkerWhereThatIsClear) {
    const LightLabelArea area{{0, 0}, {640, 480}, {{{320, 300}, 80}}, {}};
    const LabelPlacement p = placeLightLabel(area, {100, 100}, 15.0f, kSize, kPad, kStep);
    EXPECT_FALSE(p.tied);
    EXPECT_FLOAT_EQ(p.text.x, 115.0f);  // right of it, centred on it
    EXPECT_FLOAT_EQ(p.text.y, 100.0f - kSize.y * 0.5f);
}

TEST(LightLabelPlacement, OffTheModel) {
    // A marker on the model's rim: no place beside it is off the disc, so it moves out and is tied.
    const LightLabelArea area{{0, 0}, {640, 480}, {{{320, 240}, 150}}, {}};
    const LabelPlacement p = placeLightLabel(area, {320, 100}, 15.0f, kSize, kPad, kStep);
    EXPECT_FALSE(rectOnModel(area, p.box(kSize, kPad)));
    EXPECT_TRUE(insideArea(area, p.box(kSize, kPad)));
}

TEST(LightLabelPlacement, TwoLightsSideBySideKeepTheirLabelsApart) {
    // Two markers 20 units apart (two lights seen nearly behind each other): the second label does not
    // go where the first one is, nor touch it.
    LightLabelArea area{{0, 0}, {640, 480}, {{{320, 300}, 80}}, {}};
    const LabelRect first = placeLightLabel(area, {100, 100}, 15.0f, kSize, kPad, kStep).box(kSize, kPad);
    area.taken.push_back(first);
    const LabelRect second = placeLightLabel(area, {100, 120}, 15.0f, kSize, kPad, kStep).box(kSize, kPad);
    EXPECT_GE(apart(first, second), kLabelSeparation * kSize.y);
    EXPECT_FALSE(rectOnModel(area, second));
}

TEST(LightLabelPlacement, ClearOfABorderArrowsHead) {
    // Compare layout at 2x, preset 19's area light above the view: the middle pane (640..1280), its
    // arrow at the top border near the pane's right edge; the head's box taken. Right of the head the
    // pane ends: the label goes left of it, clear of the head and inside the pane.
    LightLabelArea area{{640, 432.5f}, {1280, 1488}, {{{960, 900}, 170}}, {}};
    const LabelRect head{{1162.25f, 450.5f}, {1197.6f, 488.1f}};
    area.taken.push_back(head);
    const glm::vec2 half = (head.hi - head.lo) * 0.5f;
    const float gap = std::max(half.x, half.y) + kPad + 2.0f * kLabelSeparation * kFont;
    const LabelRect box = placeLightLabel(area, head.lo + half, gap, kSize, kPad, kStep).box(kSize, kPad);
    EXPECT_GE(apart(box, head), kLabelSeparation * kSize.y);
    EXPECT_TRUE(insideArea(area, box));
    EXPECT_LT(box.hi.x, head.lo.x);
}

TEST(LightLabelPlacement, NothingClearStaysBesideTheMarker) {
    // A model filling the pane: right of the marker, inside the pane.
    const LightLabelArea area{{0, 0}, {640, 480}, {{{320, 240}, 1000}}, {}};
    const LabelPlacement p = placeLightLabel(area, {320, 240}, 15.0f, kSize, kPad, kStep);
    EXPECT_FALSE(p.tied);
    EXPECT_FLOAT_EQ(p.text.x, 335.0f);
}

}  // namespace
}  // namespace shadelab
