#include "core/figures/intersection_image.hpp"

#include "core/base/error.hpp"
#include "core/image/truetype_text.hpp"
#include "core/shading/environment.hpp"
#include "core/shading/lighting.hpp"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace shadelab {
namespace {

// The arrows' colours: those of the viewer's probe arrows (viewer/probe_arrows.cpp) where they mean
// the same vector; T its own.
constexpr Rgba8 kIncoming{90, 215, 255, 255};   // I: the ray from the eye (V reversed)
constexpr Rgba8 kNormal{255, 255, 255, 255};
constexpr Rgba8 kReflected{255, 115, 90, 255};
constexpr Rgba8 kRefracted{120, 255, 140, 255};
constexpr Rgba8 kText{240, 240, 240, 255};

// Blends `color` over the pixels within `width` / 2 of the segment a-b (image pixels), edges anti-aliased.
void drawSegment(Image& image, glm::vec2 a, glm::vec2 b, float width, Rgba8 color) {
    const float r = 0.5f * width;
    const int x0 = std::max(int(std::floor(std::min(a.x, b.x) - r - 1.0f)), 0);
    const int x1 = std::min(int(std::ceil(std::max(a.x, b.x) + r + 1.0f)), image.width - 1);
    const int y0 = std::max(int(std::floor(std::min(a.y, b.y) - r - 1.0f)), 0);
    const int y1 = std::min(int(std::ceil(std::max(a.y, b.y) + r + 1.0f)), image.height - 1);
    const glm::vec2 ab = b - a;
    const float len2 = std::max(glm::dot(ab, ab), 1e-12f);
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const glm::vec2 p(float(x) + 0.5f, float(y) + 0.5f);
            const float t = std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f);
            const float cover = std::clamp(r + 0.5f - glm::length(p - (a + t * ab)), 0.0f, 1.0f);
            if (cover <= 0.0f) continue;
            std::uint8_t* q = image.pixel(x, y);
            const float w = cover * float(color.a) / 255.0f;
            q[0] = std::uint8_t(std::lround(float(q[0]) + (float(color.r) - float(q[0])) * w));
            q[1] = std::uint8_t(std::lround(float(q[1]) + (float(color.g) - float(q[1])) * w));
            q[2] = std::uint8_t(std::lround(float(q[2]) + (float(color.b) - float(q[2])) * w));
        }
}

void drawArrow(Image& image, glm::vec2 from, glm::vec2 to, float width, Rgba8 color) {
    drawSegment(image, from, to, width, color);
    const glm::vec2 d = to - from;
    const float len = glm::length(d);
    if (len < 1e-3f) return;
    const glm::vec2 u = d / len, side(-u.y, u.x);
    const float head = std::min(4.0f * width + 6.0f, 0.4f * len);
    drawSegment(image, to, to - head * u + 0.5f * head * side, width, color);
    drawSegment(image, to, to - head * u - 0.5f * head * side, width, color);
}

void fillBox(Image& image, float x0, float y0, float x1, float y1, Rgba8 color) {
    const float a = float(color.a) / 255.0f;
    for (int y = std::max(int(y0), 0); y < std::min(int(y1), image.height); ++y)
        for (int x = std::max(int(x0), 0); x < std::min(int(x1), image.width); ++x) {
            std::uint8_t* q = image.pixel(x, y);
            for (int c = 0; c < 3; ++c) q[c] = std::uint8_t(std::lround(float(q[c]) * (1.0f - a) + float((&color.r)[c]) * a));
        }
}

std::string fixed(const char* fmt, double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, fmt, v);
    return buffer;
}

}  // namespace

IntersectionNumbers intersectionNumbers(const Scene& scene, const IntersectionPoint& at) {
    const glm::vec3 v = glm::normalize(scene.camera.eye - at.posWorld);
    Material probe;
    const EnvironmentTerm t = environmentTerm(probe, lightingEnvironment(scene), at.nrmWorld, v);
    IntersectionNumbers n;
    constexpr double kDeg = 180.0 / 3.14159265358979323846;
    n.thetaIDeg = float(std::acos(double(t.cosThetaI)) * kDeg);
    n.totalInternal = t.totalInternal;
    n.thetaTDeg = t.totalInternal ? 0.0f : float(std::acos(double(t.cosThetaT)) * kDeg);
    n.etaI = t.eta.etaI, n.etaT = t.eta.etaT;
    const FresnelTerms f = fresnelExact(t.cosThetaI, t.eta.etaI, t.eta.etaT);
    n.rParallel = f.parallel, n.rPerpendicular = f.perpendicular, n.r = f.average;
    return n;
}

