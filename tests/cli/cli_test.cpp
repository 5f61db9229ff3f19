// The shadelab executable as a user (or CI) runs it: headless output with no display, one-line errors
// with exit status 2 and no output file for every kind of bad input, the benchmark's JSON lines.
#include "cli/cli_fixture.hpp"
#include "cli/run_shadelab.hpp"
#include "core/figures/formula_image.hpp"
#include "core/figures/shader_listing.hpp"
#include "core/image/image.hpp"

#include <gtest/gtest.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <utility>

using namespace shadelab;
namespace fs = std::filesystem;

using test::Cli;
using test::RunResult;
using test::slurp;

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
    if (!SHADELAB_HAVE_OSMESA || !SHADELAB_HAVE_EGL) GTEST_SKIP() << "this build has one headless backend";
    ASSERT_EQ(run({"--backend", "osmesa", "--layout", "compare", "--size", "240x80", "--output", path("o.png")}).exitCode, 0);
    const RunResult egl = run({"--backend", "egl", "--layout", "compare", "--size", "240x80", "--output", path("e.png")});
    ASSERT_EQ(egl.exitCode, 0) << egl.err;
    const CompareResult d = compareImages(readPng(path("e.png")), readPng(path("o.png")), 0);
    EXPECT_TRUE(d.sizeMatches);
    EXPECT_LE(d.maxDiff, 1);
    const RunResult bench = run({"--backend", "egl", "--benchmark", "2", "--size", "64x48", "--shading", "phong"});
    ASSERT_EQ(bench.exitCode, 0) << bench.err;
    EXPECT_EQ(nlohmann::json::parse(bench.out.substr(0, bench.out.find('\n'))).at("backend"), "egl") << bench.out;
}

// llvmpipe's 128-bit path (LP_NATIVE_VECTOR_WIDTH=128, what it takes on a CPU without AVX): Mesa 22.3
// corrupted its heap drawing Phong's interpolated-inputs variant and glibc aborted (lecture preset 03,
// and a Blinn-Phong icosphere at 320x240). The renderer picks the uniform variant there
// (Renderer::autoMayInterpolate_): the same picture, no abort. Elsewhere the variable is ignored.
TEST_F(Cli, LlvmpipeOn128BitsDrawsPhongWithoutCrashing) {
    const std::string preset = std::string(SHADELAB_SOURCE_DIR) + "/assets/scenes/lecture/03-gouraud-misses-highlight.json";
    const RunResult wide = run({preset, "--size", "320x240", "--output", path("wide.png")});
    ASSERT_EQ(wide.exitCode, 0) << wide.err;
    const RunResult narrow = run({preset, "--size", "320x240", "--output", path("narrow.png")}, {"LP_NATIVE_VECTOR_WIDTH=128"});
    ASSERT_EQ(narrow.exitCode, 0) << narrow.err;
    const CompareResult d = compareImages(readPng(path("narrow.png")), readPng(path("wide.png")), 0);
    EXPECT_TRUE(d.sizeMatches);
    EXPECT_LE(d.maxDiff, 2);
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
    EXPECT_EQ(compareImages(tile, one).maxDiff, 0);
    const RunResult noOutput = run({"--sweep", "ke=1,2"});
    EXPECT_EQ(noOutput.exitCode, 2);
    EXPECT_NE(noOutput.err.find("--sweep: renders a sheet to a PNG"), std::string::npos) << noOutput.err;
    const RunResult cube = run({"--mesh", "cube", "--sweep", "tessellation=4,8", "--output", path("c.png")});
    EXPECT_EQ(cube.exitCode, 2);
    EXPECT_NE(cube.err.find("--sweep: tessellation: the first object is a cube"), std::string::npos) << cube.err;
    EXPECT_FALSE(fs::exists(path("c.png")));
}

