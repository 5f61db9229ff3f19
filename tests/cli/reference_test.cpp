// Issue 19, one image against a reference: `shadelab SCENE --output out.png --reference ref.png` as a
// user's CI runs it. Exit status 0 when they match, 1 when they differ (one line on stdout with the
// numbers says which), 2 for a missing or malformed reference; the output is written whenever there
// was something to compare; --diff-output is the diff layout's difference pane.
#include "cli/cli_fixture.hpp"
#include "core/image/image.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

using namespace shadelab;
namespace fs = std::filesystem;

using test::Cli;
using test::RunResult;
using test::slurp;

namespace {

// The defaults (core/image/image.hpp), as the line prints them.
const ImageTolerance kDefaults;

// The numbers of the stdout line "shadelab: A against B: max 3/255 (limit 4), mean 0.0157 (limit 0.002): differs".
struct Verdict {
    bool parsed = false;
    int max = -1, maxLimit = -1;
    double mean = -1, meanLimit = -1;
    bool matches = false;
};
Verdict verdictOf(const std::string& out) {
    static const std::regex line(R"(^shadelab: .* against .*: max (\d+)/255 \(limit (\d+)\), mean ([0-9.e+-]+) )"
                                 R"(\(limit ([0-9.e+-]+)\): (matches|differs)\n$)");
    std::smatch m;
    Verdict v;
    if (!std::regex_match(out, m, line)) return v;
    v.parsed = true;
    v.max = std::stoi(m[1]);
    v.maxLimit = std::stoi(m[2]);
    v.mean = std::stod(m[3]);
    v.meanLimit = std::stod(m[4]);
    v.matches = m[5] == "matches";
    return v;
}

// The default scene, small, with its light given (so a test can move it).
const std::vector<std::string> kScene = {"--size", "160x120", "--light", "point:3,4,5"};
std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
    args.insert(args.end(), more.begin(), more.end());
    return args;
}

}  // namespace

// A render against its own reference matches, also from the other llvmpipe front end (EGL against
// OSMesa: a handful of pixels 1/255 apart); the output is written, and a plot compares the same way.
TEST_F(Cli, ReferenceMatchesTheSameRender) {
    // Across the two backends where the build has both (else the one it has, twice).
    const std::string first = SHADELAB_HAVE_OSMESA ? "osmesa" : "egl";
    const std::string other = SHADELAB_HAVE_EGL ? "egl" : "osmesa";
    ASSERT_EQ(run(with(kScene, {"--backend", first, "--output", path("ref.png")})).exitCode, 0);
    const RunResult r = run(with(kScene, {"--backend", other, "--output", path("out.png"), "--reference", path("ref.png")}));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    const Verdict v = verdictOf(r.out);
    ASSERT_TRUE(v.parsed) << r.out;
    EXPECT_TRUE(v.matches);
    EXPECT_LE(v.max, 1);
    EXPECT_EQ(v.maxLimit, kDefaults.maxDiff);
    EXPECT_DOUBLE_EQ(v.meanLimit, kDefaults.meanDiff);
    EXPECT_NE(r.out.find("shadelab: " + path("out.png") + " against " + path("ref.png") + ": max "), std::string::npos);
    EXPECT_TRUE(r.err.empty()) << r.err;
    EXPECT_EQ(readPng(path("out.png")).width, 160);

    ASSERT_EQ(run({"--plot", "lobe", "--output", path("lobe-ref.png")}).exitCode, 0);
    const RunResult plot = run({"--plot", "lobe", "--output", path("lobe.png"), "--reference", path("lobe-ref.png")});
    EXPECT_EQ(plot.exitCode, 0) << plot.err;
    EXPECT_TRUE(verdictOf(plot.out).matches) << plot.out;
}

