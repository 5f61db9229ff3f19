// glTF import: the real models in ../shared/assets/gltf (counts from its README), and small broken or
// hostile files this test writes itself. Every broken file must give an InputError that names the
// file and the offending accessor/primitive; none may crash (CI also runs this under ASan + UBSan).
#include "core/base/error.hpp"
#include "core/geometry/gltf_import.hpp"
#include "core/shading/lighting.hpp"
#include "core/image/image.hpp"
#include "core/geometry/scene_geometry.hpp"
#include "test_dir.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

using namespace shadelab;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const fs::path kShared = fs::path(SHADELAB_SOURCE_DIR) / ".." / "shared" / "assets" / "gltf";

std::string base64(const std::vector<unsigned char>& in) {
    static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < in.size(); i += 3) {
        const unsigned v = unsigned(in[i]) << 16 | (i + 1 < in.size() ? unsigned(in[i + 1]) << 8 : 0u) |
                           (i + 2 < in.size() ? unsigned(in[i + 2]) : 0u);
        out += t[v >> 18 & 63];
        out += t[v >> 12 & 63];
        out += i + 1 < in.size() ? t[v >> 6 & 63] : '=';
        out += i + 2 < in.size() ? t[v & 63] : '=';
    }
    return out;
}

template <typename T>
void append(std::vector<unsigned char>& b, std::initializer_list<T> values) {
    for (T v : values) {
        unsigned char bytes[sizeof(T)];
        std::memcpy(bytes, &v, sizeof(T));
        b.insert(b.end(), bytes, bytes + sizeof(T));
    }
}

// A valid file: one quad (4 vertices, 2 triangles, u16 indices), positions only, in one buffer:
// bytes 0..47 positions, 48..59 indices. Tests break one thing at a time.
struct Doc {
    json j;
    std::vector<unsigned char> bin;
    Doc() {
        append<float>(bin, {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});
        append<std::uint16_t>(bin, {0, 1, 2, 0, 2, 3});
        j = json::parse(R"({
          "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
          "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 4}]}],
          "buffers": [{"byteLength": 60}],
          "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                          {"buffer": 0, "byteOffset": 48, "byteLength": 12}],
          "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                         "min": [0, 0, 0], "max": [1, 1, 0]},
                        {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}]})");
    }
};

class Gltf : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("shadelab-gltf-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir_);
        fs::create_directories(dir_ / "model");
    }
    void TearDown() override { fs::remove_all(dir_); }

    // Writes the document as model/NAME.gltf with its buffer embedded as a data: URI (unless the
    // document already names a uri).
    std::string writeGltf(const std::string& name, Doc d) const {
        if (!d.j["buffers"][0].contains("uri"))
            d.j["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(d.bin);
        const fs::path p = dir_ / "model" / (name + ".gltf");
        std::ofstream(p) << d.j.dump();
        return p.string();
    }
    // Writes the document as model/NAME.glb: its buffer in the BIN chunk (padded by `padding` zero
    // bytes past byteLength), or with withBin = false no BIN chunk at all.
    std::string writeGlb(const std::string& name, const Doc& d, bool withBin = true, std::size_t padding = 0) const {
        std::string js = d.j.dump();
        while (js.size() % 4) js += ' ';
        std::vector<unsigned char> bin = d.bin;
        bin.resize(bin.size() + padding, 0);
        while (bin.size() % 4) bin.push_back(0);
        std::vector<unsigned char> out;
        const std::size_t binBytes = withBin ? 8 + bin.size() : 0;
        append<std::uint32_t>(out, {0x46546C67u, 2u, std::uint32_t(12 + 8 + js.size() + binBytes)});
        append<std::uint32_t>(out, {std::uint32_t(js.size()), 0x4E4F534Au});
        out.insert(out.end(), js.begin(), js.end());
        if (withBin) {
            append<std::uint32_t>(out, {std::uint32_t(bin.size()), 0x004E4942u});
            out.insert(out.end(), bin.begin(), bin.end());
        }
        const fs::path p = dir_ / "model" / (name + ".glb");
        std::ofstream(p, std::ios::binary).write(reinterpret_cast<const char*>(out.data()), std::streamsize(out.size()));
        return p.string();
    }
    // Loading must fail with one line that starts with the file and contains every fragment.
    static void expectRefused(const std::string& file, std::initializer_list<const char*> fragments) {
        try {
            loadGltf(file);
            ADD_FAILURE() << file << " loaded";
        } catch (const InputError& e) {
            const std::string msg = e.what();
            EXPECT_EQ(msg.rfind(file, 0), 0u) << msg;
            EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
            for (const char* f : fragments) EXPECT_NE(msg.find(f), std::string::npos) << "'" << f << "' not in: " << msg;
        }
    }
    fs::path dir_;
};

}  // namespace

