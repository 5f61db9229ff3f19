#include "viewer/probe_view.hpp"

#include "core/geometry/camera.hpp"
#include "core/ui/view_names.hpp"
#include "viewer/panel.hpp"

#include <imgui.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace shadelab {
namespace {

ImU32 imColor(const glm::vec4& c) { return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, c.a)); }

// What the screen shows for a linear colour: the scene's output encoding applied (swatches are drawn as is).
glm::vec3 displayed(const Scene& scene, const glm::vec3& linear) {
    if (scene.outputEncoding != OutputEncoding::Srgb) return linear;
    const glm::vec3 c = glm::clamp(linear, 0.0f, 1.0f);
    return {encodeSrgb(c.r), encodeSrgb(c.g), encodeSrgb(c.b)};
}

void swatch(const char* id, const glm::vec3& shown) {
    const float side = ImGui::GetFrameHeight();
    ImGui::ColorButton(id, ImVec4(shown.r, shown.g, shown.b, 1.0f), ImGuiColorEditFlags_NoTooltip, ImVec2(side, side));
}

void rgbRow(const char* term, const glm::vec3& v) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(term);
    for (int k = 0; k < 3; ++k) {
        ImGui::TableNextColumn();
        // A tiny share (a dull lobe's 0.64^32 = 6e-7) is not shown as zero.
        const double x = double(v[k]);
        ImGui::Text(x != 0.0 && std::fabs(x) < 1e-3 ? "%.1e" : "%.4f", x);
    }
}

const char* modeExplanation(ShadingMode mode) {
    switch (mode) {
    case ShadingMode::Flat: return "flat: once per triangle, at its centroid with the face normal";
    case ShadingMode::Gouraud: return "gouraud: at the triangle's three corners; their colours are interpolated";
    case ShadingMode::Phong: return "phong: at the point, with the interpolated normal";
    }
    return "";
}

// The vectors and dot products per light, then every addend of the formula by channel.
void evaluationTables(const Scene& scene, const ProbeEvaluation& e) {
    const glm::vec3 &n = e.nrmWorld, &v = e.viewWorld;
    ImGui::Text("N (%.3f, %.3f, %.3f)", double(n.x), double(n.y), double(n.z));
    ImGui::Text("V (%.3f, %.3f, %.3f)", double(v.x), double(v.y), double(v.z));
    const bool shadows = scene.shadows.enabled;
    const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp;
    if (!e.lights.empty() && ImGui::BeginTable("vectors", shadows ? 5 : 4, flags)) {
        ImGui::TableSetupColumn("light");
        ImGui::TableSetupColumn("N·I");
        ImGui::TableSetupColumn(scene.reflection == ReflectionModel::Phong ? "R·V (lobe)" : "R·V");
        ImGui::TableSetupColumn(scene.reflection == ReflectionModel::BlinnPhong ? "H·N (lobe)" : "H·N");
        if (shadows) ImGui::TableSetupColumn("v");
        ImGui::TableHeadersRow();
        for (std::size_t l = 0; l < e.lights.size(); ++l) {
            const ProbeLight& p = e.lights[l];
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::Text("%zu %s", l, toString(scene.lights[l].type));
            ImGui::TableNextColumn();
            // N.I <= 0: the light is behind the surface and adds nothing; its lobe values do not count.
            if (p.nDotI <= 0.0f) ImGui::TextDisabled("%.3f", double(p.nDotI));
            else ImGui::Text("%.3f", double(p.nDotI));
            ImGui::TableNextColumn();
            ImGui::Text("%.3f", double(p.rDotV));
            ImGui::TableNextColumn();
            ImGui::Text("%.3f", double(p.hDotN));
            if (shadows) {
                ImGui::TableNextColumn();
                ImGui::Text("%d/%d", p.samplesVisible, p.samplesTested);
            }
        }
        ImGui::EndTable();
    }
    if (ImGui::BeginTable("terms", 4, flags)) {
        ImGui::TableSetupColumn("term", ImGuiTableColumnFlags_WidthStretch, 2.0f);
        for (const char* channel : {"R", "G", "B"})
            ImGui::TableSetupColumn(channel, ImGuiTableColumnFlags_WidthStretch, 1.0f);
        ImGui::TableHeadersRow();
        if (scene.emissiveModel || e.terms.emissive != glm::vec3(0.0f)) rgbRow("emission E", e.terms.emissive);
        rgbRow("ambient k_a A C", e.terms.ambient);
        char label[48];
        for (std::size_t l = 0; l < e.lights.size(); ++l) {
            std::snprintf(label, sizeof label, "light %zu diffuse", l);
            rgbRow(label, e.lights[l].diffuse);
            std::snprintf(label, sizeof label, "light %zu specular", l);
            rgbRow(label, e.lights[l].specular);
        }
        rgbRow(scene.show.term == ShowTerm::All ? "sum" : ("sum (show " + toString(scene.show) + ")").c_str(),
               e.terms.shown);
        rgbRow("clamped to [0, 1]", e.terms.total);
        ImGui::EndTable();
    }
}

