#include "core/geometry/mesh.hpp"
#include "render/cpu/vertex_order.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <gtest/gtest.h>
#include <tuple>

using namespace shadelab;

namespace {

// A triangle as its three corners (position and normal) in index order: the rotation counts,
// because the last corner is GL's provoking vertex and the order of the corners is the winding.
using Corner = std::array<float, 6>;
using Triangle = std::array<Corner, 3>;

std::vector<Triangle> triangles(const Mesh& m, std::size_t firstIndex, std::size_t indexCount) {
    std::vector<Triangle> out;
    for (std::size_t i = firstIndex; i < firstIndex + indexCount; i += 3) {
        Triangle t;
        for (int c = 0; c < 3; ++c) {
            const glm::vec3 p = m.positions[m.indices[i + std::size_t(c)]], n = m.normals[m.indices[i + std::size_t(c)]];
            t[std::size_t(c)] = {p.x, p.y, p.z, n.x, n.y, n.z};
        }
        out.push_back(t);
    }
    std::sort(out.begin(), out.end());
    return out;
}

double runsPerTriangle(const std::vector<std::uint32_t>& indices) {
    return double(vertexShaderRuns(indices)) / double(indices.size() / 3);
}

}  // namespace

TEST(VertexOrder, ModelOfMesasDrawModuleCountsMissesPerSegment) {
    // Repeats inside a segment are free, a new segment starts empty, and indices 256 apart share a slot.
    EXPECT_EQ(vertexShaderRuns({0, 1, 2, 2, 1, 3}), 4u);
    EXPECT_EQ(vertexShaderRuns({0, 1, 2, 2, 1, 3}, 3), 6u);
    EXPECT_EQ(vertexShaderRuns({0, 256, 0}), 3u);
    EXPECT_EQ(vertexShaderRuns({}), 0u);
}

TEST(VertexOrder, SameTrianglesSameCornersSameRotation) {
    for (const Mesh& m : {makeUvSphere(48, 24, 1.0f), makeIcoSphere(3, 1.0f), makeTorus(1, 0.3f, 40, 20), makeCube(2.0f),
                          makePlane(2.0f, 7)}) {
        const Mesh o = orderedForVertexCache(m);
        ASSERT_EQ(o.positions.size(), m.positions.size());
        ASSERT_EQ(o.normals.size(), m.normals.size());
        ASSERT_EQ(o.indices.size(), m.indices.size());
        EXPECT_EQ(triangles(o, 0, o.indices.size()), triangles(m, 0, m.indices.size()));
        // A permutation of the vertices: each one kept, none duplicated.
        std::vector<std::array<float, 6>> before, after;
        for (std::size_t v = 0; v < m.positions.size(); ++v) {
            before.push_back({m.positions[v].x, m.positions[v].y, m.positions[v].z, m.normals[v].x, m.normals[v].y, m.normals[v].z});
            after.push_back({o.positions[v].x, o.positions[v].y, o.positions[v].z, o.normals[v].x, o.normals[v].y, o.normals[v].z});
        }
        std::sort(before.begin(), before.end());
        std::sort(after.begin(), after.end());
        EXPECT_EQ(before, after);
    }
}

