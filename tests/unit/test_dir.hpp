#pragma once
// A fresh folder for one test, removed when it ends: one per test and process, as CTest runs the tests
// of a file in parallel processes and the temporary folder is shared with other users of the machine.
#include "platform/platform.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace shadelab::test {

struct TestDir {
    std::filesystem::path path;
    // "<temp>/shadelab-<kind>-test-<test name>-<process id>"
    explicit TestDir(const std::string& kind)
        : path(std::filesystem::temp_directory_path() /
               ("shadelab-" + kind + "-test-" + ::testing::UnitTest::GetInstance()->current_test_info()->name() + "-" +
                std::to_string(platform::processId()))) {
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~TestDir() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
    TestDir(const TestDir&) = delete;
    TestDir& operator=(const TestDir&) = delete;
};

}  // namespace shadelab::test
