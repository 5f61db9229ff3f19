#include "viewer/progressive_sampling.hpp"

#include "core/scene/scene_limits.hpp"

namespace shadelab {

int ProgressiveSampling::adaptStride(int stride, int samples, double lastPassMs) {
    if (stride <= 0) {
        stride = 1;
        while (samples / (stride * stride) > 4) stride *= 2;
        return stride;
    }
    if (lastPassMs > kPassBudgetMs && stride < kAreaSamplesPerSideRange.hi) return stride * 2;
    if (lastPassMs > 0.0 && lastPassMs < kPassBudgetMs / 4 && stride > 1) return stride / 2;
    return stride;
}

void ProgressiveSampling::frameBegins(Clock::time_point now) {
    if (passDrawnLastFrame_) lastPassMs_ = std::chrono::duration<double, std::milli>(now - lastFrameStart_).count();
    lastFrameStart_ = now;
    passDrawnLastFrame_ = false;
}

void ProgressiveSampling::off() { from_.reset(); }

ProgressiveSampling::Pass ProgressiveSampling::begin(std::uint64_t viewRevision, int samples, bool moving) {
    const bool restart = from_ != viewRevision;
    from_ = viewRevision;
    // A moving frame (ViewQuality) draws one sample of each area light, the largest stride, and keeps the
    // still view's stride as it was; the still view after it restarts (its revision differs) and sums them all.
    if (restart && !moving) stride_ = fixedStride_ > 0 ? fixedStride_ : adaptStride(stride_, samples, lastPassMs_);
    // The frame's time measures a still pass only if it drew exactly one (a complete image is only redrawn).
    passDrawnLastFrame_ = !moving && (restart || !complete_);
    return Pass{restart, moving ? kAreaSamplesPerSideRange.hi : stride_};
}

void ProgressiveSampling::drawn(bool complete, bool finishedAtOnce) {
    if (finishedAtOnce) passDrawnLastFrame_ = false;
    complete_ = complete;
}

}  // namespace shadelab
