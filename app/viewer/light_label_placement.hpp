#pragma once
// Where a light's label goes over the view (view_overlays.cpp, drawLightLabels), GL- and ImGui-free so it can be
// tested: off the models (a label once read "0 point" over all three spheres) and clear of the boxes
// already taken in the pane (the pane labels above, the labels placed before, a border arrow's head), so
// no two labels touch (at 2x the labels of presets 18 and 19 once ran into their arrow's head).
// Units are the view's (ImGui's), y down.
#include <glm/vec2.hpp>

#include <vector>

namespace shadelab {

// A model's outline in the pane: the disc its bounding sphere covers.
struct LabelDisc {
    glm::vec2 centre;
    float radius;
};
struct LabelRect {
    glm::vec2 lo, hi;
};
// The part of a pane the labels keep inside (below the pane labels), the models they keep off and the
// boxes they keep `gap` away from.
struct LightLabelArea {
    glm::vec2 lo, hi;
    std::vector<LabelDisc> models;
    std::vector<LabelRect> taken;
};

// How far apart two label boxes stay, in text heights (a font's size): a visible gap, smaller than the
// labels' own padding (0.3 of the font).
constexpr float kLabelSeparation = 0.15f;

bool rectOnModel(const LightLabelArea& a, const LabelRect& r);
// Off every model and more than `gap` from every taken box.
bool rectClear(const LightLabelArea& a, const LabelRect& r, float gap);

// A label of text `size` with `pad` around it (its box) for a marker at `at`: `text` is the text's
// top-left corner, kept inside the area; `tied`: moved away from the marker, to be tied to it by a line.
struct LabelPlacement {
    glm::vec2 text;
    bool tied = false;
    LabelRect box(glm::vec2 size, float pad) const { return {text - pad, text + size + pad}; }
};
// Beside the marker (right, left, above, below, then the four corners, `gap` away) where that is clear
// (rectClear, kLabelSeparation text heights apart);
// else moved out along the line from the nearest model's centre through the marker, `step` at a time,
// until it is clear. Where nothing is clear (a model filling the pane) it stays right of the marker.
LabelPlacement placeLightLabel(const LightLabelArea& a, glm::vec2 at, float gap, glm::vec2 size, float pad, float step);

}  // namespace shadelab
