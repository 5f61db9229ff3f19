// What the viewer draws over and around the 3D view, outside the panel (view_overlays.hpp): pane labels and
// separators, the caption band, the status strip, the message, the help overlay, the lights' markers and
// labels, and picking a light's marker. The panel's widgets are panel.cpp.
#include "viewer/view_overlays.hpp"

#include "core/figures/plot.hpp"
#include "core/geometry/camera.hpp"
#include "core/scene/scene_names.hpp"
#include "core/ui/controls.hpp"
#include "viewer/light_label_placement.hpp"

#include <imgui.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <string>

namespace shadelab {

namespace {

// The pane's words: what differs between panes, the way the lecture names it.
std::string shadingName(ShadingMode m) {
    std::string name = toString(m);  // "flat" -> "Flat": a pane label starts a sentence
    name[0] = char(std::toupper(static_cast<unsigned char>(name[0])));
    return name;
}

const char* lobeName(ReflectionModel r) { return r == ReflectionModel::BlinnPhong ? "Blinn-Phong lobe" : "Phong lobe"; }

// A label on a dark box at `pos`, moved inside [lo, hi] (a pane) when given, so it is never cut.
UiRect labelBox(ImDrawList* draw, float fontSize, ImVec2 pos, const std::string& text, ImU32 colour,
                ImVec2 lo = ImVec2(-1e9f, -1e9f), ImVec2 hi = ImVec2(1e9f, 1e9f)) {
    const ImVec2 size = ImGui::GetFont()->CalcTextSizeA(fontSize, 1e9f, 0.0f, text.c_str());
    const float pad = fontSize * 0.3f;
    pos.x = std::max(std::min(pos.x, hi.x - size.x - pad), lo.x + pad);
    pos.y = std::max(std::min(pos.y, hi.y - size.y - pad), lo.y + pad);
    draw->AddRectFilled(ImVec2(pos.x - pad, pos.y - pad), ImVec2(pos.x + size.x + pad, pos.y + size.y + pad),
                        IM_COL32(0, 0, 0, 160), pad);
    draw->AddText(ImGui::GetFont(), fontSize, pos, colour, text.c_str());
    return UiRect{pos.x - pad, pos.y - pad, size.x + 2 * pad, size.y + 2 * pad};
}

}  // namespace

void drawPaneSeparators(const Scene& scene, const UiRect& view, float framebufferScale) {
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    const std::vector<Pane> panes = layoutPanes(scene.layout, scene.shading, scene.width, scene.height, scene.diff);
    const float width = 2.0f;  // ImGui units: 2 px at scale 1, 4 at 2x
    for (std::size_t i = 1; i < panes.size(); ++i) {
        const float x = std::round(view.x + float(panes[i].x) / framebufferScale);
        draw->AddRectFilled(ImVec2(x - width * 0.5f, view.y), ImVec2(x + width * 0.5f, view.y + view.height),
                            IM_COL32(150, 150, 160, 255));
    }
}

float drawPaneLabels(const Scene& scene, const UiRect& view, float framebufferScale, float fontSize) {
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    float bottom = view.y;
    if (fontSize <= 0.0f) fontSize = ImGui::GetFontSize() * 1.4f;  // read from the back of a lecture hall
    const std::string difference = "|" + shadingName(scene.diff.a) + " \u2212 " + shadingName(scene.diff.b) + "|",
                      factor = "\u00d7 " + std::to_string(int(std::lround(scene.diff.factor)));
    const std::vector<Pane> panes = layoutPanes(scene.layout, scene.shading, scene.width, scene.height, scene.diff);
    const auto textWidth = [](const std::string& s, float size) {
        return ImGui::GetFont()->CalcTextSizeA(size, 1e9f, 0.0f, s.c_str()).x;
    };
    // One line where it fits the pane, else the mode above the lobe (the difference above its factor).
    const auto labelLines = [&](const Pane& pane, float size, float width) -> std::vector<std::string> {
        const std::string first = pane.difference ? difference : shadingName(pane.mode) + " shading";
        const std::string second = pane.difference ? factor : lobeName(scene.reflection);
        const std::string one = first + (pane.difference ? " " : " \u00b7 ") + second;
        if (textWidth(one, size) + 4 * 0.3f * size <= width) return {one};
        return {first, second};
    };
    // One size for every pane: where a pane is narrower than its label's longest line (compare at a 2x
    // content scale: "Gouraud shading" in a third of the view), all get smaller, down to 60%, not cut.
    float fit = 1.0f;
    for (const Pane& pane : panes) {
        const float width = float(pane.width) / framebufferScale;
        for (const std::string& line : labelLines(pane, fontSize, width))
            fit = std::min(fit, (width - 4 * 0.3f * fontSize) / std::max(textWidth(line, fontSize), 1.0f));
    }
    fontSize *= std::clamp(fit, 0.6f, 1.0f);
    const float pad = fontSize * 0.3f;
    for (const Pane& pane : panes) {
        const float x0 = view.x + float(pane.x) / framebufferScale, width = float(pane.width) / framebufferScale;
        const std::vector<std::string> lines = labelLines(pane, fontSize, width);
        float y = view.y + float(pane.y) / framebufferScale + pad * 2;
        // Inside the pane, never over the next pane or the panel (a narrow pane cuts a long label).
        const ImVec2 lo(x0, view.y + float(pane.y) / framebufferScale), hi(x0 + width, view.y + view.height);
        draw->PushClipRect(lo, hi, true);
        for (const std::string& line : lines) {
            const float w = ImGui::GetFont()->CalcTextSizeA(fontSize, 1e9f, 0.0f, line.c_str()).x;
            labelBox(draw, fontSize, ImVec2(std::round(x0 + (width - w) * 0.5f), std::round(y)), line,
                     IM_COL32(255, 255, 255, 240), lo, hi);
            bottom = std::max(bottom, y + fontSize + pad);
            y += fontSize + pad * 2.5f;
        }
        draw->PopClipRect();
    }
    return bottom;
}

CaptionLayout layoutCaption(const Scene& scene, const std::string& counter, float width, float maxHeight, int minStep,
                            float viewText) {
    CaptionLayout l;
    if (scene.title.empty() && scene.caption.empty()) return l;
    const std::string title = lectureNotation(scene.title), caption = lectureNotation(scene.caption);
    ImFont* font = ImGui::GetFont();
    // Sizes follow the view's width (a 1000-unit view gets 1.6 times the panel's font for the title,
    // 1.25 for the caption), or the view text's size where that is larger (the caption 1.25 times
    // it: 3% of the window's height); smaller in steps while the band would take more than `maxHeight`.
    const float base = std::max(ImGui::GetFontSize() * std::clamp(width / 1000.0f, 0.7f, 1.25f), viewText);
    for (int step = std::max(minStep, 0); step < 8 * kCaptionTitleSteps; ++step) {
        // The caption's size in steps of 10%; at each, the title from 1.6 times the caption's base down to 1.3.
        const float zoom = std::pow(0.9f, float(step / kCaptionTitleSteps));  // NOLINT(bugprone-integer-division)
        l.step = step;
        l.titleSize = base * (1.6f - 0.15f * float(step % kCaptionTitleSteps)) * zoom;
        l.captionSize = base * 1.25f * zoom;
        l.pad = l.captionSize * 0.45f;
        const float counterWidth =
            counter.empty() ? 0.0f : font->CalcTextSizeA(l.captionSize, 1e9f, 0.0f, counter.c_str()).x + l.pad;
        const float wrap = std::max(width - 2.0f * l.pad - counterWidth, 1.0f);
        const float titleHeight = title.empty() ? 0.0f : font->CalcTextSizeA(l.titleSize, 1e9f, wrap, title.c_str()).y;
        const float captionHeight =
            caption.empty() ? 0.0f : font->CalcTextSizeA(l.captionSize, 1e9f, wrap, caption.c_str()).y;
        const float gap = titleHeight > 0.0f && captionHeight > 0.0f ? l.pad * 0.5f : 0.0f;
        l.height = std::ceil(titleHeight + gap + captionHeight + 2.0f * l.pad);
        if (l.height <= maxHeight) break;
    }
    l.height = std::min(l.height, maxHeight);
    return l;
}

void drawCaption(const Scene& scene, const std::string& counter, const CaptionLayout& l, const UiRect& band) {
    if (l.height <= 0.0f) return;
    // Scene files write the lecture's symbols in ASCII ("theta_i", as --captions' bitmap font needs):
    // the view shows them as the lecture does (plot.hpp, lectureNotation).
    const std::string title = lectureNotation(scene.title), caption = lectureNotation(scene.caption);
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    ImFont* font = ImGui::GetFont();
    const float counterWidth =
        counter.empty() ? 0.0f : font->CalcTextSizeA(l.captionSize, 1e9f, 0.0f, counter.c_str()).x + l.pad;
    const float wrap = std::max(band.width - 2.0f * l.pad - counterWidth, 1.0f);
    const ImVec2 lo(band.x, band.y), hi(band.x + band.width, band.y + band.height);
    draw->PushClipRect(lo, hi, true);
    draw->AddRectFilled(lo, hi, IM_COL32(24, 24, 30, 255));
    const float titleHeight = title.empty() ? 0.0f : font->CalcTextSizeA(l.titleSize, 1e9f, wrap, title.c_str()).y;
    const float gap = titleHeight > 0.0f && !caption.empty() ? l.pad * 0.5f : 0.0f;
    const ImVec2 titlePos(std::round(band.x + l.pad), std::round(band.y + l.pad));
    draw->AddText(font, l.titleSize, titlePos, IM_COL32(255, 255, 255, 255), title.c_str(), nullptr, wrap);
    draw->AddText(font, l.captionSize, ImVec2(titlePos.x, std::round(titlePos.y + titleHeight + gap)),
                  IM_COL32(225, 225, 225, 255), caption.c_str(), nullptr, wrap);
    if (!counter.empty())
        draw->AddText(font, l.captionSize, ImVec2(std::round(band.x + band.width - counterWidth), titlePos.y),
                      IM_COL32(200, 200, 200, 255), counter.c_str());
    draw->PopClipRect();
}

std::string statusStripText(const PanelStatus& status, float width,
                            const std::function<float(const std::string&)>& measure) {
    char timing[64] = "idle";
    const double ms = status.frameMs;
    if (!status.idle) {  // no frame in the last second yet: the first one after a sleep
        if (ms > 0.0 && status.movingScale < 1.0f)
            std::snprintf(timing, sizeof timing, "%.1f ms (%.0f FPS, moving at %.0f%%)", ms, 1000.0 / ms,
                          100.0 * double(status.movingScale));
        else if (ms > 0.0) std::snprintf(timing, sizeof timing, "%.1f ms (%.0f FPS)", ms, 1000.0 / ms);
        else std::snprintf(timing, sizeof timing, "\u2026 ms");
    }
    const std::string animation =
        status.animation.empty() ? "" : (status.playing ? "playing " : "paused at ") + status.animation;
    // In the order shown; the ones that may be left out where there is no room, the first first.
    struct Part {
        std::string text;
        int dropOrder;
    };
    std::vector<Part> parts = {{timing, 0},
                               {std::to_string(status.frameTriangles) + " triangles", 2},
                               {status.glRenderer, 1},
                               {status.progress, 0},
                               {animation, 0}};
    const auto join = [&parts] {
        std::string text;
        for (const Part& p : parts)
            if (!p.text.empty()) text += (text.empty() ? "" : "  \u00b7  ") + p.text;
        return text;
    };
    for (int drop = 1; drop <= 2 && measure(join()) > width; ++drop)
        for (Part& p : parts)
            if (p.dropOrder == drop) p.text.clear();
    return join();
}

void drawStatusStrip(const PanelStatus& status, const UiRect& strip) {
    if (strip.height <= 0.0f) return;
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    const ImVec2 lo(strip.x, strip.y), hi(strip.x + strip.width, strip.y + strip.height);
    draw->PushClipRect(lo, hi, true);
    draw->AddRectFilled(lo, hi, IM_COL32(16, 16, 20, 255));
    const float margin = ImGui::GetFontSize() * 0.5f;
    const std::string text = statusStripText(status, strip.width - 2.0f * margin,
                                             [](const std::string& t) { return ImGui::CalcTextSize(t.c_str()).x; });
    const float pad = (strip.height - ImGui::GetFontSize()) * 0.5f;
    draw->AddText(ImVec2(std::round(strip.x + margin), std::round(strip.y + pad)), IM_COL32(200, 200, 200, 255),
                  text.c_str());
    draw->PopClipRect();
}

void drawMessage(const PanelStatus& status, const UiRect& view) {
    if (status.message.empty()) return;
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    const float font = ImGui::GetFontSize() * 1.1f, pad = font * 0.5f;
    const float wrap = std::max(view.width * 0.8f, 100.0f);
    const ImVec2 size = ImGui::GetFont()->CalcTextSizeA(font, 1e9f, wrap, status.message.c_str());
    const ImVec2 pos(std::round(view.x + (view.width - size.x) * 0.5f),
                     std::round(view.y + view.height - size.y - 3 * pad));
    draw->AddRectFilled(ImVec2(pos.x - pad, pos.y - pad), ImVec2(pos.x + size.x + pad, pos.y + size.y + pad),
                        status.isError ? IM_COL32(120, 20, 20, 235) : IM_COL32(20, 20, 24, 220), pad * 0.5f);
    draw->AddText(ImGui::GetFont(), font, pos, IM_COL32(255, 255, 255, 255), status.message.c_str(), nullptr, wrap);
}

void drawHelpOverlay(const UiRect& view) {
    ImGui::SetNextWindowPos(ImVec2(view.x + view.width * 0.5f, view.y + view.height * 0.5f), ImGuiCond_Always,
                            ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowBgAlpha(0.92f);
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(view.width * 0.95f, view.height * 0.95f));
    // No title or resizing, but a scrollbar where the view is too small for every row at this scale.
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize |
                                   ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                   ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoMove;
    if (ImGui::Begin("##help", nullptr, flags)) {
        ImGui::TextUnformatted("Keys and mouse  (F1 or ? closes this)");
        ImGui::Separator();
        if (ImGui::BeginTable("##controls", 2, ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_RowBg)) {
            for (const Control& c : kControls) {
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(c.input);
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(c.action);
            }
            ImGui::EndTable();
        }
    }
    ImGui::End();
}

glm::vec3 lightHandleWorld(const Scene& scene, std::size_t light) {
    return lightHandle(scene.lights[light], scene.camera);
}

int lightAtPixel(const Scene& scene, const Pane& pane, glm::vec2 pixel, float radiusPixels) {
    int best = -1;
    float bestDistance = radiusPixels;
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const glm::vec3 p = projectToImage(scene.camera, pane, lightHandleWorld(scene, i));
        if (!(p.z > 0.0f)) continue;
        const float d = glm::length(glm::vec2(p) - pixel);
        if (d <= bestDistance) {
            best = int(i);
            bestDistance = d;
        }
    }
    return best;
}

