#include "viewer/shader_view.hpp"

#include "core/figures/shader_listing.hpp"
#include "core/geometry/camera.hpp"
#include "core/ui/view_names.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

namespace shadelab {
namespace {

ImVec4 imColor(Rgba8 c) {
    return ImVec4(float(c.r) / 255.0f, float(c.g) / 255.0f, float(c.b) / 255.0f, float(c.a) / 255.0f);
}
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
    if (settings.shaderPane < 0 && probe && probe->pane >= 0 && probe->pane < int(panes.size()))
        settings.shaderPane = probe->pane;
    settings.shaderPane = std::clamp(settings.shaderPane, 0, int(panes.size()) - 1);
    if (panes.size() > 1) {
        std::string items;
        for (const std::string& choice : shaderPaneChoices(scene)) items += choice + '\0';
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
    for (const auto& [name, term] :
         {std::pair{"ambient", FormulaTerm::Ambient}, std::pair{"diffuse", FormulaTerm::Diffuse},
          std::pair{"specular", FormulaTerm::Specular}, std::pair{"emission E", FormulaTerm::Emissive}}) {
        ImGui::SameLine();
        ImGui::TextColored(imColor(termColor(term)), "%s", name);
    }
}

// One line: its number, a tinted row and a bar in the term's colour, the coloured tokens, and under
// an erroneous line the driver's message in red. `columns` > 0 wraps the code at that many characters
// (a monospaced font; the rows after the first indented past the number), else one row.
void drawLine(const GlslLine& line, float width, int columns = 0) {
    // The spans cut into rows of at most `columns` characters.
    std::vector<std::vector<GlslSpan>> rows(1);
    int used = 0;
    for (const GlslSpan& s : line.spans) {
        std::string text = s.text;
        while (columns > 0 && used + int(text.size()) > columns) {
            const std::size_t fits = std::size_t(std::max(columns - used, 0));
            if (fits > 0) rows.back().push_back(GlslSpan{text.substr(0, fits), s.token});
            text.erase(0, fits);
            rows.emplace_back();
            used = 0;
        }
        if (!text.empty()) {
            rows.back().push_back(GlslSpan{text, s.token});
            used += int(text.size());
        }
    }
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const float h = ImGui::GetTextLineHeight(),
                all = h + (float(rows.size()) - 1.0f) * ImGui::GetTextLineHeightWithSpacing();
    if (!line.error.empty()) {
        draw->AddRectFilled(at, ImVec2(at.x + width, at.y + all), IM_COL32(150, 30, 30, 200));
    } else if (line.term != FormulaTerm::None) {
        draw->AddRectFilled(at, ImVec2(at.x + width, at.y + all), imColor32(termColor(line.term), 40));
        draw->AddRectFilled(at, ImVec2(at.x + 0.25f * h, at.y + all), imColor32(termColor(line.term), 255));
    }
    for (std::size_t r = 0; r < rows.size(); ++r) {
        if (r == 0) ImGui::TextColored(ImVec4(0.5f, 0.5f, 0.55f, 1.0f), "%4d ", line.number);
        else ImGui::TextUnformatted("     ");
        for (const GlslSpan& s : rows[r]) {
            ImGui::SameLine(0.0f, 0.0f);
            ImGui::PushStyleColor(ImGuiCol_Text, imColor(glslTokenColor(s.token)));
            ImGui::TextUnformatted(s.text.c_str());
            ImGui::PopStyleColor();
        }
    }
    if (!line.error.empty()) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.45f, 1.0f), "     %s", line.error.c_str());
}

}  // namespace

std::vector<std::string> shaderPaneChoices(const Scene& scene) {
    const std::vector<Pane> panes = shadedPanes(scene);
    std::vector<std::string> choices;
    if (panes.size() > 1)
        for (std::size_t i = 0; i < panes.size(); ++i)
            choices.push_back(paneName(int(i)) + ": " + toString(panes[i].mode));
    return choices;
}

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

