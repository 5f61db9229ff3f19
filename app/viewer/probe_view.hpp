#pragma once
// The pixel probe in the viewer (core/probe/probe.hpp computes it): the labelled arrows N, V, I_l, R(I_l),
// H_l drawn in the 3D view where the probed mode evaluates the formula, and the panel's "Probe"
// section listing every term. Immediate mode, like panel.hpp: called every frame, no state.
#include "core/probe/probe.hpp"
#include "core/scene/scene.hpp"
#include "viewer/probe_arrows.hpp"

#include <string>
#include <vector>

namespace shadelab {

struct UiRect;

// The arrows' labels near their tips (where an arrow leaves its pane: where it crosses the border), on
// ImGui's foreground draw list, inside the arrows' pane, clear of each other and of `avoid` (the light
// labels). `framebufferScale` converts the renderer's pixels to ImGui units.
void drawProbeLabels(const Scene& scene, const std::vector<ProbeArrow>& arrows, const UiRect& view,
                     float framebufferScale, const std::vector<UiRect>& avoid = {});

// Where the probe is: "pixel 700,300, pane 2: object 0, triangle 1234" (panes numbered by paneName,
// as the Shader section's combo numbers them).
std::string probeWhere(const ProbeResult& probe);

// The panel's "Probe" section (inside the panel window). Returns true when "clear probe" is pressed.
bool probeSection(const Scene& scene, const ProbeResult& probe);

}  // namespace shadelab