void modeSection(const Scene& scene, const ProbeResult& probe, const ModeProbe& m) {
    ImGui::TextWrapped("%s", modeExplanation(m.mode));
    if (m.mode == ShadingMode::Gouraud) {
        // The lecture's L_p = l1 L_a + l2 L_b + l3 L_c, as colours.
        for (int k = 0; k < 3; ++k) {
            ImGui::PushID(k);
            swatch("##corner", displayed(scene, m.evaluations[std::size_t(k)].terms.total));
            ImGui::SameLine();
            ImGui::Text("%.3f%s", double(probe.anchor.barycentric[k]), k < 2 ? " +" : " =");
            ImGui::SameLine();
            ImGui::PopID();
        }
        swatch("##interpolated", m.output);
    }
    static const char* const kCorners[] = {"a", "b", "c"};
    for (std::size_t k = 0; k < m.evaluations.size(); ++k) {
        const ProbeEvaluation& e = m.evaluations[k];
        char title[96];
        if (e.site == ProbeEvaluation::Site::Vertex)
            std::snprintf(title, sizeof title, "corner %s (vertex %u), weight %.3f", kCorners[k], e.vertex,
                          double(probe.anchor.barycentric[int(k)]));
        else
            std::snprintf(title, sizeof title, "%s",
                          e.site == ProbeEvaluation::Site::Centroid ? "at the centroid" : "at the point");
        ImGui::PushID(int(k));
        const ImGuiTreeNodeFlags open = k == 0 ? ImGuiTreeNodeFlags_DefaultOpen : 0;
        if (ImGui::TreeNodeEx("evaluation", open, "%s", title)) {
            const glm::vec3& p = e.posWorld;
            ImGui::Text("at (%.3f, %.3f, %.3f)", double(p.x), double(p.y), double(p.z));
            evaluationTables(scene, e);
            ImGui::TreePop();
        }
        ImGui::PopID();
    }
    swatch("##output", m.output);
    ImGui::SameLine();
    ImGui::Text("%s %.3f %.3f %.3f -> %d %d %d", scene.outputEncoding == OutputEncoding::Srgb ? "sRGB" : "linear",
                double(m.output.r), double(m.output.g), double(m.output.b), m.output8.r, m.output8.g, m.output8.b);
}

}  // namespace

namespace {

struct Box {
    float x0, y0, x1, y1;
    float overlap(const Box& o) const {
        const float w = std::min(x1, o.x1) - std::max(x0, o.x0), h = std::min(y1, o.y1) - std::max(y0, o.y0);
        return w > 0.0f && h > 0.0f ? w * h : 0.0f;
    }
};

// Where a label of `size` goes near `tip`: the first of the places around it (nearest first) that is
// inside the pane and clear of the labels already placed; else the place that overlaps them least.
Box placeLabel(ImVec2 tip, ImVec2 size, const Box& pane, const std::vector<Box>& placed, float gap) {
    const float w = size.x, h = size.y;
    const ImVec2 offsets[] = {
        {gap, -h - gap * 0.5f},    {gap, gap * 0.5f},    {-w - gap, -h - gap * 0.5f},  {-w - gap, gap * 0.5f},
        {-w * 0.5f, -h - gap * 2}, {-w * 0.5f, gap * 2}, {gap * 3, -h * 0.5f},         {-w - gap * 3, -h * 0.5f},
        {gap * 2, -h * 2 - gap},   {gap * 2, h + gap},   {-w - gap * 2, -h * 2 - gap}, {-w - gap * 2, h + gap}};
    Box best{};
    float bestCost = 1e30f;
    for (const ImVec2& o : offsets) {
        // Kept inside the pane: a label never runs over a pane border.
        const float x = std::clamp(tip.x + o.x, pane.x0, std::max(pane.x0, pane.x1 - w));
        const float y = std::clamp(tip.y + o.y, pane.y0, std::max(pane.y0, pane.y1 - h));
        const Box b{x, y, x + w, y + h};
        float cost = 0.0f;
        for (const Box& q : placed) cost += q.overlap(b);
        if (cost <= 0.0f) return b;
        if (cost < bestCost) {
            bestCost = cost;
            best = b;
        }
    }
    return best;
}

}  // namespace

