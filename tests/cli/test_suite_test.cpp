// Issue 19, a folder in one process: `shadelab --test DIR` as a user's CI runs it. The references are
// the golden images (tests/golden/, images a person looked at) of the golden scenes (tests/scenes/);
// a failing case is made by changing a scene (k_e one step up), never by the code under test. Exit
// status 0 when all match, 1 when any case fails; a case that cannot be compared fails with its
// message and the run goes on. Bad input of the run itself (exit 2) is in tests/bad-inputs/cases.txt.
#include "cli/cli_fixture.hpp"
#include "core/image/image.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <thread>
#include <vector>

using namespace shadelab;
namespace fs = std::filesystem;

using test::Cli;
using test::RunResult;
using test::slurp;

namespace {

const fs::path kSource = SHADELAB_SOURCE_DIR;
// Three golden scenes, 128x128 each, one per shading mode: in file-name order flat, gouraud, phong.
const std::vector<std::string> kNames = {"flat_uvsphere", "gouraud_uvsphere", "phong_uvsphere"};

std::size_t occurrences(const std::string& text, const std::string& part) {
    std::size_t n = 0;
    for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
    return n;
}

class TestSuite : public Cli {
protected:
    // DIR/NAME.json and, in `refs` (DIR itself when empty), NAME.png for each golden scene.
    std::string makeFolder(const std::string& dir, const std::string& refs = "") const {
        fs::create_directories(dir_ / dir);
        fs::create_directories(dir_ / (refs.empty() ? dir : refs));
        for (const std::string& n : kNames) {
            fs::copy_file(kSource / "tests" / "scenes" / (n + ".json"), dir_ / dir / (n + ".json"));
            fs::copy_file(kSource / "tests" / "golden" / (n + ".png"), dir_ / (refs.empty() ? dir : refs) / (n + ".png"));
        }
        return path(dir);
    }
    // The scene's k_e one step of the panel's slider up (32 -> 33): a change the defaults catch.
    void raiseKe(const std::string& dir, const std::string& name) const {
        const fs::path scene = dir_ / dir / (name + ".json");
        std::string text = slurp(scene);
        ASSERT_EQ(text.find("material"), std::string::npos);
        text.insert(text.find('{') + 1, "\n  \"material\": {\"ke\": 33},");
        std::ofstream(scene) << text;
    }
};

const char* const kMatch = R"(max \d+/255 \(limit 4\), mean [0-9.e+-]+ \(limit 0.002\))";

// Whether `page` holds `image` pixel for pixel (RGB of its opaque pixels) somewhere: the report shows it
// unscaled. The first opaque pixel finds the candidates, the rest confirms one.
bool containsImage(const Image& page, const Image& image) {
    int fx = -1, fy = -1;
    for (int y = 0; y < image.height && fx < 0; ++y)
        for (int x = 0; x < image.width && fx < 0; ++x)
            if (image.pixel(x, y)[3] == 255) fx = x, fy = y;
    if (fx < 0) return false;
    const auto same = [](const std::uint8_t* a, const std::uint8_t* b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; };
    for (int py = fy; py + image.height - fy <= page.height; ++py)
        for (int px = fx; px + image.width - fx <= page.width; ++px) {
            if (!same(page.pixel(px, py), image.pixel(fx, fy))) continue;
            bool all = true;
            for (int y = 0; y < image.height && all; ++y)
                for (int x = 0; x < image.width && all; ++x)
                    all = image.pixel(x, y)[3] != 255 || same(page.pixel(px - fx + x, py - fy + y), image.pixel(x, y));
            if (all) return true;
        }
    return false;
}

}  // namespace

// Every scene matches its golden image: exit 0, the summary line alone on stdout, JUnit without failures.
TEST_F(TestSuite, AllMatch) {
    const std::string dir = makeFolder("cases");
    const RunResult r = run({"--test", dir, "--junit", path("junit.xml"), "--report", path("report.html")});
    EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_EQ(r.out, "shadelab: --test " + dir + ": 3 scenes, 3 match\n");
    EXPECT_TRUE(r.err.empty()) << r.err;
    const std::string xml = slurp(path("junit.xml"));
    EXPECT_NE(xml.find("tests=\"3\" failures=\"0\" errors=\"0\""), std::string::npos) << xml;
    EXPECT_EQ(occurrences(xml, "<testcase "), 3u);
    EXPECT_EQ(occurrences(slurp(path("report.html")), "<img "), 0u);  // nothing failed: no images
}

