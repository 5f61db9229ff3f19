#include "core/figures/formula_image.hpp"

#include "core/base/error.hpp"

#include <algorithm>
#include <cmath>

namespace shadelab {
namespace {

// Blends `color` (its alpha the weight) over the rectangle [x0, x1) x [y0, y1) with corners rounded
// by `radius`, clipped to the image.
void blendRoundedRect(Image& image, float x0, float y0, float x1, float y1, float radius, Rgba8 color) {
    const int ix0 = std::max(int(std::floor(x0)), 0), iy0 = std::max(int(std::floor(y0)), 0);
    const int ix1 = std::min(int(std::ceil(x1)), image.width), iy1 = std::min(int(std::ceil(y1)), image.height);
    const float a = float(color.a) / 255.0f;
    for (int y = iy0; y < iy1; ++y)
        for (int x = ix0; x < ix1; ++x) {
            const float px = float(x) + 0.5f, py = float(y) + 0.5f;
            const float dx = std::max({x0 + radius - px, px - (x1 - radius), 0.0f});
            const float dy = std::max({y0 + radius - py, py - (y1 - radius), 0.0f});
            if (dx * dx + dy * dy > radius * radius) continue;
            std::uint8_t* p = image.pixel(x, y);
            p[0] = std::uint8_t(std::lround(float(p[0]) + (float(color.r) - float(p[0])) * a));
            p[1] = std::uint8_t(std::lround(float(p[1]) + (float(color.g) - float(p[1])) * a));
            p[2] = std::uint8_t(std::lround(float(p[2]) + (float(color.b) - float(p[2])) * a));
        }
}

}  // namespace

TextMetrics trueTypeMetrics(const TrueTypeFont& font) {
    // stb_truetype sizes by the em, ImGui (and the layout) by the line height: em = size / lineHeight(1).
    const float linePerEm = font.height(1.0f);
    const TrueTypeFont* f = &font;
    return TextMetrics{[f, linePerEm](const std::string& s, float size) { return f->width(s, size / linePerEm); },
                       font.ascent(1.0f) / linePerEm};
}

float formulaFontSize(int imageHeight) { return 16.0f * std::clamp(float(imageHeight) / 720.0f, 0.6f, 4.0f); }

FormulaOverlay imageFormulaOverlay(const Image& image, const FormulaInput& in, const std::vector<FormulaPane>& panes,
                                   const TrueTypeFont& font) {
    return layoutFormulaOverlay(in, float(image.width), float(image.height), panes, formulaFontSize(image.height),
                                trueTypeMetrics(font));
}

void drawFormulaOverlay(Image& image, const FormulaInput& in, const std::vector<FormulaPane>& panes) {
    const TrueTypeFont* font = TrueTypeFont::dejaVuSans();
    if (!font)
        throw InputError("--formula: needs the DejaVu Sans font (Debian: fonts-dejavu-core), which was not found");
    const FormulaOverlay o = imageFormulaOverlay(image, in, panes, *font);
    const float linePerEm = font->height(1.0f);
    const auto text = [&](float x, float top, const std::string& s, float size, Rgba8 color) {
        font->draw(image, x, top, s, size / linePerEm, color);
    };
    const Rgba8 backing{0, 0, 0, kFormulaBackingAlpha};
    for (const FormulaNote& n : o.notes) {
        blendRoundedRect(image, n.x - n.pad, n.y - n.pad, n.x + n.width + n.pad, n.y + n.size + n.pad, n.pad, backing);
        text(n.x, n.y, n.text, n.size, Rgba8{235, 235, 235, 255});
    }
    const FormulaLayout& f = o.formula;
    blendRoundedRect(image, o.x, o.y, o.x + f.width, o.y + f.height, f.corner, backing);
    for (const FormulaBox& b : f.boxes) {
        if (!b.isolated) continue;
        Rgba8 tint = termColor(b.term);
        tint.a = kIsolatedBoxAlpha;
        blendRoundedRect(image, o.x + b.x0, o.y + b.y0, o.x + b.x1, o.y + b.y1, 0.25f * (b.y1 - b.y0), tint);
    }
    const float ascent = font->ascent(1.0f) / linePerEm;
    for (const FormulaRun& r : f.runs) text(o.x + r.x, o.y + r.baseline - ascent * r.size, r.text, r.size, r.color);
}

}  // namespace shadelab
