#include "run_shadelab.hpp"

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace shadelab::test {
namespace {
std::string quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}
}  // namespace

std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

RunResult runShadelab(const std::vector<std::string>& args, const std::filesystem::path& cwd,
                      const std::filesystem::path& captureDir, const std::vector<std::string>& env) {
    return runProgram(SHADELAB_EXE, args, cwd, captureDir, env);
}

RunResult runProgram(const std::filesystem::path& program, const std::vector<std::string>& args, const std::filesystem::path& cwd,
                     const std::filesystem::path& captureDir, const std::vector<std::string>& env) {
    std::string cmd = "cd " + quote(cwd.string()) + " && env -u DISPLAY -u WAYLAND_DISPLAY";
    for (const auto& e : env) cmd += " " + quote(e);
    cmd += " " + quote(program.string());
    for (const auto& a : args) cmd += " " + quote(a);
    cmd += " >" + quote((captureDir / "stdout").string()) + " 2>" + quote((captureDir / "stderr").string());
    const int status = std::system(cmd.c_str());
    RunResult r;
    // sh reports a child killed by signal N as exit status 128 + N.
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.signaled = WIFSIGNALED(status) || r.exitCode > 128;
    r.out = slurp(captureDir / "stdout");
    r.err = slurp(captureDir / "stderr");
    return r;
}

}  // namespace shadelab::test