// One scene changed (k_e one step up): exit 1, its line with the numbers, the others match; JUnit and the
// HTML page name it; --update is not given, so nothing is rewritten.
TEST_F(TestSuite, OneFailingScene) {
    const std::string dir = makeFolder("cases");
    raiseKe("cases", "phong_uvsphere");
    const std::string reference = slurp(path("cases/phong_uvsphere.png"));
    const RunResult r = run({"--test", dir, "--junit", path("junit.xml"), "--report", path("report.html")});
    EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
    const std::regex expected("shadelab: --test " + dir + ": phong_uvsphere: differs: " + kMatch + "\n" +
                              "shadelab: --test " + dir + ": 3 scenes, 2 match, 1 differs \\(phong_uvsphere\\)\n");
    EXPECT_TRUE(std::regex_match(r.out, expected)) << r.out;
    EXPECT_EQ(slurp(path("cases/phong_uvsphere.png")), reference);

    const std::string xml = slurp(path("junit.xml"));
    EXPECT_NE(xml.find("tests=\"3\" failures=\"1\" errors=\"0\""), std::string::npos) << xml;
    EXPECT_TRUE(std::regex_search(xml, std::regex(std::string("<testcase [^>]*name=\"phong_uvsphere\"[^>]*>\\s*") +
                                                  "<failure type=\"differs\" message=\"" + kMatch + "\">")))
        << xml;
    for (const char* passing : {"flat_uvsphere", "gouraud_uvsphere"})
        EXPECT_TRUE(std::regex_search(xml, std::regex(std::string("<testcase [^>]*name=\"") + passing + "\"[^>]*/>"))) << xml;

    const std::string html = slurp(path("report.html"));
    EXPECT_NE(html.find("<h2>phong_uvsphere: differs</h2>"), std::string::npos);
    EXPECT_EQ(occurrences(html, "<img "), 3u);  // reference, render, difference of the one failing case
    EXPECT_NE(html.find("<tr><td>flat_uvsphere</td>"), std::string::npos);
    EXPECT_NE(html.find("<tr><td>gouraud_uvsphere</td>"), std::string::npos);
}

// The HTML report in a real browser: the failing case's reference, render and difference are on the
// screen, pixel for pixel. The render and the difference come from the one-image mode
// (--reference --diff-output), the reference is the golden image.
TEST_F(TestSuite, ReportShowsTheFailingImagesInABrowser) {
    if (std::system("command -v chromium >/dev/null 2>&1") != 0) GTEST_SKIP() << "chromium is not installed";
    const std::string dir = makeFolder("cases");
    raiseKe("cases", "phong_uvsphere");
    ASSERT_EQ(run({"--test", dir, "--report", path("report.html")}).exitCode, 1);
    ASSERT_EQ(run({path("cases/phong_uvsphere.json"), "--output", path("actual.png"), "--reference",
                   path("cases/phong_uvsphere.png"), "--diff-output", path("diff.png")})
                  .exitCode,
              1);
    const std::string command = "cd " + dir_.string() +
                                " && timeout 120 chromium --headless --no-sandbox --disable-gpu --hide-scrollbars "
                                "--disable-dev-shm-usage --user-data-dir=" + path("profile") +  // (a container's small /dev/shm)
                                " --force-device-scale-factor=1 --screenshot=" + path("page.png") +
                                " --window-size=900,700 file://" + path("report.html") + " >chromium.log 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << slurp(path("chromium.log"));
    const Image page = readPng(path("page.png"));
    EXPECT_TRUE(containsImage(page, readPng(path("cases/phong_uvsphere.png")))) << "the reference is not on the page";
    EXPECT_TRUE(containsImage(page, readPng(path("actual.png")))) << "the render is not on the page";
    EXPECT_TRUE(containsImage(page, readPng(path("diff.png")))) << "the difference is not on the page";
    // And not just any sphere: the passing cases' images are not shown.
    EXPECT_FALSE(containsImage(page, readPng((kSource / "tests/golden/flat_uvsphere.png").string())));
}