TEST_F(Gltf, ValidQuadLoadsFromGltfAndGlb) {
    for (const std::string& file : {writeGltf("quad", Doc()), writeGlb("quad", Doc())}) {
        GltfInfo info;
        const Mesh m = loadGltf(file, &info);
        EXPECT_EQ(m.triangleCount(), 2u) << file;
        EXPECT_EQ(info.fileTriangles, 2u);
        EXPECT_EQ(info.generatedNormals, 4u);  // the file has none
        for (const auto& n : m.normals) EXPECT_NEAR(glm::distance(n, glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
    }
}

// shadelab splits a .glb itself and reads buffer 0 from the BIN chunk straight into tinygltf's buffer
// (from the file, or from memory): the chunk layouts the spec allows load, the broken ones are refused.
TEST_F(Gltf, GlbChunksAreSplitAndBufferZeroReadFromTheBinChunk) {
    const std::string padded = writeGlb("padded", Doc(), true, 7);  // byteLength < the chunk's length
    const Mesh fromFile = loadGltf(padded);
    EXPECT_EQ(fromFile.triangleCount(), 2u);
    std::ifstream in(padded, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const Mesh fromMemory = loadGltfFromMemory(bytes, "padded.glb", (dir_ / "model").string());
    EXPECT_EQ(fromMemory.positions, fromFile.positions);
    EXPECT_EQ(fromMemory.indices, fromFile.indices);
    {
        Doc d;  // buffer 0 in an external file: a .glb with no BIN chunk
        std::ofstream(dir_ / "model" / "quad.bin", std::ios::binary)
            .write(reinterpret_cast<const char*>(d.bin.data()), std::streamsize(d.bin.size()));
        d.j["buffers"][0]["uri"] = "quad.bin";
        EXPECT_EQ(loadGltf(writeGlb("external", d, false)).indices, fromFile.indices);
    }
    expectRefused(writeGlb("no_bin", Doc(), false), {"buffer 0", "no BIN chunk"});
    {
        // A header whose total length is 0 (less than its own 20 bytes of headers): refused, from a
        // file and from memory (it wrapped to 4 GiB, and overflowed the buffer from memory).
        std::string tiny = bytes.substr(0, 47);
        tiny[8] = tiny[9] = tiny[10] = tiny[11] = '\0';
        try {
            loadGltfFromMemory(tiny, "tiny.glb", (dir_ / "model").string());
            ADD_FAILURE() << "a .glb whose header says 0 bytes was loaded";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("less than its own headers"), std::string::npos) << e.what();
        }
        const fs::path file = dir_ / "model" / "tiny.glb";
        std::ofstream(file, std::ios::binary).write(tiny.data(), std::streamsize(tiny.size()));
        expectRefused(file.string(), {"less than its own headers"});
    }
    {
        Doc d;
        d.j["buffers"][0]["byteLength"] = d.bin.size() + 64;
        expectRefused(writeGlb("long_buffer", d), {"buffer 0", "byteLength"});
    }
    {
        const std::string v1 = writeGlb("version1", Doc());
        std::fstream f(v1, std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(4);
        const std::uint32_t one = 1;
        f.write(reinterpret_cast<const char*>(&one), 4);
        f.close();
        expectRefused(v1, {"version 1"});
    }
}

TEST_F(Gltf, BrokenFilesAreRefusedWithTheirCulprit) {
    {
        Doc d;
        d.bin[48] = 9;  // first index 9 of 4 vertices
        expectRefused(writeGltf("index_range", d), {"mesh 0 primitive 0 indices", "accessor 1", "out of range"});
    }
    {
        Doc d;
        d.j["bufferViews"][1]["byteLength"] = 200;  // the view runs past its 60-byte buffer
        expectRefused(writeGltf("view_past_buffer", d), {"bufferView 1"});
    }
    {
        Doc d;  // an external buffer file shorter than the views that read it
        d.j["buffers"][0]["uri"] = "short.bin";
        std::ofstream(dir_ / "model" / "short.bin", std::ios::binary).write(reinterpret_cast<const char*>(d.bin.data()), 20);
        expectRefused(writeGltf("short_buffer", d), {});
    }
    {
        Doc d;
        d.j["accessors"][0]["count"] = 2147483648LL;  // a 2 GB element count
        expectRefused(writeGltf("huge_count", d), {"accessor 0"});
    }
    {
        Doc d;
        d.j["accessors"][0]["count"] = 5;  // 5 positions do not fit in a 48-byte view
        expectRefused(writeGltf("accessor_past_view", d), {"POSITION", "accessor 0", "do not fit"});
    }
    {
        Doc d;
        d.j["meshes"][0]["primitives"][0]["attributes"] = json::parse(R"({"NORMAL": 0})");
        expectRefused(writeGltf("no_position", d), {"mesh 0 primitive 0", "POSITION"});
    }
    {
        Doc d;
        // POSITION as 32-bit integers: not even KHR_mesh_quantization allows them (bytes and shorts it does)
        d.j["accessors"][0]["componentType"] = 5125;
        expectRefused(writeGltf("position_type", d), {"POSITION", "accessor 0", "unsupported type/componentType"});
    }
    {
        Doc d;
        d.j["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 7;
        expectRefused(writeGltf("no_accessor", d), {"accessor"});
    }
    {
        Doc d;
        d.bin[50] = 0xff, d.bin[51] = 0xff;  // 65535 in u16 indices: the primitive-restart value
        expectRefused(writeGltf("restart", d), {"primitive-restart"});
    }
    {
        Doc d;
        d.j["nodes"][0]["children"] = json::array({0});  // a node that is its own child
        expectRefused(writeGltf("cycle", d), {"node 0"});
    }
    {
        Doc d;
        d.j["buffers"][0]["uri"] = "data:application/octet-stream;base64,@@@not base64@@@";
        expectRefused(writeGltf("bad_data_uri", d), {});
    }
    {
        std::string glb = writeGlb("truncated", Doc());
        fs::resize_file(glb, fs::file_size(glb) / 2);
        expectRefused(glb, {});
    }
    {
        std::string glb = writeGlb("chunk_lies", Doc());
        std::fstream f(glb, std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(12);
        const std::uint32_t huge = 0x7ffffff0u;  // the JSON chunk claims 2 GB
        f.write(reinterpret_cast<const char*>(&huge), 4);
        f.close();
        expectRefused(glb, {});
    }
    std::ofstream(dir_ / "model" / "junk.gltf") << "\x01\x02\x03 junk";
    expectRefused((dir_ / "model" / "junk.gltf").string(), {});
}

// A URI may only name files inside the model's folder: "..", absolute paths and network schemes are
// refused before anything is opened.
// shadelab decodes a .gltf's base64 buffers itself (tinygltf's decoder is slow on large files): every
// padding, both MIME types, and one clear line for a payload that is not base64.
TEST_F(Gltf, Base64BuffersDecodeWithEveryPadding) {
    // The indices, a filler, then the positions, whose last byte is not zero (the last z is 0.5): with
    // a filler of 0, 4 and 8 bytes the payload ends in no '=', "==" and "=", and a wrong decode of
    // its last characters changes that vertex.
    for (std::size_t filler : {0u, 4u, 8u}) {
        for (const char* mime : {"data:application/octet-stream;base64,", "data:application/gltf-buffer;base64,"}) {
            Doc d;
            d.bin.clear();
            append<std::uint16_t>(d.bin, {0, 1, 2, 0, 2, 3});
            d.bin.resize(d.bin.size() + filler, 0xAB);
            append<float>(d.bin, {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0.5f});
            d.j["bufferViews"][0]["byteOffset"] = 12 + filler;
            d.j["bufferViews"][1]["byteOffset"] = 0;
            d.j["buffers"][0]["byteLength"] = d.bin.size();
            d.j["buffers"][0]["uri"] = mime + base64(d.bin);
            const Mesh m = loadGltf(writeGltf("filler" + std::to_string(filler), d));
            ASSERT_EQ(m.triangleCount(), 2u) << filler << " " << mime;
            EXPECT_EQ(m.positions[3], glm::vec3(0, 1, 0.5f)) << filler << " " << mime;
            EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
        }
    }
    Doc d;
    d.j["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(d.bin).substr(3);  // 77 characters: 4n + 1
    expectRefused(writeGltf("bad_length", d), {"buffer 0", "not valid base64"});
    Doc wrongSize;
    wrongSize.j["buffers"][0]["byteLength"] = 64;  // the payload holds 60
    expectRefused(writeGltf("wrong_size", wrongSize), {});
}

// Each node lists the next one twice, 40 levels deep: 2^40 instances from a file of a few kB. Refused
// at the instance limit in well under a second (it ran for minutes under the depth limit alone).
TEST_F(Gltf, ChildrenListedManyTimesAreBoundedByTheInstanceCount) {
    Doc d;
    json nodes = json::array();
    for (int i = 0; i < 40; ++i) nodes.push_back({{"children", {i + 1, i + 1}}});
    nodes.push_back({{"mesh", 0}});
    d.j["nodes"] = nodes;
    expectRefused(writeGltf("doubling", d), {"node instances"});
}

TEST_F(Gltf, UrisThatLeaveTheModelFolderAreRefused) {
    Doc d;
    std::ofstream(dir_ / "outside.bin", std::ios::binary).write(reinterpret_cast<const char*>(d.bin.data()), std::streamsize(d.bin.size()));
    for (const std::string& uri : {std::string("../outside.bin"), (dir_ / "outside.bin").string(),
                                   std::string("http://example.invalid/x.bin"), std::string("file:///etc/passwd")}) {
        Doc bad;
        bad.j["buffers"][0]["uri"] = uri;
        expectRefused(writeGltf("escape", bad), {});
    }
    // A 300-character name is a refusal (InputError), not an exception.
    Doc longName;
    longName.j["buffers"][0]["uri"] = std::string(300, 'a') + ".bin";
    expectRefused(writeGltf("odd_uri", longName), {});
    // The same buffer inside the folder is fine.
    std::ofstream(dir_ / "model" / "inside.bin", std::ios::binary).write(reinterpret_cast<const char*>(d.bin.data()), std::streamsize(d.bin.size()));
    Doc ok;
    ok.j["buffers"][0]["uri"] = "inside.bin";
    EXPECT_EQ(loadGltf(writeGltf("inside", ok)).triangleCount(), 2u);
}

TEST_F(Gltf, SymbolicLinksThatLeaveTheModelFolderAreRefused) {
    Doc d;
    std::ofstream(dir_ / "outside.bin", std::ios::binary).write(reinterpret_cast<const char*>(d.bin.data()), std::streamsize(d.bin.size()));
    // Windows lets only privileged users make links, and wine not at all: there the test has nothing to try.
    std::error_code noLinks;
    fs::remove(dir_ / "model" / "link.bin");
    fs::create_symlink(dir_ / "outside.bin", dir_ / "model" / "link.bin", noLinks);
    if (noLinks) GTEST_SKIP() << "cannot make a symbolic link here: " << noLinks.message();
    // Through a symbolic link in the folder, or a linked subfolder, to the file outside: refused too.
    fs::remove(dir_ / "model" / "linked");
    fs::create_directory_symlink(dir_, dir_ / "model" / "linked");
    for (const std::string& uri : {std::string("link.bin"), std::string("linked/outside.bin")}) {
        Doc bad;
        bad.j["buffers"][0]["uri"] = uri;
        expectRefused(writeGltf("escape_link", bad), {});
    }
    // A symbolic link loop is a refusal (InputError), not an exception.
    fs::remove(dir_ / "model" / "loop.bin");
    fs::create_symlink("loop.bin", dir_ / "model" / "loop.bin");
    Doc loop;
    loop.j["buffers"][0]["uri"] = "loop.bin";
    expectRefused(writeGltf("odd_uri", loop), {});
}

TEST_F(Gltf, MirroredNodesKeepOutwardWindingAndTransformedNormals) {
    Doc d;
    append<float>(d.bin, {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});  // normals +z at bytes 60..107
    d.j["buffers"][0]["byteLength"] = 108;
    d.j["bufferViews"].push_back(json::parse(R"({"buffer": 0, "byteOffset": 60, "byteLength": 48})"));
    d.j["accessors"].push_back(json::parse(R"({"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC3"})"));
    d.j["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 2;
    d.j["nodes"][0]["scale"] = json::array({1, 1, -1});  // mirror in z: the quad now faces -z
    const Mesh m = loadGltf(writeGltf("mirror", d));
    ASSERT_EQ(m.triangleCount(), 2u);
    for (const auto& n : m.normals) EXPECT_NEAR(glm::distance(n, glm::vec3(0, 0, -1)), 0.0f, 1e-6f);
    for (size_t t = 0; t < m.indices.size(); t += 3)
        EXPECT_GT(glm::dot(faceNormal(m.positions[m.indices[t]], m.positions[m.indices[t + 1]], m.positions[m.indices[t + 2]]),
                           glm::vec3(0, 0, -1)), 0.99f);
}

TEST_F(Gltf, StripsAndFansAreTriangulatedCounterClockwise) {
    for (int mode : {5, 6}) {  // TRIANGLE_STRIP over 0 1 3 2, TRIANGLE_FAN over 0 1 2 3
        Doc d;
        const std::uint16_t order[2][4] = {{0, 1, 3, 2}, {0, 1, 2, 3}};
        std::memcpy(&d.bin[48], order[mode - 5], 8);
        d.j["accessors"][1]["count"] = 4;
        d.j["meshes"][0]["primitives"][0]["mode"] = mode;
        const Mesh m = loadGltf(writeGltf("mode" + std::to_string(mode), d));
        ASSERT_EQ(m.triangleCount(), 2u) << mode;
        for (size_t t = 0; t < m.indices.size(); t += 3)
            EXPECT_GT(faceNormal(m.positions[m.indices[t]], m.positions[m.indices[t + 1]], m.positions[m.indices[t + 2]]).z, 0.99f)
                << "mode " << mode << " triangle " << t / 3;
    }
}

TEST_F(Gltf, BaseColourOfEachPrimitiveBecomesAPart) {
    Doc d;
    d.j["materials"] = json::parse(R"([{"pbrMetallicRoughness": {"baseColorFactor": [0.25, 0.5, 0.75, 1.0]}}])");
    d.j["meshes"][0]["primitives"][0]["material"] = 0;
    const Mesh m = loadGltf(writeGltf("material", d));
    ASSERT_EQ(m.parts.size(), 1u);
    EXPECT_EQ(m.parts[0].indexCount, 6u);
    EXPECT_EQ(m.parts[0].baseColor, glm::vec3(0.25f, 0.5f, 0.75f));
}

// glTF's material.doubleSided becomes the part's: both primitives draw the same quad in the same
// colour, so they would share a part but for their sidedness. --info counts the double-sided materials.
TEST_F(Gltf, DoubleSidedIsReadPerMaterialAndKeepsPartsApart) {
    Doc d;
    d.j["materials"] = json::parse(R"([{"doubleSided": true}, {"doubleSided": false}, {}])");
    const json primitive = d.j["meshes"][0]["primitives"][0];
    d.j["meshes"][0]["primitives"] = json::array();
    for (int material : {0, 0, 1, 2}) {
        json p = primitive;
        p["material"] = material;
        d.j["meshes"][0]["primitives"].push_back(p);
    }
    GltfInfo info;
    const Mesh m = loadGltf(writeGltf("double_sided", d), &info);
    ASSERT_EQ(m.parts.size(), 2u);  // materials 0, 0 | 1, 2 (false, and the default false)
    EXPECT_TRUE(m.parts[0].doubleSided);
    EXPECT_EQ(m.parts[0].indexCount, 12u);
    EXPECT_FALSE(m.parts[1].doubleSided);
    EXPECT_EQ(m.parts[1].firstIndex, 12u);
    EXPECT_EQ(info.doubleSidedMaterials, 1);
    EXPECT_NE(describe("m.gltf", info).find("double-sided materials: 1"), std::string::npos) << describe("m.gltf", info);
    // Procedural meshes have no parts: single-sided, culled as always.
    EXPECT_TRUE(makeProceduralMesh(MeshSpec{}).parts.empty());
}

// Every model of ../shared/assets/gltf loads, with the triangle counts of that folder's README:
// "Triangles" (TRIANGLES primitives, each counted once) and "drawn" (each mesh instance, plus the
// triangles of strips and fans, which the README lists separately).
TEST(SharedModels, LoadWithTheReadmeTriangleCounts) {
    if (!fs::exists(kShared / "README.md")) GTEST_SKIP() << kShared << " not found: ../shared is absent";
    struct Expect {
        const char* file;
        std::size_t fileTriangles, drawn;
    };
    const std::string sa = "sample-assets/", ag = "asset-generator/Positive/Mesh_PrimitiveMode/Mesh_PrimitiveMode_";
    const std::vector<std::pair<std::string, std::pair<std::size_t, std::size_t>>> models = {
        {sa + "Triangle/glTF/Triangle.gltf", {1, 1}},
        {sa + "Triangle/glTF-Embedded/Triangle.gltf", {1, 1}},
        {sa + "TriangleWithoutIndices/glTF/TriangleWithoutIndices.gltf", {1, 1}},
        {sa + "TriangleWithoutIndices/glTF-Embedded/TriangleWithoutIndices.gltf", {1, 1}},
        {sa + "Box/glTF/Box.gltf", {12, 12}},
        {sa + "Box/glTF-Binary/Box.glb", {12, 12}},
        {sa + "Box/glTF-Embedded/Box.gltf", {12, 12}},
        {sa + "BoxInterleaved/glTF/BoxInterleaved.gltf", {12, 12}},
        {sa + "BoxInterleaved/glTF-Binary/BoxInterleaved.glb", {12, 12}},
        {sa + "BoxVertexColors/glTF/BoxVertexColors.gltf", {12, 12}},
        {sa + "BoxVertexColors/glTF-Binary/BoxVertexColors.glb", {12, 12}},
        {sa + "Cube/glTF/Cube.gltf", {12, 12}},
        {sa + "SimpleSparseAccessor/glTF/SimpleSparseAccessor.gltf", {12, 12}},
        {sa + "SimpleSparseAccessor/glTF-Embedded/SimpleSparseAccessor.gltf", {12, 12}},
        {sa + "SimpleMeshes/glTF/SimpleMeshes.gltf", {1, 2}},
        {sa + "SimpleMeshes/glTF-Embedded/SimpleMeshes.gltf", {1, 2}},
        {sa + "MultiUVTest/glTF/MultiUVTest.gltf", {12, 12}},
        {sa + "MultiUVTest/glTF-Binary/MultiUVTest.glb", {12, 12}},
        {sa + "MeshPrimitiveModes/glTF/MeshPrimitiveModes.gltf", {6, 16}},
        {sa + "MeshPrimitiveModes/glTF-Embedded/MeshPrimitiveModes.gltf", {6, 16}},
        {sa + "Suzanne/glTF/Suzanne.gltf", {3936, 3936}},
        {sa + "Avocado/glTF/Avocado.gltf", {682, 682}},
        {sa + "SheenCloth/glTF/SheenCloth.gltf", {115200, 115200}},
        {sa + "ToyCar/glTF/ToyCar.gltf", {108936, 108936}},
        {sa + "TransmissionTest/glTF-Binary/TransmissionTest.glb", {128775, 128775}},
        {sa + "NegativeScaleTest/glTF/NegativeScaleTest.gltf", {3884, 7724}},
        {sa + "OrientationTest/glTF/OrientationTest.gltf", {524, 524}},
        {sa + "MetalRoughSpheresNoTextures/glTF/MetalRoughSpheresNoTextures.gltf", {1040409, 1040409}},
        {sa + "Box With Spaces/glTF/Box With Spaces.gltf", {12, 12}},
        {sa + "MultipleScenes/glTF/MultipleScenes.gltf", {3, 2}},
        {ag + "00.gltf", {0, 0}}, {ag + "01.gltf", {0, 0}}, {ag + "02.gltf", {0, 0}}, {ag + "03.gltf", {0, 0}},
        {ag + "04.gltf", {0, 2}}, {ag + "05.gltf", {0, 2}}, {ag + "06.gltf", {2, 2}},
        {ag + "07.gltf", {0, 0}}, {ag + "08.gltf", {0, 0}}, {ag + "09.gltf", {0, 0}}, {ag + "10.gltf", {0, 0}},
        {ag + "11.gltf", {0, 2}}, {ag + "12.gltf", {0, 2}}, {ag + "13.gltf", {2, 2}},
        {ag + "14.gltf", {2, 2}}, {ag + "15.gltf", {2, 2}},
    };
    for (const auto& [file, counts] : models) {
        SCOPED_TRACE(file);
        GltfInfo info;
        Mesh m;
        ASSERT_NO_THROW(m = loadGltf((kShared / file).string(), &info));
        EXPECT_EQ(info.fileTriangles, counts.first);
        EXPECT_EQ(info.triangles, counts.second);
        EXPECT_EQ(m.triangleCount(), counts.second);
        for (auto i : m.indices) ASSERT_LT(i, m.positions.size());
        for (const auto& n : m.normals) ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f);
    }
}

// Names outside ASCII (UTF-8 on Linux). Windows reads shadelab's narrow path strings in its ANSI code
// page, which has no ❤ or ♻: such a name does not open there (README, "Windows").
TEST(SharedModels, ModelsWithNamesOutsideAsciiLoad) {
    if (!fs::exists(kShared / "README.md")) GTEST_SKIP() << kShared << " not found: ../shared is absent";
#ifdef _WIN32
    GTEST_SKIP() << "Windows: paths are narrow strings in the ANSI code page, which has no \u2764 or \u267B";
#endif
    for (const char* file : {"sample-assets/Unicode❤♻Test/glTF/Unicode❤♻Test.gltf",
                             "sample-assets/Unicode❤♻Test/glTF-Binary/Unicode❤♻Test.glb"}) {
        GltfInfo info;
        ASSERT_NO_THROW(loadGltf((kShared / file).string(), &info)) << file;
        EXPECT_EQ(info.triangles, 2u) << file;
    }
}

// The four negative Asset-Generator files are refused (no POSITION; primitive-restart indices).
TEST(SharedModels, NegativeAssetGeneratorFilesAreRefused) {
    const fs::path neg = kShared / "asset-generator" / "Negative";
    if (!fs::exists(neg)) GTEST_SKIP() << neg << " not found: ../shared is absent";
    for (const char* f : {"Mesh_NoPosition/Mesh_NoPosition_00.gltf", "Mesh_NoPosition/Mesh_NoPosition_01.gltf",
                          "Mesh_PrimitiveRestart/Mesh_PrimitiveRestart_08.gltf",
                          "Mesh_PrimitiveRestart/Mesh_PrimitiveRestart_09.gltf"}) {
        EXPECT_THROW(loadGltf((neg / f).string()), InputError) << f;
    }
}

// The sparse accessor substitutes three positions: the loaded vertices are the substituted ones.
TEST(SharedModels, SparseAccessorValuesAreApplied) {
    const fs::path file = kShared / "sample-assets/SimpleSparseAccessor/glTF/SimpleSparseAccessor.gltf";
    if (!fs::exists(file)) GTEST_SKIP() << file << " not found: ../shared is absent";
    const Mesh m = loadGltf(file.string());
    ASSERT_EQ(m.positions.size(), 14u);
    // The base is a 7 x 2 grid (x = 0..6, y = 0..1); the sparse values move vertices 8, 10 and 12 of
    // the top row to (1, 2), (3, 3) and (5, 4). The others keep their base positions.
    EXPECT_EQ(m.positions[6], glm::vec3(6, 0, 0));
    EXPECT_EQ(m.positions[7], glm::vec3(0, 1, 0));
    EXPECT_EQ(m.positions[8], glm::vec3(1, 2, 0));
    EXPECT_EQ(m.positions[9], glm::vec3(2, 1, 0));
    EXPECT_EQ(m.positions[10], glm::vec3(3, 3, 0));
    EXPECT_EQ(m.positions[12], glm::vec3(5, 4, 0));
}

// KHR_mesh_quantization: each integer type read as glTF 2.0 (3.11) defines it, against values worked
// out by hand: signed normalized max(c / (2^(b-1) - 1), -1), unsigned normalized c / (2^b - 1), and
// unnormalized integers as they are.
TEST_F(Gltf, QuantizedPositionsAndNormalsDequantizeByTheSpec) {
    struct Case {
        int componentType;
        bool normalized;
        std::vector<unsigned char> bytes;  // three VEC3 elements, each padded to 4-byte alignment
        std::vector<float> expected;       // nine components
    };
    const auto pad = [](std::vector<unsigned char> b, std::size_t elementSize, std::size_t stride) {
        std::vector<unsigned char> out;
        for (std::size_t i = 0; i < b.size(); i += elementSize) {
            out.insert(out.end(), b.begin() + long(i), b.begin() + long(i + elementSize));
            out.resize(out.size() + stride - elementSize, 0);
        }
        return out;
    };
    std::vector<unsigned char> shorts, ushorts;
    append<std::int16_t>(shorts, {-32768, -32767, 16384, 0, 32767, 1, -1, 100, 0});
    append<std::uint16_t>(ushorts, {0, 65535, 13107, 1, 2, 3, 65535, 0, 0});
    const std::vector<Case> cases = {
        {5120, true, pad({0x80, 0x81, 64, 0, 127, 1, 0xff, 100, 0}, 3, 4),  // BYTE normalized
         {-1.0f, -1.0f, 64.0f / 127, 0, 1, 1.0f / 127, -1.0f / 127, 100.0f / 127, 0}},
        {5121, true, pad({0, 255, 51, 1, 2, 3, 255, 0, 0}, 3, 4),  // UNSIGNED_BYTE normalized
         {0, 1, 0.2f, 1.0f / 255, 2.0f / 255, 3.0f / 255, 1, 0, 0}},
        {5120, false, pad({0xfb, 3, 7, 0, 1, 2, 127, 0x80, 0}, 3, 4),  // BYTE as it is
         {-5, 3, 7, 0, 1, 2, 127, -128, 0}},
        {5122, true, pad(shorts, 6, 8),  // SHORT normalized
         {-1, -1, 16384.0f / 32767, 0, 1, 1.0f / 32767, -1.0f / 32767, 100.0f / 32767, 0}},
        {5123, true, pad(ushorts, 6, 8),  // UNSIGNED_SHORT normalized
         {0, 1, 0.2f, 1.0f / 65535, 2.0f / 65535, 3.0f / 65535, 1, 0, 0}},
        {5123, false, pad(ushorts, 6, 8),  // UNSIGNED_SHORT as it is (gltfpack's positions)
         {0, 65535, 13107, 1, 2, 3, 65535, 0, 0}},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(std::to_string(c.componentType) + (c.normalized ? " normalized" : ""));
        Doc d;
        d.bin = c.bytes;
        d.j["buffers"][0]["byteLength"] = d.bin.size();
        d.j["bufferViews"] = json::array({{{"buffer", 0}, {"byteLength", d.bin.size()}, {"byteStride", d.bin.size() / 3}}});
        d.j["accessors"] = json::array({{{"bufferView", 0}, {"componentType", c.componentType}, {"normalized", c.normalized},
                                         {"count", 3}, {"type", "VEC3"}}});
        d.j["meshes"][0]["primitives"][0].erase("indices");
        d.j["extensionsUsed"] = d.j["extensionsRequired"] = json::array({"KHR_mesh_quantization"});
        const Mesh m = loadGltf(writeGltf("quantized", d));
        ASSERT_EQ(m.positions.size(), 3u);
        for (int v = 0; v < 3; ++v)
            for (int k = 0; k < 3; ++k)
                EXPECT_FLOAT_EQ(m.positions[std::size_t(v)][k], c.expected[std::size_t(3 * v + k)]) << "vertex " << v;
    }
}

TEST_F(Gltf, IntegerNormalsMustBeNormalized) {
    Doc d;
    append<std::int8_t>(d.bin, {0, 0, 127, 0, 0, 127, 0, 0, 127, 0, 0, 127});
    d.j["buffers"][0]["byteLength"] = d.bin.size();
    d.j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 60}, {"byteLength", 12}});
    d.j["accessors"].push_back({{"bufferView", 2}, {"componentType", 5120}, {"count", 4}, {"type", "VEC3"}});
    d.j["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 2;
    expectRefused(writeGltf("unnormalized", d), {"NORMAL (accessor 2)", "integer normals must be normalized"});
    d.j["accessors"][2]["normalized"] = true;
    const Mesh m = loadGltf(writeGltf("normalized", d));
    EXPECT_FLOAT_EQ(m.normals[0].z, 1.0f);
}

// extensionsRequired is read first: one shadelab does not decode is named; one only used is a warning.
TEST_F(Gltf, RequiredExtensionsAreNamedAndUsedOnesWarned) {
    Doc d;
    d.j["extensionsUsed"] = json::array({"KHR_texture_basisu", "KHR_materials_sheen", "KHR_lights_punctual", "EXT_lights_ies"});
    d.j["extensionsRequired"] = json::array({"KHR_texture_basisu"});
    expectRefused(writeGltf("basisu", d), {"requires KHR_texture_basisu, which shadelab does not read"});
    d.j.erase("extensionsRequired");
    GltfInfo info;
    loadGltf(writeGltf("used", d), &info);
    ASSERT_EQ(info.warnings.size(), 1u);  // one line for all of them
    EXPECT_EQ(info.warnings[0],
              "uses KHR_texture_basisu, KHR_materials_sheen, EXT_lights_ies, which shadelab does not read: textures "
              "stored only in those formats are not drawn (a PNG or JPEG fallback is); the lecture's model and the base "
              "colour shade every material; what the others add is not drawn");
}

// EXT_mesh_gpu_instancing: the node's mesh once per instance, T * R * S of each, after the node's own
// transform; instances count as nodes against the instance cap.
TEST_F(Gltf, EveryGpuInstanceIsDrawn) {
    Doc d;
    append<float>(d.bin, {10, 0, 0, 0, 20, 0});                            // TRANSLATION, 2 instances
    append<float>(d.bin, {0, 0, 0, 1, 0, 0, 0.70710678f, 0.70710678f});    // ROTATION: identity, 90° about z
    append<float>(d.bin, {1, 1, 1, 2, 2, 2});                              // SCALE
    d.j["buffers"][0]["byteLength"] = d.bin.size();
    d.j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 60}, {"byteLength", 24}});
    d.j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 84}, {"byteLength", 32}});
    d.j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 116}, {"byteLength", 24}});
    d.j["accessors"].push_back({{"bufferView", 2}, {"componentType", 5126}, {"count", 2}, {"type", "VEC3"}});
    d.j["accessors"].push_back({{"bufferView", 3}, {"componentType", 5126}, {"count", 2}, {"type", "VEC4"}});
    d.j["accessors"].push_back({{"bufferView", 4}, {"componentType", 5126}, {"count", 2}, {"type", "VEC3"}});
    d.j["nodes"][0]["translation"] = {0, 0, 5};
    d.j["nodes"][0]["extensions"] = {{"EXT_mesh_gpu_instancing", {{"attributes", {{"TRANSLATION", 2}, {"ROTATION", 3}, {"SCALE", 4}}}}}};
    d.j["extensionsUsed"] = d.j["extensionsRequired"] = json::array({"EXT_mesh_gpu_instancing"});
    GltfInfo info;
    const Mesh m = loadGltf(writeGltf("instanced", d), &info);
    ASSERT_EQ(m.positions.size(), 8u);
    EXPECT_EQ(info.triangles, 4u);
    EXPECT_EQ(info.nodes, 2);
    // Instance 0: moved by (10, 0, 5). Instance 1: scaled 2, turned 90° about z, moved by (0, 20, 5):
    // the quad's corner (1, 0, 0) lands at (0, 2, 0) + (0, 20, 5).
    EXPECT_NEAR(glm::distance(m.positions[1], glm::vec3(11, 0, 5)), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::distance(m.positions[5], glm::vec3(0, 22, 5)), 0.0f, 1e-5f);
    // For the renderer's instanced draws: the quad once (as instance 0 places it) and each instance's
    // transform relative to that, the first the identity.
    ASSERT_TRUE(m.instanced);
    const Mesh& once = *m.instanced;
    ASSERT_EQ(once.positions.size(), 4u);
    ASSERT_EQ(once.parts.size(), 1u);
    ASSERT_EQ(once.parts[0].instances.size(), 2u);
    EXPECT_EQ(once.parts[0].instances[0], glm::mat4(1.0f));
    for (int v = 0; v < 4; ++v) {
        const glm::vec3 second(once.parts[0].instances[1] * glm::vec4(once.positions[std::size_t(v)], 1.0f));
        EXPECT_NEAR(glm::distance(second, m.positions[std::size_t(4 + v)]), 0.0f, 1e-4f) << v;
    }
}

