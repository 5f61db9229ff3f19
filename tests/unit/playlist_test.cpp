// Lecture playlists without GL: which files a folder's playlist holds and in what order, the errors for
// a missing, empty or broken one, the overrides applied to every preset, the caption strip, and the
// presets shipped in assets/scenes/lecture.
#include "core/base/error.hpp"
#include "core/scene/playlist.hpp"
#include "core/image/text.hpp"
#include "test_dir.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>

using namespace shadelab;
namespace fs = std::filesystem;

namespace {

struct TempDir : test::TestDir {
    TempDir() : TestDir("playlist") {}
    std::string write(const std::string& name, const std::string& text) const {
        std::ofstream(path / name) << text;
        return (path / name).string();
    }
};

std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

std::vector<std::string> fileNames(const std::vector<std::string>& paths) {
    std::vector<std::string> names;
    for (const std::string& p : paths) names.push_back(fs::path(p).filename().string());
    return names;
}

}  // namespace

TEST(Playlist, ListsSceneFilesByNameLeavingOutEverythingElse) {
    TempDir dir;
    for (const char* name : {"10-b.json", "02-a.json", "1-c.json", "UPPER.JSON", "notes.txt", ".hidden.json", "x.json.bak"})
        dir.write(name, "{}");
    fs::create_directories(dir.path / "sub.json");  // a folder with a scene-like name is no scene
    // Byte order: '-' (45) sorts before '0' (48), so "1-c" comes before "10-b"; letters sort after
    // digits. The extension is matched in any case.
    EXPECT_EQ(fileNames(listPresetFiles(dir.path.string())),
              (std::vector<std::string>{"02-a.json", "1-c.json", "10-b.json", "UPPER.JSON"}));
    EXPECT_EQ(listPresetFiles(dir.path.string()).front(), (dir.path / "02-a.json").string());
}

TEST(Playlist, MissingEmptyOrNonFolderNamesTheFolder) {
    TempDir dir;
    const std::string missing = (dir.path / "nope").string();
    EXPECT_EQ(errorOf([&] { listPresetFiles(missing); }), missing + ": no such folder");
    const std::string file = dir.write("a.json", "{}");
    EXPECT_NE(errorOf([&] { listPresetFiles(file); }).find(file + ": not a folder"), std::string::npos);
    fs::create_directories(dir.path / "empty");
    dir.write("empty/readme.txt", "no scenes here");
    const std::string empty = (dir.path / "empty").string();
    EXPECT_EQ(errorOf([&] { listPresetFiles(empty); }), empty + ": no scene files (*.json) in the folder");
}

TEST(Playlist, OneBadFileFailsTheWholePlaylistNamingIt) {
    TempDir dir;
    dir.write("01-good.json", R"({"title": "good"})");
    const std::string bad = dir.write("02-bad.json", R"({"material": {"ke": 0}})");
    dir.write("03-good.json", R"({"title": "also good"})");
    EXPECT_EQ(errorOf([&] { loadPlaylist(dir.path.string()); }), bad + ": material.ke: must be >= 1 (got 0)");
}

TEST(Playlist, LoadsInOrderWithNamesTitlesAndAdjustments) {
    TempDir dir;
    dir.write("02-second.json", R"({"title": "Second", "caption": "Two.", "lights": []})");
    dir.write("01-first.json", R"({"title": "First", "caption": "One.", "shading": "flat"})");
    dir.write("03-untitled.json", "{}");
    int calls = 0;
    const std::vector<Preset> presets = loadPlaylist(dir.path.string(), [&](Scene& s) {
        ++calls;
        s.width = 96, s.height = 54;
    });
    ASSERT_EQ(presets.size(), 3u);
    EXPECT_EQ(calls, 3);
    EXPECT_EQ(presets[0].name, "01-first");
    EXPECT_EQ(presets[0].path, (dir.path / "01-first.json").string());
    EXPECT_EQ(presets[0].scene.title, "First");
    EXPECT_EQ(presets[0].scene.caption, "One.");
    EXPECT_EQ(presets[0].scene.shading, ShadingMode::Flat);
    EXPECT_EQ(presets[1].name, "02-second");
    EXPECT_TRUE(presets[1].scene.lights.empty());
    for (const Preset& p : presets) EXPECT_EQ(p.scene.width, 96) << p.name;
    EXPECT_EQ(presetTitle(presets[1]), "Second");
    EXPECT_EQ(presetTitle(presets[2]), "03-untitled");  // no title: the file name stands in

    // An adjustment that does not fit a preset (--show light:3 with one light) names the preset.
    const std::string message = errorOf([&] {
        loadPlaylist(dir.path.string(), [](Scene& s) {
            if (s.lights.empty()) throw InputError("--show: light 3 does not exist");
        });
    });
    EXPECT_EQ(message, (dir.path / "02-second.json").string() + ": --show: light 3 does not exist");
}

