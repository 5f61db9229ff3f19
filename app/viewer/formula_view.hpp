#pragma once
// The formula overlay (key E, --formula) painted with Dear ImGui over the 3D view: the layout of
// core/figures/formula.hpp, measured with the panel's font (DejaVu Sans) at the UI scale, so the view
// shows what `--formula --output` writes into a PNG.
#include "core/probe/probe.hpp"
#include "core/scene/scene.hpp"
#include "viewer/panel.hpp"

struct ImFont;

namespace shadelab {

// `material`: whose k the formula shows (the probed surface's when `probe` hits, else this one);
// `view`: the 3D view in ImGui units; `framebufferScale` converts the panes' pixels to them. Returns
// the overlay's top (ImGui units), so the status message can sit above it. `font`: the panel's font
// rasterised at the formula's size (ImGuiLayer::formulaFont); null: the current font, magnified.
// `textSize`: the text size the layout is for (its main line kFormulaSize times that; 0: the current
// font's). The values under the symbols are drawn as large as the symbols (read from the back of a
// hall; the PNG keeps them smaller).
float drawFormulaOverView(const Scene& scene, const Material& material, const ProbeResult* probe, const UiRect& view,
                          float framebufferScale, ImFont* font = nullptr, float textSize = 0.0f);

}  // namespace shadelab
