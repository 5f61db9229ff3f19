#pragma once
// Progressive sampling in the viewer: scenes with sampled area lights refine over frames
// (Renderer::renderProgressive), a pass a frame, so dragging a slider or the camera stays fluid and a
// still view converges to the one-pass image. This class decides, frame by frame, whether the sum
// restarts (the view's revision moved, view_revision.hpp) and with which stride, and whether it is
// still refining (the viewer does not sleep until it is complete); the renderer does the drawing.
// GL-free.
#include <chrono>
#include <cstdint>
#include <optional>

namespace shadelab {

class ProgressiveSampling {
public:
    using Clock = std::chrono::steady_clock;
    // The stride (every S-th area-light sample per axis in a pass) is a power of two: first the one that
    // leaves about 4 samples per pass, then at each restart doubled while a pass took longer than
    // kPassBudgetMs and halved while it took under a quarter of that (llvmpipe at 1280x720: an 8x8
    // light with shadows settles at 8, one sample a frame).
    static constexpr double kPassBudgetMs = 90.0;
    static int adaptStride(int stride, int samples, double lastPassMs);

    // `fixedStride` (--progressive S): always that stride; 0 adapts it.
    explicit ProgressiveSampling(int fixedStride = 0) : fixedStride_(fixedStride) {}

    // A frame starts drawing the scene at `now`: the time since the last one is a pass's time if that
    // frame drew exactly one pass.
    void frameBegins(Clock::time_point now);
    // The scene needs no sampling (no area light with more than one sample): no sum is kept.
    void off();
    // This frame's pass of a scene whose largest area light has `samples` samples, drawn from the view
    // at `viewRevision`: whether the sum restarts, and the stride; `moving`: a moving frame's one sample.
    struct Pass {
        bool restart = false;
        int stride = 1;
    };
    Pass begin(std::uint64_t viewRevision, int samples, bool moving = false);
    // What the frame drew: the sum is `complete` now; `finishedAtOnce` when the frame drew every
    // remaining pass (a screenshot, the last frame), so its time measures no single pass.
    void drawn(bool complete, bool finishedAtOnce);
    // Nothing to refine (a minimised view, a program that failed): the viewer may sleep.
    void abandon() { complete_ = true; }

    // A sum is under way and not complete: the next frame draws another pass.
    bool refining() const { return from_.has_value() && !complete_; }
    int stride() const { return stride_; }
    double lastPassMs() const { return lastPassMs_; }

private:
    int fixedStride_ = 0;
    std::optional<std::uint64_t> from_;  // the view revision the sum was started at; none while off
    int stride_ = 0;
    double lastPassMs_ = 0.0;
    bool passDrawnLastFrame_ = false;
    bool complete_ = false;
    Clock::time_point lastFrameStart_;
};

}  // namespace shadelab
