#include "viewer/probe_arrows.hpp"

#include "core/figures/intersection_image.hpp"
#include "core/shading/environment.hpp"
#include "core/shading/lighting.hpp"

#include <glm/geometric.hpp>

#include <cstdio>

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
const glm::vec4 kRefractedColor{0.47f, 1.0f, 0.55f, 1.0f};  // T (the intersection diagram)

// The intersection diagram's arrows at the probed point, with the normal its mode has there (phong:
// interpolated; flat: the face's; gouraud: the corners' weighted like the colours).
std::vector<ProbeArrow> intersectionArrows(const Scene& scene, const ProbeResult& probe) {
    const std::vector<ProbeEvaluation>& e = probe.modes[0].evaluations;
    glm::vec3 n = e[0].nrmWorld;
    if (e.size() == 3)
        n = glm::normalize(probe.anchor.barycentric.x * e[0].nrmWorld + probe.anchor.barycentric.y * e[1].nrmWorld +
                           probe.anchor.barycentric.z * e[2].nrmWorld);
    IntersectionPoint at;
    at.posWorld = probe.posWorld;
    at.nrmWorld = n;
    const IntersectionNumbers num = intersectionNumbers(scene, at);
    const glm::vec3 p = probe.posWorld, v = glm::normalize(scene.camera.eye - p);
    const EnvironmentTerm t = environmentTerm(Material{}, lightingEnvironment(scene), n, v);
    const float length = kArrowShare * glm::length(scene.camera.eye - p);
    auto fixed = [](const char* fmt, double x) {
        char b[48];
        std::snprintf(b, sizeof b, fmt, x);
        return std::string(b);
    };
    std::vector<ProbeArrow> arrows;
    const int pane = probe.pane;
    arrows.push_back({OverlayArrow{p, p, kMarkerColor, pane}, ""});
    arrows.push_back({OverlayArrow{p + length * v, p, kViewColor, pane},
                      "I   θ_i = " + fixed("%.1f°", num.thetaIDeg) + "   η_i = " + fixed("%.2f", num.etaI)});
    arrows.push_back({OverlayArrow{p, p + length * n, kNormalColor, pane}, "N"});
    arrows.push_back({OverlayArrow{p, p + length * t.reflectedDirection, kReflectedColor, pane},
                      "R = " + fixed("%.3f", num.r) + "  (R∥ " + fixed("%.3f", num.rParallel) + ", R⊥ " +
                          fixed("%.3f", num.rPerpendicular) + ")"});
    if (t.totalInternal) arrows.back().label += "   total internal reflection";
    else
        arrows.push_back({OverlayArrow{p, p + length * t.transmittedDirection, kRefractedColor, pane},
                          "T   θ_t = " + fixed("%.1f°", num.thetaTDeg) + "   η_t = " + fixed("%.2f", num.etaT) +
                              "   1 − R = " + fixed("%.3f", 1.0 - double(num.r))});
    return arrows;
}

}  // namespace

std::vector<ProbeArrow> probeArrows(const Scene& scene, const ProbeResult& probe, int selectedLight,
                                    bool intersection) {
    std::vector<ProbeArrow> arrows;
    if (probe.miss) return arrows;
    if (intersection && !probe.modes.empty() && !probe.modes[0].evaluations.empty())
        return intersectionArrows(scene, probe);
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