// A one-step change of k_e (32 -> 33: about a pixel of the panel's logarithmic slider), the light moved
// by one step of its drag (0.05) and another shading mode each differ: exit status 1, the output still
// written. The mean catches the small changes (k_e + 1 moves no channel more than 2/255, as the two
// llvmpipe front ends may); the max alone catches a changed mode.
TEST_F(Cli, ReferenceCatchesOneStepChanges) {
    ASSERT_EQ(run(with(kScene, {"--output", path("ref.png")})).exitCode, 0);
    struct Change {
        const char* name;
        std::vector<std::string> args;
        bool maxAloneCatchesIt;
    };
    const Change changes[] = {
        {"ke", {"--ke", "33"}, false},
        {"light", {"--light", "point:3.05,4,5"}, false},
        {"mode", {"--shading", "gouraud"}, true},
    };
    for (const Change& c : changes) {
        SCOPED_TRACE(c.name);
        std::vector<std::string> args = c.name == std::string("light") ? std::vector<std::string>{"--size", "160x120"} : kScene;
        args = with(with(args, c.args), {"--output", path(std::string(c.name) + ".png"), "--reference", path("ref.png")});
        fs::remove(path(std::string(c.name) + ".png"));
        const RunResult r = run(args);
        EXPECT_EQ(r.exitCode, 1) << r.err;
        const Verdict v = verdictOf(r.out);
        ASSERT_TRUE(v.parsed) << r.out;
        EXPECT_FALSE(v.matches);
        EXPECT_GT(v.mean, kDefaults.meanDiff);  // the mean catches every one
        EXPECT_EQ(v.max > kDefaults.maxDiff, c.maxAloneCatchesIt) << v.max;
        EXPECT_TRUE(fs::exists(path(std::string(c.name) + ".png")));
        // Each threshold on its own: the mean with the max opened wide; the max with the mean opened wide.
        EXPECT_EQ(run(with(args, {"--max-diff", "255"})).exitCode, 1);
        EXPECT_EQ(run(with(args, {"--mean-diff", "255"})).exitCode, c.maxAloneCatchesIt ? 1 : 0);
        // And both opened to the measured numbers: it matches.
        const RunResult loose = run(with(args, {"--max-diff", std::to_string(v.max), "--mean-diff", std::to_string(v.mean * 1.01)}));
        EXPECT_EQ(loose.exitCode, 0) << loose.out;
        EXPECT_TRUE(verdictOf(loose.out).matches) << loose.out;
    }
}

// A reference of another size differs (exit status 1) with a line of its own; the output is written and
// there is no difference image to write.
TEST_F(Cli, ReferenceOfAnotherSizeDiffers) {
    ASSERT_EQ(run({"--size", "160x120", "--output", path("ref.png")}).exitCode, 0);
    const RunResult r = run({"--size", "120x160", "--output", path("out.png"), "--reference", path("ref.png"),
                             "--diff-output", path("diff.png")});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_EQ(r.out, "shadelab: " + path("out.png") + " against " + path("ref.png") +
                         ": size 120x160, the reference's 160x120: differs (no --diff-output)\n");
    EXPECT_EQ(readPng(path("out.png")).width, 120);
    EXPECT_FALSE(fs::exists(path("diff.png")));
}

// A missing reference is bad input (exit status 2, one line, nothing written) unless
// --reference-missing=write, which makes it from the render (exit status 0, and says so); an existing
// reference is compared, never rewritten.
TEST_F(Cli, MissingReferenceFailsOrIsWritten) {
    const std::vector<std::string> args = with(kScene, {"--output", path("out.png"), "--reference", path("ref.png")});
    const RunResult missing = run(args);
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_EQ(missing.err, "shadelab: --reference: " + path("ref.png") +
                               " does not exist (--reference-missing=write creates it from this render)\n");
    EXPECT_TRUE(missing.out.empty());
    EXPECT_FALSE(fs::exists(path("ref.png")));
    EXPECT_FALSE(fs::exists(path("out.png")));

    const RunResult written = run(with(args, {"--reference-missing=write", "--diff-output", path("diff.png")}));
    EXPECT_EQ(written.exitCode, 0) << written.err;
    EXPECT_EQ(written.out, "shadelab: " + path("out.png") + ": the reference " + path("ref.png") +
                               " did not exist: written from this render\n");
    EXPECT_EQ(readPng(path("ref.png")).rgba, readPng(path("out.png")).rgba);
    EXPECT_FALSE(fs::exists(path("diff.png")));  // nothing to compare with

    // Now it exists: compared, not rewritten.
    const RunResult again = run(with(args, {"--reference-missing", "write", "--ke", "8"}));
    EXPECT_EQ(again.exitCode, 1) << again.out;
    EXPECT_FALSE(verdictOf(again.out).matches);
    EXPECT_NE(readPng(path("ref.png")).rgba, readPng(path("out.png")).rgba);
}

