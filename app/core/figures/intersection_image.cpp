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
constexpr Rgba8 kIncoming{90, 215, 255, 255};  // I: the ray from the eye (V reversed)
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
            for (int c = 0; c < 3; ++c)
                q[c] = std::uint8_t(std::lround(float(q[c]) * (1.0f - a) + float((&color.r)[c]) * a));
        }
}

std::string fixed(const char* fmt, double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, fmt, v);
    return buffer;
}

// What every part of the diagram draws with: the image, the font, and sizes that grow with the image's
// height (720 pixels: 17-pixel text, 2.5-pixel arrows).
struct Pen {
    Image& image;
    const TrueTypeFont& font;
    float scale, width, size, em;  // em: the font's scale for text `size` pixels tall

    Pen(Image& im, const TrueTypeFont& f)
        : image(im),
          font(f),
          scale(std::clamp(float(im.height) / 720.0f, 0.6f, 4.0f)),
          width(2.5f * scale),
          size(17.0f * scale),
          em(size / f.height(1.0f)) {}
    void text(float x, float y, const std::string& s, Rgba8 color) const { font.draw(image, x, y, s, em, color); }
    float textWidth(const std::string& s) const { return font.width(s, em); }
};

// A world point's image pixel in the probed pane.
glm::vec2 panePixelOf(const IntersectionPoint& at, const glm::vec3& posWorld) {
    const glm::vec4 c = at.clipFromWorld * glm::vec4(posWorld, 1.0f);
    const glm::vec2 ndc = glm::vec2(c) / std::max(c.w, 1e-6f);
    return glm::vec2(at.paneX + (0.5f + 0.5f * ndc.x) * at.paneWidth, at.paneY + (0.5f - 0.5f * ndc.y) * at.paneHeight);
}

// On the model: the probed point, N, R and T as the 3-D vectors they are (I is the pixel's own ray,
// seen end-on: the schematic draws it), each letter beyond its arrow's tip. Returns R's tip, which the
// box must leave visible.
glm::vec2 drawOnModel(const Pen& pen, const Scene& scene, const IntersectionPoint& at) {
    const glm::vec3 n = at.nrmWorld, v = glm::normalize(scene.camera.eye - at.posWorld);
    Material probe;
    const EnvironmentTerm t = environmentTerm(probe, lightingEnvironment(scene), n, v);
    const float length = 0.2f * glm::length(scene.camera.eye - at.posWorld);  // as the viewer's probe arrows
    const glm::vec2 p = panePixelOf(at, at.posWorld);
    auto arrow = [&](const glm::vec3& d, const std::string& name, Rgba8 color) {
        const glm::vec2 tip = panePixelOf(at, at.posWorld + length * d);
        drawArrow(pen.image, p, tip, pen.width, color);
        const glm::vec2 along = glm::length(tip - p) > 1e-3f ? glm::normalize(tip - p) : glm::vec2(0, -1);
        const glm::vec2 at2 = tip + 0.9f * pen.size * along;
        pen.text(at2.x - 0.5f * pen.textWidth(name), at2.y - 0.5f * pen.size, name, color);
        return tip;
    };
    drawSegment(pen.image, p - glm::vec2(0.6f * pen.size, 0), p + glm::vec2(0.6f * pen.size, 0), pen.width, kIncoming);
    drawSegment(pen.image, p - glm::vec2(0, 0.6f * pen.size), p + glm::vec2(0, 0.6f * pen.size), pen.width, kIncoming);
    arrow(n, "N", kNormal);
    const glm::vec2 rTip = arrow(t.reflectedDirection, "R", kReflected);
    if (!t.totalInternal) arrow(t.transmittedDirection, "T", kRefracted);
    return rTip;
}

// The numbers under the schematic: the angles, Snell's law, and the Fresnel split.
std::vector<std::string> numberLines(const IntersectionNumbers& num) {
    return {"θ_i = " + fixed("%.1f°", num.thetaIDeg) +
                (num.totalInternal ? "   θ_t: none (total internal reflection)"
                                   : "   θ_t = " + fixed("%.1f°", num.thetaTDeg)),
            "η_i sin θ_i = " + fixed("%.3f", num.etaI * std::sin(num.thetaIDeg * 3.14159265f / 180.0f)) +
                (num.totalInternal ? "  > η_t" : " = η_t sin θ_t"),
            "R_∥ = " + fixed("%.3f", num.rParallel) + "   R_⊥ = " + fixed("%.3f", num.rPerpendicular),
            "R = (R_∥ + R_⊥)/2 = " + fixed("%.3f", num.r) + "   1 − R = " + fixed("%.3f", 1.0 - double(num.r))};
}

// The box beside the point (image pixels): the schematic, `sketch` tall, on top and the numbers' lines
// under it, `pad` around each.
struct Box {
    float x = 0, y = 0, width = 0, height = 0;
    float pad = 0, sketch = 0, lineHeight = 0;
};

// On the side the reflected arrow does not point to (it stays visible), else where there is room;
// inside the pane.
Box placeBox(const Pen& pen, const IntersectionPoint& at, glm::vec2 p, glm::vec2 rTip,
             const std::vector<std::string>& lines) {
    const float size = pen.size;
    float textWidth = 0.0f;
    for (const std::string& l : lines) textWidth = std::max(textWidth, pen.textWidth(l));
    Box b;
    b.pad = 0.6f * size;
    b.lineHeight = 1.3f * size;
    b.width = std::max(textWidth, 14.0f * size) + 2.0f * b.pad;
    b.sketch = 9.0f * size;
    b.height = b.pad + b.sketch + b.pad + b.lineHeight * float(lines.size()) + b.pad;
    const float right = at.paneX + at.paneWidth, bottom = at.paneY + at.paneHeight;
    const bool left = rTip.x > p.x ? p.x - 3.0f * size - b.width >= at.paneX : p.x + 3.0f * size + b.width > right;
    b.x = std::clamp(left ? p.x - 3.0f * size - b.width : p.x + 3.0f * size, at.paneX,
                     std::max(at.paneX, right - b.width));
    b.y = std::clamp(p.y - 0.5f * b.height, at.paneY, std::max(at.paneY, bottom - b.height));
    return b;
}

