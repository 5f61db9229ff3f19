// The platform layer (app/platform): atomic writes, opening by path, local time, memory and process id.
// The same tests run on Linux (./dev test) and on Windows under wine (./dev test-windows), each
// against its own implementation. Signals during a write are tested on the executable (tests/cli).
#include "platform/platform.hpp"
#include "test_dir.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

#ifndef _WIN32
#include <sys/stat.h>
#endif

using namespace shadelab;
namespace fs = std::filesystem;

namespace {

struct TempDir : test::TestDir {
    TempDir() : TestDir("platform") {}
    std::vector<std::string> names() const {
        std::vector<std::string> out;
        for (const auto& e : fs::directory_iterator(path)) out.push_back(e.path().filename().u8string());
        return out;
    }
};

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

std::function<bool(std::FILE*)> writes(const std::string& text) {
    return [text](std::FILE* f) { return std::fwrite(text.data(), 1, text.size(), f) == text.size(); };
}

}  // namespace

TEST(Platform, AtomicWriteCreatesThenReplacesAWholeFile) {
    TempDir dir;
    const fs::path file = dir.path / "out.txt";
    EXPECT_EQ(platform::writeFileAtomic(file, writes("first")), "");
    EXPECT_EQ(slurp(file), "first");
    EXPECT_EQ(platform::writeFileAtomic(file, writes("second, longer")), "");
    EXPECT_EQ(slurp(file), "second, longer");
    EXPECT_EQ(dir.names(), std::vector<std::string>{"out.txt"}) << "no temporary left beside it";
}

TEST(Platform, AFailedWriteKeepsTheOldFileAndLeavesNoTemporary) {
    TempDir dir;
    const fs::path file = dir.path / "keep.txt";
    ASSERT_EQ(platform::writeFileAtomic(file, writes("old")), "");
    const std::string failed = platform::writeFileAtomic(file, [](std::FILE* f) {
        std::fputs("partial", f);
        return false;
    });
    EXPECT_FALSE(failed.empty());
    EXPECT_THROW(platform::writeFileAtomic(file, [](std::FILE* f) -> bool {
                     std::fputs("partial", f);
                     throw std::runtime_error("stopped");
                 }),
                 std::runtime_error);
    EXPECT_EQ(slurp(file), "old");
    EXPECT_EQ(dir.names(), std::vector<std::string>{"keep.txt"});
}

TEST(Platform, AWriteIntoAMissingFolderSaysWhyAndCreatesNothing) {
    TempDir dir;
    const std::string why = platform::writeFileAtomic(dir.path / "missing" / "x.txt", writes("x"));
    EXPECT_FALSE(why.empty());
    EXPECT_EQ(why.find('\n'), std::string::npos) << why;
    EXPECT_TRUE(dir.names().empty());
}

// Names outside ASCII: Windows opens through the path's wide name (_wfopen, MoveFileExW).
TEST(Platform, OpensAndWritesNamesOutsideAscii) {
    TempDir dir;
    const fs::path written = dir.path / fs::u8path("caf\xc3\xa9-\xce\xbb.txt");
    ASSERT_EQ(platform::writeFileAtomic(written, writes("\xce\xbb")), "");
    std::FILE* f = platform::openFile(written, "rb");
    ASSERT_NE(f, nullptr);
    char text[8] = {};
    EXPECT_EQ(std::fread(text, 1, sizeof text, f), 2u);
    std::fclose(f);
    EXPECT_EQ(std::string(text), "\xce\xbb");
    EXPECT_EQ(dir.names(), std::vector<std::string>{"caf\xc3\xa9-\xce\xbb.txt"});
    EXPECT_EQ(platform::openFile(dir.path / "absent.txt", "rb"), nullptr);
}

#ifndef _WIN32
// A new output file has the usual permissions, 0666 less the umask, on both of Linux's ways to write
// it: unnamed (O_TMPFILE, linked in) and named (mkstemp's 0600, then chmod).
TEST(Platform, NewFilesGetTheUsualPermissions) {
    TempDir dir;
    const mode_t before = ::umask(027);
    for (const bool named : {false, true}) {
        if (named) ::setenv("SHADELAB_NO_TMPFILE", "1", 1);
        const fs::path file = dir.path / (named ? "named.txt" : "unnamed.txt");
        EXPECT_EQ(platform::writeFileAtomic(file, writes("x")), "");
        EXPECT_EQ(fs::status(file).permissions(), fs::perms(0640)) << file;
        // Replacing an existing file goes through a temporary name and a rename: same permissions.
        EXPECT_EQ(platform::writeFileAtomic(file, writes("y")), "");
        EXPECT_EQ(fs::status(file).permissions(), fs::perms(0640)) << file;
    }
    ::unsetenv("SHADELAB_NO_TMPFILE");
    ::umask(before);
    EXPECT_EQ(dir.names().size(), 2u);
}
#endif

TEST(Platform, LocalTimeIsTheCLibrarysLocalTime) {
    for (const std::time_t t : {std::time_t(0), std::time_t(1'700'000'000), std::time(nullptr)}) {
        const std::tm ours = platform::localTime(t);
        const std::tm theirs = *std::localtime(&t);  // the C library's, not thread-safe: fine in a test
        EXPECT_EQ(ours.tm_year, theirs.tm_year);
        EXPECT_EQ(ours.tm_yday, theirs.tm_yday);
        EXPECT_EQ(ours.tm_hour, theirs.tm_hour);
        EXPECT_EQ(ours.tm_min, theirs.tm_min);
        EXPECT_EQ(ours.tm_sec, theirs.tm_sec);
    }
}

TEST(Platform, MachineFacts) {
    EXPECT_GT(platform::physicalMemoryBytes(), std::uint64_t(256) << 20);
    EXPECT_GT(platform::processId(), 0);
}
