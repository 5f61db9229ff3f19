#pragma once
// Lecture playlists: a folder of scene files, one per point of the lecture, shown in the order of
// their file names (`01-flat-gouraud-phong.json`, `02-...`), each with an optional `title` and
// `caption`. GL-free: listing and loading the presets, and the caption strip that headless renders
// can carry under the image (`--captions`). The viewer steps through them (viewer/playlist_navigator).
#include "core/image/image.hpp"
#include "core/scene/scene.hpp"

#include <functional>
#include <string>
#include <vector>

namespace shadelab {

struct Preset {
    std::string path;  // the scene file, as found in the folder ("assets/scenes/lecture/01-x.json")
    std::string name;  // its file name without ".json" ("01-x"): the PNG's name, the panel's list
    Scene scene;       // as loaded, with `adjust` applied (see loadPlaylist)
};

// Called on every preset after it is parsed, e.g. the command line's overrides (--size, --shading).
// May throw InputError; the message is then prefixed with the preset's path.
using SceneAdjust = std::function<void(Scene&)>;

// The `*.json` files directly in `folder` (the extension in any case; hidden files, whose names start
// with '.', and sub-folders are left out), sorted by file name byte by byte, so "NN-" prefixes give the
// lecture order. Throws InputError "FOLDER: ..." when the folder is missing, not a folder, unreadable,
// or holds no scene file.
std::vector<std::string> listPresetFiles(const std::string& folder);

// Loads one preset file; errors name the file and the field (as loadSceneFile).
Preset loadPreset(const std::string& path, const SceneAdjust& adjust = {});

// The folder --playlist names: `given` where it exists; else, for a bare name ("lecture"), the scene
// folder of that name beside the program: an installed shadelab's share/shadelab/scenes/NAME, a
// checkout's assets/scenes/NAME for a program in a build folder inside it, or a build folder's own
// share/shadelab/scenes/NAME (dataFoldersBesideProgram). Otherwise `given` (listPresetFiles then says
// it is missing).
std::string playlistFolder(const std::string& given);

// Every preset of `folder` (listPresetFiles), all loaded before any is returned: one bad file fails
// the whole playlist with an InputError naming that file and what is wrong.
std::vector<Preset> loadPlaylist(const std::string& folder, const SceneAdjust& adjust = {});

// What a preset is called on screen and on a handout: its title, or its file name when it has none.
std::string presetTitle(const Preset& preset);

// The image with a strip below it holding `title` (large) and `caption` (word-wrapped to the image's
// width), white on dark grey, drawn with core/image/text.hpp. The font scale follows the image's width so a
// handout of 1280-wide renders and a test's 160-wide ones both stay readable; returns the image as is
// when both texts are empty.
Image withCaptionStrip(const Image& image, const std::string& title, const std::string& caption);

// Splits `text` at spaces into lines no wider than `maxWidth` pixels at `scale` (core/image/text.hpp); a
// single word wider than that gets a line of its own (cut by the image edge).
std::vector<std::string> wrapText(const std::string& text, int scale, int maxWidth);

}  // namespace shadelab