// --plot fresnel: a PNG of the requested size whose curves are where the lecture's formulas put them.
// The test finds the plot's frame in the image itself (the rows and columns that are a third or more the
// axis colour), then looks up R_perp, R_par and the average at 70 degrees, computed here from the tan/sin forms.
TEST_F(Cli, FresnelPlotCurvesAreWhereTheFormulasPutThem) {
    const Image img = runToPng({"--plot", "fresnel", "--ior", "1.5", "--size", "640x480"}, "f.png");
    ASSERT_EQ(img.width, 640);
    ASSERT_EQ(img.height, 480);
    // The axis colour (170, 170, 175) on the dark background, at 75% coverage or more (a line 1.5 pixels
    // wide covers at least one pixel of each row or column that much).
    auto axisLike = [&](int x, int y) {
        const std::uint8_t* p = img.pixel(x, y);
        return std::abs(p[0] - 170) <= 45 && std::abs(p[1] - 170) <= 45 && std::abs(p[2] - 175) <= 45 &&
               std::abs(p[0] - p[2]) < 20;
    };
    // The centres of the runs of rows (or columns) in which more than half the pixels are axis-like.
    auto edges = [&](bool rows) {
        std::vector<double> centres;
        const int outer = rows ? img.height : img.width, inner = rows ? img.width : img.height;
        int runStart = -1;
        for (int k = 0; k <= outer; ++k) {
            int count = 0;
            for (int j = 0; k < outer && j < inner; ++j) count += rows ? axisLike(j, k) : axisLike(k, j);
            const bool full = count > inner / 3;  // the frame; grid lines and text are other colours
            if (full && runStart < 0) runStart = k;
            if (!full && runStart >= 0) centres.push_back(0.5 * (runStart + k - 1) + 0.5), runStart = -1;
        }
        return centres;
    };
    const std::vector<double> horizontal = edges(true), vertical = edges(false);
    ASSERT_EQ(horizontal.size(), 2u) << "expected the frame's top and bottom";
    ASSERT_EQ(vertical.size(), 2u) << "expected the frame's left and right";
    const double top = horizontal[0], bottom = horizontal[1], left = vertical[0], right = vertical[1];
    EXPECT_GT(right - left, 400);
    EXPECT_GT(bottom - top, 200);

    const double kPi = 3.14159265358979323846, t1 = 70.0 * kPi / 180.0, t3 = std::asin(std::sin(t1) / 1.5);
    const double perp = std::pow(std::sin(t1 - t3) / std::sin(t1 + t3), 2.0);  // 0.300
    const double par = std::pow(std::tan(t1 - t3) / std::tan(t1 + t3), 2.0);   // 0.043
    const int x = int(left + 70.0 / 90.0 * (right - left));
    auto rowOf = [&](double reflectance) { return int(std::lround(bottom - reflectance * (bottom - top) - 0.5)); };
    // A pixel within 3 rows of `reflectance` whose colour is within 40 of `rgb`.
    auto curveNear = [&](double reflectance, std::array<int, 3> rgb) {
        for (int y = rowOf(reflectance) - 3; y <= rowOf(reflectance) + 3; ++y) {
            const std::uint8_t* p = img.pixel(x, y);
            if (std::abs(p[0] - rgb[0]) <= 40 && std::abs(p[1] - rgb[1]) <= 40 && std::abs(p[2] - rgb[2]) <= 40) return true;
        }
        return false;
    };
    const std::array<int, 3> vermillion{240, 100, 60}, skyBlue{86, 180, 233}, white{235, 235, 235};
    EXPECT_TRUE(curveNear(perp, vermillion)) << "R_perp at 70 degrees, R = " << perp;
    EXPECT_TRUE(curveNear(par, skyBlue)) << "R_par at 70 degrees, R = " << par;
    EXPECT_TRUE(curveNear((par + perp) / 2.0, white)) << "the average at 70 degrees";
    EXPECT_FALSE(curveNear(0.6, vermillion)) << "R_perp is not at 0.6";
    EXPECT_FALSE(curveNear(perp, skyBlue)) << "R_par is not where R_perp is";
}

// --plot lobe: the requested size (800x600 by default), and the lobes on R's side of N.
TEST_F(Cli, LobePlotHasItsLobesOnTheMirrorSide) {
    const Image img = runToPng({"--plot", "lobe", "--ke", "64", "--incidence", "30"}, "l.png");
    ASSERT_EQ(img.width, 800);
    ASSERT_EQ(img.height, 600);
    // Below the title and legend: Phong's orange (240, 170, 40) only right of the centre (N).
    int left = 0, right = 0;
    for (int y = img.height * 2 / 5; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const std::uint8_t* p = img.pixel(x, y);
            if (std::abs(p[0] - 240) <= 20 && std::abs(p[1] - 170) <= 20 && std::abs(p[2] - 40) <= 30)
                (x < img.width / 2 ? left : right)++;
        }
    EXPECT_EQ(left, 0);
    EXPECT_GT(right, 300);
}

