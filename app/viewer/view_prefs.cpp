#include "viewer/view_prefs.hpp"

#include "core/base/file_io.hpp"
#include "core/scene/panel_sections.hpp"
#include "core/ui/controls.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <iterator>

namespace shadelab {

std::string viewPrefsPath() {
    namespace fs = std::filesystem;
    const char* config = std::getenv("XDG_CONFIG_HOME");
    const char* home = std::getenv("HOME");
    if (config && *config) return (fs::path(config) / "shadelab" / "viewer.json").string();
    if (home && *home) return (fs::path(home) / ".config" / "shadelab" / "viewer.json").string();
    return "";
}

ViewPrefs loadViewPrefs(const std::string& path) {
    ViewPrefs p;
    if (path.empty() || !std::filesystem::exists(path)) return p;
    try {
        const nlohmann::json j = nlohmann::json::parse(readTextFile(path, 64 * 1024));
        // Numbers are read as doubles and range-checked before they become ints (1e30 is valid JSON).
        const auto number = [](const nlohmann::json& v, double lo, double hi) -> std::optional<int> {
            if (!v.is_number()) return std::nullopt;
            const double d = v.get<double>();
            if (!(d >= lo && d <= hi)) return std::nullopt;
            return int(d);
        };
        if (j.contains("window")) {
            const auto& w = j.at("window");
            const auto x = number(w.value("x", nlohmann::json()), -100000, 100000);
            const auto y = number(w.value("y", nlohmann::json()), -100000, 100000);
            const auto width = number(w.value("width", nlohmann::json()), 200, 16384);
            const auto height = number(w.value("height", nlohmann::json()), 150, 16384);
            if (x && y && width && height) p.window = WindowPlacement{*x, *y, *width, *height};
        }
        p.fullscreen = j.value("fullscreen", false);
        if (j.contains("open_sections")) {
            std::vector<std::string> open;
            for (const auto& name : j.at("open_sections")) {
                const std::string s = name.get<std::string>();
                if (valueNamed(kPanelSections, s)) open.push_back(s);
            }
            p.openSections = open;
        }
        if (j.contains("ui_scale") && j.at("ui_scale").is_number()) {
            const double scale = j.at("ui_scale").get<double>();
            if (scale >= kUiScaleRange.lo && scale <= kUiScaleRange.hi) p.uiScale = float(scale);
        }
        if (j.contains("msaa")) p.msaa = number(j.at("msaa"), 0, 8);
    } catch (const std::exception& e) {
        std::cerr << "shadelab: " << path << ": ignored (" << e.what() << ")\n";
        return ViewPrefs{};
    }
    return p;
}

bool saveViewPrefs(const std::string& path, const ViewPrefs& p) {
    if (path.empty()) return false;
    nlohmann::json j;
    if (p.window)
        j["window"] = {
            {"x", p.window->x}, {"y", p.window->y}, {"width", p.window->width}, {"height", p.window->height}};
    j["fullscreen"] = p.fullscreen;
    if (p.openSections) j["open_sections"] = *p.openSections;
    if (p.uiScale) j["ui_scale"] = *p.uiScale;
    if (p.msaa) j["msaa"] = *p.msaa;
    const std::string text = j.dump(2) + "\n";
    try {
        std::filesystem::create_directories(std::filesystem::path(path).parent_path());
        writeFileAtomic(path, [&](std::FILE* f) { return std::fwrite(text.data(), 1, text.size(), f) == text.size(); });
        return true;
    } catch (const std::exception& e) {
        std::cerr << "shadelab: could not remember the window layout in " << path << ": " << e.what() << "\n";
        return false;
    }
}

}  // namespace shadelab