void drawIntersectionDiagram(Image& image, const Scene& scene, const IntersectionPoint& at) {
    const TrueTypeFont* font = TrueTypeFont::dejaVuSans();
    if (!font) throw InputError("--intersection: needs the DejaVu Sans font (Debian: fonts-dejavu-core), which was not found");
    auto project = [&](const glm::vec3& p) {
        const glm::vec4 c = at.clipFromWorld * glm::vec4(p, 1.0f);
        const glm::vec2 ndc = glm::vec2(c) / std::max(c.w, 1e-6f);
        return glm::vec2(at.paneX + (0.5f + 0.5f * ndc.x) * at.paneWidth, at.paneY + (0.5f - 0.5f * ndc.y) * at.paneHeight);
    };
    const glm::vec3 n = at.nrmWorld, v = glm::normalize(scene.camera.eye - at.posWorld);
    Material probe;
    const EnvironmentTerm t = environmentTerm(probe, lightingEnvironment(scene), n, v);
    const IntersectionNumbers num = intersectionNumbers(scene, at);

    const float scale = std::clamp(float(image.height) / 720.0f, 0.6f, 4.0f);
    const float width = 2.5f * scale, size = 17.0f * scale, em = size / font->height(1.0f);
    const float length = 0.2f * glm::length(scene.camera.eye - at.posWorld);  // as the viewer's probe arrows
    const glm::vec2 p = project(at.posWorld);
    auto label = [&](glm::vec2 tip, glm::vec2 from, const std::string& text, Rgba8 color) {
        const glm::vec2 d = glm::length(tip - from) > 1e-3f ? glm::normalize(tip - from) : glm::vec2(0, -1);
        const glm::vec2 at2 = tip + 0.9f * size * d;
        font->draw(image, at2.x - 0.5f * font->width(text, em), at2.y - 0.5f * size, text, em, color);
    };
    // On the model: the probed point, N, R and T as the 3-D vectors they are (I is the pixel's own ray,
    // seen end-on: the schematic below draws it).
    drawSegment(image, p - glm::vec2(0.6f * size, 0), p + glm::vec2(0.6f * size, 0), width, kIncoming);
    drawSegment(image, p - glm::vec2(0, 0.6f * size), p + glm::vec2(0, 0.6f * size), width, kIncoming);
    const glm::vec2 nTip = project(at.posWorld + length * n);
    drawArrow(image, p, nTip, width, kNormal);
    label(nTip, p, "N", kNormal);
    const glm::vec2 rTip = project(at.posWorld + length * t.reflectedDirection);
    drawArrow(image, p, rTip, width, kReflected);
    label(rTip, p, "R", kReflected);
    if (!t.totalInternal) {
        const glm::vec2 tTip = project(at.posWorld + length * t.transmittedDirection);
        drawArrow(image, p, tTip, width, kRefracted);
        label(tTip, p, "T", kRefracted);
    }

    // The slide's picture in the plane of incidence, with the numbers under it, in a box beside the point.
    const std::vector<std::string> lines = {
        "θ_i = " + fixed("%.1f°", num.thetaIDeg) +
            (num.totalInternal ? "   θ_t: none (total internal reflection)" : "   θ_t = " + fixed("%.1f°", num.thetaTDeg)),
        "η_i sin θ_i = " + fixed("%.3f", num.etaI * std::sin(num.thetaIDeg * 3.14159265f / 180.0f)) +
            (num.totalInternal ? "  > η_t" : " = η_t sin θ_t"),
        "R_∥ = " + fixed("%.3f", num.rParallel) + "   R_⊥ = " + fixed("%.3f", num.rPerpendicular),
        "R = (R_∥ + R_⊥)/2 = " + fixed("%.3f", num.r) + "   1 − R = " + fixed("%.3f", 1.0 - double(num.r))};
    float textWidth = 0.0f;
    for (const std::string& l : lines) textWidth = std::max(textWidth, font->width(l, em));
    const float pad = 0.6f * size, lineHeight = 1.3f * size;
    const float boxWidth = std::max(textWidth, 14.0f * size) + 2.0f * pad;
    const float sketch = 9.0f * size;  // the schematic's height
    const float boxHeight = pad + sketch + pad + lineHeight * float(lines.size()) + pad;
    const float right = at.paneX + at.paneWidth, bottom = at.paneY + at.paneHeight;
    // On the side the reflected arrow does not point to (it stays visible), else where there is room.
    const bool left = rTip.x > p.x ? p.x - 3.0f * size - boxWidth >= at.paneX : p.x + 3.0f * size + boxWidth > right;
    float x = left ? p.x - 3.0f * size - boxWidth : p.x + 3.0f * size, y = p.y - 0.5f * boxHeight;
    x = std::clamp(x, at.paneX, std::max(at.paneX, right - boxWidth));
    y = std::clamp(y, at.paneY, std::max(at.paneY, bottom - boxHeight));
    fillBox(image, x, y, x + boxWidth, y + boxHeight, Rgba8{0, 0, 0, 190});
    drawSegment(image, p, glm::vec2(x < p.x ? x + boxWidth : x, std::clamp(p.y, y, y + boxHeight)), 1.0f * scale,
                Rgba8{255, 255, 255, 110});  // a leader from the box to the point
    // The interface: eta_i above, eta_t below (tinted), the point O in the middle.
    const glm::vec2 o(x + 0.5f * boxWidth, y + pad + 0.5f * sketch);
    const float arm = 0.42f * sketch;
    fillBox(image, x + pad, o.y, x + boxWidth - pad, y + pad + sketch, Rgba8{90, 140, 200, 70});
    drawSegment(image, glm::vec2(x + pad, o.y), glm::vec2(x + boxWidth - pad, o.y), 0.6f * width, Rgba8{200, 200, 200, 255});
    const std::string etaI = "η_i = " + fixed("%.2f", num.etaI), etaT = "η_t = " + fixed("%.2f", num.etaT);
    font->draw(image, x + pad + 0.3f * size, y + pad, etaI, em, kText);
    font->draw(image, x + pad + 0.3f * size, y + pad + sketch - size, etaT, em, kText);
    drawSegment(image, o - glm::vec2(0, arm), o + glm::vec2(0, arm), 0.4f * width, Rgba8{255, 255, 255, 120});  // the normal's line
    drawArrow(image, o, o - glm::vec2(0, arm), 0.8f * width, kNormal);
    font->draw(image, o.x + 0.3f * size, o.y - arm - 0.5f * size, "N", em, kNormal);
    const float ti = num.thetaIDeg * 3.14159265f / 180.0f, tt = num.thetaTDeg * 3.14159265f / 180.0f;
    const glm::vec2 iFrom = o + arm * glm::vec2(-std::sin(ti), -std::cos(ti));
    drawArrow(image, iFrom, o, width, kIncoming);
    font->draw(image, iFrom.x - 1.0f * size, iFrom.y - 0.6f * size, "I", em, kIncoming);
    // R and T with the share of the light each carries.
    const glm::vec2 rTo = o + arm * glm::vec2(std::sin(ti), -std::cos(ti));
    drawArrow(image, o, rTo, width, kReflected);
    font->draw(image, rTo.x + 0.3f * size, rTo.y - 0.8f * size, "R  " + fixed("%.3f", num.r), em, kReflected);
    if (!num.totalInternal) {
        const glm::vec2 tTo = o + arm * glm::vec2(std::sin(tt), std::cos(tt));
        drawArrow(image, o, tTo, width, kRefracted);
        font->draw(image, tTo.x + 0.4f * size, tTo.y - 0.8f * size, "T  " + fixed("%.3f", 1.0 - double(num.r)), em, kRefracted);
        const glm::vec2 at2 = o + 0.6f * arm * glm::vec2(std::sin(0.5f * tt), std::cos(0.5f * tt));
        font->draw(image, std::max(at2.x, o.x + 0.1f * size) - 0.5f * font->width("θ_t", em) + 0.4f * size, at2.y - 0.2f * size, "θ_t", em, kRefracted);
    }
    const glm::vec2 at1 = o + 0.6f * arm * glm::vec2(-std::sin(0.5f * ti), -std::cos(0.5f * ti));
    font->draw(image, std::min(at1.x, o.x - 0.1f * size) - 0.5f * font->width("θ_i", em), at1.y - 0.8f * size, "θ_i", em, kIncoming);
    for (std::size_t k = 0; k < lines.size(); ++k)
        font->draw(image, x + pad, y + pad + sketch + pad + float(k) * lineHeight, lines[k], em, kText);
}

}  // namespace shadelab
