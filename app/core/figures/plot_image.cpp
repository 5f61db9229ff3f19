#include "core/figures/plot_image.hpp"

#include "core/image/truetype_text.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace shadelab {
namespace {

// Draws into an Image. A stroke first collects each pixel's coverage (the largest over the polyline's
// segments) and then blends once, so joints between segments are not darker than the line.
class ImagePainter final : public PlotPainter {
public:
    ImagePainter(Image& image, int textScale)
        : image_(image),
          textScale_(textScale),
          font_(TrueTypeFont::dejaVuSans()),
          coverage_(std::size_t(image.width) * std::size_t(image.height), 0.0f) {}

    // DejaVu Sans at 9 pixels per text scale (capitals about 6.5 tall, the bitmap font has 7). The
    // bitmap fallback draws capitals 7 font pixels tall with descenders 2 below; its own line height of
    // 12 adds leading. Text boxes are the 9 pixels that hold ink, so centred labels look centred.
    // Whole pixels, so the layout's lines land on pixel rows and columns and stay crisp.
    float lineHeight() const override {
        return font_ ? std::round(font_->height(pixels())) : 10.0f * float(textScale_);
    }
    glm::vec2 measure(const std::string& text) const override {
        if (font_)
            return {std::ceil(font_->width(lectureNotation(text), pixels())), std::round(font_->height(pixels()))};
        return {float(textWidth(text, textScale_)), 9.0f * float(textScale_)};
    }
    void stroke(const std::vector<glm::vec2>& pixels, Rgba8 color, float width) override {
        const float halfWidth = std::max(0.5f * width, 0.5f);
        Box dirty;
        for (std::size_t k = 0; k + 1 < pixels.size(); ++k) {
            const glm::vec2 a = pixels[k], b = pixels[k + 1];
            const Box box = clipped(glm::min(a, b) - (halfWidth + 1.0f), glm::max(a, b) + (halfWidth + 1.0f));
            dirty.add(box);
            for (int y = box.y0; y < box.y1; ++y)
                for (int x = box.x0; x < box.x1; ++x) {
                    const float d = distanceToSegment(glm::vec2(float(x) + 0.5f, float(y) + 0.5f), a, b);
                    cover(x, y, glm::clamp(halfWidth + 0.5f - d, 0.0f, 1.0f));
                }
        }
        flush(dirty, color);
    }
    void fillTriangle(glm::vec2 a, glm::vec2 b, glm::vec2 c, Rgba8 color) override {
        // Coverage from the signed distance to the nearest edge: 0.5 on the edge, 1 half a pixel inside.
        const float orientation = cross(b - a, c - a) >= 0.0f ? 1.0f : -1.0f;
        const Box box = clipped(glm::min(a, glm::min(b, c)) - 1.0f, glm::max(a, glm::max(b, c)) + 1.0f);
        for (int y = box.y0; y < box.y1; ++y)
            for (int x = box.x0; x < box.x1; ++x) {
                const glm::vec2 p(float(x) + 0.5f, float(y) + 0.5f);
                float inside = 1e9f;
                for (const auto& [e0, e1] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) {
                    const float length = glm::length(e1 - e0);
                    if (length > 0.0f) inside = std::min(inside, orientation * cross(e1 - e0, p - e0) / length);
                }
                cover(x, y, glm::clamp(inside + 0.5f, 0.0f, 1.0f));
            }
        flush(box, color);
    }
    // Pixels whose centres lie in [lo, hi): cells that share an edge share no pixel and leave none out.
    void fillRect(glm::vec2 lo, glm::vec2 hi, Rgba8 color) override {
        const int x0 = std::max(0, int(std::ceil(lo.x - 0.5f))),
                  x1 = std::min(image_.width, int(std::ceil(hi.x - 0.5f)));
        const int y0 = std::max(0, int(std::ceil(lo.y - 0.5f))),
                  y1 = std::min(image_.height, int(std::ceil(hi.y - 0.5f)));
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) {
                std::uint8_t* p = image_.pixel(x, y);
                p[0] = color.r;
                p[1] = color.g;
                p[2] = color.b;
            }
    }
    void text(glm::vec2 topLeft, const std::string& text, Rgba8 color) override {
        if (font_) return font_->draw(image_, topLeft.x, topLeft.y, lectureNotation(text), pixels(), color);
        drawText(image_, int(std::lround(topLeft.x)), int(std::lround(topLeft.y)), text, textScale_, color);
    }

private:
    struct Box {
        int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // [x0, x1) x [y0, y1)
        void add(const Box& b) {
            if (b.x0 >= b.x1 || b.y0 >= b.y1) return;
            if (x0 >= x1 || y0 >= y1) {
                *this = b;
                return;
            }
            x0 = std::min(x0, b.x0);
            y0 = std::min(y0, b.y0);
            x1 = std::max(x1, b.x1);
            y1 = std::max(y1, b.y1);
        }
    };
    static float cross(glm::vec2 u, glm::vec2 v) { return u.x * v.y - u.y * v.x; }
    static float distanceToSegment(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
        const glm::vec2 ab = b - a;
        const float len2 = glm::dot(ab, ab);
        const float t = len2 > 0.0f ? glm::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
        return glm::length(p - (a + t * ab));
    }
    Box clipped(glm::vec2 lo, glm::vec2 hi) const {
        Box b;
        b.x0 = std::max(0, int(std::floor(lo.x)));
        b.y0 = std::max(0, int(std::floor(lo.y)));
        b.x1 = std::min(image_.width, int(std::ceil(hi.x)) + 1);
        b.y1 = std::min(image_.height, int(std::ceil(hi.y)) + 1);
        return b;
    }
    void cover(int x, int y, float c) {
        float& stored = coverage_[std::size_t(y) * std::size_t(image_.width) + std::size_t(x)];
        stored = std::max(stored, c);
    }
    // Blends `color` by each pixel's coverage and clears the coverage for the next primitive.
    void flush(const Box& box, Rgba8 color) {
        const float rgb[3] = {float(color.r), float(color.g), float(color.b)};
        for (int y = box.y0; y < box.y1; ++y)
            for (int x = box.x0; x < box.x1; ++x) {
                float& c = coverage_[std::size_t(y) * std::size_t(image_.width) + std::size_t(x)];
                if (c <= 0.0f) continue;
                std::uint8_t* p = image_.pixel(x, y);
                for (int ch = 0; ch < 3; ++ch)
                    p[ch] = std::uint8_t(std::lround(float(p[ch]) + (rgb[ch] - float(p[ch])) * c));
                c = 0.0f;
            }
    }

    Image& image_;
    float pixels() const { return 9.0f * float(textScale_); }
    int textScale_;
    const TrueTypeFont* font_;
    std::vector<float> coverage_;
};

}  // namespace

Image renderPlotImage(const Plot& plot, int width, int height) {
    Image image(width, height);
    fillRect(image, 0, 0, width, height, kPlotBackground);
    const int textScale = std::max(1, int(std::lround(std::min(width / 400.0, height / 300.0))));
    ImagePainter painter(image, textScale);
    paintPlot(plot, glm::vec2(float(width), float(height)), 0.75f * float(textScale), painter);
    return image;
}

}  // namespace shadelab