// The plot needs no GL: no shaders (a broken --shader-dir does not matter) and no GL library loaded.
// glibc's loader reports every library it loads, dlopen'ed ones included, under LD_DEBUG=libs; a
// render run with the same setting is the control that the report names libOSMesa.
TEST_F(Cli, PlotsNeedNoGl) {
    if (!SHADELAB_HAVE_OSMESA) GTEST_SKIP() << "the control render loads OSMesa, which this build has not got";
    fs::create_directories(dir_ / "broken-shaders");
    std::ofstream(dir_ / "broken-shaders" / "lighting.glsl") << "this is not GLSL\n";
    const std::vector<std::string> env = {"LD_DEBUG=libs", "LD_DEBUG_OUTPUT=" + path("ld-plot")};
    const RunResult plot = test::runShadelab({"--plot", "lobe", "--shader-dir", path("broken-shaders"), "--output",
                                              path("p.png")},
                                             fs::current_path(), dir_, env);
    ASSERT_EQ(plot.exitCode, 0) << plot.err;
    const RunResult render = test::runShadelab({"--size", "32x32", "--backend", "osmesa", "--output", path("r.png")},
                                               fs::current_path(), dir_, {"LD_DEBUG=libs", "LD_DEBUG_OUTPUT=" + path("ld-render")});
    ASSERT_EQ(render.exitCode, 0) << render.err;
    std::string plotLog, renderLog;
    for (const auto& entry : fs::directory_iterator(dir_)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind("ld-plot", 0) == 0) plotLog += slurp(entry.path());
        if (name.rfind("ld-render", 0) == 0) renderLog += slurp(entry.path());
    }
    ASSERT_NE(renderLog.find("libOSMesa"), std::string::npos) << "LD_DEBUG reports nothing here";
    EXPECT_EQ(plotLog.find("libOSMesa"), std::string::npos);
    EXPECT_EQ(plotLog.find("libEGL"), std::string::npos);
    EXPECT_EQ(plotLog.find("libGL"), std::string::npos);
}