TEST(VertexOrder, PartsKeepTheirRangesAndTheirTriangles) {
    // Two spheres in one mesh, as a glTF file with two primitives is imported, plus an unused vertex.
    Mesh m = makeUvSphere(32, 16, 1.0f);
    const Mesh second = makeIcoSphere(2, 0.5f);
    const auto offset = std::uint32_t(m.positions.size());
    const auto firstCount = std::uint32_t(m.indices.size());
    m.positions.insert(m.positions.end(), second.positions.begin(), second.positions.end());
    m.normals.insert(m.normals.end(), second.normals.begin(), second.normals.end());
    for (std::uint32_t i : second.indices) m.indices.push_back(offset + i);
    m.positions.push_back(glm::vec3(9.0f));
    m.normals.push_back(glm::vec3(0, 1, 0));
    const auto part = [](std::uint32_t first, std::uint32_t count, bool hasColor, glm::vec3 color) {
        MeshPart p;
        p.firstIndex = first, p.indexCount = count, p.hasBaseColor = hasColor, p.baseColor = color;
        return p;
    };
    m.parts = {part(0, firstCount, true, glm::vec3(1, 0, 0)),
               part(firstCount, std::uint32_t(second.indices.size()), false, glm::vec3(1.0f))};

    const Mesh o = orderedForVertexCache(m);
    ASSERT_EQ(o.parts.size(), 2u);
    for (const MeshPart& p : o.parts)
        EXPECT_EQ(triangles(o, p.firstIndex, p.indexCount), triangles(m, p.firstIndex, p.indexCount));
    EXPECT_EQ(o.parts[0].baseColor, glm::vec3(1, 0, 0));
    // The unused vertex is kept, after every used one.
    EXPECT_EQ(o.positions.back(), glm::vec3(9.0f));

    // One part over only some of the indices: the triangles after it stay where they are.
    m.parts.resize(1);
    const Mesh one = orderedForVertexCache(m);
    EXPECT_EQ(triangles(one, 0, firstCount), triangles(m, 0, firstCount));
    for (std::size_t i = firstCount; i < m.indices.size(); ++i)
        ASSERT_EQ(one.positions[one.indices[i]], m.positions[m.indices[i]]) << "index " << i;
}

TEST(VertexOrder, FewerVertexShaderRunsOnTheBenchmarkSphere) {
    // ../shared/bench's sphere in its row order shades about one vertex per triangle in llvmpipe;
    // compact fans shade ~0.6. The measured frame-time effect is in bench/README.md.
    if (!SHADELAB_HAVE_MESHOPT) GTEST_SKIP() << "built without meshoptimizer (SHADELAB_MESHOPT off): triangles keep their order";
    const Mesh sphere = makeUvSphere(200, 100, 1.0f);
    const Mesh ordered = orderedForVertexCache(sphere);
    EXPECT_GT(runsPerTriangle(sphere.indices), 0.95);
    EXPECT_LT(runsPerTriangle(ordered.indices), 0.65);
    // Flat: every triangle needs a provoking vertex of its own, so at least one run per triangle.
    EXPECT_GT(runsPerTriangle(makeFlatMesh(sphere).indices), 1.4);
    EXPECT_LT(runsPerTriangle(makeOrderedFlatMesh(ordered).indices), 1.15);
}

TEST(VertexOrder, OrderedFlatMeshKeepsEachTrianglesFaceData) {
    const Mesh ordered = orderedForVertexCache(makeTorus(1, 0.3f, 24, 12));
    const FlatMesh f = makeOrderedFlatMesh(ordered);
    ASSERT_EQ(f.indices.size(), ordered.indices.size());
    std::vector<int> provokes(f.positions.size(), 0);
    for (std::size_t t = 0; t < ordered.triangleCount(); ++t) {
        const glm::vec3 a = ordered.positions[ordered.indices[3 * t]], b = ordered.positions[ordered.indices[3 * t + 1]],
                        c = ordered.positions[ordered.indices[3 * t + 2]];
        const std::uint32_t p = f.indices[3 * t + 2];
        const glm::vec3 fa = f.positions[f.indices[3 * t]], fb = f.positions[f.indices[3 * t + 1]], fc = f.positions[p];
        EXPECT_TRUE((fa == a && fb == b && fc == c) || (fa == b && fb == c && fc == a) || (fa == c && fb == a && fc == b));
        EXPECT_EQ(f.normals[p], faceNormal(a, b, c));
        EXPECT_NEAR(glm::distance(f.centroids[p], (a + b + c) / 3.0f), 0.0f, 1e-6f);
        ++provokes[p];
    }
    for (int count : provokes) EXPECT_LE(count, 1);
}

TEST(VertexOrder, TinyAndEmptyMeshes) {
    Mesh empty;
    EXPECT_TRUE(orderedForVertexCache(empty).indices.empty());
    Mesh one;
    one.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    one.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    one.indices = {2, 0, 1};
    const Mesh o = orderedForVertexCache(one);
    EXPECT_EQ(triangles(o, 0, 3), triangles(one, 0, 3));
    EXPECT_EQ(o.indices, (std::vector<std::uint32_t>{0, 1, 2}));  // renumbered by first use
}
