#pragma once
// When the viewer draws (render on demand): after an event a few more frames, so ImGui's hover and
// click states settle, then it may sleep until the next one; while an animation plays or a recording
// runs, at most one frame a display refresh (60 Hz where the monitor does not say), also where swapping
// buffers does not wait for the display (llvmpipe on X11 and Xvfb, where it burnt 1.6 cores). Whether
// anything else still wants a frame (a progressive sum, the still view anti-aliased) the viewer asks
// its other parts (Viewer::idle). GL-free: the window's event count and clock come in as numbers.
#include <chrono>

namespace shadelab {

class FramePacing {
public:
    using Clock = std::chrono::steady_clock;
    static constexpr int kFramesAfterEvent = 3;

    // At a frame's start, with the window's event count: whether no event came since the last frame.
    // After one, kFramesAfterEvent frames are drawn (this one included).
    bool countEvents(unsigned long eventCount);
    // Frames are still to be drawn: an event not yet counted, or frames after the last one.
    bool pending(unsigned long eventCount) const { return framesToDraw_ > 0 || eventCount != eventsSeen_; }
    // Something changed outside the events (a status message): at least one more frame.
    void drawAnother() { framesToDraw_ = framesToDraw_ > 1 ? framesToDraw_ : 1; }

    // The cap while something plays: the display's refresh rate where it is plausible, else 60 Hz.
    static int capHz(int refreshRate) { return refreshRate >= 24 && refreshRate <= 240 ? refreshRate : 60; }
    // A frame begins (after any wait); the next capped one is due a refresh after it.
    void frameBegins(Clock::time_point now) { frameBegun_ = now; }
    Clock::time_point nextDue(int capHz) const {
        return frameBegun_ + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / capHz));
    }

private:
    unsigned long eventsSeen_ = 0;
    int framesToDraw_ = 2;
    Clock::time_point frameBegun_;
};

inline bool FramePacing::countEvents(unsigned long eventCount) {
    const bool still = eventCount == eventsSeen_;
    if (!still) {
        eventsSeen_ = eventCount;
        framesToDraw_ = kFramesAfterEvent;
    }
    if (framesToDraw_ > 0) --framesToDraw_;
    return still;
}

}  // namespace shadelab