namespace {

// How the light labels are drawn.
struct LightLabelStyle {
    ImDrawList* draw;
    float font, thick, ring;  // text size, line width, marker radius
};

glm::vec2 vec(ImVec2 v) { return glm::vec2(v.x, v.y); }
ImVec2 imVec(glm::vec2 v) { return ImVec2(v.x, v.y); }

// A marker's label where it covers no model and touches no other label (placeLightLabel), tied to the
// marker by a thin line where it had to move away from it.
UiRect placeLabel(const LightLabelStyle& s, const LightLabelArea& a, ImVec2 at, float gap, const std::string& label,
                  ImU32 colour) {
    const glm::vec2 size = vec(ImGui::GetFont()->CalcTextSizeA(s.font, 1e9f, 0.0f, label.c_str()));
    const float pad = s.font * 0.3f;
    const LabelPlacement place = placeLightLabel(a, vec(at), gap, size, pad, s.font * 0.33f);
    if (place.tied) {
        const LabelRect box = place.box(size, pad);
        const ImVec2 near(std::clamp(at.x, box.lo.x, box.hi.x), std::clamp(at.y, box.lo.y, box.hi.y));
        const float dx = near.x - at.x, dy = near.y - at.y, d = std::hypot(dx, dy);
        if (d > s.ring)
            s.draw->AddLine(ImVec2(at.x + dx / d * s.ring, at.y + dy / d * s.ring), near, colour,
                            1.0f + s.thick * 0.4f);
    }
    return labelBox(s.draw, s.font, imVec(place.text), label, colour, imVec(a.lo), imVec(a.hi));
}

// A directional light: an arrow from `from` along the light's travel to `to`; its tail is the handle
// that drags the direction, and the label sits beside it.
UiRect drawDirectionArrow(const LightLabelStyle& s, const LightLabelArea& a, ImVec2 from, ImVec2 to,
                          const std::string& label, ImU32 colour) {
    s.draw->AddLine(from, to, colour, s.thick);
    const ImVec2 d(to.x - from.x, to.y - from.y);
    const float len = std::max(std::sqrt(d.x * d.x + d.y * d.y), 1e-3f);
    const ImVec2 u(d.x / len, d.y / len), n(-u.y, u.x);
    const float head = s.font * 0.7f;
    s.draw->AddTriangleFilled(to, ImVec2(to.x - u.x * head + n.x * head * 0.5f, to.y - u.y * head + n.y * head * 0.5f),
                              ImVec2(to.x - u.x * head - n.x * head * 0.5f, to.y - u.y * head - n.y * head * 0.5f),
                              colour);
    return placeLabel(s, a, from, s.ring, label, colour);
}

// A light in view: a ring and a dot at it, the label beside it off the models (placeLabel).
UiRect drawLightMarker(const LightLabelStyle& s, const LightLabelArea& a, ImVec2 at, const std::string& label,
                       ImU32 colour) {
    s.draw->AddCircle(at, s.ring, colour, 24, s.thick);
    s.draw->AddCircleFilled(at, s.thick, colour);
    return placeLabel(s, a, at, s.ring * 1.4f, label, colour);
}

// A light outside the pane (or behind the eye, `behind`): an arrow at the border pointing toward `at`,
// the label beside it along the border, on the side away from the pane's centre (where the model is):
// toward the nearer corner.
UiRect drawBorderArrow(const LightLabelStyle& s, const LightLabelArea& a, ImVec2 at, bool behind,
                       const std::string& label, ImU32 colour) {
    const ImVec2 centre((a.lo.x + a.hi.x) * 0.5f, (a.lo.y + a.hi.y) * 0.5f);
    ImVec2 d(at.x - centre.x, at.y - centre.y);
    if (behind) d = ImVec2(-d.x, -d.y);
    const float len = std::max(std::sqrt(d.x * d.x + d.y * d.y), 1e-3f);
    const ImVec2 u(d.x / len, d.y / len), n(-u.y, u.x);
    const float halfW = (a.hi.x - a.lo.x) * 0.5f - s.font * 0.5f, halfH = (a.hi.y - a.lo.y) * 0.5f - s.font * 0.5f;
    const float t = std::min(std::fabs(u.x) > 1e-4f ? halfW / std::fabs(u.x) : 1e9f,
                             std::fabs(u.y) > 1e-4f ? halfH / std::fabs(u.y) : 1e9f);
    const ImVec2 tip(centre.x + u.x * t, centre.y + u.y * t);
    const float head = s.font * 0.9f;
    const ImVec2 c1(tip.x - u.x * head + n.x * head * 0.6f, tip.y - u.y * head + n.y * head * 0.6f);
    const ImVec2 c2(tip.x - u.x * head - n.x * head * 0.6f, tip.y - u.y * head - n.y * head * 0.6f);
    s.draw->AddTriangleFilled(tip, c1, c2, colour);
    const ImVec2 size = ImGui::GetFont()->CalcTextSizeA(s.font, 1e9f, 0.0f, label.c_str());
    const bool sideEdge = std::fabs(u.x) * halfH >= std::fabs(u.y) * halfW;  // left or right border
    ImVec2 pos;
    if (sideEdge) {
        pos.x = u.x > 0.0f ? tip.x - head * 1.2f - size.x : tip.x + head * 1.2f;
        pos.y = u.y < 0.0f ? tip.y - head * 0.6f - size.y : tip.y + head * 0.6f;
    } else {
        pos.x = u.x > 0.0f ? tip.x + head * 0.6f : tip.x - head * 0.6f - size.x;
        pos.y = u.y > 0.0f ? tip.y - head * 1.2f - size.y : tip.y + head * 1.2f;
    }
    const float pad = s.font * 0.3f;
    pos.x = std::max(std::min(pos.x, a.hi.x - size.x - pad), a.lo.x + pad);
    pos.y = std::max(std::min(pos.y, a.hi.y - size.y - pad), a.lo.y + pad);
    // The label keeps clear of the arrow's head too (pushed along the border, it ran into it).
    LightLabelArea withHead = a;
    const LabelRect headBox{glm::min(vec(tip), glm::min(vec(c1), vec(c2))),
                            glm::max(vec(tip), glm::max(vec(c1), vec(c2)))};
    withHead.taken.push_back(headBox);
    const float separation = kLabelSeparation * s.font;
    if (rectClear(withHead, LabelRect{vec(pos) - pad, vec(pos) + vec(size) + pad}, separation))
        return labelBox(s.draw, s.font, pos, label, colour, imVec(a.lo), imVec(a.hi));
    // A model, a label or the head itself is there: beside the head, clear of its box.
    const glm::vec2 half = (headBox.hi - headBox.lo) * 0.5f;
    return placeLabel(s, withHead, imVec(headBox.lo + half), std::max(half.x, half.y) + pad + 2.0f * separation, label,
                      colour);
}

// Each model's disc in the view's units (the view's top-left at `origin`): its bounding sphere's centre
// and the farthest of four points on its rim across the view (a sphere off the axis projects a little
// wider than its centre's distance says).
std::vector<LabelDisc> modelDiscs(const Scene& scene, const Pane& pane, const std::vector<BoundingSphere>& models,
                                  glm::vec2 origin, float framebufferScale) {
    std::vector<LabelDisc> discs;
    const glm::vec3 forward = glm::normalize(scene.camera.target - scene.camera.eye);
    const glm::vec3 right = glm::normalize(glm::cross(forward, scene.camera.up)), up = glm::cross(right, forward);
    for (const BoundingSphere& m : models) {
        const glm::vec3 c = projectToImage(scene.camera, pane, m.center);
        if (!(c.z > 0.0f) || m.radius <= 0.0f) continue;
        float radius = 0.0f;
        for (const glm::vec3& rim : {right, -right, up, -up}) {
            const glm::vec3 p = projectToImage(scene.camera, pane, m.center + rim * m.radius);
            if (p.z > 0.0f) radius = std::max(radius, glm::length(glm::vec2(p) - glm::vec2(c)));
        }
        discs.push_back({origin + glm::vec2(c) / framebufferScale, radius * 1.05f / framebufferScale});
    }
    return discs;
}

}  // namespace

