#pragma once
// A frame in at most 256 colours, for GIF: the frame's own palette (GIF allows one per frame). A frame
// of at most 256 colours keeps them all, exactly; a larger one gets 256 colours by median cut over its
// distinct colours (not over its pixels: the few pixels of a Phong highlight get as many palette
// entries as their many shades need, so the highlight does not band). No libav: unit-tested alone.
#include "core/image/image.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace shadelab {

struct PalettedImage {
    int width = 0, height = 0;
    std::vector<std::array<std::uint8_t, 3>> palette;  // RGB, at most 256 entries, no two the same
    std::vector<std::uint8_t> indices;                 // one per pixel, rows top to bottom
};

// The frame's palette and each pixel's entry (alpha is ignored). Without `dither`, each pixel takes its
// colour's entry (its own colour in a frame of <= 256 colours); with it, Floyd-Steinberg error
// diffusion onto the palette (exact too where the frame has <= 256 colours: there is no error).
PalettedImage paletteFrame(const Image& frame, bool dither);

}  // namespace shadelab
