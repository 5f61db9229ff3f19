#pragma once
// Files for the viewer's GL-free tests: a fresh folder per test under VIEWER_TEST_OUT (emptied first, so
// a stale file never passes a test) and small text files written into it.
#include <filesystem>
#include <fstream>
#include <string>

namespace shadelab::test {

inline std::string outDir(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::path(VIEWER_TEST_OUT) / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir.string();
}

inline void writeText(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

}  // namespace shadelab::test