TEST_F(Cli, PlotNeedsAnOutputFile) {
    const RunResult r = run({"--plot", "lobe"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--plot: writes a PNG: give --output FILE.png"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
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

// Output names of any legal length: the temporary file's name does not grow with the target's.
TEST_F(Cli, AnOutputNameOf250BytesIsWritten) {
    const std::string name = std::string(246, 'a') + ".png";
    const RunResult r = run({"--size", "16x16", "--output", path(name)});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(readPng(path(name)).width, 16);
    const RunResult again = run({"--size", "16x16", "--output", path(name)}, {"SHADELAB_NO_TMPFILE=1"});
    EXPECT_EQ(again.exitCode, 0) << again.err;
    EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 3) << "stdout, stderr, the PNG";
}

// A run stopped by a signal while it writes leaves no temporary file, and the output is either the
// old one or the new one, whole. With O_TMPFILE nothing has a name until it is complete (SIGKILL
// too); without it (SHADELAB_NO_TMPFILE) SIGINT and SIGTERM remove the named temporary.
TEST_F(Cli, ASignalDuringTheWriteLeavesNoTemporaryFile) {
    const fs::path out = dir_ / "frames";
    fs::create_directories(out);
    ASSERT_EQ(run({"--size", "64x64", "--output", (out / "o.png").string()}).exitCode, 0);
    for (const char* tmpfile : {"", "SHADELAB_NO_TMPFILE=1"})
        for (const char* signal : {"INT", "TERM", "KILL"})
            for (const char* after : {"0.6", "1.0", "1.4", "1.8"}) {
                const std::string cmd = std::string("cd ") + out.string() + " && env " + (*tmpfile ? tmpfile : "") +
                                        " timeout -s " + signal + " " + after + " " + SHADELAB_EXE +
                                        " --size 4096x4096 --output o.png >/dev/null 2>&1";
                const int stopped = std::system(cmd.c_str());  // timeout: 124, or the signal's status
                (void)stopped;
                SCOPED_TRACE(std::string(tmpfile) + " SIG" + signal + " after " + after + " s");
                std::vector<std::string> names;
                for (const auto& e : fs::directory_iterator(out)) names.push_back(e.path().filename().string());
                if (std::string(signal) == "KILL" && *tmpfile) {
                    // Nothing can catch SIGKILL: a named temporary may stay; remove it for the next round.
                    for (const auto& n : names)
                        if (n != "o.png") fs::remove(out / n);
                } else {
                    EXPECT_EQ(names, std::vector<std::string>{"o.png"});
                }
                const Image img = readPng((out / "o.png").string());
                EXPECT_TRUE(img.width == 64 || img.width == 4096) << img.width;
            }
}

// A full disk is one line from shadelab (libpng's own "Write Error" line is not printed), exit 2,
// and the file that was there stays. Needs a small tmpfs: root only.
TEST_F(Cli, AFullDiskIsOneLineAndKeepsTheOldFile) {
    // Outside the test's folder, and unmounted however the test ends: a mount left behind would stop
    // the next run's SetUp from clearing the folder.
    const fs::path small = fs::temp_directory_path() / ("shadelab-full-disk-" + std::to_string(::getpid()));
    fs::create_directories(small);
    struct Unmount {
        fs::path at;
        ~Unmount() {
            const int status = std::system(("umount " + at.string() + " 2>/dev/null").c_str());
            (void)status;  // not mounted (the test skipped): nothing to undo
            std::error_code ec;
            fs::remove_all(at, ec);
        }
    } unmount{small};
    if (std::system(("mount -t tmpfs -o size=64k tmpfs " + small.string() + " 2>/dev/null").c_str()) != 0)
        GTEST_SKIP() << "cannot mount a tmpfs here (not root?)";
    ASSERT_EQ(run({"--size", "16x16", "--output", (small / "o.png").string()}).exitCode, 0);
    const std::string before = slurp(small / "o.png");
    const RunResult r = run({"--size", "1024x1024", "--output", (small / "o.png").string()});
    const RunResult named = run({"--size", "1024x1024", "--output", (small / "o.png").string()}, {"SHADELAB_NO_TMPFILE=1"});
    const std::string after = slurp(small / "o.png");
    const auto entries = std::distance(fs::directory_iterator(small), fs::directory_iterator());
    for (const RunResult* x : {&r, &named}) {
        EXPECT_EQ(x->exitCode, 2) << x->err;
        EXPECT_EQ(x->err, "shadelab: " + (small / "o.png").string() + ": cannot write: No space left on device\n");
    }
    EXPECT_EQ(after, before);
    EXPECT_EQ(entries, 1);
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

// --msaa takes a sample count GL offers (0, 1, 2, 4, 8); with 4 the image differs from the default
// (one sample), at the sphere's edges only (tests/gl/msaa_test.cpp looks at which pixels).
TEST_F(Cli, MsaaTakesSampleCountsAndChangesTheOutput) {
    const RunResult bad = run({"--msaa", "3", "--output", path("bad.png")});
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
    EXPECT_NE(bad.err.find("--msaa"), std::string::npos) << bad.err;
    EXPECT_NE(bad.err.find("0, 1, 2, 4, 8"), std::string::npos) << bad.err;
    EXPECT_FALSE(fs::exists(path("bad.png")));

    const Image four = runToPng({"--msaa", "4", "--size", "96x64"}, "x.png");
    const Image one = runToPng({"--size", "96x64"}, "one.png");
    ASSERT_EQ(four.width, 96);
    EXPECT_GT(compareImages(four, one, 2).differingPixels, 20u);

    const RunResult bench = run({"--benchmark", "2", "--size", "64x48", "--shading", "phong", "--msaa", "4"});
    ASSERT_EQ(bench.exitCode, 0) << bench.err;
    EXPECT_GE(nlohmann::json::parse(bench.out.substr(0, bench.out.find('\n'))).at("msaa").get<int>(), 2) << bench.out;
}

TEST_F(Cli, HelpAndVersion) {
    const RunResult help = run({"--help"});
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_NE(help.out.find("--output FILE.png"), std::string::npos);
    const RunResult version = run({"--version"});
    EXPECT_EQ(version.exitCode, 0);
    EXPECT_EQ(version.out.rfind("shadelab ", 0), 0u);
}

// --probe with --output: the PNG and, on stdout, the JSON of that pixel, whose 8-bit total is the
// written pixel (phong: 1/255 for GPU and CPU rounding the same formula differently; the background
// exactly).
TEST_F(Cli, ProbePrintsThePixelItWrote) {
    const RunResult r = run({"--layout", "compare", "--size", "240x80", "--probe", "200,35", "--output", path("p.png")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const Image img = readPng(path("p.png"));
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j.at("mode"), "phong");  // the third pane
    EXPECT_EQ(j.at("miss"), false);
    EXPECT_EQ(j.at("evaluations").size(), 1u);
    for (int k = 0; k < 3; ++k)
        EXPECT_LE(std::abs(j.at("output_8bit")[std::size_t(k)].get<int>() - int(img.pixel(200, 35)[k])), 1) << r.out;

    const RunResult miss = run({"--size", "240x80", "--probe", "0,0", "--output", path("m.png")});
    ASSERT_EQ(miss.exitCode, 0) << miss.err;
    const auto m = nlohmann::json::parse(miss.out);
    EXPECT_EQ(m.at("miss"), true);
    const Image missImage = readPng(path("m.png"));  // kept alive: `corner` points into it
    const std::uint8_t* corner = missImage.pixel(0, 0);
    EXPECT_EQ(m.at("output_8bit"), nlohmann::json::array({corner[0], corner[1], corner[2]}));
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

    // The probe sees the auto-framed camera and the model's own base colour.
    const RunResult probe = run({box.string(), "--size", "96x96", "--probe", "48,48", "--output", path("probe.png")});
    ASSERT_EQ(probe.exitCode, 0) << probe.err;
    const auto j = nlohmann::json::parse(probe.out);
    ASSERT_EQ(j.at("miss"), false);
    const Image probeImage = readPng(path("probe.png"));  // kept alive: `centre` points into it
    const std::uint8_t* centre = probeImage.pixel(48, 48);
    for (int k = 0; k < 3; ++k) EXPECT_LE(std::abs(j.at("output_8bit")[std::size_t(k)].get<int>() - int(centre[k])), 1);
}

// --camera N looks through the model's own camera: a unit quad at z = 0 seen from (0.5, 0.5, 4) with a
// vertical field of view of 0.5 rad covers 1 / (2 * 4 * tan 0.25) = 49% of the image's height and width,
// centred (shadelab's own framing would fill more of it).
TEST_F(Cli, CameraFromTheModelFramesTheView) {
    const std::string quad =
        R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1]}],
            "nodes": [{"mesh": 0}, {"camera": 0, "translation": [0.5, 0.5, 4]}],
            "cameras": [{"type": "perspective", "perspective": {"yfov": 0.5, "znear": 0.1, "zfar": 100}}],
            "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
            "materials": [],
            "buffers": [{"byteLength": 60, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAACAPwAAgD8AAAAAAAAAAAAAgD8AAAAAAAABAAIAAAACAAMA"}],
            "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 12}],
            "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
                          {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}]})";
    const std::string model = file("quad_camera.gltf", quad);
    const Image seen = runToPng({model, "--camera", "0", "--size", "100x100", "--shading", "flat", "--ka", "1"}, "camera.png");
    ASSERT_EQ(seen.width, 100);
    const std::uint8_t* bg = seen.pixel(0, 0);
    int covered = 0, minX = 100, maxX = -1;
    for (int y = 0; y < 100; ++y)
        for (int x = 0; x < 100; ++x) {
            const std::uint8_t* p = seen.pixel(x, y);
            if (std::abs(int(p[0]) - int(bg[0])) + std::abs(int(p[1]) - int(bg[1])) + std::abs(int(p[2]) - int(bg[2])) > 30) {
                ++covered;
                minX = std::min(minX, x), maxX = std::max(maxX, x);
            }
        }
    EXPECT_NEAR(covered, 49 * 49, 250);
    EXPECT_NEAR(minX, 25, 2);
    EXPECT_NEAR(maxX, 74, 2);
    const Image framed = runToPng({model, "--size", "100x100", "--shading", "flat", "--ka", "1"}, "framed.png");
    EXPECT_NE(framed.rgba, seen.rgba) << "--camera changed nothing";
    const RunResult missing = run({model, "--camera", "1", "--output", path("o.png")});
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_NE(missing.err.find("has 1 camera in its drawn scene (0..0)"), std::string::npos) << missing.err;
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
    EXPECT_EQ(compareImages(readPng(path("slides/" + last)), readPng(path("single.png"))).maxDiff, 0) << preset;
}

