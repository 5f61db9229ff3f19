#pragma once
// Text drawn into images on the CPU (sweep-sheet labels, plot axes): Sean Barrett's stb_easy_font
// (Debian's libstb-dev) turns a string into axis-aligned quads of a tiny 6 x 7 pixel vector font,
// which are filled here at an integer scale. No GL, so headless sheets and plots need no font files.
#include "core/image/image.hpp"

#include <cstdint>
#include <string>

namespace shadelab {

struct Rgba8 {
    std::uint8_t r = 255, g = 255, b = 255, a = 255;
};

// Draws `text` with its top-left corner at (x, y), each font pixel `scale` x `scale` image pixels.
// Clipped to the image. Characters outside printable ASCII (any UTF-8 character, DEL, control bytes)
// are drawn as '?': the font has nothing else, and reading its tables with them is out of bounds.
void drawText(Image& image, int x, int y, const std::string& text, int scale, Rgba8 color);
// The size drawText covers, in image pixels.
int textWidth(const std::string& text, int scale);
int textHeight(const std::string& text, int scale);

// Fills the rectangle [x0, x1) x [y0, y1), clipped to the image.
void fillRect(Image& image, int x0, int y0, int x1, int y1, Rgba8 color);

}  // namespace shadelab
