#include "viewer/view_quality.hpp"

#include <algorithm>
#include <cmath>

namespace shadelab {

void ViewQuality::plan(const Frame& f) {
    antiAliasThisFrame_ =
        samples_ > 1 && (!softwareGl_ || (f.still && !f.mouseDown && !f.playing) || f.capture || f.last);
    // A moving frame on a software rasterizer: smaller while the last moving frames took longer than
    // kMovingBudgetMs (at most halved a frame: one slow frame, e.g. the first that compiles the moving
    // frames' programs, does not drop it to the floor), larger again while they took under half of it
    // (never for files or a scripted run).
    const bool moving = softwareGl_ && !f.scripted && !f.capture && !f.last && (f.mouseDown || f.playing);
    if (moving && movingLastFrame_) {
        if (f.lastFrameMs > kMovingBudgetMs)
            movingScale_ =
                std::max(kMinMovingScale,
                         movingScale_ * std::max(float(std::sqrt(kMovingBudgetMs / f.lastFrameMs)), 0.5f) * 0.95f);
        else if (f.lastFrameMs < 0.5 * kMovingBudgetMs) movingScale_ = std::min(1.0f, movingScale_ * 1.1f);
    }
    movingLastFrame_ = moving;
    reducedThisFrame_ = moving && movingScale_ < 0.98f;
}

}  // namespace shadelab
