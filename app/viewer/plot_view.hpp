#pragma once
// A lecture plot (core/figures/plot.hpp) drawn live in the panel with ImGui's draw list: the same Plot and the
// same layout as the PNG that --plot writes, painted with ImGui's antialiased lines and its font.
#include "core/figures/plot.hpp"

namespace shadelab {

// Reserves the full available width and `height` (ImGui units) at the cursor, like a widget, and draws
// the plot there on its own background.
void plotWidget(const char* id, const Plot& plot, float height);

}  // namespace shadelab