// Cases that cannot be compared fail with their own message and the run goes on: a missing reference, a
// reference that is no PNG, a scene file that is not JSON; each is a JUnit error. Overrides apply to
// every scene: --size makes the sizes differ.
TEST_F(TestSuite, BrokenCasesFailAndTheRunGoesOn) {
    const std::string dir = makeFolder("cases", "refs");
    fs::remove(path("refs/gouraud_uvsphere.png"));
    std::ofstream(path("refs/flat_uvsphere.png")) << "not a png";
    std::ofstream(path("cases/broken.json")) << "{\"mesh\": ";
    const RunResult r = run({"--test", dir, "--references", path("refs"), "--junit", path("junit.xml")});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    const std::string prefix = "shadelab: --test " + dir + ": ";
    EXPECT_NE(r.out.find(prefix + "broken: error: " + path("cases/broken.json") + ": malformed JSON"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find(prefix + "flat_uvsphere: error: the reference: " + path("refs/flat_uvsphere.png") +
                         ": cannot read PNG"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find(prefix + "gouraud_uvsphere: error: the reference " + path("refs/gouraud_uvsphere.png") +
                         " does not exist (--update writes it from this render)\n"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find(prefix + "4 scenes, 1 match, 3 errors (broken, flat_uvsphere, gouraud_uvsphere)\n"),
              std::string::npos)
        << r.out;
    EXPECT_NE(slurp(path("junit.xml")).find("tests=\"4\" failures=\"0\" errors=\"3\""), std::string::npos);

    fs::remove(path("cases/broken.json"));
    const RunResult sized = run({"--test", dir, "--references", path("refs"), "--size", "64x48"});
    EXPECT_EQ(sized.exitCode, 1);
    EXPECT_NE(sized.out.find(prefix + "phong_uvsphere: differs: size 64x48, the reference's 128x128\n"), std::string::npos)
        << sized.out;
}

// The assignment: a --shader-dir whose flat.frag does not compile fails the flat case with the located
// error (file:line) in its line, the summary, JUnit and the page; gouraud and phong, rendered after it
// on the same context, still match.
TEST_F(TestSuite, BrokenShaderFailsItsCasesAndTheRunGoesOn) {
    const std::string dir = makeFolder("cases");
    fs::create_directories(path("student"));
    std::string flat = slurp(kSource / "shaders" / "flat.frag");
    const std::size_t main = flat.find("void main()");
    ASSERT_NE(main, std::string::npos);
    const int line = 1 + int(std::count(flat.begin(), flat.begin() + long(main), '\n'));
    flat.insert(main, "vec3 broken = ;\n");
    std::ofstream(path("student/flat.frag")) << flat;
    const RunResult r = run({"--test", dir, "--shader-dir", path("student"), "--junit", path("junit.xml"), "--report",
                             path("report.html")});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    const std::string located = "flat.frag:" + std::to_string(line);
    const std::string prefix = "shadelab: --test " + dir + ": ";
    EXPECT_NE(r.out.find(prefix + "flat_uvsphere: error: program flat, fragment stage"), std::string::npos) << r.out;
    const std::string summary = r.out.substr(r.out.find(prefix + "3 scenes"));
    EXPECT_EQ(summary.rfind(prefix + "3 scenes, 2 match, 1 error (flat_uvsphere); shader: program flat, fragment stage", 0),
              0u)
        << summary;
    EXPECT_NE(summary.find(located), std::string::npos) << summary;
    const std::string xml = slurp(path("junit.xml"));
    EXPECT_NE(xml.find("tests=\"3\" failures=\"0\" errors=\"1\""), std::string::npos) << xml;
    EXPECT_TRUE(std::regex_search(xml, std::regex("<error type=\"shader\" message=\"[^\"]*" + located))) << xml;
    EXPECT_NE(slurp(path("report.html")).find(located), std::string::npos);
}

// --update rewrites exactly the references of the failing cases that have a render (one that differs,
// one that is missing) and says which; the matching one keeps its bytes and time; a second run matches.
TEST_F(TestSuite, UpdateRewritesExactlyTheFailingReferences) {
    const std::string dir = makeFolder("cases", "refs");
    raiseKe("cases", "phong_uvsphere");
    fs::remove(path("refs/gouraud_uvsphere.png"));
    const fs::path kept = path("refs/flat_uvsphere.png");
    const std::string keptBytes = slurp(kept);
    const auto keptTime = fs::last_write_time(kept);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));  // a rewrite would show in the time
    const RunResult r = run({"--test", dir, "--references", path("refs"), "--update"});
    EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
    const std::string prefix = "shadelab: --test " + dir + ": ";
    for (const char* name : {"gouraud_uvsphere", "phong_uvsphere"})
        EXPECT_NE(r.out.find(prefix + name + ": --update: wrote " + path(std::string("refs/") + name + ".png") +
                             " from this render\n"),
                  std::string::npos)
            << r.out;
    EXPECT_EQ(occurrences(r.out, "--update: wrote"), 2u) << r.out;
    EXPECT_EQ(slurp(kept), keptBytes);
    EXPECT_EQ(fs::last_write_time(kept), keptTime);
    // Three references and nothing else (no temporary file left behind).
    EXPECT_EQ(std::distance(fs::directory_iterator(path("refs")), fs::directory_iterator()), 3);
    const RunResult again = run({"--test", dir, "--references", path("refs")});
    EXPECT_EQ(again.exitCode, 0) << again.out;
    EXPECT_EQ(again.out, prefix + "3 scenes, 3 match\n");
    // The rewritten phong reference is the changed scene, not the golden image any more.
    EXPECT_NE(slurp(path("refs/phong_uvsphere.png")), slurp(kSource / "tests/golden/phong_uvsphere.png"));
}
