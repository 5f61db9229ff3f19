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
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <regex>
#include <string>
#include <thread>
#include <vector>

using namespace shadelab;
namespace fs = std::filesystem;

using test::Cli;
using test::RunResult;
using test::runShadelab;
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
    // `name` in this test's folder as the reports give it: relative to the folder shadelab runs in.
    std::string shown(const std::string& name) const {
        return (dir_ / name).lexically_relative(fs::current_path()).generic_string();
    }
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
    // The page's difference is scaled so the largest is at full brightness: x 255/max.
    const RunResult one = run({path("cases/phong_uvsphere.json"), "--output", path("actual.png"), "--reference",
                               path("cases/phong_uvsphere.png")});
    ASSERT_EQ(one.exitCode, 1) << one.out << one.err;
    std::smatch largest;
    ASSERT_TRUE(std::regex_search(one.out, largest, std::regex("max (\\d+)/255"))) << one.out;
    char factor[32];
    std::snprintf(factor, sizeof factor, "%.9g", double(255.0f / float(std::stoi(largest[1]))));
    ASSERT_EQ(run({path("cases/phong_uvsphere.json"), "--output", path("actual.png"), "--reference",
                   path("cases/phong_uvsphere.png"), "--diff-output", path("diff.png"), "--diff-factor", factor})
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
    EXPECT_NE(r.out.find(prefix + "broken: error: " + shown("cases/broken.json") + ": malformed JSON"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find(prefix + "flat_uvsphere: error: the reference: " + shown("refs/flat_uvsphere.png") +
                         ": cannot read PNG"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find(prefix + "gouraud_uvsphere: error: the reference " + shown("refs/gouraud_uvsphere.png") +
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
        EXPECT_NE(r.out.find(prefix + name + ": --update: wrote " + shown(std::string("refs/") + name + ".png") +
                             " from this render\n"),
                  std::string::npos)
            << r.out;
    EXPECT_EQ(occurrences(r.out, "--update: wrote"), 2u) << r.out;
    // Issue 32: the summary says what was written, not "errors", with exit status 0.
    EXPECT_NE(r.out.find(prefix + "3 scenes, 1 match, 2 written (gouraud_uvsphere, phong_uvsphere)\n"), std::string::npos)
        << r.out;
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

// ---- Issue 32: what a CI maintainer hit on a first try, and sharding, artifacts, per-scene settings.

namespace {

// xmllint --schema against the constraints of Jenkins xunit's junit-10.xsd (tests/cli/junit-xunit.xsd):
// "" when `xml` is valid, else what xmllint said.
std::string schemaErrors(const std::string& xmlPath, const std::string& logPath) {
    const std::string command = "xmllint --noout --schema '" + (kSource / "tests/cli/junit-xunit.xsd").string() + "' '" +
                                xmlPath + "' >'" + logPath + "' 2>&1";
    return std::system(command.c_str()) == 0 ? "" : slurp(logPath) + "";
}

bool haveXmllint() { return std::system("command -v xmllint >/dev/null 2>&1") == 0; }

// The JUnit testcases' names, in order.
std::vector<std::string> junitCases(const std::string& xml) {
    std::vector<std::string> names;
    const std::regex testcase("<testcase [^>]*name=\"([^\"]*)\"");
    for (auto it = std::sregex_iterator(xml.begin(), xml.end(), testcase); it != std::sregex_iterator(); ++it)
        names.push_back((*it)[1]);
    return names;
}

// A shared library of this process that is no GL library (zlib or libpng: the PNG code's), for a folder
// that holds it under GL's names; empty where /proc/self/maps does not tell.
std::string someOtherLibrary() {
    std::ifstream maps("/proc/self/maps");
    for (std::string line; std::getline(maps, line);) {
        const std::size_t at = line.find('/');
        if (at == std::string::npos) continue;
        const std::string file = line.substr(at);
        const std::string name = fs::path(file).filename().string();
        if (name.rfind("libz.so", 0) == 0 || name.rfind("libpng", 0) == 0) return file;
    }
    return "";
}

}  // namespace

// Defect 1: OpenGL cannot start (its libraries broken: libOSMesa.so.8 and libEGL.so.1 found first are a
// library of another kind, so the real dlopen and symbol lookup fail): exit status 2 (the run cannot
// start, not "pixels differ"), one line on stderr, and the --junit file written with one error saying
// why, valid against the schema.
TEST_F(TestSuite, OpenGlThatCannotStartIsStatusTwoWithJunit) {
    const std::string library = someOtherLibrary();
    if (library.empty()) GTEST_SKIP() << "no shared library found in /proc/self/maps";
    fs::create_directories(path("brokengl"));
    for (const char* name : {"libOSMesa.so.8", "libEGL.so.1"}) fs::copy_file(library, path("brokengl") + "/" + name);
    const std::string dir = makeFolder("cases");
    const RunResult r = run({"--test", dir, "--junit", path("junit.xml"), "--report", path("report.html")},
                            {"LD_LIBRARY_PATH=" + path("brokengl")});
    EXPECT_EQ(r.exitCode, 2) << r.out << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_EQ(occurrences(r.err, "\n"), 1u) << r.err;
    EXPECT_EQ(r.err.rfind("shadelab: --test " + dir + ": OpenGL cannot start: ", 0), 0u) << r.err;
    const std::string xml = slurp(path("junit.xml"));
    EXPECT_NE(xml.find("tests=\"1\" failures=\"0\" errors=\"1\""), std::string::npos) << xml;
    EXPECT_NE(xml.find("<error type=\"gl\" message=\"OpenGL cannot start: "), std::string::npos) << xml;
    EXPECT_NE(slurp(path("report.html")).find("OpenGL cannot start"), std::string::npos);
    if (haveXmllint()) {
        EXPECT_EQ(schemaErrors(path("junit.xml"), path("xmllint.log")), "");
    }
}

// Defect 2: one scene over the memory budget errors alone; the others render and match.
TEST_F(TestSuite, OneSceneOverTheBudgetErrorsAlone) {
    const std::string dir = makeFolder("cases");
    std::ofstream(path("cases/huge.json")) << R"({"size": [8192, 8192]})";
    const RunResult r = run({"--test", dir, "--max-memory", "600M"});
    EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
    const std::string prefix = "shadelab: --test " + dir + ": ";
    EXPECT_NE(r.out.find(prefix + "huge: error: " + shown("cases/huge.json") + ": a 8192x8192 frame"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find(prefix + "4 scenes, 3 match, 1 error (huge)\n"), std::string::npos) << r.out;
}

// Defect 3: the JUnit validates against Jenkins xunit's schema (no testcase@file), for matching, failing
// and broken cases and --update; GitLab's parts (classname, name, time, failure, system-out) are there.
TEST_F(TestSuite, JunitIsValidAgainstTheXunitSchema) {
    if (!haveXmllint()) GTEST_SKIP() << "xmllint is not installed (Debian package libxml2-utils)";
    const std::string dir = makeFolder("cases", "refs");
    raiseKe("cases", "phong_uvsphere");
    fs::remove(path("refs/gouraud_uvsphere.png"));
    std::ofstream(path("cases/broken.json")) << "{\"mesh\": <&>";
    ASSERT_EQ(run({"--test", dir, "--references", path("refs"), "--junit", path("junit.xml"), "--artifacts",
                   path("artifacts")})
                  .exitCode,
              1);
    const std::string xml = slurp(path("junit.xml"));
    EXPECT_EQ(xml.find(" file="), std::string::npos) << xml;
    EXPECT_NE(xml.find("<system-out>"), std::string::npos) << xml;
    EXPECT_EQ(schemaErrors(path("junit.xml"), path("xmllint.log")), "") << xml;
    ASSERT_EQ(run({"--test", dir, "--references", path("refs"), "--junit", path("update.xml"), "--update"}).exitCode, 1);
    EXPECT_EQ(schemaErrors(path("update.xml"), path("xmllint.log")), "");
    // The schema does refuse what it should: the old testcase@file.
    std::string old = xml;
    old.insert(old.find("<testcase ") + 10, "file=\"cases/flat_uvsphere.json\" ");
    std::ofstream(path("old.xml")) << old;
    EXPECT_NE(schemaErrors(path("old.xml"), path("xmllint.log")), "");
}

// Defect 5: a failure of the mean alone (a 1/255 change) has a visible difference image: scaled so the
// largest difference is at full brightness, and the page says by how much.
TEST_F(TestSuite, DifferenceIsScaledToBeVisible) {
    const std::string dir = makeFolder("cases");
    raiseKe("cases", "phong_uvsphere");
    const RunResult r = run({"--test", dir, "--report", path("report.html"), "--artifacts", path("art")});
    ASSERT_EQ(r.exitCode, 1) << r.out << r.err;
    std::smatch largest;
    ASSERT_TRUE(std::regex_search(r.out, largest, std::regex("max (\\d+)/255"))) << r.out;
    const Image diff = readPng(path("art/phong_uvsphere.diff.png"));
    int brightest = 0;
    for (std::size_t i = 0; i < diff.rgba.size(); i += 4)
        brightest = std::max({brightest, int(diff.rgba[i]), int(diff.rgba[i + 1]), int(diff.rgba[i + 2])});
    EXPECT_EQ(brightest, 255);  // x4 of 1 or 2 /255 was black to the eye
    char caption[64];
    std::snprintf(caption, sizeof caption, "x %.4g (the largest, %s/255, at full)",
                  double(255.0f / float(std::stoi(largest[1]))), largest[1].str().c_str());
    EXPECT_NE(slurp(path("report.html")).find(caption), std::string::npos) << caption;
}

// Defect 7: --references NEWDIR --update makes the folder; report paths are relative to where shadelab
// ran; the suite's time is the sum of its cases'; scenes in subfolders are cases named by their path,
// and a reference with no scene is warned about.
TEST_F(TestSuite, SubfoldersNewReferencesRelativePathsAndTimes) {
    makeFolder("cases");
    fs::create_directories(path("cases/more"));
    fs::rename(path("cases/gouraud_uvsphere.json"), path("cases/more/gouraud_uvsphere.json"));
    fs::copy_file(path("cases/gouraud_uvsphere.png"), path("cases/orphan.png"));
    const RunResult made =
        runShadelab({"--test", path("cases"), "--references", path("new/refs"), "--update"}, dir_, dir_);
    EXPECT_EQ(made.exitCode, 0) << made.out << made.err;
    EXPECT_TRUE(fs::exists(path("new/refs/more/gouraud_uvsphere.png")));
    EXPECT_TRUE(fs::exists(path("new/refs/flat_uvsphere.png")));
    // Run from the test's folder with the absolute folder name: the reports say cases/..., refs/...
    const RunResult r = runShadelab({"--test", path("cases"), "--junit", path("junit.xml")}, dir_, dir_);
    EXPECT_EQ(r.exitCode, 1) << r.out << r.err;  // more/gouraud_uvsphere has no reference beside it
    EXPECT_NE(r.out.find(": more/gouraud_uvsphere: error: the reference cases/more/gouraud_uvsphere.png does not exist"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.err.find("shadelab: warning: --test " + path("cases") + ": 2 references have no scene in " +
                         path("cases") + ": gouraud_uvsphere.png, orphan.png"),
              std::string::npos)
        << r.err;
    const std::string xml = slurp(path("junit.xml"));
    EXPECT_EQ(junitCases(xml), (std::vector<std::string>{"flat_uvsphere", "more/gouraud_uvsphere", "phong_uvsphere"}));
    EXPECT_NE(xml.find("scene cases/more/gouraud_uvsphere.json\nreference cases/more/gouraud_uvsphere.png"),
              std::string::npos)
        << xml;
    EXPECT_EQ(xml.find(dir_.string()), std::string::npos) << xml;
    double sum = 0, suite = -1;
    const std::regex caseTime("<testcase [^>]* time=\"([0-9.]+)\""), suiteTime("<testsuite [^>]* time=\"([0-9.]+)\"");
    for (auto it = std::sregex_iterator(xml.begin(), xml.end(), caseTime); it != std::sregex_iterator(); ++it)
        sum += std::stod((*it)[1]);
    std::smatch m;
    if (std::regex_search(xml, m, suiteTime)) suite = std::stod(m[1]);
    EXPECT_NEAR(suite, sum, 0.0025) << xml;  // each printed to the millisecond
}

// --artifacts: a failing case's render, difference and reference (the file itself) in DIR, linked from
// its testcase as GitLab's [[ATTACHMENT|...]] in system-out; a matching case writes nothing there.
TEST_F(TestSuite, ArtifactsOfTheFailingCases) {
    makeFolder("cases");
    raiseKe("cases", "phong_uvsphere");
    const RunResult r = runShadelab({"--test", "cases", "--artifacts", "art", "--junit", "junit.xml"}, dir_, dir_);
    EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
    std::vector<std::string> files;
    for (const auto& e : fs::directory_iterator(path("art"))) files.push_back(e.path().filename().string());
    std::sort(files.begin(), files.end());
    EXPECT_EQ(files, (std::vector<std::string>{"phong_uvsphere.actual.png", "phong_uvsphere.diff.png",
                                               "phong_uvsphere.reference.png"}));
    EXPECT_EQ(slurp(path("art/phong_uvsphere.reference.png")), slurp(path("cases/phong_uvsphere.png")));
    const Image actual = readPng(path("art/phong_uvsphere.actual.png"));
    EXPECT_EQ(actual.width, 128);
    const std::string xml = slurp(path("junit.xml"));
    EXPECT_NE(xml.find("[[ATTACHMENT|art/phong_uvsphere.diff.png]]\n[[ATTACHMENT|art/phong_uvsphere.actual.png]]\n"
                       "[[ATTACHMENT|art/phong_uvsphere.reference.png]]</system-out>"),
              std::string::npos)
        << xml;
}

// --list, --filter and --shard: shards 1..N of a folder take every case exactly once (by name: the
// other cases do not move when one is added), each with its own JUnit, and pass.
TEST_F(TestSuite, ShardsRunEveryCaseOnce) {
    const std::string dir = makeFolder("cases");
    for (const char* extra : {"phong_reflection", "diff_icosphere"}) {
        fs::copy_file(kSource / "tests/scenes" / (std::string(extra) + ".json"), path("cases/") + extra + ".json");
        fs::copy_file(kSource / "tests/golden" / (std::string(extra) + ".png"), path("cases/") + extra + ".png");
    }
    const RunResult all = run({"--test", dir, "--list"});
    ASSERT_EQ(all.exitCode, 0) << all.err;
    EXPECT_EQ(all.out, "diff_icosphere\nflat_uvsphere\ngouraud_uvsphere\nphong_reflection\nphong_uvsphere\n");
    EXPECT_EQ(run({"--test", dir, "--list", "--filter", "phong_*", "--filter", "?iff*"}).out,
              "diff_icosphere\nphong_reflection\nphong_uvsphere\n");
    std::multiset<std::string> listed, ran;
    std::map<std::string, int> shardOf;
    for (int k = 1; k <= 3; ++k) {
        const std::string shard = std::to_string(k) + "/3";
        const RunResult list = run({"--test", dir, "--list", "--shard", shard});
        std::istringstream names(list.out);
        for (std::string n; std::getline(names, n);) listed.insert(n), shardOf[n] = k;
        const std::string junit = path("shard" + std::to_string(k) + ".xml");
        const RunResult r = run({"--test", dir, "--shard", shard, "--junit", junit});
        EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
        EXPECT_NE(r.out.find("(shard " + shard + ")"), std::string::npos) << r.out;
        for (const std::string& n : junitCases(slurp(junit))) ran.insert(n);
        if (haveXmllint()) {
            EXPECT_EQ(schemaErrors(junit, path("xmllint.log")), "");
        }
    }
    const std::multiset<std::string> expected = {"diff_icosphere", "flat_uvsphere", "gouraud_uvsphere",
                                                 "phong_reflection", "phong_uvsphere"};
    EXPECT_EQ(listed, expected);
    EXPECT_EQ(ran, expected);
    // A new case moves no other.
    fs::copy_file(path("cases/flat_uvsphere.json"), path("cases/aaa_new.json"));
    for (int k = 1; k <= 3; ++k) {
        std::istringstream names(run({"--test", dir, "--list", "--shard", std::to_string(k) + "/3"}).out);
        for (std::string n; std::getline(names, n);) {
            if (n != "aaa_new") {
                EXPECT_EQ(shardOf[n], k) << n;
            }
        }
    }
}

// A scene's own "test" settings: thresholds over the command line's, masks left out of the comparison
// (hatched in the difference), max_diff_pixels; unknown keys refused (a case error here; exit 2 alone,
// tests/bad-inputs/cases.txt).
TEST_F(TestSuite, PerSceneThresholdsAndMasks) {
    const std::string dir = makeFolder("cases");
    raiseKe("cases", "phong_uvsphere");
    // (`with` in place of `was` in `text`)
    const auto replaced = [](std::string text, const std::string& was, const std::string& with) {
        return text.replace(text.find(was), was.size(), with);
    };
    const auto withTest = [this](const std::string& name, const std::string& test) {
        const fs::path scene = dir_ / "cases" / (name + ".json");
        std::string text = slurp(scene);
        text.insert(text.find('{') + 1, "\n  \"test\": " + test + ",");
        std::ofstream(scene) << text;
    };
    // Looser limits for the changed scene: it matches; the others keep the defaults.
    withTest("phong_uvsphere", R"({"max_diff": 8, "mean_diff": 1})");
    RunResult r = run({"--test", dir});
    EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
    // A pixel count: the changed highlight is more pixels than allowed.
    std::string phong = replaced(slurp(path("cases/phong_uvsphere.json")), R"({"max_diff": 8, "mean_diff": 1})",
                                 R"({"mean_diff": 255, "max_diff_pixels": 10})");
    std::ofstream(path("cases/phong_uvsphere.json")) << phong;
    r = run({"--test", dir});
    EXPECT_EQ(r.exitCode, 1) << r.out;
    EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(phong_uvsphere: differs: max \d+/255 \(limit 4\), mean [0-9.e+-]+ \(limit 255\), \d+ pixels differ \(limit 10\))")))
        << r.out;
    // The whole image masked, as two halves: nothing is compared, it matches.
    phong = replaced(phong, R"({"mean_diff": 255, "max_diff_pixels": 10})", R"({"masks": [[0, 0, 64, 128], [64, 0, 64, 128]]})");
    std::ofstream(path("cases/phong_uvsphere.json")) << phong;
    r = run({"--test", dir});
    EXPECT_EQ(r.exitCode, 0) << r.out;
    // A strip of background masked: it still differs, and its difference is hatched over the strip.
    phong = replaced(phong, "[[0, 0, 64, 128], [64, 0, 64, 128]]", "[[0, 0, 16, 128]]");
    std::ofstream(path("cases/phong_uvsphere.json")) << phong;
    r = run({"--test", dir, "--artifacts", path("art")});
    EXPECT_EQ(r.exitCode, 1) << r.out;
    const Image diff = readPng(path("art/phong_uvsphere.diff.png"));
    ASSERT_EQ(diff.width, 128);
    int hatched = 0;
    for (int y = 0; y < 128; ++y)
        for (int x = 0; x < 16; ++x) hatched += diff.pixel(x, y)[0] == 128 && diff.pixel(x, y)[1] == 128;
    EXPECT_EQ(hatched, 6 * 128);  // 3 pixels of every 8 along each row
    // An unknown key: that case is an error, the others run.
    std::ofstream(path("cases/gouraud_uvsphere.json")) << "{\"test\": {\"max_pixels\": 3}}";
    r = run({"--test", dir});
    EXPECT_NE(r.out.find("gouraud_uvsphere: error: " + shown("cases/gouraud_uvsphere.json") +
                         ": test.max_pixels: unknown field"),
              std::string::npos)
        << r.out;
}
