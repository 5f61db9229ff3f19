#pragma once
// Runs the shadelab executable as a user would, with no display, and captures what it said.
#include <filesystem>
#include <string>
#include <vector>

namespace shadelab::test {

struct RunResult {
    int exitCode = -1;   // 128 + signal number if it died of a signal
    bool signaled = false;
    std::string out, err;
};

// Runs SHADELAB_EXE with `args` in folder `cwd`, DISPLAY and WAYLAND_DISPLAY unset (as in CI);
// stdout and stderr are captured through files in `captureDir`. `env`: more NAME=VALUE settings.
RunResult runShadelab(const std::vector<std::string>& args, const std::filesystem::path& cwd,
                      const std::filesystem::path& captureDir, const std::vector<std::string>& env = {});
// The same for another copy of the program, at `program`.
RunResult runProgram(const std::filesystem::path& program, const std::vector<std::string>& args, const std::filesystem::path& cwd,
                     const std::filesystem::path& captureDir, const std::vector<std::string>& env = {});

std::string slurp(const std::filesystem::path& p);

}  // namespace shadelab::test
