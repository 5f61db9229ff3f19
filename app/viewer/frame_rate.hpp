#pragma once
// The status strip's frame time: the mean of the frames drawn in the last second
// (at most kMaxFrames of them), so it says what moving the view costs now; with none drawn in that
// second the view is idle (render on demand) and the strip says so instead of an old frame's time.
#include <chrono>
#include <cstddef>
#include <deque>
#include <optional>
#include <utility>

namespace shadelab {

class FrameRate {
public:
    using Clock = std::chrono::steady_clock;
    static constexpr std::size_t kMaxFrames = 120;
    static constexpr double kWindowSeconds = 1.0;

    // A frame drawn, ending at `end`, that took `ms` of its own (polling to swap, no waiting).
    void add(Clock::time_point end, double ms) {
        frames_.emplace_back(end, ms);
        if (frames_.size() > kMaxFrames) frames_.pop_front();
    }
    // The mean frame time of the frames that ended within kWindowSeconds before `now`; none: idle.
    std::optional<double> meanMs(Clock::time_point now) {
        while (!frames_.empty() && std::chrono::duration<double>(now - frames_.front().first).count() > kWindowSeconds)
            frames_.pop_front();
        if (frames_.empty()) return std::nullopt;
        double sum = 0.0;
        for (const auto& f : frames_) sum += f.second;
        return sum / double(frames_.size());
    }
    std::size_t count() const { return frames_.size(); }

private:
    std::deque<std::pair<Clock::time_point, double>> frames_;
};

}  // namespace shadelab
