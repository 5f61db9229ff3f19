#pragma once
// Animations: `--animate light-orbit`, `--animate camera-orbit:8`, `--animate ke=1..1000:log:4`, several
// at once. GL-free: parsing the specs and the scene at a time t, which the headless video (run/run_headless.cpp)
// renders frame by frame. A ramp's parameters and how a value is set on a scene are the sweep's
// (core/scene/sweep.hpp): a ramp is a sweep whose value moves with time.
#include "core/scene/scene.hpp"
#include "core/scene/scene_limits.hpp"

#include <string>
#include <vector>

namespace shadelab {

inline constexpr double kDefaultAnimationSeconds = 4.0;  // one orbit, or one ramp from A to B
inline constexpr double kMaxAnimationSeconds = 600.0;    // a spec's SECONDS and --duration
inline constexpr std::size_t kMaxAnimations = 8;         // --animate given at most this often
inline constexpr Range<int> kVideoFpsRange{1, 120};      // --fps
inline constexpr int kDefaultVideoFps = 30;

struct Animation {
    enum class Kind {
        LightOrbit,   // the first light circles the camera's target about its up axis, at its height
        CameraOrbit,  // the camera circles its target about its up axis (a turntable, seen from the camera)
        Ramp,         // `parameter` goes from `from` to `to`, then stays at `to`
    };
    Kind kind = Kind::Ramp;
    double seconds = kDefaultAnimationSeconds;  // one full turn, or the ramp's length
    std::string parameter;                      // a sweep parameter (Ramp)
    std::string from, to;                       // as written, each checked as the sweep checks its values
    bool logarithmic = false;                   // equal ratios per second rather than equal steps (":log")
    std::string text;                           // the spec as given, for messages
};

// "light-orbit[:SECONDS]", "camera-orbit[:SECONDS]" or "PARAM=A..B[:log][:SECONDS]" -> Animation.
// Throws InputError "FLAG: SPEC: what is wrong" naming the part that is wrong (an unknown animation or
// parameter, a value out of the parameter's range, ":log" with a bound <= 0 or on names, bad SECONDS).
Animation parseAnimation(const std::string& spec, const std::string& flag);

// The longest animation's seconds (0 for none): --duration's default.
double animationsDuration(const std::vector<Animation>& animations);

// How many frames a video of `seconds` at `fps` has: frame i shows time i / fps. With a ramp the last
// frame is at `seconds` or just past it, so the video ends on the ramp's end value (B); with orbits
// alone the frame at `seconds` would repeat the first one of the next turn, so the loop stops before it.
int animationFrameCount(const std::vector<Animation>& animations, double seconds, int fps);

// The scene `base` as the animations make it at `t` seconds. Orbits turn by 360 degrees per SECONDS and
// go on turning; a ramp's value is A at t <= 0 and B from t = SECONDS on; names (shading=flat..phong)
// switch from A to B half way. Throws InputError "FLAG: ..." where an animation does not fit the scene
// (light-orbit without lights, tessellation of a cube): call it for t = 0 before any work.
Scene sceneAtTime(const Scene& base, const std::vector<Animation>& animations, double t, const std::string& flag);

}  // namespace shadelab