void drawProbeLabels(const Scene& scene, const std::vector<ProbeArrow>& arrows, const UiRect& view,
                     float framebufferScale, const std::vector<UiRect>& avoid) {
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    const float font = ImGui::GetFontSize();
    const float pad = std::max(2.0f, font * 0.15f), gap = font * 0.3f;
    const std::vector<Pane> panes = layoutPanes(scene.layout, scene.shading, scene.width, scene.height, scene.diff);
    for (std::size_t p = 0; p < panes.size(); ++p) {
        const Pane& pane = panes[p];
        const Box paneBox{view.x + float(pane.x) / framebufferScale + pad,
                          view.y + float(pane.y) / framebufferScale + pad,
                          view.x + float(pane.x + pane.width) / framebufferScale - pad,
                          view.y + float(pane.y + pane.height) / framebufferScale - pad};
        draw->PushClipRect(ImVec2(paneBox.x0 - pad, paneBox.y0 - pad), ImVec2(paneBox.x1 + pad, paneBox.y1 + pad),
                           true);
        std::vector<Box> placed;
        placed.reserve(avoid.size());
        for (const UiRect& r : avoid) placed.push_back(Box{r.x, r.y, r.x + r.width, r.y + r.height});
        const auto inside = [&](const glm::vec3& q) {
            return q.z > 0.0f && q.x >= float(pane.x) && q.x < float(pane.x + pane.width) && q.y >= float(pane.y) &&
                   q.y < float(pane.y + pane.height);
        };
        for (const ProbeArrow& a : arrows) {
            if (a.label.empty() || (a.arrow.pane >= 0 && std::size_t(a.arrow.pane) != p)) continue;
            glm::vec3 tip = projectToImage(scene.camera, pane, a.arrow.toWorld);
            if (!inside(tip)) {
                // Cut at the pane's border: the last point of the arrow still inside (bisection along it
                // in world space, so a tip behind the eye is handled too).
                const glm::vec3 base = projectToImage(scene.camera, pane, a.arrow.fromWorld);
                if (!inside(base)) continue;
                float lo = 0.0f, hi = 1.0f;
                for (int i = 0; i < 24; ++i) {
                    const float mid = 0.5f * (lo + hi);
                    (inside(projectToImage(scene.camera, pane, glm::mix(a.arrow.fromWorld, a.arrow.toWorld, mid)))
                         ? lo
                         : hi) = mid;
                }
                tip = projectToImage(scene.camera, pane, glm::mix(a.arrow.fromWorld, a.arrow.toWorld, lo));
            }
            const ImVec2 at(view.x + tip.x / framebufferScale, view.y + tip.y / framebufferScale);
            const ImVec2 text = ImGui::CalcTextSize(a.label.c_str());
            const Box b = placeLabel(at, ImVec2(text.x + 2 * pad, text.y + 2 * pad), paneBox, placed, gap);
            placed.push_back(b);
            // A label moved away from its arrow's tip is tied to it by a thin line.
            const float cx = std::clamp(at.x, b.x0, b.x1), cy = std::clamp(at.y, b.y0, b.y1);
            if (std::hypot(cx - at.x, cy - at.y) > gap * 2.5f)
                draw->AddLine(at, ImVec2(cx, cy), imColor(a.arrow.color), std::max(1.0f, font * 0.08f));
            draw->AddRectFilled(ImVec2(b.x0, b.y0), ImVec2(b.x1, b.y1), IM_COL32(0, 0, 0, 170), pad);
            draw->AddText(ImVec2(b.x0 + pad, b.y0 + pad), imColor(a.arrow.color), a.label.c_str());
        }
        draw->PopClipRect();
    }
}

std::string probeWhere(const ProbeResult& probe) {
    return "pixel " + std::to_string(probe.x) + "," + std::to_string(probe.y) + ", " + paneName(probe.pane) +
           ": object " + std::to_string(probe.anchor.object) + ", triangle " + std::to_string(probe.anchor.triangle);
}

bool probeSection(const Scene& scene, const ProbeResult& probe) {
    const bool clear = ImGui::Button("clear probe (Esc)");
    ImGui::SameLine();
    ImGui::TextDisabled("click the view to probe");
    ImGui::TextUnformatted(probeWhere(probe).c_str());
    const glm::vec3& p = probe.posWorld;
    ImGui::Text("P (%.3f, %.3f, %.3f)", double(p.x), double(p.y), double(p.z));
    if (probe.backFace) ImGui::TextWrapped("back face of a double-sided material: lit with N flipped");
    const bool difference = probe.modes.size() == 2;
    for (std::size_t k = 0; k < probe.modes.size(); ++k) {
        ImGui::PushID(int(k));
        if (difference) {
            ImGui::Separator();
            ImGui::Text("%s: %s", k == 0 ? "A" : "B", toString(probe.modes[k].mode));
        }
        modeSection(scene, probe, probe.modes[k]);
        ImGui::PopID();
    }
    if (difference) {
        ImGui::Separator();
        ImGui::Text("|A - B| x %.1f -> %d %d %d", double(scene.diff.factor), probe.output8.r, probe.output8.g,
                    probe.output8.b);
    }
    return clear;
}

}  // namespace shadelab
