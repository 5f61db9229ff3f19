#include "viewer/plot_view.hpp"

#include <imgui.h>

namespace shadelab {
namespace {

ImU32 imColor(Rgba8 c) { return IM_COL32(c.r, c.g, c.b, c.a); }

class ImGuiPainter final : public PlotPainter {
public:
    ImGuiPainter(ImDrawList* draw, ImVec2 origin) : draw_(draw), origin_(origin) {}

    float lineHeight() const override { return ImGui::GetFontSize(); }
    glm::vec2 measure(const std::string& text) const override {
        const ImVec2 size = ImGui::CalcTextSize(lectureNotation(text).c_str());
        return {size.x, size.y};
    }
    void stroke(const std::vector<glm::vec2>& pixels, Rgba8 color, float width) override {
        points_.clear();
        for (const glm::vec2& p : pixels) points_.push_back(at(p));
        draw_->AddPolyline(points_.Data, points_.Size, imColor(color), ImDrawFlags_None, width);
    }
    void fillTriangle(glm::vec2 a, glm::vec2 b, glm::vec2 c, Rgba8 color) override {
        // ImGui's antialiased fill puts its fringe outside only for clockwise corners (on screen, y down).
        const glm::vec2 ab = b - a, ac = c - a;
        if (ab.x * ac.y - ab.y * ac.x < 0.0f) std::swap(b, c);
        draw_->AddTriangleFilled(at(a), at(b), at(c), imColor(color));
    }
    void fillRect(glm::vec2 lo, glm::vec2 hi, Rgba8 color) override {
        draw_->AddRectFilled(at(lo), at(hi), imColor(color));  // not antialiased: heat map cells meet without seams
    }
    void text(glm::vec2 topLeft, const std::string& text, Rgba8 color) override {
        draw_->AddText(at(topLeft), imColor(color), lectureNotation(text).c_str());
    }

private:
    ImVec2 at(glm::vec2 p) const { return ImVec2(origin_.x + p.x, origin_.y + p.y); }

    ImDrawList* draw_;
    ImVec2 origin_;
    ImVector<ImVec2> points_;
};

}  // namespace

void plotWidget(const char* id, const Plot& plot, float height) {
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ImVec2 size(ImGui::GetContentRegionAvail().x, height);
    ImGui::InvisibleButton(id, size);
    if (!ImGui::IsItemVisible()) return;  // scrolled out of the panel: nothing to draw
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->PushClipRect(origin, ImVec2(origin.x + size.x, origin.y + size.y), true);
    draw->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y), imColor(kPlotBackground));
    ImGuiPainter painter(draw, origin);
    paintPlot(plot, glm::vec2(size.x, size.y), 1.0f, painter);
    draw->PopClipRect();
}

}  // namespace shadelab