// A glTF camera looks down its node's -Z with +Y up (glTF 2.0, 3.10.1), placed by the node's world
// transform; --info lists them in the order the scene reaches them and --camera N looks through one.
TEST_F(Gltf, CamerasArePlacedByTheirNodes) {
    Doc d;
    d.j["cameras"] = json::array({{{"type", "perspective"}, {"name", "front"},
                                   {"perspective", {{"yfov", 0.5}, {"znear", 0.05}, {"zfar", 50}}}},
                                  {{"type", "orthographic"}, {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0}, {"zfar", 9}}}}});
    // Node 1: the first camera 4 units along +z looking back at the quad; node 2, a child of it turned
    // 90 degrees about y: the orthographic one, looking along -x.
    d.j["nodes"] = json::array({{{"mesh", 0}, {"children", {1}}},
                                {{"camera", 0}, {"translation", {0.5, 0.5, 4}}, {"children", {2}}},
                                {{"camera", 1}, {"rotation", {0, 0.70710678, 0, 0.70710678}}}});
    GltfInfo info;
    loadGltf(writeGltf("cameras", d), &info);
    ASSERT_EQ(info.cameras.size(), 2u);
    const GltfCamera& c = info.cameras[0];
    EXPECT_EQ(c.name, "front");
    EXPECT_TRUE(c.perspective);
    EXPECT_NEAR(glm::distance(c.eye, glm::vec3(0.5f, 0.5f, 4.0f)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(c.target, glm::vec3(0.5f, 0.5f, 0.0f)), 0.0f, 1e-5f);  // level with the quad's centre
    EXPECT_NEAR(glm::distance(c.up, glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
    EXPECT_NEAR(c.yfovDeg, 28.6479f, 1e-3f);
    EXPECT_FLOAT_EQ(c.znear, 0.05f);
    EXPECT_FLOAT_EQ(c.zfar, 50.0f);
    EXPECT_FALSE(info.cameras[1].perspective);
    const glm::vec3 look = glm::normalize(info.cameras[1].target - info.cameras[1].eye);
    EXPECT_NEAR(glm::distance(look, glm::vec3(-1, 0, 0)), 0.0f, 1e-5f);
    EXPECT_NE(describe("cameras.gltf", info).find("camera 0: front, perspective, 29 degrees (--camera 0)"), std::string::npos);
}

// The object texture of the lecture's C (issue 15): a base colour texture's image, sampler, texture
// coordinates and the vertex colours, as the importer hands them to the renderer.
namespace {

// The quad of Doc with TEXCOORD_0 (accessor 2), COLOR_0 (accessor 3, normalized UNSIGNED_BYTE VEC4)
// and a material whose base colour texture is image 0 with sampler 0.
Doc texturedQuad(const json& image) {
    Doc d;
    append<float>(d.bin, {0, 0, 1, 0, 1, 1, 0, 1});                      // 60..91: TEXCOORD_0
    d.bin.insert(d.bin.end(), {255, 51, 0, 255, 0, 255, 102, 255, 255, 255, 255, 255, 0, 0, 0, 128});  // 92..107: COLOR_0
    d.j["buffers"][0]["byteLength"] = d.bin.size();
    d.j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 60}, {"byteLength", 32}});
    d.j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 92}, {"byteLength", 16}});
    d.j["accessors"].push_back({{"bufferView", 2}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}});
    d.j["accessors"].push_back(
        {{"bufferView", 3}, {"componentType", 5121}, {"normalized", true}, {"count", 4}, {"type", "VEC4"}});
    json& prim = d.j["meshes"][0]["primitives"][0];
    prim["attributes"]["TEXCOORD_0"] = 2;
    prim["attributes"]["COLOR_0"] = 3;
    prim["material"] = 0;
    d.j["materials"] = json::array({{{"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 1, 1, 1}}, {"baseColorTexture", {{"index", 0}}}}}}});
    d.j["textures"] = json::array({{{"source", 0}, {"sampler", 0}}});
    d.j["samplers"] = json::array({{{"magFilter", 9728}, {"minFilter", 9729}, {"wrapS", 33071}, {"wrapT", 33648}}});
    d.j["images"] = json::array({image});
    return d;
}

// A 2 x 2 RGBA image: red, green / blue, white (top row first).
Image twoByTwo() {
    Image im(2, 2);
    const std::uint8_t px[4][4] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {255, 255, 255, 255}};
    for (int i = 0; i < 4; ++i) std::memcpy(im.pixel(i % 2, i / 2), px[i], 4);
    return im;
}

std::vector<unsigned char> fileBytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void expectTwoByTwo(const Mesh& m) {
    ASSERT_EQ(m.textures.size(), 1u);
    const TextureImage& t = *m.textures[0];
    ASSERT_EQ(t.width, 2);
    ASSERT_EQ(t.height, 2);
    const std::vector<std::uint8_t> expected = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
    EXPECT_EQ(t.rgba, expected);
}

// The file loads, its one part without a texture (in its base colour), with a warning containing `why`.
Mesh expectDrawnWithoutTexture(const std::string& file, const std::string& why) {
    GltfInfo info;
    Mesh m = loadGltf(file, &info);
    EXPECT_EQ(m.parts.size(), 1u);
    EXPECT_TRUE(!m.parts.empty() && m.parts[0].texture == -1);
    bool found = false;
    for (const std::string& w : info.warnings) found = found || w.find(why) != std::string::npos;
    EXPECT_TRUE(found) << (info.warnings.empty() ? "no warning" : info.warnings[0]);
    return m;
}

}  // namespace

TEST_F(Gltf, BaseColourTextureCoordinatesAndVertexColoursAreRead) {
    writePng((dir_ / "model" / "tex.png").string(), twoByTwo());
    GltfInfo info;
    const Mesh m = loadGltf(writeGltf("textured", texturedQuad({{"uri", "tex.png"}})), &info);
    EXPECT_EQ(info.textures, 1);
    expectTwoByTwo(m);
    EXPECT_EQ(m.textures[0]->wrapS, 0x812F);      // CLAMP_TO_EDGE
    EXPECT_EQ(m.textures[0]->wrapT, 0x8370);      // MIRRORED_REPEAT
    EXPECT_EQ(m.textures[0]->magFilter, 0x2600);  // NEAREST
    EXPECT_EQ(m.textures[0]->minFilter, 0x2601);  // LINEAR: no mipmaps
    ASSERT_TRUE(m.variesColor());
    ASSERT_EQ(m.texcoords.size(), 4u);
    EXPECT_EQ(m.texcoords[2], glm::vec2(1, 1));
    ASSERT_EQ(m.colors.size(), 4u);
    EXPECT_FLOAT_EQ(m.colors[0].g, 0.2f);         // 51 / 255
    EXPECT_EQ(m.colors[1], glm::vec4(0, 1, 0.4f, 1));
    EXPECT_FLOAT_EQ(m.colors[3].a, 128.0f / 255);  // a VEC4's alpha (the coverage's, with MASK or BLEND)
    ASSERT_EQ(m.parts.size(), 1u);
    EXPECT_EQ(m.parts[0].texture, 0);
    EXPECT_EQ(m.parts[0].baseColor, glm::vec3(0.5f, 1, 1));

    // The same image embedded as a data: URI and, in a .glb, in a buffer view.
    const std::vector<unsigned char> png = fileBytes(dir_ / "model" / "tex.png");
    expectTwoByTwo(loadGltf(writeGltf("data_uri", texturedQuad({{"uri", "data:image/png;base64," + base64(png)}}))));
    Doc glb = texturedQuad({{"bufferView", 4}, {"mimeType", "image/png"}});
    glb.j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", glb.bin.size()}, {"byteLength", png.size()}});
    glb.bin.insert(glb.bin.end(), png.begin(), png.end());
    glb.j["buffers"][0]["byteLength"] = glb.bin.size();
    expectTwoByTwo(loadGltf(writeGlb("buffer_view", glb)));
    // A byteStride on the image's view does not apply to it; an empty view is a warning, not a crash.
    glb.j["bufferViews"][4]["byteStride"] = 4;
    expectTwoByTwo(loadGltf(writeGlb("buffer_view_stride", glb)));
    glb.j["bufferViews"][4].erase("byteStride");
    glb.j["bufferViews"][4]["byteLength"] = 0;
    expectDrawnWithoutTexture(writeGlb("buffer_view_empty", glb), "bufferView is empty");
}

// KHR_mesh_quantization allows TEXCOORD_n and COLOR_n in integer types too.
TEST_F(Gltf, QuantizedTextureCoordinatesAndColoursDequantize) {
    writePng((dir_ / "model" / "tex.png").string(), twoByTwo());
    Doc d = texturedQuad({{"uri", "tex.png"}});
    d.bin.resize(60);
    append<std::uint16_t>(d.bin, {0, 0, 65535, 0, 65535, 32768, 13107, 65535});  // 60..75: UNSIGNED_SHORT normalized
    append<std::int8_t>(d.bin, {-3, 2, 5, 0, 0, 1, 127, -128});                  // 76..83: BYTE as it is
    append<std::uint16_t>(d.bin, {65535, 0, 13107, 0, 0, 0, 1, 2, 3, 4, 5, 6});     // 84..107: COLOR_0 UNSIGNED_SHORT normalized VEC3
    d.j["buffers"][0]["byteLength"] = d.bin.size();
    d.j["bufferViews"][2] = {{"buffer", 0}, {"byteOffset", 60}, {"byteLength", 16}};
    d.j["bufferViews"][3] = {{"buffer", 0}, {"byteOffset", 84}, {"byteLength", 24}};
    d.j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 76}, {"byteLength", 8}});
    d.j["accessors"][2] = {{"bufferView", 2}, {"componentType", 5123}, {"normalized", true}, {"count", 4}, {"type", "VEC2"}};
    d.j["accessors"][3] = {{"bufferView", 3}, {"componentType", 5123}, {"normalized", true}, {"count", 4}, {"type", "VEC3"}};
    d.j["accessors"].push_back({{"bufferView", 4}, {"componentType", 5120}, {"count", 4}, {"type", "VEC2"}});
    d.j["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_1"] = 4;
    d.j["extensionsUsed"] = d.j["extensionsRequired"] = json::array({"KHR_mesh_quantization"});
    Mesh m = loadGltf(writeGltf("quantized", d));
    ASSERT_EQ(m.texcoords.size(), 4u);
    EXPECT_EQ(m.texcoords[1], glm::vec2(1, 0));
    EXPECT_FLOAT_EQ(m.texcoords[2].y, 32768.0f / 65535);
    EXPECT_FLOAT_EQ(m.texcoords[3].x, 0.2f);
    EXPECT_FLOAT_EQ(m.colors[0].r, 1.0f);
    EXPECT_FLOAT_EQ(m.colors[0].b, 0.2f);
    EXPECT_FLOAT_EQ(m.colors[3].g, 5.0f / 65535);
    // The texture reads TEXCOORD_1: unnormalized BYTEs as they are.
    d.j["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["texCoord"] = 1;
    m = loadGltf(writeGltf("quantized_set1", d));
    EXPECT_EQ(m.texcoords[0], glm::vec2(-3, 2));
    EXPECT_EQ(m.texcoords[3], glm::vec2(127, -128));
}