// A reference that is no PNG (a text file named .png, a cut-off PNG) is bad input: exit status 2, one
// line naming it, nothing written. So is a reference that is the --output file itself.
TEST_F(Cli, MalformedReferenceIsBadInput) {
    const std::string text = file("ref.png", "this is a text file, not an image\n");
    const RunResult r = run(with(kScene, {"--output", path("out.png"), "--reference", text}));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err, "shadelab: --reference: " + text + ": cannot read PNG: Not a PNG file\n");
    EXPECT_FALSE(fs::exists(path("out.png")));
    EXPECT_EQ(slurp(text), "this is a text file, not an image\n");

    ASSERT_EQ(run(with(kScene, {"--output", path("whole.png")})).exitCode, 0);
    const std::string whole = slurp(path("whole.png"));
    const std::string cut = file("cut.png", whole.substr(0, whole.size() / 2));
    const RunResult truncated = run(with(kScene, {"--output", path("out.png"), "--reference", cut}));
    EXPECT_EQ(truncated.exitCode, 2);
    EXPECT_NE(truncated.err.find("shadelab: --reference: " + cut + ": cannot read PNG: "), std::string::npos);
    EXPECT_FALSE(fs::exists(path("out.png")));

    const RunResult self = run(with(kScene, {"--output", path("whole.png"), "--reference", path("whole.png")}));
    EXPECT_EQ(self.exitCode, 2);
    EXPECT_NE(self.err.find("is the --output file"), std::string::npos) << self.err;
}

// --diff-output is the diff layout's third pane: the difference of a Gouraud and a Phong render equals,
// pixel for pixel, the pane the GPU draws (shaders/difference.frag) for lecture preset 03 (layout diff,
// gouraud | phong, the scene's factor 2), from panes of the same size; --diff-factor scales both alike.
TEST_F(Cli, DiffOutputIsTheDiffLayoutsPane) {
    const std::string preset = std::string(SHADELAB_SOURCE_DIR) + "/assets/scenes/lecture/03-gouraud-misses-highlight.json";
    const std::vector<std::string> single = {preset, "--layout", "single", "--size", "160x120"};
    ASSERT_EQ(run(with(single, {"--shading", "gouraud", "--output", path("gouraud.png")})).exitCode, 0);
    const std::vector<std::string> phong = with(single, {"--shading", "phong", "--output", path("phong.png"),
                                                         "--reference", path("gouraud.png")});
    const RunResult r = run(with(phong, {"--diff-output", path("diff.png")}));
    EXPECT_EQ(r.exitCode, 1) << r.err;
    const Image diff = readPng(path("diff.png"));
    ASSERT_EQ(diff.width, 160);

    const Image layout = runToPng({preset, "--size", "480x120"}, "layout.png");
    ASSERT_EQ(layout.width, 480);
    auto pane = [&layout](int index) {
        Image p(160, 120);
        for (int y = 0; y < 120; ++y) std::copy_n(layout.pixel(160 * index, y), 160 * 4, p.pixel(0, y));
        return p;
    };
    // The GPU's pane is the CPU's mapping of its own two panes, exactly...
    EXPECT_EQ(compareImages(amplifiedDifference(pane(0), pane(1), 2.0f), pane(2), 0).maxDiff, 0);
    // ...the panes are the single renders, and so the difference image is the pane.
    EXPECT_EQ(compareImages(pane(0), readPng(path("gouraud.png")), 0).maxDiff, 0);
    EXPECT_EQ(compareImages(pane(1), readPng(path("phong.png")), 0).maxDiff, 0);
    EXPECT_EQ(compareImages(diff, pane(2), 0).maxDiff, 0);

    // What a person sees: black where the modes agree (the background, most of the sphere), bright in the
    // highlight Gouraud misses.
    int black = 0, bright = 0;
    for (int y = 0; y < 120; ++y)
        for (int x = 0; x < 160; ++x) {
            const std::uint8_t* p = diff.pixel(x, y);
            black += p[0] == 0 && p[1] == 0 && p[2] == 0;
            bright += std::min({p[0], p[1], p[2]}) > 100;
            EXPECT_EQ(p[3], 255);
        }
    EXPECT_GT(black, 160 * 120 / 2);
    EXPECT_GT(bright, 10);

    // --diff-factor 16 is eight times the preset's 2, clamped.
    ASSERT_EQ(run(with(phong, {"--diff-output", path("diff16.png"), "--diff-factor", "16"})).exitCode, 1);
    const Image diff16 = readPng(path("diff16.png"));
    for (std::size_t i = 0; i < diff.rgba.size(); i += 4)
        for (std::size_t c = 0; c < 3; ++c)
            if (diff.rgba[i + c] < 255) {
                ASSERT_EQ(diff16.rgba[i + c], std::min(255, 8 * diff.rgba[i + c])) << i;
            }
}
