// The limits that keep a refusal one short line and a small file from asking for unbounded work:
// messages quoting the input, JSON nesting measured on the text, the memory budget's estimate.
#include "core/base/error.hpp"
#include "core/base/json_depth.hpp"
#include "core/scene/memory_budget.hpp"
#include "core/geometry/mesh.hpp"
#include "core/base/message.hpp"
#include "test_dir.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace shadelab;

TEST(Message, ControlCharactersAreEscapedAndUtf8Kept) {
    EXPECT_EQ(escapeControls("a\nb\tc\x1b[31m\x07\x7f"), "a\\nb\\tc\\x1b[31m\\x07\\x7f");
    EXPECT_EQ(escapeControls("ombr\xc3\xa9" "e \xce\xb1"), "ombr\xc3\xa9" "e \xce\xb1");  // é, α
    EXPECT_EQ(escapeControls("\xc2\x9b" "2J"), "\\xc2\\x9b2J");  // C1 CSI, as UTF-8: a terminal command
    EXPECT_EQ(escapeControls("\xff\xc3"), "\\xff\\xc3");             // not UTF-8
    EXPECT_EQ(escapeControls("\xe0\x80\xaf"), "\\xe0\\x80\\xaf");    // overlong
}

TEST(Message, QuotedInputIsCutAndSaysHowLongItWas) {
    EXPECT_EQ(quoteInput("short"), "short");
    EXPECT_EQ(quoteInput(std::string(1000, 'x'), 10), "xxxxxxxxxx...(1000 bytes)");
    // A cut never splits a UTF-8 sequence.
    EXPECT_EQ(quoteInput("aaaaaaaaa\xc3\xa9" "bbb", 10), "aaaaaaaaa...(14 bytes)");
}

TEST(Message, OneLineKeepsTheStartAndTheEnd) {
    const std::string long_ = "file.json: malformed JSON: '" + std::string(5'000'000, '7') + "' is too long";
    const std::string line = oneLine(long_);
    EXPECT_LE(line.size(), 400u);
    EXPECT_EQ(line.rfind("file.json: malformed JSON: '777", 0), 0u) << line;
    EXPECT_NE(line.find("' is too long"), std::string::npos) << line;
    EXPECT_NE(line.find(" bytes ...] "), std::string::npos) << line;
    EXPECT_EQ(oneLine("two\nlines"), "two\\nlines");
}

