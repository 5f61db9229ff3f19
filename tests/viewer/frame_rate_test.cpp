// The status strip's frame time (app/viewer/frame_rate.hpp): the mean of the frames drawn in the last
// second, not the last frame's; nothing drawn in that second is idle.
#include "viewer/frame_rate.hpp"

#include <gtest/gtest.h>

namespace shadelab {
namespace {

using namespace std::chrono_literals;

TEST(FrameRate, MeanOfTheFramesDrawnInTheLastSecond) {
    FrameRate rate;
    const auto t0 = FrameRate::Clock::time_point{} + 100s;
    EXPECT_FALSE(rate.meanMs(t0).has_value());  // nothing drawn yet: idle
    // Ten 20-ms frames, then one 200-ms anti-aliased still frame: the mean, not the last one.
    for (int i = 0; i < 10; ++i) rate.add(t0 + i * 20ms, 20.0);
    rate.add(t0 + 400ms, 200.0);
    ASSERT_TRUE(rate.meanMs(t0 + 400ms).has_value());
    EXPECT_NEAR(*rate.meanMs(t0 + 400ms), (10 * 20.0 + 200.0) / 11.0, 1e-9);
    // 1.1 s after the first frame the first five (0..80 ms) are older than a second.
    EXPECT_NEAR(*rate.meanMs(t0 + 1090ms), (5 * 20.0 + 200.0) / 6.0, 1e-9);
    // A second after the last frame: nothing drawn since, idle.
    EXPECT_FALSE(rate.meanMs(t0 + 1500ms).has_value());
}

TEST(FrameRate, AtMost120Frames) {
    FrameRate rate;
    const auto t0 = FrameRate::Clock::time_point{} + 100s;
    for (int i = 0; i < 200; ++i) rate.add(t0 + i * 1ms, i < 80 ? 100.0 : 1.0);
    EXPECT_EQ(rate.count(), FrameRate::kMaxFrames);
    EXPECT_NEAR(*rate.meanMs(t0 + 200ms), 1.0, 1e-9);  // the 80 slow ones were the oldest
}

}  // namespace
}  // namespace shadelab