// The schematic at the top of the box: the interface with eta_i above and eta_t below (tinted), the
// point O in the middle, N, I arriving at theta_i, and R and T leaving with the share of the light
// each carries (T at theta_t; none past the critical angle).
void drawSchematic(const Pen& pen, const Box& box, const IntersectionNumbers& num) {
    const float x = box.x, y = box.y, pad = box.pad, sketch = box.sketch, size = pen.size, width = pen.width;
    const glm::vec2 o(x + 0.5f * box.width, y + pad + 0.5f * sketch);
    const float arm = 0.42f * sketch;
    fillBox(pen.image, x + pad, o.y, x + box.width - pad, y + pad + sketch, Rgba8{90, 140, 200, 70});
    drawSegment(pen.image, glm::vec2(x + pad, o.y), glm::vec2(x + box.width - pad, o.y), 0.6f * width,
                Rgba8{200, 200, 200, 255});
    pen.text(x + pad + 0.3f * size, y + pad, "η_i = " + fixed("%.2f", num.etaI), kText);
    pen.text(x + pad + 0.3f * size, y + pad + sketch - size, "η_t = " + fixed("%.2f", num.etaT), kText);
    drawSegment(pen.image, o - glm::vec2(0, arm), o + glm::vec2(0, arm), 0.4f * width,
                Rgba8{255, 255, 255, 120});  // the normal's line
    drawArrow(pen.image, o, o - glm::vec2(0, arm), 0.8f * width, kNormal);
    pen.text(o.x + 0.3f * size, o.y - arm - 0.5f * size, "N", kNormal);
    const float ti = num.thetaIDeg * 3.14159265f / 180.0f, tt = num.thetaTDeg * 3.14159265f / 180.0f;
    const glm::vec2 iFrom = o + arm * glm::vec2(-std::sin(ti), -std::cos(ti));
    drawArrow(pen.image, iFrom, o, width, kIncoming);
    pen.text(iFrom.x - 1.0f * size, iFrom.y - 0.6f * size, "I", kIncoming);
    const glm::vec2 rTo = o + arm * glm::vec2(std::sin(ti), -std::cos(ti));
    drawArrow(pen.image, o, rTo, width, kReflected);
    pen.text(rTo.x + 0.3f * size, rTo.y - 0.8f * size, "R  " + fixed("%.3f", num.r), kReflected);
    if (!num.totalInternal) {
        const glm::vec2 tTo = o + arm * glm::vec2(std::sin(tt), std::cos(tt));
        drawArrow(pen.image, o, tTo, width, kRefracted);
        pen.text(tTo.x + 0.4f * size, tTo.y - 0.8f * size, "T  " + fixed("%.3f", 1.0 - double(num.r)), kRefracted);
        const glm::vec2 at2 = o + 0.6f * arm * glm::vec2(std::sin(0.5f * tt), std::cos(0.5f * tt));
        pen.text(std::max(at2.x, o.x + 0.1f * size) - 0.5f * pen.textWidth("θ_t") + 0.4f * size, at2.y - 0.2f * size,
                 "θ_t", kRefracted);
    }
    const glm::vec2 at1 = o + 0.6f * arm * glm::vec2(-std::sin(0.5f * ti), -std::cos(0.5f * ti));
    pen.text(std::min(at1.x, o.x - 0.1f * size) - 0.5f * pen.textWidth("θ_i"), at1.y - 0.8f * size, "θ_i", kIncoming);
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
    n.etaI = t.eta.etaI;
    n.etaT = t.eta.etaT;
    const FresnelTerms f = fresnelExact(t.cosThetaI, t.eta.etaI, t.eta.etaT);
    n.rParallel = f.parallel;
    n.rPerpendicular = f.perpendicular;
    n.r = f.average;
    return n;
}

void drawIntersectionDiagram(Image& image, const Scene& scene, const IntersectionPoint& at) {
    const TrueTypeFont* font = TrueTypeFont::dejaVuSans();
    if (!font)
        throw InputError("--intersection: needs the DejaVu Sans font (Debian: fonts-dejavu-core), which was not found");
    const Pen pen(image, *font);
    const glm::vec2 p = panePixelOf(at, at.posWorld), rTip = drawOnModel(pen, scene, at);
    // The slide's picture in the plane of incidence, with the numbers under it, in a box beside the point.
    const IntersectionNumbers num = intersectionNumbers(scene, at);
    const std::vector<std::string> lines = numberLines(num);
    const Box box = placeBox(pen, at, p, rTip, lines);
    fillBox(image, box.x, box.y, box.x + box.width, box.y + box.height, Rgba8{0, 0, 0, 190});
    drawSegment(image, p,
                glm::vec2(box.x < p.x ? box.x + box.width : box.x, std::clamp(p.y, box.y, box.y + box.height)),
                1.0f * pen.scale, Rgba8{255, 255, 255, 110});  // a leader from the box to the point
    drawSchematic(pen, box, num);
    for (std::size_t k = 0; k < lines.size(); ++k)
        pen.text(box.x + box.pad, box.y + box.pad + box.sketch + box.pad + float(k) * box.lineHeight, lines[k], kText);
}

}  // namespace shadelab
