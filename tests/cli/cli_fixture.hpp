#pragma once
// The fixture of the tests that run the shadelab executable (cli_test.cpp, reference_test.cpp): a folder
// of its own per test under build/tests/output/cli/, and shadelab run there with no display.
#include "cli/run_shadelab.hpp"
#include "core/image/image.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace shadelab::test {

class Cli : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = std::filesystem::path(SHADELAB_TEST_OUTPUT_DIR) / "cli" / ::testing::UnitTest::GetInstance()->current_test_info()->name();
        std::filesystem::remove_all(dir_);
        std::filesystem::create_directories(dir_);
    }
    // Runs shadelab with no display (DISPLAY and WAYLAND_DISPLAY unset), as CI does.
    RunResult run(const std::vector<std::string>& args, const std::vector<std::string>& env = {}) const {
        return test::runShadelab(args, std::filesystem::current_path(), dir_, env);
    }
    std::string file(const std::string& name, const std::string& contents) const {
        std::ofstream(dir_ / name) << contents;
        return (dir_ / name).string();
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    // Runs `args` plus --output NAME and reads the PNG it wrote (an empty image if it failed).
    Image runToPng(std::vector<std::string> args, const std::string& name) const {
        args.insert(args.end(), {"--output", path(name)});
        const RunResult r = run(args);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return r.exitCode == 0 ? readPng(path(name)) : Image();
    }
    std::filesystem::path dir_;
};

}  // namespace shadelab::test
