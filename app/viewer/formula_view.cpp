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

}  // namespace

float drawFormulaOverView(const Scene& scene, const Material& material, const ProbeResult* probe, const UiRect& view,
                          float framebufferScale, ImFont* font, float textSize) {
    if (!font) font = ImGui::GetFont();
    if (textSize <= 0.0f) textSize = ImGui::GetFontSize();
    const TextMetrics metrics{[font](const std::string& s, float size) {
                                  return font->CalcTextSizeA(size, FLT_MAX, 0.0f, s.c_str()).x;
                              },
                              font->Ascent / font->FontSize};
    const bool hit = probe && !probe->miss;
    FormulaInput in = formulaInput(scene, hit ? probe->material : material);
    if (hit) in.probed = probedTerms(*probe), in.probedAt = probedPlace(*probe);
    in.valueSize = 1.0f;
    std::vector<FormulaPane> panes;
    for (const Pane& p : layoutPanes(scene.layout, scene.shading, scene.width, scene.height, scene.diff))
        panes.push_back({float(p.x) / framebufferScale, float(p.y) / framebufferScale, float(p.width) / framebufferScale,
                         float(p.height) / framebufferScale, p.mode, p.difference});
    const FormulaOverlay o = layoutFormulaOverlay(in, view.width, view.height, panes, textSize, metrics);

    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    const ImU32 backing = IM_COL32(0, 0, 0, kFormulaBackingAlpha);
    draw->PushClipRect(ImVec2(view.x, view.y), ImVec2(view.x + view.width, view.y + view.height), true);
    for (const FormulaNote& n : o.notes) {
        const ImVec2 at(view.x + n.x, view.y + n.y);
        draw->AddRectFilled(ImVec2(at.x - n.pad, at.y - n.pad), ImVec2(at.x + n.width + n.pad, at.y + n.size + n.pad),
                            backing, n.pad);
        draw->AddText(font, n.size, at, IM_COL32(235, 235, 235, 255), n.text.c_str());
    }
    const FormulaLayout& f = o.formula;
    const ImVec2 origin(view.x + o.x, view.y + o.y);
    draw->AddRectFilled(origin, ImVec2(origin.x + f.width, origin.y + f.height), backing, f.corner);
    for (const FormulaBox& b : f.boxes) {
        if (!b.isolated) continue;
        Rgba8 tint = termColor(b.term);
        tint.a = kIsolatedBoxAlpha;
        draw->AddRectFilled(ImVec2(origin.x + b.x0, origin.y + b.y0), ImVec2(origin.x + b.x1, origin.y + b.y1),
                            imColor(tint), 0.25f * (b.y1 - b.y0));
    }
    for (const FormulaRun& r : f.runs)
        draw->AddText(font, r.size,
                      ImVec2(std::round(origin.x + r.x), std::round(origin.y + r.baseline - metrics.ascent * r.size)),
                      imColor(r.color), r.text.c_str());
    draw->PopClipRect();
    float top = origin.y;
    for (const FormulaNote& n : o.notes) top = std::min(top, view.y + n.y - n.pad);
    return top;
}

}  // namespace shadelab
