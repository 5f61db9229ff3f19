// The bad-input suite: shadelab run on every case of tests/bad-inputs/cases.txt. For each: exit status
// 2, one line naming the file (or flag) and what is wrong, no signal, no output file, and no other file
// created, changed or removed. The inputs are copied to a scratch folder first, which is where
// shadelab runs, so "nothing else touched" is checked on the whole folder it can see.
#include "run_shadelab.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>

using namespace shadelab::test;
namespace fs = std::filesystem;

namespace {

struct Case {
    std::vector<std::string> args;
    std::string fragment;
    int line = 0;
};

std::vector<Case> readCases(const fs::path& file) {
    std::vector<Case> cases;
    std::ifstream in(file);
    std::string text;
    for (int n = 1; std::getline(in, text); ++n) {
        if (text.empty() || text[0] == '#') continue;
        const size_t tab = text.find('\t');
        if (tab == std::string::npos) throw std::runtime_error(file.string() + ":" + std::to_string(n) + ": no tab");
        Case c;
        std::istringstream words(text.substr(0, tab));
        for (std::string w; words >> w;) c.args.push_back(w);
        c.fragment = text.substr(tab + 1);
        c.line = n;
        cases.push_back(c);
    }
    return cases;
}

// Every file below `dir` with its size and contents, to tell whether a run changed anything.
std::map<std::string, std::string> snapshot(const fs::path& dir) {
    std::map<std::string, std::string> files;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        files[fs::relative(e.path(), dir).string()] = e.is_regular_file() ? slurp(e.path()) : std::string("<dir>");
    return files;
}

// The inputs too large or too binary to keep in the repository.
void makeGeneratedInputs(const fs::path& dir) {
    std::mt19937 rng(12345);
    std::string junk(4096, '\0');
    for (char& c : junk) c = char(rng() & 0xff);
    std::ofstream(dir / "junk.json", std::ios::binary) << junk;
    std::string deep, deepArray;
    for (int i = 0; i < 10000; ++i) deep += "{\"a\": ", deepArray += "[";
    deep += "1";
    deepArray += "1";
    for (int i = 0; i < 10000; ++i) deep += "}", deepArray += "]";
    std::ofstream(dir / "deep.json") << deep;
    std::ofstream(dir / "deep_array.json") << deepArray;
}

}  // namespace

TEST(BadInputs, EveryCaseExitsTwoWithOneLineAndTouchesNothing) {
    const fs::path source = fs::path(SHADELAB_SOURCE_DIR) / "tests" / "bad-inputs";
    const fs::path scratch = fs::path(SHADELAB_TEST_OUTPUT_DIR) / "bad-inputs";
    const fs::path capture = fs::path(SHADELAB_TEST_OUTPUT_DIR) / "bad-inputs-capture";
    fs::remove_all(scratch);
    fs::remove_all(capture);
    fs::create_directories(capture);
    fs::create_directories(scratch / "inputs");
    fs::copy(source, scratch / "inputs", fs::copy_options::recursive);
    makeGeneratedInputs(scratch / "inputs");
    fs::create_directories(scratch / "inputs" / "a_folder.png");
    const std::vector<Case> cases = readCases(source / "cases.txt");
    ASSERT_GE(cases.size(), 30u);

    // The output path is always inside the scratch folder; the output-path cases name their own.
    std::vector<Case> all = cases;
    all.push_back({{"--output", "no/such/folder/out.png"}, "the folder no/such/folder does not exist", 0});
    all.push_back({{"--output", "a_folder.png"}, "a_folder.png is a directory", 0});
    for (const Case& c : all) {
        std::vector<std::string> args;
        for (const std::string& a : c.args) args.push_back(a[0] == '@' ? a.substr(1) : a);
        const bool ownOutput = std::find(args.begin(), args.end(), "--output") != args.end();
        if (!ownOutput) args.insert(args.end(), {"--output", "out.png"});
        SCOPED_TRACE("cases.txt:" + std::to_string(c.line) + ": " + args.front());
        const auto before = snapshot(scratch);
        const RunResult r = runShadelab(args, scratch / "inputs", capture);
        EXPECT_FALSE(r.signaled) << "died of a signal: " << r.err;
        EXPECT_EQ(r.exitCode, 2) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "not one line:\n" << r.err;
        EXPECT_EQ(r.err.rfind("shadelab: ", 0), 0u) << r.err;
        EXPECT_NE(r.err.find(c.fragment), std::string::npos) << "expected \"" << c.fragment << "\" in: " << r.err;
        EXPECT_TRUE(r.out.empty()) << r.out;
        EXPECT_FALSE(fs::exists(scratch / "inputs" / "out.png"));
        EXPECT_EQ(snapshot(scratch), before) << "a file was created, changed or removed";
    }
}