TEST(JsonDepth, MeasuredOnTheTextOutsideStrings) {
    EXPECT_EQ(jsonNestingDepth("1"), 0u);
    EXPECT_EQ(jsonNestingDepth(R"({"a": [1, {"b": []}]})"), 4u);
    EXPECT_EQ(jsonNestingDepth(R"({"a": "[[[[{{{{", "b": "\"[["})"), 1u);
    EXPECT_EQ(jsonNestingDepth("[[[[[["), 6u);  // malformed: measured as far as it goes
    EXPECT_EQ(jsonNestingDepth("]]]}}}["), 1u);
    const std::string deep = std::string(513, '[') + std::string(513, ']');
    EXPECT_THROW(checkJsonDepth(deep, "x.json"), InputError);
    EXPECT_NO_THROW(checkJsonDepth(std::string(512, '[') + std::string(512, ']'), "x.json"));
}

TEST(MemoryBudget, SizesParseWithBinaryUnits) {
    EXPECT_EQ(parseByteSize("2G"), std::uint64_t(2) << 30);
    EXPECT_EQ(parseByteSize("512M"), std::uint64_t(512) << 20);
    EXPECT_EQ(parseByteSize("1.5GiB"), std::uint64_t(3) << 29);
    EXPECT_EQ(parseByteSize("4096"), 4096u);
    EXPECT_EQ(parseByteSize("12Q"), std::nullopt);
    EXPECT_EQ(parseByteSize("-1G"), std::nullopt);
    EXPECT_EQ(parseByteSize("G"), std::nullopt);
    EXPECT_EQ(parseByteSize("1e30T"), std::nullopt);
}

TEST(MemoryBudget, ProceduralTriangleCountsMatchTheMeshes) {
    for (const MeshSpec::Type type : {MeshSpec::Type::UvSphere, MeshSpec::Type::IcoSphere, MeshSpec::Type::Torus,
                                      MeshSpec::Type::Cube, MeshSpec::Type::Plane}) {
        MeshSpec spec;
        spec.type = type;
        spec.planeSubdivisions = 5;
        EXPECT_EQ(proceduralTriangles(spec), makeProceduralMesh(spec).triangleCount()) << int(type);
    }
}

TEST(MemoryBudget, EstimateCountsFramebuffersShadowMapsAndMeshes) {
    Scene s;
    s.width = 1000, s.height = 1000;
    s.objects.front().mesh.type = MeshSpec::Type::Cube;
    s.layout = Layout::Single;
    s.shading = ShadingMode::Phong;
    const MemoryUse plain = estimateFrame(s, 1);
    EXPECT_EQ(plain.framebuffers, 20'000'000u);
    EXPECT_EQ(plain.shadowMaps, 0u);
    EXPECT_GT(estimateFrame(s, 4).framebuffers, plain.framebuffers);
    s.shadows.enabled = true;
    s.shadows.mapSize = 1024;
    s.lights = {Light{}};  // a point light: six maps
    EXPECT_EQ(estimateFrame(s, 1).shadowMaps, 6u * 1024 * 1024 * 4);
    EXPECT_EQ(estimateFrame(s, 1, 1'000'000).meshes, 60'000'000u);
    s.layout = Layout::Compare;  // a flat pane needs vertices of its own
    EXPECT_GT(estimateFrame(s, 1, 1'000'000).meshes, 60'000'000u);
    // A model's decoded base colour images: a 4096 x 4096 texture (64 MiB) measured ~213 MB.
    EXPECT_EQ(estimateFrame(s, 1, 0, std::uint64_t(64) << 20).textures, (std::uint64_t(640) << 20) / 3);

    setMemoryBudget(std::uint64_t(128) << 20);
    s.layout = Layout::Single;
    s.shadows.enabled = false;
    EXPECT_NO_THROW(checkMemory(estimateFrame(s, 1), "a frame"));
    s.width = s.height = 4096;
    try {
        checkMemory(estimateFrame(s, 1), "a 4096x4096 frame");
        ADD_FAILURE() << "not refused";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "a 4096x4096 frame needs about 416 MiB (framebuffers 320 MiB), more than the memory "
                               "budget of 128 MiB (--max-memory)");
    }
    setMemoryBudget(std::nullopt);
    EXPECT_EQ(memoryBudget(), defaultMemoryBudget());
    EXPECT_GT(defaultMemoryBudget(), std::uint64_t(256) << 20);
}

// Issue 32: a container's memory limit (its cgroup's) bounds the default budget, not the host's memory.
// Folders laid out as /sys/fs/cgroup is, and /proc/self/cgroup's lines as the kernel writes them.
TEST(MemoryBudget, CgroupLimitIsRead) {
    const test::TestDir dir("cgroup");
    namespace fs = std::filesystem;
    const auto write = [&dir](const std::string& name, const std::string& text) {
        fs::create_directories((dir.path / name).parent_path());
        std::ofstream(dir.path / name) << text;
        return (dir.path / name).string();
    };
    const std::string root = (dir.path / "sys").string();
    // cgroup v2: the process's own group's memory.max, or a parent's when smaller; "max" is no limit.
    write("sys/ci/job/memory.max", "805306368\n");
    write("sys/ci/memory.max", "max\n");
    EXPECT_EQ(cgroupMemoryLimit(root, write("self", "0::/ci/job\n")), 805306368u);
    write("sys/ci/memory.max", "536870912\n");
    EXPECT_EQ(cgroupMemoryLimit(root, (dir.path / "self").string()), 536870912u);
    // In a container's namespace the group's path is the host's; its files are at the root.
    write("sys/memory.max", "268435456\n");
    EXPECT_EQ(cgroupMemoryLimit(root, write("self", "0::/host/path/of/the/container\n")), 268435456u);
    // cgroup v1: the memory controller's memory.limit_in_bytes; 2^63 less a page is no limit.
    fs::remove_all(root);
    write("sys/memory/docker/abc/memory.limit_in_bytes", "1073741824\n");
    write("sys/memory/memory.limit_in_bytes", "9223372036854771712\n");
    EXPECT_EQ(cgroupMemoryLimit(root, write("self", "12:pids:/docker/abc\n4:cpu,memory:/docker/abc\n0::/\n")),
              1073741824u);
    EXPECT_EQ(cgroupMemoryLimit(root, write("self", "4:memory:/elsewhere\n")), 0u);
    // No cgroup file (not Linux): no limit.
    EXPECT_EQ(cgroupMemoryLimit(root, (dir.path / "missing").string()), 0u);
    // The default budget is at most half of this process's limit.
    if (const std::uint64_t limit = cgroupMemoryLimit()) {
        EXPECT_LE(defaultMemoryBudget(), limit / 2);
    }
}