TEST(Playlist, WrapKeepsEveryWordAndFillsEachLine) {
    const std::string text = "One lighting formula, evaluated once per triangle, at the vertices, or per pixel.";
    const int maxWidth = 120;
    const std::vector<std::string> lines = wrapText(text, 1, maxWidth);
    ASSERT_GT(lines.size(), 1u);
    std::string joined;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        EXPECT_LE(textWidth(lines[i], 1), maxWidth) << lines[i];
        EXPECT_EQ(lines[i].find("  "), std::string::npos);
        // Greedy: the next line's first word would not have fitted on this one.
        if (i + 1 < lines.size()) {
            const std::string next = lines[i + 1].substr(0, lines[i + 1].find(' '));
            EXPECT_GT(textWidth(lines[i] + " " + next, 1), maxWidth) << lines[i] << " | " << next;
        }
        joined += (i ? " " : "") + lines[i];
    }
    EXPECT_EQ(joined, text);
    // A word longer than the line gets a line of its own; no text, no lines.
    EXPECT_EQ(wrapText("a Supercalifragilistic b", 1, 30), (std::vector<std::string>{"a", "Supercalifragilistic", "b"}));
    EXPECT_TRUE(wrapText("   ", 1, 100).empty());
}

TEST(Playlist, CaptionStripSitsBelowTheUntouchedImage) {
    Image image(160, 90);
    for (int y = 0; y < 90; ++y)
        for (int x = 0; x < 160; ++x) {
            std::uint8_t* p = image.pixel(x, y);
            p[0] = std::uint8_t(x), p[1] = std::uint8_t(y), p[2] = 7, p[3] = 255;
        }
    const Image out = withCaptionStrip(image, "Gouraud misses a highlight", "The vertices see none of it.");
    ASSERT_EQ(out.width, 160);
    ASSERT_GT(out.height, 90 + 20);  // a title line and a caption line at scale 1 are 2 x ~12 pixels
    for (int y = 0; y < 90; ++y)
        for (int x = 0; x < 160; ++x)
            ASSERT_TRUE(std::equal(image.pixel(x, y), image.pixel(x, y) + 4, out.pixel(x, y))) << x << "," << y;
    // The strip: dark grey background with light text on it.
    std::size_t background = 0, text = 0;
    for (int y = 90; y < out.height; ++y)
        for (int x = 0; x < 160; ++x) {
            const std::uint8_t* p = out.pixel(x, y);
            background += p[0] == 40 && p[1] == 40 && p[2] == 44;
            text += p[0] > 200 && p[1] > 200 && p[2] > 200;
        }
    EXPECT_GT(text, 100u);
    EXPECT_GT(background, 10 * text);
    EXPECT_EQ(withCaptionStrip(image, "", "").height, 90);  // nothing to say: no strip
}

// Every preset shipped for the lecture loads, is named NN-short-name.json with consecutive numbers
// from 01 (so the folder's order is the lecture's), and has a title and a one-sentence caption in
// printable ASCII (what the handout font, stb_easy_font, can draw).
TEST(LecturePresets, EveryPresetLoadsWithTitleAndCaption) {
    const fs::path folder = fs::path(SHADELAB_SOURCE_DIR) / "assets" / "scenes" / "lecture";
    std::set<std::string> onDisk;
    for (const auto& e : fs::directory_iterator(folder)) onDisk.insert(e.path().filename().string());
    ASSERT_GE(onDisk.size(), 20u);
    const std::regex pattern("([0-9]{2})-[a-z0-9]+(-[a-z0-9]+)*\\.json");
    int number = 0;
    for (const std::string& name : onDisk) {  // std::set iterates in byte order, as the playlist sorts
        std::smatch m;
        ASSERT_TRUE(std::regex_match(name, m, pattern)) << name;
        EXPECT_EQ(std::stoi(m[1].str()), ++number) << name << ": numbers must run 01, 02, ...";
    }
    const std::vector<Preset> presets = loadPlaylist(folder.string());
    ASSERT_EQ(presets.size(), onDisk.size());
    auto name = onDisk.begin();
    for (const Preset& p : presets) {
        SCOPED_TRACE(p.path);
        EXPECT_EQ(p.name + ".json", *name++);
        EXPECT_FALSE(p.scene.title.empty());
        EXPECT_LE(p.scene.title.size(), 70u) << "a title is one line on a projector";
        ASSERT_FALSE(p.scene.caption.empty());
        EXPECT_EQ(p.scene.caption.back(), '.');
        for (char c : p.scene.title + p.scene.caption) EXPECT_TRUE(c >= 32 && c < 127) << "not printable ASCII: " << c;
    }
}
