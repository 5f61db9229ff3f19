#pragma once
// Text in a TrueType font drawn into images on the CPU (the PNG plots): stb_truetype from Debian's
// libstb-dev rasterises DejaVu Sans (fonts-dejavu-core) glyph by glyph at the size asked, with
// anti-aliased edges, so a plot reads θ_i and η₁ → η₂ as the lecture writes them. Where the font file
// is missing, callers fall back to the bitmap font of core/image/text.hpp.
#include "core/image/image.hpp"
#include "core/image/text.hpp"

#include <memory>
#include <string>

namespace shadelab {

class TrueTypeFont {
public:
    // DejaVu Sans, loaded once; null when the file cannot be read.
    static const TrueTypeFont* dejaVuSans();
    ~TrueTypeFont();

    // Distances in pixels for a font of `pixels` em height: from the top of the line to the baseline,
    // the line's height (ascent to descent), and the advance of a UTF-8 string.
    float ascent(float pixels) const;
    float height(float pixels) const;
    float width(const std::string& utf8, float pixels) const;
    // Draws `utf8` with its line's top-left corner at (x, y), blending each glyph's coverage over the
    // image (clipped to it).
    void draw(Image& image, float x, float y, const std::string& utf8, float pixels, Rgba8 color) const;

private:
    struct Impl;
    explicit TrueTypeFont(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace shadelab
