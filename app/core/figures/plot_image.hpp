#pragma once
// The lecture's plots (core/figures/plot.hpp) rasterised on the CPU into an image, for --plot KIND:
// antialiased lines (coverage from the distance to each segment), filled arrowheads, and
// DejaVu Sans text through stb_truetype (core/image/truetype_text.hpp; stb_easy_font, core/image/text.hpp, where
// the font file is missing). No GL, no context.
#include "core/figures/plot.hpp"
#include "core/image/image.hpp"

namespace shadelab {

// Text and line widths grow with the image: text scale max(1, round(min(width / 400, height / 300)))
// (2 at the default 800 x 600), one line unit = 0.75 pixels per text scale.
Image renderPlotImage(const Plot& plot, int width, int height);
inline constexpr int kPlotDefaultWidth = 800, kPlotDefaultHeight = 600;
// Smaller plots have no room for their labels; larger ones are not needed for a slide.
inline constexpr int kPlotMinWidth = 320, kPlotMinHeight = 240, kPlotMaxSide = 4096;
// "320x240 to 4096x4096": the plot sizes --size may ask for, as messages and --help say it.
inline std::string plotSizesText() {
    return std::to_string(kPlotMinWidth) + "x" + std::to_string(kPlotMinHeight) + " to " +
           std::to_string(kPlotMaxSide) + "x" + std::to_string(kPlotMaxSide);
}

}  // namespace shadelab
