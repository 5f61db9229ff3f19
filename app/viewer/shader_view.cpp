#include "viewer/shader_view.hpp"

#include "core/figures/shader_listing.hpp"
#include "core/geometry/camera.hpp"

#include <imgui.h>

#include <algorithm>
#include <string>

namespace shadelab {
namespace {

ImVec4 imColor(Rgba8 c) { return ImVec4(float(c.r) / 255.0f, float(c.g) / 255.0f, float(c.b) / 255.0f, float(c.a) / 255.0f); }
ImU32 imColor32(Rgba8 c, int alpha) { return IM_COL32(c.r, c.g, c.b, alpha); }

// The panes that run a mode (not the diff layout's difference), and which one the section shows:
// the one picked in the section, else the probed pane, else the first.
std::vector<Pane> shadedPanes(const Scene& scene) {
    std::vector<Pane> panes;
    for (const Pane& p : layoutPanes(scene.layout, scene.shading, scene.width, scene.height, scene.diff))
        if (!p.difference) panes.push_back(p);
    return panes;
}

ShadingMode chosenMode(const Scene& scene, ViewSettings& settings, const ProbeResult* probe) {
    const std::vector<Pane> panes = shadedPanes(scene);
    if (panes.empty()) return scene.shading;
    if (settings.shaderPane < 0 && probe && probe->pane >= 0 && probe->pane < int(panes.size())) settings.shaderPane = probe->pane;
    settings.shaderPane = std::clamp(settings.shaderPane, 0, int(panes.size()) - 1);
    if (panes.size() > 1) {
        std::string items;
        for (std::size_t i = 0; i < panes.size(); ++i)
            items += "pane " + std::to_string(i + 1) + ": " + toString(panes[i].mode) + '\0';
        ImGui::Combo("pane", &settings.shaderPane, items.c_str());
    }
    return panes[std::size_t(settings.shaderPane)].mode;
}

// DejaVu Sans Mono, where ImGuiLayer loaded it (null: the panel's font).
ImFont* monoFont() {
    for (ImFont* f : ImGui::GetIO().Fonts->Fonts)
        if (std::string(f->GetDebugName()).rfind("DejaVuSansMono", 0) == 0) return f;
    return nullptr;
}

void legend() {
    ImGui::TextUnformatted("terms:");
    for (const auto& [name, term] : {std::pair{"ambient", FormulaTerm::Ambient}, std::pair{"diffuse", FormulaTerm::Diffuse},
                                     std::pair{"specular", FormulaTerm::Specular}, std::pair{"emission E", FormulaTerm::Emissive}}) {
        ImGui::SameLine();
        ImGui::TextColored(imColor(termColor(term)), "%s", name);
    }
}

// One line: its number, a tinted row and a bar in the term's colour, the coloured tokens, and under
// an erroneous line the driver's message in red.
void drawLine(const GlslLine& line, float width) {
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const float h = ImGui::GetTextLineHeight();
    if (!line.error.empty()) {
        draw->AddRectFilled(at, ImVec2(at.x + width, at.y + h), IM_COL32(150, 30, 30, 200));
    } else if (line.term != FormulaTerm::None) {
        draw->AddRectFilled(at, ImVec2(at.x + width, at.y + h), imColor32(termColor(line.term), 40));
        draw->AddRectFilled(at, ImVec2(at.x + 0.25f * h, at.y + h), imColor32(termColor(line.term), 255));
    }
    ImGui::TextColored(ImVec4(0.5f, 0.5f, 0.55f, 1.0f), "%4d ", line.number);
    for (const GlslSpan& s : line.spans) {
        ImGui::SameLine(0.0f, 0.0f);
        ImGui::PushStyleColor(ImGuiCol_Text, imColor(glslTokenColor(s.token)));
        ImGui::TextUnformatted(s.text.c_str());
        ImGui::PopStyleColor();
    }
    if (!line.error.empty()) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.45f, 1.0f), "     %s", line.error.c_str());
}

}  // namespace

void sectionShader(const Scene& scene, ViewSettings& settings, const PanelStatus& status, const ProbeResult* probe) {
    const ShadingMode mode = chosenMode(scene, settings, probe);
    legend();
    const std::vector<GlslError> errors = glslErrors(status.shaderError);
    // A new error: its file's tab is selected and its line scrolled to, once.
    const bool newError = status.shaderError != settings.shaderErrorSeen;
    settings.shaderErrorSeen = status.shaderError;
    const std::vector<std::string> files = shaderFilesOf(mode);
    if (newError) {
        settings.shaderScrollTo.reset();
        for (const GlslError& e : errors)
            if (!settings.shaderScrollTo && std::find(files.begin(), files.end(), e.file) != files.end())
                settings.shaderScrollTo = std::pair(e.file, e.line);
    }
    if (!status.shaderError.empty()) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.45f, 1.0f), "the last reload failed (F5 again after a fix):");
    for (const GlslError& e : errors) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.45f, 1.0f), "  %s", e.message.c_str());
    if (!ImGui::BeginTabBar("##glsl files")) return;
    for (const std::string& file : files) {
        const bool scrollHere = settings.shaderScrollTo && settings.shaderScrollTo->first == file;
        if (!ImGui::BeginTabItem(file.c_str(), nullptr, newError && scrollHere ? ImGuiTabItemFlags_SetSelected : 0)) continue;
        const auto text = status.shaderSources.find(file);
        if (text == status.shaderSources.end()) {
            ImGui::TextDisabled("%s: not found", file.c_str());
        } else {
            ImFont* mono = monoFont();
            if (mono) ImGui::PushFont(mono);
            const float rows = 26.0f;
            ImGui::BeginChild("##listing", ImVec2(0.0f, rows * ImGui::GetTextLineHeightWithSpacing()), true,
                              ImGuiWindowFlags_HorizontalScrollbar);
            const float width = std::max(ImGui::GetContentRegionAvail().x, ImGui::GetFontSize() * 60.0f);
            for (const GlslLine& line : listGlsl(file, text->second, errors)) {
                if (scrollHere && line.number == settings.shaderScrollTo->second) ImGui::SetScrollHereY(0.3f);
                drawLine(line, width);
            }
            if (scrollHere) settings.shaderScrollTo.reset();
            ImGui::EndChild();
            if (mono) ImGui::PopFont();
        }
        ImGui::EndTabItem();
    }
    ImGui::EndTabBar();
}

}  // namespace shadelab