namespace {

// The Shader view's contents, in the panel or over the view (`large`): the pane's combo, the legend,
// the errors, a tab per file and the listing (`mono`: its font; null: the panel's monospaced one).
// Large, the listing fills the window's height and wraps its lines at the window's width.
void shaderListing(const Scene& scene, ViewSettings& settings, const PanelStatus& status, const ProbeResult* probe,
                   ImFont* mono, bool large) {
    const ShadingMode mode = chosenMode(scene, settings, probe);
    legend();
    const std::vector<GlslError> errors = glslErrors(status.shaderError);
    if (status.shaderError.empty()) settings.shaderErrorFile.clear();
    std::vector<std::string> files = shaderFilesOf(mode);
    if (!settings.shaderErrorFile.empty() &&
        std::find(files.begin(), files.end(), settings.shaderErrorFile) == files.end())
        files.push_back(settings.shaderErrorFile);
    if (!status.shaderError.empty())
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.45f, 1.0f), "the last reload failed (F5 again after a fix):");
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
            if (!mono) mono = monoFont();
            if (mono) ImGui::PushFont(mono);
            // Up to 26 rows, fewer where the panel is lower, so the error's line scrolled to is in sight;
            // over the view, the rest of its height.
            const float rowHeight = ImGui::GetTextLineHeightWithSpacing();
            const float rows = std::clamp(std::floor(ImGui::GetWindowHeight() / rowHeight) - 9.0f, 8.0f, 26.0f);
            ImGui::BeginChild("##listing", ImVec2(0.0f, large ? 0.0f : rows * rowHeight), true,
                              large ? ImGuiWindowFlags_None : ImGuiWindowFlags_HorizontalScrollbar);
            const float avail = ImGui::GetContentRegionAvail().x;
            const float width = large ? avail : std::max(avail, ImGui::GetFontSize() * 60.0f);
            const float advance = ImGui::GetFont()->CalcTextSizeA(ImGui::GetFontSize(), 1e9f, 0.0f, "M").x;
            const int columns = large ? std::max(int(avail / std::max(advance, 1.0f)) - 6, 20) : 0;
            for (const GlslLine& line : listGlsl(file, text->second, errors)) {
                if (scrollHere && line.number == scrollTo->second) ImGui::SetScrollHereY(0.3f);
                drawLine(line, width, columns);
            }
            if (scrollHere && (large || !settings.shaderOverView))
                settings.shaderScrollTo.reset();  // the large one scrolls too
            ImGui::EndChild();
            if (mono) ImGui::PopFont();
        }
        ImGui::EndTabItem();
    }
    ImGui::EndTabBar();
    if (scrollTo && std::find(files.begin(), files.end(), scrollTo->first) == files.end())
        settings.shaderScrollTo.reset();
}

}  // namespace

void sectionShader(const Scene& scene, ViewSettings& settings, const PanelStatus& status, const ProbeResult* probe) {
    shaderListing(scene, settings, status, probe, nullptr, false);
}

void drawShaderOverView(const Scene& scene, ViewSettings& settings, const PanelStatus& status, const ProbeResult* probe,
                        const UiRect& view, ImFont* text, ImFont* mono) {
    const float width = std::max(std::round(view.width * kShaderOverViewShare), std::min(view.width, 200.0f));
    ImGui::SetNextWindowPos(ImVec2(view.x, view.y));
    ImGui::SetNextWindowSize(ImVec2(width, view.height));
    ImGui::SetNextWindowBgAlpha(0.88f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove |
                                   ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                                   ImGuiWindowFlags_NoNavInputs | ImGuiWindowFlags_NoFocusOnAppearing;
    if (text) ImGui::PushFont(text);
    if (ImGui::Begin("##shader over the view", nullptr, flags)) {
        ImGui::TextDisabled("S closes this");
        shaderListing(scene, settings, status, probe, mono, true);
    }
    ImGui::End();
    if (text) ImGui::PopFont();
}

}  // namespace shadelab