// KHR_texture_transform's own example (its README): offset [0, 1], rotation pi/2, scale 0.5 uses
// "only the lower left quadrant of the source image, rotated clockwise 90 degrees".
TEST_F(Gltf, TextureTransformFollowsTheExtensionsExample) {
    writePng((dir_ / "model" / "tex.png").string(), twoByTwo());
    Doc d = texturedQuad({{"uri", "tex.png"}});
    d.j["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"]["KHR_texture_transform"] = {
        {"offset", {0, 1}}, {"rotation", 1.57079632679}, {"scale", {0.5, 0.5}}};
    d.j["extensionsUsed"] = d.j["extensionsRequired"] = json::array({"KHR_texture_transform"});
    GltfInfo info;
    const Mesh m = loadGltf(writeGltf("transform", d), &info);
    EXPECT_TRUE(info.warnings.empty());
    const glm::vec2 expected[4] = {{0, 1}, {0, 0.5f}, {0.5f, 0.5f}, {0.5f, 1}};  // uv (0,0), (1,0), (1,1), (0,1)
    for (int i = 0; i < 4; ++i) {
        EXPECT_NEAR(m.texcoords[std::size_t(i)].x, expected[i].x, 1e-6f) << i;
        EXPECT_NEAR(m.texcoords[std::size_t(i)].y, expected[i].y, 1e-6f) << i;
    }
}