// --playlist NAME: a bare name that is no folder where shadelab runs is the scene folder of that name
// beside the program (here, for the program in a build folder, the checkout's assets/scenes/lecture
// where the build folder is inside the checkout, else the build folder's share/shadelab/scenes/lecture;
// installed, share/shadelab/scenes/lecture: packaging/check-deb.sh); a folder of that name where it
// runs comes first; an unknown name says where it was looked for.
TEST_F(Cli, PlaylistByNameFindsTheScenesBesideTheProgram) {
    std::set<std::string> expected;
    for (const auto& e : fs::directory_iterator(fs::path(SHADELAB_SOURCE_DIR) / "assets" / "scenes" / "lecture"))
        if (e.path().extension() == ".json") expected.insert(e.path().stem().string() + ".png");
    const RunResult r = test::runShadelab({"--playlist", "lecture", "--output", "byname/", "--size", "32x18"}, dir_, dir_);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::set<std::string> written;
    for (const auto& e : fs::directory_iterator(dir_ / "byname")) written.insert(e.path().filename().string());
    EXPECT_EQ(written, expected);

    fs::create_directories(dir_ / "lecture");
    file("lecture/only.json", R"({"mesh": {"type": "cube"}})");
    ASSERT_EQ(test::runShadelab({"--playlist", "lecture", "--output", "local/", "--size", "32x18"}, dir_, dir_).exitCode, 0);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir_ / "local"), fs::directory_iterator()), 1);

    const RunResult unknown = test::runShadelab({"--playlist", "no-such-lecture", "--output", "x/"}, dir_, dir_);
    EXPECT_EQ(unknown.exitCode, 2);
    EXPECT_NE(unknown.err.find("no-such-lecture: no such folder (nor a scene folder of that name beside the program)"),
              std::string::npos) << unknown.err;
}

