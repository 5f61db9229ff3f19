#include "viewer/animation_playback.hpp"

#include "core/base/error.hpp"

#include <cmath>
#include <utility>

namespace shadelab {

AnimationPlayback::AnimationPlayback(std::vector<Animation> animations, bool scripted, Clock::time_point now)
    : animations_(std::move(animations)), scripted_(scripted), playing_(!animations_.empty()), tick_(now) {}

void AnimationPlayback::restart() {
    seconds_ = 0.0;
    playing_ = any();
}

std::optional<std::string> AnimationPlayback::advance(const Scene& base, Clock::time_point now) {
    if (!any()) return std::nullopt;
    std::optional<std::string> error;
    shown_ = std::fmod(seconds_, loopSeconds());
    try {
        scene_ = sceneAtTime(base, animations_, shown_, "--animate");
    } catch (const InputError& e) {
        scene_.reset();
        playing_ = false;
        error = e.what();
    }
    if (playing_) {
        seconds_ += scripted_ ? 1.0 / kDefaultVideoFps : std::chrono::duration<double>(now - tick_).count();
        ++step_;
    }
    tick_ = now;
    return error;
}

}  // namespace shadelab