std::vector<UiRect> drawLightLabels(const Scene& scene, const UiRect& view, float framebufferScale, int selected,
                                    float top, const std::vector<BoundingSphere>& models) {
    std::vector<UiRect> boxes;
    if (scene.lights.empty()) return boxes;
    const float font = ImGui::GetFontSize();
    // Lines 3 px at scale 1, thicker with the UI scale.
    const LightLabelStyle style{ImGui::GetBackgroundDrawList(), font, std::max(3.0f, font * 0.2f), font * 0.6f};
    for (const Pane& pane : layoutPanes(scene.layout, scene.shading, scene.width, scene.height, scene.diff)) {
        const float x0 = view.x + float(pane.x) / framebufferScale, paneTop = view.y + float(pane.y) / framebufferScale;
        const float x1 = x0 + float(pane.width) / framebufferScale,
                    y1 = paneTop + float(pane.height) / framebufferScale;
        // Labels and border arrows stay below the pane labels (`top`).
        const float y0 = std::min(std::max(paneTop, top), y1);
        style.draw->PushClipRect(ImVec2(x0, paneTop), ImVec2(x1, y1), true);
        // Labels keep clear of each other (placeLightLabel): each box placed is taken for the next.
        LightLabelArea area{glm::vec2(x0, y0), glm::vec2(x1, y1), {}, {}};
        const auto placed = [&](const UiRect& r) {
            boxes.push_back(r);
            area.taken.push_back({glm::vec2(r.x, r.y), glm::vec2(r.x + r.width, r.y + r.height)});
        };
        // projectToImage gives image pixels of the whole view (the pane's offset included).
        auto toUi = [&](const glm::vec3& p) {
            return ImVec2(view.x + p.x / framebufferScale, view.y + p.y / framebufferScale);
        };
        area.models = modelDiscs(scene, pane, models, glm::vec2(view.x, view.y), framebufferScale);
        for (std::size_t i = 0; i < scene.lights.size(); ++i) {
            const Light& l = scene.lights[i];
            const ImU32 colour = int(i) == selected ? IM_COL32(255, 210, 60, 255) : IM_COL32(255, 245, 190, 255);
            const std::string label = std::to_string(i) + " " + toString(l.type);
            if (l.type == LightType::Directional) {
                // Toward the target (what it lights), from the handle.
                const glm::vec3 dir = glm::normalize(l.direction);
                const float reach = directionalHandleDistance(scene.camera);
                const glm::vec3 a = projectToImage(scene.camera, pane, lightHandleWorld(scene, i));
                const glm::vec3 b = projectToImage(scene.camera, pane, scene.camera.target - dir * (reach * 0.4f));
                if (a.z > 0.0f && b.z > 0.0f) placed(drawDirectionArrow(style, area, toUi(a), toUi(b), label, colour));
                continue;
            }
            const glm::vec3 p = projectToImage(scene.camera, pane, l.position);
            const ImVec2 at = toUi(p);
            const bool inside = p.z > 0.0f && at.x >= x0 && at.x <= x1 && at.y >= y0 && at.y <= y1;
            placed(inside ? drawLightMarker(style, area, at, label, colour)
                          : drawBorderArrow(style, area, at, p.z <= 0.0f, label, colour));
        }
        style.draw->PopClipRect();
    }
    return boxes;
}

}  // namespace shadelab
