#pragma once
// The formula overlay (core/figures/formula.hpp) painted into an image on the CPU, for `--formula`
// with `--output`: DejaVu Sans through stb_truetype (core/image/truetype_text.hpp), the same layout
// the viewer paints with ImGui.
#include "core/figures/formula.hpp"
#include "core/image/image.hpp"
#include "core/image/truetype_text.hpp"

#include <vector>

namespace shadelab {

// The font's measures as the layout takes them (sizes are line heights, as ImGui's).
TextMetrics trueTypeMetrics(const TrueTypeFont& font);

// The UI text size an image of this height gets: 16 px at 720 rows (the viewer's at content scale 1),
// in proportion to the height from 0.6 to 4 times that.
float formulaFontSize(int imageHeight);

// The overlay for `image`: layoutFormulaOverlay at formulaFontSize, panes in image pixels.
FormulaOverlay imageFormulaOverlay(const Image& image, const FormulaInput& in, const std::vector<FormulaPane>& panes,
                                   const TrueTypeFont& font);

// Paints it: the translucent backings, the isolated term's tint, the runs, the pane notes. Throws
// InputError "--formula: ..." when DejaVu Sans is missing (the bitmap font has no Greek).
void drawFormulaOverlay(Image& image, const FormulaInput& in, const std::vector<FormulaPane>& panes);

}  // namespace shadelab
