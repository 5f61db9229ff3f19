#include "core/image/text.hpp"

#include <stb/stb_easy_font.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace shadelab {

void fillRect(Image& image, int x0, int y0, int x1, int y1, Rgba8 c) {
    x0 = std::max(x0, 0);
    y0 = std::max(y0, 0);
    x1 = std::min(x1, image.width);
    y1 = std::min(y1, image.height);
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            std::uint8_t* p = image.pixel(x, y);
            p[0] = c.r;
            p[1] = c.g;
            p[2] = c.b;
            p[3] = c.a;
        }
}

namespace {

// stb_easy_font has glyphs for printable ASCII only and indexes its tables with (c - 32): any other
// byte would read outside them. Each UTF-8 character (or stray byte) outside that range becomes '?'.
std::vector<char> printableAscii(const std::string& text) {
    std::vector<char> out;
    out.reserve(text.size() + 1);
    for (std::size_t i = 0; i < text.size(); ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c >= 32 && c < 127) {
            out.push_back(char(c));
            continue;
        }
        out.push_back('?');
        if (c >= 0xC0)  // a UTF-8 lead byte: skip its continuation bytes
            while (i + 1 < text.size() && (static_cast<unsigned char>(text[i + 1]) & 0xC0) == 0x80) ++i;
    }
    out.push_back('\0');
    return out;
}

}  // namespace

void drawText(Image& image, int x, int y, const std::string& text, int scale, Rgba8 color) {
    // stb_easy_font writes 4 vertices of 16 bytes (x, y, z as floats, then RGBA) per quad; a character
    // needs at most ~10 quads, and 270 bytes per character is the header's own rule of thumb.
    std::vector<char> mutableText = printableAscii(text);
    std::vector<float> buffer(text.size() * 270 / sizeof(float) + 64);
    unsigned char rgba[4] = {255, 255, 255, 255};
    const int quads =
        stb_easy_font_print(0.0f, 0.0f, mutableText.data(), rgba, buffer.data(), int(buffer.size() * sizeof(float)));
    for (int q = 0; q < quads; ++q) {
        const float* v = &buffer[std::size_t(q) * 16];  // 4 vertices x (x, y, z, colour)
        const float qx0 = std::min(v[0], v[8]), qx1 = std::max(v[0], v[8]);
        const float qy0 = std::min(v[1], v[9]), qy1 = std::max(v[1], v[9]);
        fillRect(image, x + int(std::lround(qx0 * float(scale))), y + int(std::lround(qy0 * float(scale))),
                 x + int(std::lround(qx1 * float(scale))), y + int(std::lround(qy1 * float(scale))), color);
    }
}

int textWidth(const std::string& text, int scale) {
    std::vector<char> t = printableAscii(text);
    return stb_easy_font_width(t.data()) * scale;
}

int textHeight(const std::string& text, int scale) {
    std::vector<char> t = printableAscii(text);
    return stb_easy_font_height(t.data()) * scale;
}

}  // namespace shadelab
