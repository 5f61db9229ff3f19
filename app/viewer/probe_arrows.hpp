#pragma once
// The pixel probe's arrows in the 3D view: N, V, I_l, R(I_l) and H_l where the probed mode evaluates
// the formula. GL-free and without ImGui: the desktop viewer (viewer/probe_view.hpp labels them) and
// the web page (app/web) both draw them with the renderer's OverlayRenderer.
#include "core/probe/probe.hpp"
#include "core/scene/scene.hpp"
#include "render/overlay_renderer.hpp"

#include <string>
#include <vector>

namespace shadelab {

struct ProbeArrow {
    OverlayArrow arrow;
    std::string label;  // drawn at the tip; empty for the marker at the probed point
};

// At each evaluation of the probe (phong: the point; flat: the centroid; gouraud: the three corners)
// N and V, and for each light (only `selectedLight` when it names one) I, R(I) and H, as unit vectors
// drawn at a length that looks the same wherever the point is; plus a cross at the probed point. All
// in the probed pane only: the other panes of a compare layout evaluate the formula elsewhere.
// With `intersection` (the viewer's key I) instead the lecture's "At the Intersection" at the probed
// point: I arriving from the eye, N, the mirror direction R and the refracted T (Snell's law at the
// surface, core/shading/environment.hpp), labelled with theta_i, theta_t, eta_i, eta_t and the exact
// Fresnel split R_par, R_perp, R and 1 - R (as core/figures/intersection_image.hpp draws it headless).
std::vector<ProbeArrow> probeArrows(const Scene& scene, const ProbeResult& probe, int selectedLight, bool intersection);

}  // namespace shadelab
