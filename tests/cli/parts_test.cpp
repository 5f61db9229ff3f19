// The shadelab program with whatever parts this build has (CMake options SHADELAB_VIEWER, SHADELAB_OSMESA,
// SHADELAB_EGL): what needs no GL works in every build; a part the build has not got is refused with one
// line that names it and exit status 2, nothing written; a part it has works. Built and run in every
// configuration (CI: the full build, "core + EGL only" and "core only").
#include "cli/run_shadelab.hpp"
#include "core/image/image.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

using namespace shadelab;
namespace fs = std::filesystem;

namespace {

class Parts : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::path(SHADELAB_TEST_OUTPUT_DIR) / "parts" / ::testing::UnitTest::GetInstance()->current_test_info()->name();
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    test::RunResult run(const std::vector<std::string>& args) const {
        return test::runShadelab(args, fs::current_path(), dir_);
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    fs::path dir_;
};

// One line on stderr, exit status 2, naming `what`; the file the run was asked for is not there.
void expectRefused(const test::RunResult& r, const std::string& what, const std::string& file) {
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(what), std::string::npos) << r.err;
    if (!file.empty()) {
        EXPECT_FALSE(fs::exists(file)) << file;
    }
}

}  // namespace

TEST_F(Parts, NoGlNeededForHelpVersionPlotAndInfo) {
    const test::RunResult version = run({"--version"});
    EXPECT_EQ(version.exitCode, 0) << version.err;
    EXPECT_EQ(version.out.rfind("shadelab ", 0), 0u) << version.out;
    const test::RunResult help = run({"--help"});
    EXPECT_EQ(help.exitCode, 0) << help.err;
    EXPECT_NE(help.out.find("--output"), std::string::npos);
    const test::RunResult plot = run({"--plot", "lobe", "--output", path("lobe.png")});
    ASSERT_EQ(plot.exitCode, 0) << plot.err;
    EXPECT_GT(readPng(path("lobe.png")).width, 0);
    const test::RunResult info = run({"--info"});
    EXPECT_EQ(info.exitCode, 0) << info.err;
    EXPECT_NE(info.out.find("triangles"), std::string::npos) << info.out;
}

TEST_F(Parts, OutputRendersOrSaysWhichPartIsMissing) {
    const test::RunResult r = run({"--size", "48x32", "--output", path("frame.png")});
    if (SHADELAB_HAVE_OSMESA || SHADELAB_HAVE_EGL) {
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const Image image = readPng(path("frame.png"));
        EXPECT_EQ(image.width, 48);
        EXPECT_EQ(image.height, 32);
    } else {
        expectRefused(r, "--output: this shadelab was built without a headless GL context", path("frame.png"));
        expectRefused(run({"--benchmark", "1"}), "--benchmark: this shadelab was built without", "");
        expectRefused(run({"--test", dir_.string(), "--junit", path("junit.xml")}), "--test: this shadelab was built without",
                      path("junit.xml"));
    }
}

TEST_F(Parts, EachBackendWorksOrIsRefusedByName) {
    for (const char* backend : {"osmesa", "egl"}) {
        const bool built = std::string(backend) == "osmesa" ? SHADELAB_HAVE_OSMESA : SHADELAB_HAVE_EGL;
        const std::string file = path(std::string(backend) + ".png");
        const test::RunResult r = run({"--backend", backend, "--size", "16x16", "--output", file});
        if (built) {
            EXPECT_EQ(r.exitCode, 0) << backend << ": " << r.err;
        } else if (SHADELAB_HAVE_OSMESA || SHADELAB_HAVE_EGL) {
            expectRefused(r, std::string("--backend ") + backend + ": this shadelab was built without", file);
        } else {
            expectRefused(r, "without a headless GL context", file);
        }
    }
}

// Without the viewer, a run that would open a window says so (with a display or without one).
// A video needs a headless context and video encoding (SHADELAB_VIDEO): either it is written, or one
// line names the part that is missing and no file is left.
TEST_F(Parts, VideoIsWrittenOrTheMissingPartNamed) {
    const test::RunResult r =
        run({"--size", "16x16", "--animate", "ke=1..2:0.1", "--fps", "10", "--output", path("ramp.gif")});
    if (SHADELAB_HAVE_VIDEO) {
        EXPECT_EQ(r.exitCode, 0) << r.err;
        EXPECT_TRUE(fs::exists(path("ramp.gif")));
    } else if (SHADELAB_HAVE_OSMESA || SHADELAB_HAVE_EGL) {
        expectRefused(r, "this shadelab was built without video encoding (CMake option SHADELAB_VIDEO", path("ramp.gif"));
    } else {
        expectRefused(r, "--output: this shadelab was built without a headless GL context", path("ramp.gif"));
    }
}

TEST_F(Parts, ViewerOrItsAbsenceNamed) {
    if (SHADELAB_HAVE_VIEWER) GTEST_SKIP() << "this build has the viewer (tests/viewer runs it)";
    expectRefused(run({"--frames", "1"}), "this shadelab was built without the viewer", "");
}
