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

ProgressiveSampling::Pass ProgressiveSampling::begin(std::uint64_t viewRevision, int samples) {
    const bool restart = from_ != viewRevision;
    if (restart) {
        from_ = viewRevision;
        stride_ = fixedStride_ > 0 ? fixedStride_ : adaptStride(stride_, samples, lastPassMs_);
    }
    // The frame's time measures a pass only if it drew exactly one (a complete image is only redrawn).
    passDrawnLastFrame_ = restart || !complete_;
    return Pass{restart, stride_};
}

void ProgressiveSampling::drawn(bool complete, bool finishedAtOnce) {
    if (finishedAtOnce) passDrawnLastFrame_ = false;
    complete_ = complete;
}

}  // namespace shadelab