// Which way KHR_texture_transform's rotation turns (issue 27). The spec's formula is uv' = T R S uv with
// R = [[cos, sin], [-sin, cos]] (rows), the matrix its example needs ("the lower left quadrant ...
// rotated clockwise 90 degrees", the test above) and that three.js, Babylon.js and Blender use; its
// GLSL listing, read as GLSL reads a mat3 (column by column), is the transpose, which turns the other
// way (KhronosGroup/glTF#1563). A 4 x 4 image with a red texel at its top-left and a green one at its
// top-right, repeated, rotation 90 degrees alone: at the quad's point (u, v) the texel at (v, -u)
// shows, so the quad shows the image turned 90 degrees clockwise as an image is drawn (v down): red
// top-right, green bottom-right. Turned the other way, red would be bottom-left; mirrored, green
// would stay in the top row.
TEST_F(Gltf, TextureRotationTurnsTheImageClockwise) {
    Image image(4, 4);
    std::fill(image.rgba.begin(), image.rgba.end(), std::uint8_t(255));  // white
    const std::uint8_t red[4] = {255, 0, 0, 255}, green[4] = {0, 255, 0, 255};
    std::memcpy(image.pixel(0, 0), red, 4);
    std::memcpy(image.pixel(3, 0), green, 4);
    writePng((dir_ / "model" / "marks.png").string(), image);
    Doc d = texturedQuad({{"uri", "marks.png"}});
    d.j["samplers"][0] = {{"magFilter", 9728}, {"minFilter", 9728}, {"wrapS", 10497}, {"wrapT", 10497}};  // NEAREST, REPEAT
    d.j["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"]["KHR_texture_transform"] = {
        {"rotation", 1.5707963267948966}};
    d.j["extensionsUsed"] = json::array({"KHR_texture_transform"});
    const Mesh m = loadGltf(writeGltf("rotation", d));
    ASSERT_EQ(m.textures.size(), 1u);
    ASSERT_EQ(m.texcoords.size(), 4u);
    // The quad's own coordinates are its x and y (texturedQuad); the transform is affine, so the
    // coordinates at (u, v) follow from three corners.
    const glm::vec2 t0 = m.texcoords[0], du = m.texcoords[1] - t0, dv = m.texcoords[3] - t0;
    const auto shown = [&](int x, int y) {  // the colour at the quad's texel (x, y), row 0 at v = 0
        const glm::vec3 c = sampleTexture(*m.textures[0], t0 + du * ((float(x) + 0.5f) / 4) + dv * ((float(y) + 0.5f) / 4));
        return glm::ivec3(glm::round(c * 255.0f));
    };
    EXPECT_EQ(shown(3, 0), glm::ivec3(255, 0, 0));  // red: from the top-left to the top-right
    EXPECT_EQ(shown(3, 3), glm::ivec3(0, 255, 0));  // green: from the top-right to the bottom-right
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            const std::uint8_t* turned = image.pixel(y, 3 - x);  // the image turned 90 degrees clockwise
            EXPECT_EQ(shown(x, y), glm::ivec3(turned[0], turned[1], turned[2])) << x << ", " << y;
        }
}

