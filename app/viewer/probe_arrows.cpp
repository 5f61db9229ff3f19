#include "viewer/probe_arrows.hpp"

#include <glm/geometric.hpp>

namespace shadelab {
namespace {

// Arrow colours (linear RGB, drawn as is): the lecture's vectors, told apart at a glance.
const glm::vec4 kNormalColor{1.0f, 1.0f, 1.0f, 1.0f};
const glm::vec4 kViewColor{0.35f, 0.85f, 1.0f, 1.0f};
const glm::vec4 kLightColor{1.0f, 0.85f, 0.25f, 1.0f};
const glm::vec4 kReflectedColor{1.0f, 0.45f, 0.35f, 1.0f};
const glm::vec4 kHalfwayColor{0.55f, 1.0f, 0.45f, 1.0f};
const glm::vec4 kMarkerColor{1.0f, 0.3f, 1.0f, 1.0f};
// Arrow length as a share of the distance to the eye: about a quarter of the view's height at 45 degrees.
constexpr float kArrowShare = 0.2f;

}  // namespace

std::vector<ProbeArrow> probeArrows(const Scene& scene, const ProbeResult& probe, int selectedLight) {
    std::vector<ProbeArrow> arrows;
    if (probe.miss) return arrows;
    // Only in the probed pane: the other panes of a compare layout evaluate the formula elsewhere.
    const int pane = probe.pane;
    arrows.push_back({OverlayArrow{probe.posWorld, probe.posWorld, kMarkerColor, pane}, ""});
    const bool oneLight = selectedLight >= 0 && std::size_t(selectedLight) < scene.lights.size();
    for (const ModeProbe& m : probe.modes)
        for (const ProbeEvaluation& e : m.evaluations) {
            const glm::vec3 from = e.posWorld;
            const float length = kArrowShare * glm::length(scene.camera.eye - from);
            auto add = [&](const glm::vec3& dir, const glm::vec4& color, const std::string& label) {
                arrows.push_back({OverlayArrow{from, from + length * dir, color, pane}, label});
            };
            add(e.nrmWorld, kNormalColor, "N");
            add(e.viewWorld, kViewColor, "V");
            for (std::size_t l = 0; l < e.lights.size(); ++l) {
                if (oneLight && l != std::size_t(selectedLight)) continue;
                const std::string index = scene.lights.size() > 1 ? std::to_string(l) : "";
                const ProbeLight& p = e.lights[l];
                add(p.towardLight, kLightColor, "I" + index);
                add(glm::normalize(p.reflected), kReflectedColor, "R" + index);
                add(p.halfway, kHalfwayColor, "H" + index);
            }
        }
    return arrows;
}

}  // namespace shadelab
