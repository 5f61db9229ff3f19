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

    // A valid one-triangle model whose extras nest 20,000 deep (a stack overflow in a recursive dump).
    std::string extras;
    for (int i = 0; i < 20000; ++i) extras += "{\"a\": ";
    extras += "1";
    for (int i = 0; i < 20000; ++i) extras += "}";
    const std::string deepModel =
        "{\"asset\": {\"version\": \"2.0\"}, \"extras\": " + extras +
        ", \"buffers\": [{\"byteLength\": 36, \"uri\": \"data:application/octet-stream;base64,"
        "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA\"}]}";
    std::ofstream(dir / "deep_extras.gltf") << deepModel;
    // The same JSON in a .glb (no BIN chunk): 12-byte header, then the JSON chunk padded to 4 bytes.
    std::string json = deepModel;
    while (json.size() % 4) json += ' ';
    const auto u32 = [](std::uint32_t v) {
        return std::string{char(v & 0xff), char(v >> 8 & 0xff), char(v >> 16 & 0xff), char(v >> 24 & 0xff)};
    };
    std::ofstream(dir / "deep_extras.glb", std::ios::binary)
        << "glTF" << u32(2) << u32(std::uint32_t(20 + json.size())) << u32(std::uint32_t(json.size())) << "JSON" << json;

    // Inputs that used to be echoed whole into the message: a 5 MB data: URI, an 8 MB number.
    std::ofstream(dir / "big_data_uri.gltf")
        << "{\"asset\": {\"version\": \"2.0\"}, \"buffers\": [{\"byteLength\": 3, "
           "\"uri\": \"data:application/octet-stream;base64,"
        << std::string(5'000'000, '!') << "\"}]}";
    std::ofstream(dir / "big_number.json") << "{\"material\": {\"ka\": " << std::string(8'000'000, '7') << "x}}";

    // 256 objects of the largest UV sphere: ~2 billion triangles asked for in 11 kB.
    std::string objects = "{\"objects\": [";
    for (int i = 0; i < 256; ++i)
        objects += std::string(i ? ", " : "") + "{\"mesh\": {\"type\": \"uvsphere\", \"slices\": 2048, \"stacks\": 2048}}";
    std::ofstream(dir / "many_spheres.json") << objects << "]}";
}

// A refusal's line: short, and nothing a terminal would act on.
bool printableLine(const std::string& line) {
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
        const auto c = static_cast<unsigned char>(line[i]);
        if (c < 0x20 || c == 0x7f) return false;
    }
    return true;
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
        // --test writes no --output (the --test rows that name one check that it is refused).
        const bool ownOutput = std::find(args.begin(), args.end(), "--output") != args.end() ||
                               std::find(args.begin(), args.end(), "--test") != args.end();
        if (!ownOutput) args.insert(args.end(), {"--output", "out.png"});
        SCOPED_TRACE("cases.txt:" + std::to_string(c.line) + ": " + args.front());
        const auto before = snapshot(scratch);
        const RunResult r = runShadelab(args, scratch / "inputs", capture);
        EXPECT_FALSE(r.signaled) << "died of a signal: " << r.err;
        EXPECT_EQ(r.exitCode, 2) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "not one line:\n" << r.err.substr(0, 2000);
        EXPECT_LE(r.err.size(), 401u) << "longer than 400 bytes: " << r.err.substr(0, 2000);
        EXPECT_TRUE(printableLine(r.err)) << "control characters in: " << r.err.substr(0, 2000);
        EXPECT_EQ(r.err.rfind("shadelab: ", 0), 0u) << r.err;
        EXPECT_NE(r.err.find(c.fragment), std::string::npos) << "expected \"" << c.fragment << "\" in: " << r.err.substr(0, 2000);
        EXPECT_TRUE(r.out.empty()) << r.out;
        EXPECT_FALSE(fs::exists(scratch / "inputs" / "out.png"));
        EXPECT_EQ(snapshot(scratch), before) << "a file was created, changed or removed";
    }
}
