#pragma once
// Stepping the viewer's document through a lecture playlist (core/scene/playlist.hpp), without GL or window.
// Each preset keeps its live edits and camera while the lecturer steps to other presets and back, as
// slides would; reset() reloads the current one from its file (so an edit made to the file in an
// editor shows too). Every step is all-or-nothing: when a preset's geometry cannot be built, or its
// file no longer loads, the document and the position stay as they were.
#include "core/scene/playlist.hpp"
#include "viewer/scene_document.hpp"

#include <optional>
#include <vector>

namespace shadelab {

class PlaylistNavigator {
public:
    // `presets` as loadPlaylist returned them; `adjust` is applied again when a preset is reloaded
    // from its file (the command line's overrides). An empty playlist makes an inactive navigator.
    // The document is expected to show presets[0] already.
    PlaylistNavigator(std::vector<Preset> presets, SceneAdjust adjust);

    bool active() const { return !entries_.empty(); }
    std::size_t size() const { return entries_.size(); }
    std::size_t current() const { return current_; }
    // The preset as loaded (or last reset) from its file: its title and caption for the list.
    const Preset& preset(std::size_t index) const { return entries_.at(index).preset; }

    // Shows preset `index` (clamped to the playlist) in `document`; the current preset's live scene
    // is kept for coming back. Returns false when it already was the current one. Throws on failure.
    bool goTo(std::size_t index, SceneDocument& document);
    bool next(SceneDocument& document) { return goTo(current_ + 1, document); }
    bool previous(SceneDocument& document) { return current_ > 0 && goTo(current_ - 1, document); }
    // Reloads the current preset from its file, discarding its edits, and shows it. Throws InputError.
    void reset(SceneDocument& document);
    // The document now shows something else (a file loaded or dropped): the next step does not keep
    // it as the current preset's edits.
    void detach() { attached_ = false; }

private:
    struct Entry {
        Preset preset;
        std::optional<Scene> live;  // the scene as the lecturer left it, with edits
        Camera home;                // its home camera (R) at that time
        bool following = true;      // whether its camera followed the view (not zoomed or panned)
    };
    std::vector<Entry> entries_;
    SceneAdjust adjust_;
    std::size_t current_ = 0;
    bool attached_ = true;  // the document shows entries_[current_]
};

}  // namespace shadelab
