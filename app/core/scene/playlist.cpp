#include "core/scene/playlist.hpp"

#include "core/base/error.hpp"
#include "core/base/file_io.hpp"
#include "core/image/text.hpp"
#include "core/scene/scene_json.hpp"
#include "platform/platform.hpp"

#include <algorithm>
#include <filesystem>
#include <sstream>

namespace shadelab {
namespace fs = std::filesystem;

std::string playlistFolder(const std::string& given) {
    std::error_code ec;
    const bool bareName =
        !given.empty() && given.find_first_of("/\\") == std::string::npos && given != "." && given != "..";
    if (fs::exists(given, ec) || !bareName) return given;
    for (const fs::path& scenes : dataFoldersBesideProgram(platform::executablePath(), "scenes", "assets/scenes")) {
        const fs::path folder = scenes / given;
        if (fs::is_directory(folder, ec)) return fs::weakly_canonical(folder, ec).string();
    }
    return given;
}

std::vector<std::string> listPresetFiles(const std::string& folder) {
    std::error_code ec;
    if (!fs::exists(folder, ec))
        throw InputError(folder + ": no such folder" +
                         (folder.find_first_of("/\\") == std::string::npos
                              ? " (nor a scene folder of that name beside the program)"
                              : ""));
    if (!fs::is_directory(folder, ec))
        throw InputError(folder + ": not a folder (--playlist takes a folder of scene files)");
    std::vector<std::string> names;
    fs::directory_iterator it(folder, ec);
    for (; !ec && it != fs::directory_iterator(); it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.empty() || name[0] == '.' || !hasExtension(name, ".json")) continue;
        std::error_code typeError;
        if (it->is_directory(typeError)) continue;
        names.push_back(name);
    }
    if (ec) throw InputError(folder + ": cannot read the folder: " + ec.message());
    if (names.empty()) throw InputError(folder + ": no scene files (*.json) in the folder");
    std::sort(names.begin(), names.end());
    std::vector<std::string> paths;
    paths.reserve(names.size());
    for (const std::string& n : names) paths.push_back((fs::path(folder) / n).string());
    return paths;
}

Preset loadPreset(const std::string& path, const SceneAdjust& adjust) {
    Preset p;
    p.path = path;
    const std::string file = fs::path(path).filename().string();
    p.name = file.substr(0, file.size() - std::min<std::size_t>(file.size(), 5));  // less ".json"
    p.scene = loadSceneFile(path);
    if (adjust) {
        try {
            adjust(p.scene);
        } catch (const InputError& e) {
            throw InputError(path + ": " + e.what());
        }
    }
    return p;
}

std::vector<Preset> loadPlaylist(const std::string& folder, const SceneAdjust& adjust) {
    std::vector<Preset> presets;
    for (const std::string& path : listPresetFiles(playlistFolder(folder))) presets.push_back(loadPreset(path, adjust));
    return presets;
}

std::string presetTitle(const Preset& preset) { return preset.scene.title.empty() ? preset.name : preset.scene.title; }

std::vector<std::string> wrapText(const std::string& text, int scale, int maxWidth) {
    std::vector<std::string> lines;
    std::istringstream words(text);
    std::string line;
    for (std::string word; words >> word;) {
        const std::string longer = line.empty() ? word : line + " " + word;
        if (!line.empty() && textWidth(longer, scale) > maxWidth) {
            lines.push_back(line);
            line = word;
        } else {
            line = longer;
        }
    }
    if (!line.empty()) lines.push_back(line);
    return lines;
}

Image withCaptionStrip(const Image& image, const std::string& title, const std::string& caption) {
    if (title.empty() && caption.empty()) return image;
    // Font pixels per image pixel: the title a little larger than the caption, both growing with the
    // image so the strip reads the same on a 160-wide test render and a 1280-wide handout.
    const int titleScale = std::clamp(image.width / 300, 1, 3);
    const int captionScale = std::clamp(image.width / 600, 1, 2);
    const int margin = 4 * captionScale;
    const int textArea = std::max(image.width - 2 * margin, 1);
    const std::vector<std::string> titleLines = wrapText(title, titleScale, textArea);
    const std::vector<std::string> captionLines = wrapText(caption, captionScale, textArea);
    const int titleLine = textHeight("Ag", titleScale) + 2 * titleScale;
    const int captionLine = textHeight("Ag", captionScale) + 2 * captionScale;
    const int gap = titleLines.empty() || captionLines.empty() ? 0 : margin;
    const int strip = 2 * margin + int(titleLines.size()) * titleLine + gap + int(captionLines.size()) * captionLine;

    Image out(image.width, image.height + strip);
    std::copy(image.rgba.begin(), image.rgba.end(), out.rgba.begin());
    fillRect(out, 0, image.height, out.width, out.height, Rgba8{40, 40, 44, 255});
    int y = image.height + margin;
    for (const std::string& l : titleLines) {
        drawText(out, margin, y, l, titleScale, Rgba8{250, 250, 250, 255});
        y += titleLine;
    }
    y += gap;
    for (const std::string& l : captionLines) {
        drawText(out, margin, y, l, captionScale, Rgba8{210, 210, 210, 255});
        y += captionLine;
    }
    return out;
}

}  // namespace shadelab
