#pragma once
// The formula overlay (key E, --formula) painted with Dear ImGui over the 3D view: the layout of
// core/figures/formula.hpp, measured with the panel's font (DejaVu Sans) at the UI scale, so the view
// shows what `--formula --output` writes into a PNG.
#include "core/probe/probe.hpp"
#include "core/scene/scene.hpp"
#include "viewer/panel.hpp"

struct ImFont;

namespace shadelab {

// The formula (key E, --formula) in a band of its own between the caption and the 3D view, so it
// never covers the model (in a 1200x800 window it once covered the sphere): the formula centred,
// and below it, above each pane, the line that says where that pane's mode evaluates it.
// `material`: whose k the formula shows (the probed surface's when `probe` hits, else this one);
// `viewWidth`: the view's width in ImGui units; `framebufferScale` converts the panes' pixels to them.
// `font`: the panel's font rasterised at the formula's size (ImGuiLayer::formulaFont); null: the current
// font, magnified. `textSize`: the text size the layout is for (its main line kFormulaSize times that;
// 0: the current font's). The values under the symbols are drawn as large as the symbols (read from
// the back of a hall; the PNG of `--formula --output`, drawn over the image, keeps them smaller).
struct FormulaBandStyle {
    float framebufferScale = 1.0f;
    ImFont* font = nullptr;
    float textSize = 0.0f;
};
// The band's height (ImGui units) for a view `viewWidth` wide.
float formulaBandHeight(const Scene& scene, const Material& material, const ProbeResult* probe, float viewWidth,
                        const FormulaBandStyle& style);
// Draws it into `band` (as wide as the view, formulaBandHeight high).
void drawFormulaBand(const Scene& scene, const Material& material, const ProbeResult* probe, const UiRect& band,
                     const FormulaBandStyle& style);

}  // namespace shadelab
