#include "viewer/shader_view.hpp"

#include "core/figures/shader_listing.hpp"
#include "core/geometry/camera.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

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

bool focusShaderError(const Scene& scene, ViewSettings& settings, const std::string& log) {
    settings.shaderErrorFile.clear();
    settings.shaderScrollTo.reset();
    const std::vector<GlslError> errors = glslErrors(log);
    const auto located = std::find_if(errors.begin(), errors.end(), [](const GlslError& e) { return !e.file.empty(); });
    if (located == errors.end()) return false;
    const std::vector<Pane> panes = shadedPanes(scene);
    const auto runs = [&](const Pane& p) {
        const std::vector<std::string> files = shaderFilesOf(p.mode);
        return std::find(files.begin(), files.end(), located->file) != files.end();
    };
    // The pane shown now when it runs the file (lighting.glsl: every pane), else the first that does.
    const int shown = std::clamp(settings.shaderPane, 0, std::max(int(panes.size()) - 1, 0));
    if (panes.empty() || !runs(panes[std::size_t(shown)])) {
        const auto pane = std::find_if(panes.begin(), panes.end(), runs);
        if (pane != panes.end()) settings.shaderPane = int(pane - panes.begin());
        else settings.shaderErrorFile = located->file;  // e.g. phong.frag while the single pane is flat
    } else {
        settings.shaderPane = shown;
    }
    settings.shaderScrollTo = std::pair(located->file, located->line);
    return true;
}

void sectionShader(const Scene& scene, ViewSettings& settings, const PanelStatus& status, const ProbeResult* probe) {
    const ShadingMode mode = chosenMode(scene, settings, probe);
    legend();
    const std::vector<GlslError> errors = glslErrors(status.shaderError);
    if (status.shaderError.empty()) settings.shaderErrorFile.clear();
    std::vector<std::string> files = shaderFilesOf(mode);
    if (!settings.shaderErrorFile.empty() && std::find(files.begin(), files.end(), settings.shaderErrorFile) == files.end())
        files.push_back(settings.shaderErrorFile);
    if (!status.shaderError.empty()) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.45f, 1.0f), "the last reload failed (F5 again after a fix):");
    for (const GlslError& e : errors) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.45f, 1.0f), "  %s", e.message.c_str());
    if (!ImGui::BeginTabBar("##glsl files")) return;
    // The error's tab is selected (ImGui shows it from the next frame) and its line scrolled to once
    // its text is drawn; then a click on another tab stays.
    const std::optional<std::pair<std::string, int>> scrollTo = settings.shaderScrollTo;
    for (const std::string& file : files) {
        const bool scrollHere = scrollTo && scrollTo->first == file;
        if (!ImGui::BeginTabItem(file.c_str(), nullptr, scrollHere ? ImGuiTabItemFlags_SetSelected : 0)) continue;
        const auto text = status.shaderSources.find(file);
        if (text == status.shaderSources.end()) {
            ImGui::TextDisabled("%s: not found", file.c_str());
        } else {
            ImFont* mono = monoFont();
            if (mono) ImGui::PushFont(mono);
            // Up to 26 rows, fewer where the panel is lower, so the error's line scrolled to is in sight.
            const float rowHeight = ImGui::GetTextLineHeightWithSpacing();
            const float rows = std::clamp(std::floor(ImGui::GetWindowHeight() / rowHeight) - 9.0f, 8.0f, 26.0f);
            ImGui::BeginChild("##listing", ImVec2(0.0f, rows * rowHeight), true,
                              ImGuiWindowFlags_HorizontalScrollbar);
            const float width = std::max(ImGui::GetContentRegionAvail().x, ImGui::GetFontSize() * 60.0f);
            for (const GlslLine& line : listGlsl(file, text->second, errors)) {
                if (scrollHere && line.number == scrollTo->second) ImGui::SetScrollHereY(0.3f);
                drawLine(line, width);
            }
            if (scrollHere) settings.shaderScrollTo.reset();
            ImGui::EndChild();
            if (mono) ImGui::PopFont();
        }
        ImGui::EndTabItem();
    }
    ImGui::EndTabBar();
    if (scrollTo && std::find(files.begin(), files.end(), scrollTo->first) == files.end()) settings.shaderScrollTo.reset();
}

}  // namespace shadelab
