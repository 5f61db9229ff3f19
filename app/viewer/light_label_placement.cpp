#include "viewer/light_label_placement.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace shadelab {

bool rectOnModel(const LightLabelArea& a, const LabelRect& r) {
    for (const LabelDisc& m : a.models) {
        const glm::vec2 d = glm::clamp(m.centre, r.lo, r.hi) - m.centre;
        if (glm::dot(d, d) < m.radius * m.radius) return true;
    }
    return false;
}

bool rectClear(const LightLabelArea& a, const LabelRect& r, float gap) {
    if (rectOnModel(a, r)) return false;
    for (const LabelRect& t : a.taken)
        if (r.lo.x < t.hi.x + gap && t.lo.x < r.hi.x + gap && r.lo.y < t.hi.y + gap && t.lo.y < r.hi.y + gap)
            return false;
    return true;
}

LabelPlacement placeLightLabel(const LightLabelArea& a, glm::vec2 at, float gap, glm::vec2 size, float pad,
                               float step) {
    // The text's top-left corner kept inside the area, as view_overlays.cpp's labelBox does.
    const auto inside = [&](glm::vec2 p) {
        return glm::vec2(std::max(std::min(p.x, a.hi.x - size.x - pad), a.lo.x + pad),
                         std::max(std::min(p.y, a.hi.y - size.y - pad), a.lo.y + pad));
    };
    const float separation = kLabelSeparation * size.y;
    const auto clear = [&](glm::vec2 p) { return rectClear(a, LabelRect{p - pad, p + size + pad}, separation); };
    // Right, left, above, below; then the corners: below right, below left, above right, above left.
    const glm::vec2 beside[] = {{at.x + gap, at.y - size.y * 0.5f},
                                {at.x - gap - size.x, at.y - size.y * 0.5f},
                                {at.x - size.x * 0.5f, at.y - gap - size.y},
                                {at.x - size.x * 0.5f, at.y + gap},
                                {at.x + gap, at.y + gap},
                                {at.x - gap - size.x, at.y + gap},
                                {at.x + gap, at.y - gap - size.y},
                                {at.x - gap - size.x, at.y - gap - size.y}};
    for (const glm::vec2& p : beside)
        if (clear(inside(p))) return {inside(p), false};
    // Out from the nearest model's centre (up when the marker is at it; straight down from the area's
    // top when there is no model: away from the pane labels).
    const LabelDisc* nearest = nullptr;
    float best = 1e30f;
    for (const LabelDisc& m : a.models) {
        const float d = glm::length(at - m.centre) - m.radius;
        if (d < best) {
            best = d;
            nearest = &m;
        }
    }
    glm::vec2 u = nearest ? at - nearest->centre : glm::vec2(0.0f, 1.0f);
    const float len = glm::length(u);
    u = len > 1e-3f ? u / len : glm::vec2(0.0f, -1.0f);
    const float reach = glm::length(a.hi - a.lo);
    for (float t = gap; t < reach; t += step) {
        const glm::vec2 c = at + u * t;  // the box's centre, then its nearest point to the marker
        const glm::vec2 p = inside(c - size * 0.5f + u * size * 0.5f);
        if (clear(p)) return {p, true};
    }
    return {inside(beside[0]), false};
}

}  // namespace shadelab
