// The shadelab executable as a user (or CI) runs it: headless output with no display, one-line errors
// with exit status 2 and no output file for every kind of bad input, the benchmark's JSON lines.
#include "cli/run_shadelab.hpp"
#include "core/image.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

using namespace shadelab;
namespace fs = std::filesystem;

namespace {

using test::RunResult;
using test::slurp;

class Cli : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::path(SHADELAB_TEST_OUTPUT_DIR) / "cli" / ::testing::UnitTest::GetInstance()->current_test_info()->name();
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    // Runs shadelab with no display (DISPLAY and WAYLAND_DISPLAY unset), as CI does.
    RunResult run(const std::vector<std::string>& args) const { return test::runShadelab(args, fs::current_path(), dir_); }
    std::string file(const std::string& name, const std::string& contents) const {
        std::ofstream(dir_ / name) << contents;
        return (dir_ / name).string();
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    fs::path dir_;
};

}  // namespace

TEST_F(Cli, RendersTheDefaultCompareLayoutWithoutADisplay) {
    const RunResult r = run({"--layout", "compare", "--size", "240x80", "--output", path("x.png")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const Image img = readPng(path("x.png"));
    EXPECT_EQ(img.width, 240);
    EXPECT_EQ(img.height, 80);
    // Not a blank frame: each pane has lit sphere pixels well above the dark background.
    for (int pane = 0; pane < 3; ++pane) {
        int lit = 0;
        for (int y = 0; y < 80; ++y)
            for (int x = pane * 80; x < pane * 80 + 80; ++x) lit += img.pixel(x, y)[0] > 100;
        EXPECT_GT(lit, 200) << "pane " << pane;
    }
    // Only the image is written (the temporary file was renamed, none left behind).
    EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 3);  // x.png, stdout, stderr
}

// --backend osmesa and --backend egl draw the same picture (llvmpipe behind both; the OSMesa buffer
// and EGL's FBO round a handful of pixels differently by 1/255).
TEST_F(Cli, BothHeadlessBackendsRenderTheSameImage) {
    ASSERT_EQ(run({"--backend", "osmesa", "--layout", "compare", "--size", "240x80", "--output", path("o.png")}).exitCode, 0);
    const RunResult egl = run({"--backend", "egl", "--layout", "compare", "--size", "240x80", "--output", path("e.png")});
    ASSERT_EQ(egl.exitCode, 0) << egl.err;
    const CompareResult d = compareImages(readPng(path("e.png")), readPng(path("o.png")), 0);
    EXPECT_TRUE(d.sizeMatches);
    EXPECT_LE(d.maxDifference, 1);
    const RunResult bench = run({"--backend", "egl", "--benchmark", "2", "--size", "64x48", "--shading", "phong"});
    ASSERT_EQ(bench.exitCode, 0) << bench.err;
    EXPECT_NE(bench.out.find("\"backend\": \"egl\""), std::string::npos) << bench.out;
}

// --sweep: one labelled tile per value in one PNG, a second sweep makes rows; the tiles are the renders
// of each value (the middle one equals a plain --output render with that value).
TEST_F(Cli, SweepSheetHasOneTilePerValue) {
    const RunResult r = run({"--sweep", "ke=1,32,512", "--sweep", "shading=gouraud,phong", "--size", "64x48",
                             "--output", path("sheet.png")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const Image sheet = readPng(path("sheet.png"));
    EXPECT_EQ(sheet.width, 3 * 64 + 4 * 4);
    const int bar = (sheet.height - 3 * 4) / 2 - 48;
    EXPECT_GT(bar, 10);
    ASSERT_EQ(run({"--ke", "32", "--shading", "phong", "--size", "64x48", "--output", path("one.png")}).exitCode, 0);
    const Image one = readPng(path("one.png"));
    Image tile(64, 48);
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x)
            std::copy_n(sheet.pixel(4 + 68 + x, 4 + (48 + bar + 4) + bar + y), 4, tile.pixel(x, y));
    EXPECT_EQ(compareImages(tile, one, 0).maxDifference, 0);
    const RunResult noOutput = run({"--sweep", "ke=1,2"});
    EXPECT_EQ(noOutput.exitCode, 2);
    EXPECT_NE(noOutput.err.find("--sweep: renders a sheet to a PNG"), std::string::npos) << noOutput.err;
    const RunResult cube = run({"--mesh", "cube", "--sweep", "tessellation=4,8", "--output", path("c.png")});
    EXPECT_EQ(cube.exitCode, 2);
    EXPECT_NE(cube.err.find("--sweep: tessellation: the first object is a cube"), std::string::npos) << cube.err;
    EXPECT_FALSE(fs::exists(path("c.png")));
}

TEST_F(Cli, ScenePlusOverrides) {
    const std::string scene = file("s.json", R"({"mesh": {"type": "cube"}, "shading": "flat", "size": [50, 40]})");
    const RunResult r = run({scene, "--shading", "gouraud", "--ke", "8", "--size", "64x48", "--output", path("o.png")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(readPng(path("o.png")).width, 64);
}

TEST_F(Cli, BadInputGivesOneLineExitTwoAndNoOutput) {
    const std::string malformed = file("malformed.json", "{\"mesh\": ");
    const std::string unknown = file("unknown.json", R"({"material": {"shininess": 4}})");
    const std::string negative = file("negative.json", R"({"material": {"kd": -0.5}})");
    const std::string badSize = file("size.json", R"({"size": [0, 10]})");
    const std::string badModel = file("model.json", R"({"mesh": {"type": "gltf", "path": "nowhere.glb"}})");
    const std::string junk = file("junk.gltf", "\x01\x02 not gltf");
    fs::create_directories(dir_ / "adir.png");
    struct Case {
        std::vector<std::string> args;
        std::vector<std::string> fragments;
        std::string output;
    };
    const std::string out = path("out.png");
    const std::vector<Case> cases = {
        {{path("missing.json")}, {"missing.json", "cannot read"}, out},
        {{malformed}, {"malformed.json", "malformed JSON"}, out},
        {{unknown}, {"unknown.json", "material.shininess", "unknown field"}, out},
        {{negative}, {"negative.json", "material.kd", ">= 0"}, out},
        {{badSize}, {"size.json", "size"}, out},
        {{badModel}, {"nowhere.glb"}, out},
        {{junk}, {"junk.gltf"}, out},
        {{"--size", "0x10"}, {"--size"}, out},
        {{"--size", "100000x100000"}, {"--size", "16384"}, out},
        {{"--ka", "-1"}, {"--ka"}, out},
        {{"--ke", "0"}, {"--ke"}, out},
        {{"--shading", "toon"}, {"--shading", "toon"}, out},
        {{"--mesh", "uvsphere:10000000"}, {"--mesh"}, out},
        {{"--no-such-flag"}, {"--no-such-flag"}, out},
        {{}, {"does not exist"}, path("no/such/dir/out.png")},
        {{}, {"is a directory"}, path("adir.png")},
    };
    for (const Case& c : cases) {
        std::vector<std::string> args = c.args;
        args.push_back("--output");
        args.push_back(c.output);
        const RunResult r = run(args);
        const std::string what = args.front();
        EXPECT_EQ(r.exitCode, 2) << what << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << what << ": not one line: " << r.err;
        EXPECT_EQ(r.err.rfind("shadelab: ", 0), 0u) << r.err;
        for (const auto& f : c.fragments) EXPECT_NE(r.err.find(f), std::string::npos) << "'" << f << "' not in: " << r.err;
        EXPECT_FALSE(fs::is_regular_file(c.output)) << what << " wrote " << c.output;
    }
}

TEST_F(Cli, FailedRunLeavesAnExistingImageUntouched) {
    ASSERT_EQ(run({"--size", "32x32", "--output", path("keep.png")}).exitCode, 0);
    const auto before = slurp(path("keep.png"));
    const std::string bad = file("bad.json", R"({"lights": [{"type": "directional", "direction": [0, 0, 0]}]})");
    const RunResult r = run({bad, "--output", path("keep.png")});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("lights[0].direction"), std::string::npos) << r.err;
    EXPECT_EQ(slurp(path("keep.png")), before);
}

TEST_F(Cli, BenchmarkReportsEachShadingMode) {
    const RunResult r = run({"--benchmark", "3", "--size", "64x48", "--mesh", "uvsphere:16:8"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::istringstream lines(r.out);
    std::vector<std::string> modes;
    for (std::string line; std::getline(lines, line);) {
        const auto j = nlohmann::json::parse(line);
        EXPECT_EQ(j.at("frames").get<int>(), 3);
        EXPECT_EQ(j.at("triangles").get<int>(), 2 * 16 * 7);
        EXPECT_EQ(j.at("size"), nlohmann::json::array({64, 48}));
        EXPECT_GT(j.at("median_ms").get<double>(), 0.0);
        EXPECT_GE(j.at("p95_ms").get<double>(), j.at("median_ms").get<double>());
        modes.push_back(j.at("shading").get<std::string>());
    }
    EXPECT_EQ(modes, (std::vector<std::string>{"flat", "gouraud", "phong"}));
}

TEST_F(Cli, HelpAndVersion) {
    const RunResult help = run({"--help"});
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_NE(help.out.find("--output FILE.png"), std::string::npos);
    const RunResult version = run({"--version"});
    EXPECT_EQ(version.exitCode, 0);
    EXPECT_EQ(version.out.rfind("shadelab ", 0), 0u);
}

// A real model made by others, from ../shared (skipped where the folder is absent).
TEST_F(Cli, RendersASharedGltfModel) {
    const fs::path box = fs::path(SHADELAB_SHARED_DIR) / "assets/gltf/sample-assets/Box/glTF-Binary/Box.glb";
    if (!fs::exists(box)) GTEST_SKIP() << box << " not found: ../shared is absent";
    const RunResult r = run({box.string(), "--size", "96x96", "--output", path("box.png")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const Image img = readPng(path("box.png"));
    int lit = 0;
    for (int y = 0; y < 96; ++y)
        for (int x = 0; x < 96; ++x) lit += img.pixel(x, y)[0] > 60;
    EXPECT_GT(lit, 500) << "auto-framed model should fill a good part of the image";
}

// --playlist DIR --output OUT/: exactly one PNG per preset, named after its file, at the --size given
// (an override every preset takes), none of them blank; each is the image the preset file renders on
// its own. The output folder is created (its parent exists).
TEST_F(Cli, PlaylistWritesOnePngPerPreset) {
    const fs::path lecture = fs::path(SHADELAB_SOURCE_DIR) / "assets" / "scenes" / "lecture";
    std::set<std::string> expected;
    for (const auto& e : fs::directory_iterator(lecture))
        if (e.path().extension() == ".json") expected.insert(e.path().stem().string() + ".png");
    ASSERT_GE(expected.size(), 20u);

    const std::string out = path("slides") + "/";
    const RunResult r = run({"--playlist", lecture.string(), "--output", out, "--size", "96x54"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::set<std::string> written;
    for (const auto& e : fs::directory_iterator(out)) written.insert(e.path().filename().string());
    EXPECT_EQ(written, expected);  // nothing else: no temporary file left behind
    for (const std::string& name : written) {
        const Image img = readPng(path("slides/" + name));
        ASSERT_EQ(img.width, 96) << name;
        ASSERT_EQ(img.height, 54) << name;
        // Not blank: some pixels differ clearly from the background in the top-left corner (the
        // darkest preset, a floor seen at a grazing angle, has ~5% such pixels at this size).
        const std::uint8_t* corner = img.pixel(0, 0);
        int drawn = 0;
        for (int y = 0; y < 54; ++y)
            for (int x = 0; x < 96; ++x) {
                const std::uint8_t* p = img.pixel(x, y);
                drawn += std::abs(p[0] - corner[0]) + std::abs(p[1] - corner[1]) + std::abs(p[2] - corner[2]) > 24;
            }
        EXPECT_GT(drawn, 96 * 54 / 50) << name << " looks blank";
    }
    // The playlist's image of a preset is that preset rendered on its own: the last one, drawn after
    // every other preset on the same context, so no state is carried over from them.
    const std::string last = *expected.rbegin();
    const fs::path preset = lecture / (last.substr(0, last.size() - 4) + ".json");
    ASSERT_EQ(run({preset.string(), "--size", "96x54", "--output", path("single.png")}).exitCode, 0);
    EXPECT_EQ(compareImages(readPng(path("slides/" + last)), readPng(path("single.png")), 0).maxDifference, 0) << preset;
}

// --captions: each image gets a strip with its title (or file name) and caption below the unchanged
// render; without a trailing '/' a folder that does not exist is refused, and a broken preset stops
// the run before anything is created.
TEST_F(Cli, PlaylistCaptionsAndOutputFolder) {
    fs::create_directories(dir_ / "mini");
    file("mini/01-titled.json", R"({"title": "Titled", "caption": "With a caption.", "mesh": {"type": "cube"}})");
    file("mini/02-bare.json", R"({"mesh": {"type": "torus"}})");
    const std::string mini = path("mini");
    ASSERT_EQ(run({"--playlist", mini, "--output", path("plain") + "/", "--size", "160x90"}).exitCode, 0);
    const RunResult r = run({"--playlist", mini, "--output", path("captioned") + "/", "--size", "160x90", "--captions"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const char* name : {"01-titled.png", "02-bare.png"}) {
        const Image plain = readPng(path(std::string("plain/") + name));
        const Image captioned = readPng(path(std::string("captioned/") + name));
        ASSERT_EQ(plain.height, 90);
        ASSERT_GT(captioned.height, 90 + 10) << name;
        Image top(160, 90);
        std::copy_n(captioned.rgba.begin(), top.rgba.size(), top.rgba.begin());
        EXPECT_EQ(compareImages(top, plain, 0).maxDifference, 0) << name;
    }
    // A title and a caption take more room than a file name alone.
    EXPECT_GT(readPng(path("captioned/01-titled.png")).height, readPng(path("captioned/02-bare.png")).height);

    const RunResult noSlash = run({"--playlist", mini, "--output", path("new")});
    EXPECT_EQ(noSlash.exitCode, 2);
    EXPECT_NE(noSlash.err.find("end the name with /"), std::string::npos) << noSlash.err;
    EXPECT_FALSE(fs::exists(path("new")));
    file("mini/03-broken.json", R"({"shading": "toon"})");
    const RunResult broken = run({"--playlist", mini, "--output", path("never") + "/"});
    EXPECT_EQ(broken.exitCode, 2);
    EXPECT_NE(broken.err.find("03-broken.json: shading: unknown value \"toon\""), std::string::npos) << broken.err;
    EXPECT_FALSE(fs::exists(path("never")));
}
