#include "viewer/formula_view.hpp"

#include "core/figures/formula.hpp"
#include "core/geometry/camera.hpp"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace shadelab {
namespace {

ImU32 imColor(Rgba8 c) { return IM_COL32(c.r, c.g, c.b, c.a); }

// The formula and the panes' lines laid out for a band `viewWidth` wide, from its top: the formula
// centred, then each pane's line above that pane. The layout of core/figures/formula.hpp (the same as
// --formula's PNG), its parts moved into the band.
struct Band {
    FormulaOverlay overlay;
    TextMetrics metrics;
    float height = 0.0f;
};
Band layoutBand(const Scene& scene, const Material& material, const ProbeResult* probe, float viewWidth,
                const FormulaBandStyle& style) {
    ImFont* font = style.font ? style.font : ImGui::GetFont();
    const float textSize = style.textSize > 0.0f ? style.textSize : ImGui::GetFontSize();
    Band b{{},
           TextMetrics{[font](const std::string& s, float size) {
                           return font->CalcTextSizeA(size, FLT_MAX, 0.0f, s.c_str()).x;
                       },
                       font->Ascent / font->FontSize}};
    const bool hit = probe && !probe->miss;
    FormulaInput in = formulaInput(scene, hit ? probe->material : material);
    if (hit) {
        in.probed = probedTerms(*probe);
        in.probedAt = probedPlace(*probe);
    }
    in.valueSize = 1.0f;
    std::vector<FormulaPane> panes;
    const float scale = style.framebufferScale;
    for (const Pane& p : layoutPanes(scene.layout, scene.shading, scene.width, scene.height, scene.diff))
        panes.push_back({float(p.x) / scale, float(p.y) / scale, float(p.width) / scale, float(p.height) / scale,
                         p.mode, p.difference});
    b.overlay = layoutFormulaOverlay(in, viewWidth, 0.0f, panes, textSize, b.metrics);
    const float margin = 0.5f * textSize;
    b.overlay.y = margin;
    float bottom = b.overlay.y + b.overlay.formula.height;
    for (FormulaNote& n : b.overlay.notes) {
        n.y = std::round(b.overlay.y + b.overlay.formula.height + margin + n.pad);
        bottom = std::max(bottom, n.y + n.size + n.pad);
    }
    b.height = std::ceil(bottom + margin);
    return b;
}

}  // namespace

float formulaBandHeight(const Scene& scene, const Material& material, const ProbeResult* probe, float viewWidth,
                        const FormulaBandStyle& style) {
    return layoutBand(scene, material, probe, viewWidth, style).height;
}

void drawFormulaBand(const Scene& scene, const Material& material, const ProbeResult* probe, const UiRect& band,
                     const FormulaBandStyle& style) {
    ImFont* font = style.font ? style.font : ImGui::GetFont();
    const Band b = layoutBand(scene, material, probe, band.width, style);
    const FormulaOverlay& o = b.overlay;
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    const ImU32 backing = IM_COL32(0, 0, 0, kFormulaBackingAlpha);
    draw->PushClipRect(ImVec2(band.x, band.y), ImVec2(band.x + band.width, band.y + band.height), true);
    draw->AddRectFilled(ImVec2(band.x, band.y), ImVec2(band.x + band.width, band.y + band.height),
                        IM_COL32(24, 24, 30, 255));
    for (const FormulaNote& n : o.notes) {
        const ImVec2 at(band.x + n.x, band.y + n.y);
        draw->AddRectFilled(ImVec2(at.x - n.pad, at.y - n.pad), ImVec2(at.x + n.width + n.pad, at.y + n.size + n.pad),
                            backing, n.pad);
        draw->AddText(font, n.size, at, IM_COL32(235, 235, 235, 255), n.text.c_str());
    }
    const FormulaLayout& f = o.formula;
    const ImVec2 origin(band.x + o.x, band.y + o.y);
    draw->AddRectFilled(origin, ImVec2(origin.x + f.width, origin.y + f.height), backing, f.corner);
    for (const FormulaBox& box : f.boxes) {
        if (!box.isolated) continue;
        Rgba8 tint = termColor(box.term);
        tint.a = kIsolatedBoxAlpha;
        draw->AddRectFilled(ImVec2(origin.x + box.x0, origin.y + box.y0), ImVec2(origin.x + box.x1, origin.y + box.y1),
                            imColor(tint), 0.25f * (box.y1 - box.y0));
    }
    for (const FormulaRun& r : f.runs)
        draw->AddText(font, r.size,
                      ImVec2(std::round(origin.x + r.x), std::round(origin.y + r.baseline - b.metrics.ascent * r.size)),
                      imColor(r.color), r.text.c_str());
    draw->PopClipRect();
}

}  // namespace shadelab