// A texture that cannot be drawn never stops the model: the part keeps its base colour, with a warning
// that names the image and says why. Its URI stays inside the model's folder.
TEST_F(Gltf, TexturesThatCannotBeDrawnAreWarnedNotFatal) {
    std::ofstream(dir_ / "model" / "not_an_image.png") << "hello";
    writePng((dir_ / "secret.png").string(), twoByTwo());
    const struct {
        json image;
        const char* warning;
    } cases[] = {
        {{{"uri", "missing.png"}}, "missing.png could not be read; drawn in its base colour"},
        {{{"uri", "not_an_image.png"}}, "not_an_image.png is not an image shadelab decodes (PNG or JPEG)"},
        {{{"uri", "../secret.png"}}, "../secret.png could not be read"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.warning);
        const Mesh m = expectDrawnWithoutTexture(writeGltf("broken", texturedQuad(c.image)), c.warning);
        EXPECT_TRUE(m.textures.empty());
        EXPECT_TRUE(m.variesColor());  // COLOR_0 is still drawn
    }
    // A texture whose coordinate set the primitive lacks.
    writePng((dir_ / "model" / "tex.png").string(), twoByTwo());
    Doc d = texturedQuad({{"uri", "tex.png"}});
    d.j["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["texCoord"] = 3;
    expectDrawnWithoutTexture(writeGltf("no_set", d), "reads TEXCOORD_3, which it does not have");
}

// KHR_lights_punctual: each node that uses a light places it (its origin, its -Z), with the file's
// colour, intensity, range and cone; the scene's lights when it gives none, converted to L_l by one
// factor (scene_geometry.hpp, lecturesLights).
TEST_F(Gltf, PunctualLightsArePlacedByTheirNodes) {
    Doc d;
    d.j["extensionsUsed"] = json::array({"KHR_lights_punctual"});
    d.j["extensions"]["KHR_lights_punctual"]["lights"] = json::array({
        {{"type", "point"}, {"intensity", 40}, {"range", 12}, {"color", {1, 0.5, 0.25}}, {"name", "bulb"}},
        {{"type", "spot"}, {"intensity", 160}, {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.5}}}},
        {{"type", "directional"}, {"intensity", 2}}});
    d.j["scenes"][0]["nodes"] = json::array({0, 1, 2, 3});
    d.j["nodes"].push_back({{"translation", {0, 2, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    // The spot 4 above the origin, turned to look down: rotation of -90 degrees about x takes -Z to -Y.
    d.j["nodes"].push_back({{"translation", {0.5, 4, 0.5}}, {"rotation", {-0.70710678, 0, 0, 0.70710678}},
                            {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
    d.j["nodes"].push_back({{"extensions", {{"KHR_lights_punctual", {{"light", 2}}}}}});
    GltfInfo info;
    loadGltf(writeGltf("lights", d), &info);
    EXPECT_TRUE(info.warnings.empty()) << info.warnings[0];
    ASSERT_EQ(info.lights.size(), 3u);
    const Light& bulb = info.lights[0].light;
    EXPECT_EQ(info.lights[0].name, "bulb");
    EXPECT_EQ(bulb.type, LightType::Point);
    EXPECT_EQ(bulb.position, glm::vec3(0, 2, 0));
    EXPECT_EQ(bulb.attenuation, Attenuation::InverseSquare);
    EXPECT_FLOAT_EQ(bulb.range, 12.0f);
    EXPECT_EQ(bulb.color, glm::vec3(1, 0.5f, 0.25f));
    const Light& spot = info.lights[1].light;
    EXPECT_EQ(spot.type, LightType::Spot);
    EXPECT_NEAR(spot.direction.y, -1.0f, 1e-6f);
    EXPECT_NEAR(spot.outerConeDeg, 28.6479f, 1e-3f);  // 0.5 rad
    EXPECT_NEAR(spot.innerConeDeg, 11.4592f, 1e-3f);
    EXPECT_EQ(info.lights[2].light.type, LightType::Directional);
    EXPECT_NEAR(info.lights[2].light.direction.z, -1.0f, 1e-6f);

    // As the scene's lights: the quad's bounding sphere is centred at (0.5, 0.5, 0), radius ~0.707.
    // Illuminance there: bulb 40 / r^2 * window (r^2 = 2.5), spot 160 / 16.25 * its cone (on its
    // axis's side), sun 2: the brightest is the bulb's, which becomes L = 1.
    const std::vector<Light> lit = lecturesLights(info.lights, glm::mat4(1.0f), BoundingSphere{{0.5f, 0.5f, 0.0f}, 0.7071f});
    ASSERT_EQ(lit.size(), 3u);
    const float q = 2.5f / 144.0f, window = (1.0f - q * q) * (1.0f - q * q);
    const float bulbAtCentre = 40.0f / 2.5f * window;
    EXPECT_NEAR(lit[0].intensity, 40.0f / bulbAtCentre, 1e-4f);
    EXPECT_NEAR(lit[2].intensity, 2.0f / bulbAtCentre, 1e-5f);
    EXPECT_NEAR(lit[1].intensity / lit[0].intensity, 4.0f, 1e-4f);  // the file's ratios stay

    // A scene that gives no lights is lit by the model's; one that gives lights keeps them.
    Scene scene;
    scene.objects[0].mesh.type = MeshSpec::Type::Gltf;
    scene.objects[0].mesh.resolvedPath = (dir_ / "model" / "lights.gltf").string();
    Scene given = scene;
    given.lightsGiven = true;
    const SceneGeometry g = buildSceneGeometry(scene);
    frameIfNeeded(scene, g);
    ASSERT_EQ(scene.lights.size(), 3u);
    EXPECT_EQ(scene.lights[1].type, LightType::Spot);
    EXPECT_TRUE(scene.lightsGiven);
    frameIfNeeded(given, g);
    ASSERT_EQ(given.lights.size(), 1u);
    EXPECT_EQ(given.lights[0].type, LightType::Point);

    // A cone narrower than shadelab's smallest (0.01 degrees) is widened to it, so the scene saves
    // and loads back.
    d.j["extensions"]["KHR_lights_punctual"]["lights"][1]["spot"] = {{"innerConeAngle", 0}, {"outerConeAngle", 1e-6}};
    GltfInfo narrow;
    loadGltf(writeGltf("narrow", d), &narrow);
    EXPECT_FLOAT_EQ(narrow.lights[1].light.outerConeDeg, 0.01f);
    EXPECT_FLOAT_EQ(narrow.lights[1].light.innerConeDeg, 0.0f);

    // A light index that does not exist, or a cone the extension forbids, is refused naming it.
    d.j["nodes"][3]["extensions"]["KHR_lights_punctual"]["light"] = 7;
    expectRefused(writeGltf("no_light", d), {"node 3 KHR_lights_punctual", "light 7 does not exist"});
    d.j["nodes"][3]["extensions"]["KHR_lights_punctual"]["light"] = 1;
    d.j["extensions"]["KHR_lights_punctual"]["lights"][1]["spot"]["innerConeAngle"] = 0.6;
    expectRefused(writeGltf("bad_cone", d), {"light 1", "innerConeAngle < outerConeAngle"});
    // The extension's types are point, directional and spot: shadelab's "area" is not one of them.
    d.j["extensions"]["KHR_lights_punctual"]["lights"][1] = {{"type", "area"}, {"intensity", 1}};
    expectRefused(writeGltf("area", d), {"light 1", "type \"area\" is not point, directional or spot"});
}

// glTF's colours are linear values meant for an sRGB display: a scene that draws a model is written
// sRGB-encoded unless it chooses its encoding, whatever stores the colour (a factor, COLOR_0, a texture)
// and whether a texture is drawn; the lecture's procedural scenes keep theirs (issue 27: textures,
// --no-textures, a scene colour or an untextured model used to switch it to linear).
TEST(SharedModels, ModelsAreWrittenSrgbUnlessTheSceneSaysOtherwise) {
    const std::string models = std::string(SHADELAB_SOURCE_DIR) + "/assets/models/";
    const auto encodingAfterFraming = [](Scene s) {
        const SceneGeometry g = buildSceneGeometry(s);
        frameIfNeeded(s, g);
        return s.outputEncoding;
    };
    Scene scene;
    scene.objects[0].mesh.type = MeshSpec::Type::Gltf;
    scene.objects[0].mesh.resolvedPath = models + "checker_globe.gltf";
    EXPECT_EQ(encodingAfterFraming(scene), OutputEncoding::Srgb);
    Scene chosen = scene;
    chosen.outputEncodingGiven = true;  // "output_encoding": "linear"
    EXPECT_EQ(encodingAfterFraming(chosen), OutputEncoding::Linear);
    Scene untextured = scene;
    untextured.textures = false;
    EXPECT_EQ(encodingAfterFraming(untextured), OutputEncoding::Srgb);
    Scene coloured = scene;
    coloured.objects[0].material.colorSet = true;
    EXPECT_EQ(encodingAfterFraming(coloured), OutputEncoding::Srgb);
    Scene factorsOnly = scene;  // colours as base colour factors, no image
    factorsOnly.objects[0].mesh.resolvedPath = models + "lowpoly_gem.gltf";
    EXPECT_EQ(encodingAfterFraming(factorsOnly), OutputEncoding::Srgb);
    Scene missingImage = scene;  // the texture's image is not there: a warning, and the same encoding
    const shadelab::test::TestDir dir("gltf");  // the model without checker_globe.png beside it
    std::filesystem::copy_file(models + "checker_globe_transform.gltf", dir.path / "globe.gltf");
    missingImage.objects[0].mesh.resolvedPath = (dir.path / "globe.gltf").string();
    EXPECT_EQ(encodingAfterFraming(missingImage), OutputEncoding::Srgb);
    EXPECT_EQ(encodingAfterFraming(Scene{}), OutputEncoding::Linear);  // procedural: the scene's own choice
}

// The materials' alpha and emission (assets/models/material_panels.gltf): MASK with its cutoff and
// COLOR_0 as RGBA, BLEND with the factor's alpha, E = factor x strength with its texture at TEXCOORD_1.
TEST(SharedModels, MaterialAlphaAndEmissionAreRead) {
    const Mesh m = loadGltf(std::string(SHADELAB_SOURCE_DIR) + "/assets/models/material_panels.gltf");
    ASSERT_EQ(m.parts.size(), 3u);
    EXPECT_EQ(m.parts[0].alphaMode, AlphaMode::Mask);
    EXPECT_FLOAT_EQ(m.parts[0].alphaCutoff, 0.5f);
    EXPECT_GE(m.parts[0].texture, 0);
    EXPECT_EQ(m.parts[1].alphaMode, AlphaMode::Blend);
    EXPECT_FLOAT_EQ(m.parts[1].baseAlpha, 0.5f);
    EXPECT_EQ(m.parts[2].alphaMode, AlphaMode::Opaque);
    EXPECT_EQ(m.parts[2].emissive, glm::vec3(2.0f, 1.0f, 0.5f));  // (1, 0.5, 0.25) x strength 2
    EXPECT_GE(m.parts[2].emissiveTexture, 0);
    EXPECT_EQ(m.parts[0].emissive, glm::vec3(0.0f));
    ASSERT_TRUE(m.hasEmissiveTexture());
    ASSERT_EQ(m.emissiveTexcoords.size(), m.positions.size());
    ASSERT_EQ(m.colors.size(), m.positions.size());
    EXPECT_EQ(m.colors[0], glm::vec4(1.0f));
    // The lamp's TEXCOORD_1 is its TEXCOORD_0 turned a quarter (make_models.py): u1 = y + 0.5, v1 = x - 1.2 + 0.5.
    for (std::uint32_t i = m.parts[2].firstIndex; i < m.parts[2].firstIndex + m.parts[2].indexCount; ++i) {
        const glm::vec3& p = m.positions[m.indices[i]];
        EXPECT_NEAR(m.emissiveTexcoords[m.indices[i]].x, p.y + 0.5f, 1e-6f);
        EXPECT_NEAR(m.emissiveTexcoords[m.indices[i]].y, p.x - 1.2f + 0.5f, 1e-6f);
    }
}

// Issue 30 (anisotropy): TANGENT is the tangent frame where the file gives it: xyz made orthogonal to
// the normal, w the handedness; a mirroring node flips the handedness. Without it the quad, which has
// no texture coordinates, gets the frame around the up axis.
TEST_F(Gltf, TangentGivesTheTangentFrame) {
    Doc d;
    append<float>(d.bin, {0, 1, 0.1f, -1, 0, 1, 0, -1, 0, 1, 0, -1, 0, 1, 0, -1});
    d.j["buffers"][0]["byteLength"] = 124;
    d.j["bufferViews"].push_back(json{{"buffer", 0}, {"byteOffset", 60}, {"byteLength", 64}});
    d.j["accessors"].push_back(json{{"bufferView", 2}, {"componentType", 5126}, {"count", 4}, {"type", "VEC4"}});
    d.j["meshes"][0]["primitives"][0]["attributes"]["TANGENT"] = 2;
    const Mesh m = loadGltf(writeGltf("tangents", d));
    ASSERT_EQ(m.tangents.size(), 4u);
    for (const glm::vec4& t : m.tangents) {
        EXPECT_NEAR(glm::distance(glm::vec3(t), glm::vec3(0, 1, 0)), 0.0f, 1e-6f);  // z removed: orthogonal to N = +z
        EXPECT_EQ(t.w, -1.0f);
    }
    d.j["nodes"][0]["scale"] = json::array({-1, 1, 1});
    const Mesh mirrored = loadGltf(writeGltf("mirrored", d));
    for (const glm::vec4& t : mirrored.tangents) EXPECT_EQ(t.w, 1.0f);
    const Mesh plain = loadGltf(writeGltf("plain", Doc()));
    ASSERT_EQ(plain.tangents.size(), 4u);
    for (const glm::vec4& t : plain.tangents) EXPECT_EQ(t, tangentAroundUp(glm::vec3(0, 0, 1)));
}