// A build folder can be anywhere (issue 27): the build lays out share/shadelab/{shaders,scenes,models}
// beside the program as an install does (README, "Installing"), each holding what the checkout's
// folder holds.
TEST_F(Cli, BuildFolderHoldsTheDataAsAnInstallDoes) {
    const fs::path data = fs::path(SHADELAB_EXE).parent_path() / "share" / "shadelab";
    const std::pair<const char*, const char*> folders[] = {{"shaders", "shaders"}, {"scenes", "assets/scenes"}, {"models", "assets/models"}};
    for (const auto& [staged, source] : folders) {
        const auto files = [](const fs::path& root) {  // relative path -> contents
            std::map<std::string, std::string> all;
            for (const auto& e : fs::recursive_directory_iterator(root))
                if (e.is_regular_file()) all[fs::relative(e.path(), root).generic_string()] = slurp(e.path());
            return all;
        };
        ASSERT_TRUE(fs::is_directory(data / staged)) << (data / staged) << " is missing";
        const auto expected = files(fs::path(SHADELAB_SOURCE_DIR) / source);
        EXPECT_FALSE(expected.empty()) << source;
        EXPECT_TRUE(files(data / staged) == expected) << (data / staged) << " differs from the checkout's " << source;
    }
}

// ... and the program reads its data there, where neither an install's ../share/shadelab nor a
// checkout's ../assets and ../shaders are: a copy of it in a folder of its own, with a scene folder and
// shaders beside it, plays that folder by name and draws with those shaders (a broken phong.frag
// there fails the run, naming the file).
TEST_F(Cli, ProgramReadsTheDataBesideIt) {
    const fs::path program = dir_ / "build" / "shadelab";
    const fs::path data = dir_ / "build" / "share" / "shadelab";
    fs::create_directories(data / "scenes" / "talk");
    fs::copy_file(SHADELAB_EXE, program);
    file("build/share/shadelab/scenes/talk/01-cube.json", R"({"mesh": {"type": "cube"}})");
    const RunResult played = test::runProgram(program, {"--playlist", "talk", "--output", "slides/", "--size", "32x18"}, dir_, dir_);
    ASSERT_EQ(played.exitCode, 0) << played.err;
    EXPECT_TRUE(fs::is_regular_file(dir_ / "slides" / "01-cube.png"));

    fs::copy(fs::path(SHADELAB_SOURCE_DIR) / "shaders", data / "shaders");
    std::ofstream(data / "shaders" / "phong.frag", std::ios::app) << "#error the phong.frag beside the program is read\n";
    const RunResult broken = test::runProgram(program, {"--shading", "phong", "--size", "16x16", "--output", "x.png"}, dir_, dir_);
    EXPECT_EQ(broken.exitCode, 2) << broken.err;
    EXPECT_NE(broken.err.find("phong.frag"), std::string::npos) << broken.err;
    EXPECT_FALSE(fs::exists(dir_ / "x.png"));
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
        EXPECT_EQ(compareImages(top, plain).maxDiff, 0) << name;
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

// A textured model (the project's checker globe): --info counts its base colour image, the probe
// reports the sampled C and the texel, and --no-textures draws the base colour factor alone.
TEST_F(Cli, TexturedModelsAreReportedProbedAndCanBeDrawnWithout) {
    const std::string globe = std::string(SHADELAB_SOURCE_DIR) + "/assets/models/checker_globe.gltf";
    const RunResult info = run({"--info", globe});
    ASSERT_EQ(info.exitCode, 0) << info.err;
    EXPECT_NE(info.out.find("textures: 1 base colour image drawn"), std::string::npos) << info.out;

    const RunResult probe = run({globe, "--size", "96x96", "--probe", "48,48", "--output", path("on.png")});
    ASSERT_EQ(probe.exitCode, 0) << probe.err;
    const auto j = nlohmann::json::parse(probe.out);
    ASSERT_EQ(j.at("miss"), false);
    ASSERT_TRUE(j.contains("texture")) << probe.out;
    const auto& C = j.at("material").at("C");
    const auto& base = j.at("material").at("C_base");
    const auto& texel = j.at("texture").at("texel");
    for (std::size_t k = 0; k < 3; ++k)
        EXPECT_NEAR(C[k].get<double>(), base[k].get<double>() * texel[k].get<double>(), 1e-3) << probe.out;

    const RunResult off = run({globe, "--size", "96x96", "--no-textures", "--probe", "48,48", "--output", path("off.png")});
    ASSERT_EQ(off.exitCode, 0) << off.err;
    EXPECT_FALSE(nlohmann::json::parse(off.out).contains("texture"));
    const Image on = readPng(path("on.png")), plain = readPng(path("off.png"));
    EXPECT_GT(compareImages(on, plain, 30).differingPixels, 500u) << "the texture should change much of the picture";
}

// A model with lights of its own (KHR_lights_punctual): --info lists them in the file's units, and a
// scene without lights is lit by them (the spot's pool on the floor, the floor dark outside it).
TEST_F(Cli, ModelLightsAreListedAndLightTheScene) {
    const std::string stage = std::string(SHADELAB_SOURCE_DIR) + "/assets/models/spot_stage.gltf";
    const RunResult info = run({"--info", stage});
    ASSERT_EQ(info.exitCode, 0) << info.err;
    EXPECT_NE(info.out.find("light 0: spot, spot, 800 cd at [0, 3, 1.5]"), std::string::npos) << info.out;
    EXPECT_NE(info.out.find("light 1: fill, directional, 0.3 lux"), std::string::npos) << info.out;

    const RunResult own = run({stage, "--size", "160x120", "--output", path("own.png")});
    ASSERT_EQ(own.exitCode, 0) << own.err;
    const RunResult given = run({stage, "--size", "160x120", "--light", "point:3,4,5", "--output", path("given.png")});
    ASSERT_EQ(given.exitCode, 0) << given.err;
    EXPECT_GT(compareImages(readPng(path("own.png")), readPng(path("given.png")), 20).differingPixels, 1000u);
}

// --formula: the PNG differs from the plain render only at the bottom, where the overlay is; the term
// --show isolates gets its colour's tint and the others dim (measured in each term's box on the
// formula's main line, where the layout puts it on this image); --probe adds the terms' values.
TEST_F(Cli, FormulaOverlayHighlightsTheShownTerm) {
    const TrueTypeFont* font = TrueTypeFont::dejaVuSans();
    if (!font) GTEST_SKIP() << "DejaVu Sans is not installed";
    const std::vector<std::string> size = {"--size", "480x270"};
    const Image plain = runToPng(size, "plain.png");
    auto args = [&](std::vector<std::string> more) {
        more.insert(more.begin(), size.begin(), size.end());
        more.push_back("--formula");
        return more;
    };
    const Image all = runToPng(args({}), "all.png");
    ASSERT_EQ(all.width, 480);
    int top = all.height, changed = 0;
    for (int y = 0; y < all.height; ++y)
        for (int x = 0; x < all.width; ++x)
            if (!std::equal(all.pixel(x, y), all.pixel(x, y) + 4, plain.pixel(x, y))) top = std::min(top, y), ++changed;
    EXPECT_GT(changed, 5000);
    EXPECT_GT(top, all.height * 6 / 10) << "the overlay reaches up to row " << top;

    // Each term's box on the main line, for --show diffuse (the boxes do not move with --show).
    Scene scene;
    FormulaInput in = formulaInput(scene, scene.objects[0].material);
    const FormulaOverlay o = imageFormulaOverlay(all, in, {{0, 0, 480, 270, ShadingMode::Phong, false}}, *font);
    // The mean of one channel minus the mean of the other two, over a term's first box.
    auto tint = [&](const Image& img, FormulaTerm term, int channel) {
        const auto box = std::find_if(o.formula.boxes.begin(), o.formula.boxes.end(), [&](const FormulaBox& b) { return b.term == term; });
        double sum = 0.0;
        int n = 0;
        for (int y = int(o.y + box->y0) + 1; y < int(o.y + box->y1) - 1; ++y)
            for (int x = int(o.x + box->x0) + 1; x < int(o.x + box->x1) - 1; ++x, ++n) {
                const std::uint8_t* p = img.pixel(x, y);
                sum += p[channel] - 0.5 * (p[(channel + 1) % 3] + p[(channel + 2) % 3]);
            }
        return sum / std::max(n, 1);
    };
    const Image diffuse = runToPng(args({"--show", "diffuse"}), "diffuse.png");
    const Image specular = runToPng(args({"--show", "specular"}), "specular.png");
    // Green is the diffuse term's colour, blue's absence the specular's (gold).
    EXPECT_GT(tint(diffuse, FormulaTerm::Diffuse, 1), tint(specular, FormulaTerm::Diffuse, 1) + 10.0);
    EXPECT_GT(tint(diffuse, FormulaTerm::Diffuse, 1), tint(all, FormulaTerm::Diffuse, 1) + 5.0);
    EXPECT_LT(tint(specular, FormulaTerm::Specular, 2), tint(diffuse, FormulaTerm::Specular, 2) - 10.0);

    // A probed pixel adds a row of values: the overlay grows upward.
    const Image probed = runToPng(args({"--probe", "240,135"}), "probed.png");
    int probedTop = probed.height;
    for (int y = 0; y < probed.height && probedTop == probed.height; ++y)
        for (int x = 0; x < probed.width; ++x)
            if (!std::equal(probed.pixel(x, y), probed.pixel(x, y) + 4, plain.pixel(x, y))) {
                probedTop = y;
                break;
            }
    EXPECT_LT(probedTop, top);
}

// The shader view's error marks come from the driver's log as the renderer words it: a real compile
// error of tests/bad-inputs/broken_shaders/phong.frag (lines 1 and 2 are wrong) is found at its lines.
TEST_F(Cli, ShaderCompileErrorsNameTheirLines) {
    const std::string broken = std::string(SHADELAB_SOURCE_DIR) + "/tests/bad-inputs/broken_shaders";
    const RunResult r = run({"--shader-dir", broken, "--shading", "phong", "--size", "16x16", "--output", path("x.png")});
    ASSERT_EQ(r.exitCode, 2) << r.err;
    const std::vector<GlslError> errors = glslErrors(r.err);
    ASSERT_GE(errors.size(), 2u) << r.err;
    EXPECT_EQ(errors[0].file, "phong.frag");
    EXPECT_EQ(errors[0].line, 1);
    EXPECT_EQ(errors[1].line, 2);
    const std::vector<GlslLine> lines = listGlsl("phong.frag", slurp(broken + "/phong.frag"), errors);
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_FALSE(lines[0].error.empty());
    EXPECT_FALSE(lines[1].error.empty());

    // An error inside a function of the lighting include is that file's line (Mesa loses the source
    // number there; the include step's line numbers keep it).
    fs::copy(fs::path(SHADELAB_SOURCE_DIR) / "shaders", dir_ / "shaders");
    const std::string lighting = slurp(dir_ / "shaders" / "lighting.glsl");
    const std::string code = "a = distanceFalloff(l, dot(d, d));";
    const std::size_t at = lighting.find(code);
    ASSERT_NE(at, std::string::npos);
    const int line = 1 + int(std::count(lighting.begin(), lighting.begin() + std::ptrdiff_t(at), '\n'));
    std::ofstream(dir_ / "shaders" / "lighting.glsl") << std::string(lighting).insert(at + code.size() - 1, " + oops");
    const RunResult inFunction = run({"--shader-dir", path("shaders"), "--size", "16x16", "--output", path("y.png")});
    const std::vector<GlslError> there = glslErrors(inFunction.err);
    ASSERT_FALSE(there.empty()) << inFunction.err;
    EXPECT_EQ(there[0].file, "lighting.glsl") << inFunction.err;
    EXPECT_EQ(there[0].line, line) << inFunction.err;
}
