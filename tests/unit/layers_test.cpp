// The layers of app/ (docs/architecture.md): every #include "folder/…" in a folder's files names that
// folder or one below it. An include that points up a layer fails here, with the file and the line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// Each folder and the folders directly below it; what lies below those is allowed too.
const std::map<std::string, std::vector<std::string>> kBelow = {
    {"platform", {}},
    {"core/base", {"platform"}},
    {"core/image", {"core/base"}},
    {"core/scene", {"core/image"}},
    {"core/ui", {"core/scene"}},
    {"core/shading", {"core/scene"}},
    {"core/geometry", {"core/shading"}},
    {"core/probe", {"core/geometry"}},
    {"core/figures", {"core/shading"}},
    {"render/cpu", {"core/geometry"}},
    {"render", {"render/cpu", "core/ui"}},
    {"headless", {"render"}},
    {"video", {"core/image"}},
    {"viewer", {"render", "core/ui", "core/probe", "core/figures", "video"}},
    // The command line as a library (the option table, the parser, Options, the shorthands): the
    // program, the web page and the Python module read it.
    {"options", {"core/ui", "core/probe", "core/figures"}},
    // The run modes without a window and what they share with the Python module (run/session.hpp).
    {"run", {"options", "headless", "video"}},
    // The program: main() and the viewer's run mode.
    {"cli", {"run", "viewer"}},
    // The web page's program: the renderer, the options, and the viewer's GL-free scene document and
    // camera controls (viewer/scene_document.hpp, viewer/orbit.hpp; the CMake target compiles only those
    // of the viewer's files).
    {"web", {"render", "options", "viewer"}},
    // The Python module (app/python): the options and the headless session's interface (run/session.hpp).
    {"python", {"run"}},
};

std::set<std::string> reachable(const std::string& folder) {
    std::set<std::string> seen{folder};
    std::vector<std::string> todo{folder};
    while (!todo.empty()) {
        const std::string f = todo.back();
        todo.pop_back();
        for (const std::string& below : kBelow.at(f))
            if (seen.insert(below).second) todo.push_back(below);
    }
    return seen;
}

// "core/scene/scene.hpp" -> "core/scene"; the longest folder of kBelow that holds the path.
std::string folderOf(const std::string& path) {
    std::string best;
    for (const auto& entry : kBelow) {
        const std::string& folder = entry.first;
        if (path.compare(0, folder.size() + 1, folder + "/") == 0 && folder.size() > best.size()) best = folder;
    }
    return best;
}

}  // namespace

TEST(Layers, EveryFolderIsKnown) {
    const fs::path app = fs::path(SHADELAB_SOURCE_DIR) / "app";
    for (const auto& entry : fs::recursive_directory_iterator(app)) {
        if (!entry.is_regular_file()) continue;
        const std::string ext = entry.path().extension().string();
        if (ext != ".cpp" && ext != ".hpp") continue;
        const std::string relative = fs::relative(entry.path(), app).generic_string();
        EXPECT_FALSE(folderOf(relative).empty()) << relative << " lies in a folder that has no place in the layers";
    }
}

TEST(Layers, NoIncludePointsUp) {
    const fs::path app = fs::path(SHADELAB_SOURCE_DIR) / "app";
    const std::regex include(R"(^\s*#\s*include\s+"([a-z_]+(/[a-z_]+)*)/[A-Za-z0-9_.]+")");
    int checked = 0;
    for (const auto& entry : fs::recursive_directory_iterator(app)) {
        if (!entry.is_regular_file()) continue;
        const std::string relative = fs::relative(entry.path(), app).generic_string();
        const std::string from = folderOf(relative);
        if (from.empty()) continue;
        const std::set<std::string> allowed = reachable(from);
        std::ifstream in(entry.path());
        std::string line;
        for (int lineNo = 1; std::getline(in, line); ++lineNo) {
            std::smatch m;
            if (!std::regex_search(line, m, include)) continue;
            const std::string to = folderOf(m[1].str() + "/x");
            if (to.empty()) continue;  // a path relative to the file (../../shaders/…)
            ++checked;
            EXPECT_TRUE(allowed.count(to)) << relative << ":" << lineNo << " includes " << m[1].str()
                                           << "/…, which is not below " << from;
        }
    }
    EXPECT_GT(checked, 100) << "the include scan found almost nothing: has app/ moved?";
}
