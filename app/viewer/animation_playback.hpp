#pragma once
// --animate in the viewer: the animations played over the scene as it is drawn (the panel's values stay
// the document's), looping over the longest one's length; Space and the panel play and pause, a new
// preset plays from the start. A scripted run (--frames) steps 1/30 s a frame, so its frame i is the
// headless video's frame i whatever the machine's speed; a person's session follows the clock. GL-free.
#include "core/scene/animation.hpp"
#include "core/scene/scene.hpp"

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace shadelab {

class AnimationPlayback {
public:
    using Clock = std::chrono::steady_clock;

    // Plays from the start when there are animations; `scripted`: 1/30 s a frame.
    AnimationPlayback(std::vector<Animation> animations, bool scripted, Clock::time_point now);

    const std::vector<Animation>& animations() const { return animations_; }
    bool any() const { return !animations_.empty(); }
    bool playing() const { return playing_; }
    void togglePlay() { playing_ = !playing_ && any(); }
    void restart();  // from 0, playing (a new preset)

    // The frame's scene: the document's `base` at the clock's time (scene() until the next call); then
    // the clock moves on while playing, by the time since the last call or, scripted, by 1/30 s.
    // Returns the error where the animations do not fit the scene (the light an orbit moves was removed
    // in the panel): then there is no animated scene and playing stops.
    std::optional<std::string> advance(const Scene& base, Clock::time_point now);
    // The scene advance() made, or nullptr (no animations, or they did not fit).
    const Scene* scene() const { return scene_ ? &*scene_ : nullptr; }
    // Where in the loop advance() drew the scene, and the loop's length, in seconds.
    double shownSeconds() const { return shown_; }
    double loopSeconds() const { return animationsDuration(animations_); }
    // Counts the frames the animation moved the scene (ViewInputs::animation).
    std::uint64_t step() const { return step_; }

private:
    std::vector<Animation> animations_;
    bool scripted_ = false;
    bool playing_ = false;
    double seconds_ = 0.0, shown_ = 0.0;
    std::uint64_t step_ = 0;
    Clock::time_point tick_;
    std::optional<Scene> scene_;
};

}  // namespace shadelab
