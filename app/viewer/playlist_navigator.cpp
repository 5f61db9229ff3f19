#include "viewer/playlist_navigator.hpp"

#include <algorithm>

namespace shadelab {

PlaylistNavigator::PlaylistNavigator(std::vector<Preset> presets, SceneAdjust adjust) : adjust_(std::move(adjust)) {
    for (Preset& p : presets) entries_.push_back(Entry{std::move(p), std::nullopt, Camera{}});
}

bool PlaylistNavigator::goTo(std::size_t index, SceneDocument& document) {
    if (entries_.empty()) return false;
    index = std::min(index, entries_.size() - 1);
    if (index == current_ && attached_) return false;
    Entry& target = entries_[index];
    // Show the target first; only once that worked is the preset being left given its edits.
    Scene leaving = document.scene();
    const Camera leavingHome = document.homeCamera();
    const bool leavingFollowing = document.following();
    if (target.live)
        document.restore(*target.live, target.home, target.following, target.preset.scene.width,
                         target.preset.scene.height);
    else document.replace(target.preset.scene);
    if (attached_ && index != current_) {
        entries_[current_].live = std::move(leaving);
        entries_[current_].home = leavingHome;
        entries_[current_].following = leavingFollowing;
    }
    current_ = index;
    attached_ = true;
    return true;
}

void PlaylistNavigator::reset(SceneDocument& document) {
    if (entries_.empty()) return;
    Entry& e = entries_[current_];
    Preset reloaded = loadPreset(e.preset.path, adjust_);
    document.replace(reloaded.scene);
    e.preset = std::move(reloaded);
    e.live.reset();
    attached_ = true;
}

}  // namespace shadelab
