#pragma once
// What the viewer remembers between a person's sessions, none of it part of a scene: where the window
// was and how large, fullscreen, whether the panel was shown and which of its sections were open, the
// UI scale and the anti-aliasing. Kept in $XDG_CONFIG_HOME/shadelab/viewer.json (or
// ~/.config/shadelab/viewer.json); scripted runs (--frames) neither read nor write it.
#include "viewer/glfw_window.hpp"

#include <optional>
#include <string>
#include <vector>

namespace shadelab {

struct ViewPrefs {
    std::optional<WindowPlacement> window;
    bool fullscreen = false;
    std::optional<std::vector<std::string>> openSections;  // kPanelSections names
    std::optional<float> uiScale;
    std::optional<int> msaa;
};

// The file's path; empty when neither XDG_CONFIG_HOME nor HOME is set.
std::string viewPrefsPath();
// Reads the file; a missing file gives the defaults, so does an unreadable or malformed one (after one
// line on stderr saying so: a broken preferences file must not keep the viewer from opening).
ViewPrefs loadViewPrefs(const std::string& path);
// Writes the file atomically, creating its folder. Returns false (after one line on stderr) on failure.
bool saveViewPrefs(const std::string& path, const ViewPrefs& prefs);

}  // namespace shadelab
