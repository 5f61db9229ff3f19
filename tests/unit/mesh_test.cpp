#include "core/geometry/camera.hpp"
#include "core/geometry/mesh.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <gtest/gtest.h>

using namespace shadelab;

namespace {

// Every triangle's lecture face normal agrees with its vertex normals (the right-hand rule gives the
// outside), and every normal is unit length.
void expectConsistent(const Mesh& m) {
    ASSERT_EQ(m.positions.size(), m.normals.size());
    ASSERT_EQ(m.indices.size() % 3, 0u);
    for (const auto& n : m.normals) ASSERT_NEAR(glm::length(n), 1.0f, 1e-5f);
    for (auto i : m.indices) ASSERT_LT(i, m.positions.size());
    for (size_t t = 0; t < m.indices.size(); t += 3) {
        const auto a = m.indices[t], b = m.indices[t + 1], c = m.indices[t + 2];
        const glm::vec3 n = faceNormal(m.positions[a], m.positions[b], m.positions[c]);
        ASSERT_GT(glm::dot(n, m.normals[a] + m.normals[b] + m.normals[c]), 0.0f) << "triangle " << t / 3;
    }
}

}  // namespace

TEST(Mesh, FaceNormalFollowsTheLectureFormula) {
    // counter-clockwise seen from +z
    EXPECT_EQ(faceNormal({0, 0, 0}, {1, 0, 0}, {0, 1, 0}), glm::vec3(0, 0, 1));
    EXPECT_EQ(faceNormal({0, 0, 0}, {0, 1, 0}, {1, 0, 0}), glm::vec3(0, 0, -1));
}

// Found by fuzz_gltf: a file's normal with denormal components (1e-44) passed a "length > 0" check
// and did not come out unit length. tests/fuzz/corpus/gltf/crash-denormal-normals.glb keeps it.
TEST(Mesh, SafeNormalizeGivesUnitVectorsOrTheFallback) {
    for (const glm::vec3& v : {glm::vec3(1e-44f, 0, 0), glm::vec3(3e-39f, 2e-39f, 0), glm::vec3(1e38f, 1e38f, 1e38f),
                               glm::vec3(0.3f, -4.0f, 12.0f), glm::vec3(1e-20f, 2e-20f, 2e-20f)}) {
        const glm::vec3 n = safeNormalize(v);
        EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f) << v.x << " " << v.y << " " << v.z;
    }
    EXPECT_EQ(safeNormalize(glm::vec3(1e-44f, 0, 0)), glm::vec3(0, 1, 0));  // direction lost: fallback
    EXPECT_EQ(safeNormalize(glm::vec3(0.0f)), glm::vec3(0, 1, 0));
    EXPECT_EQ(safeNormalize(glm::vec3(NAN, 0, 0), glm::vec3(1, 0, 0)), glm::vec3(1, 0, 0));
    EXPECT_EQ(safeNormalize(glm::vec3(INFINITY, 0, 0)), glm::vec3(0, 1, 0));
    EXPECT_EQ(safeNormalize(glm::vec3(0, NAN, 1)), glm::vec3(0, 1, 0));  // NaN after a finite component
    const glm::vec3 tiny = safeNormalize(glm::vec3(1e-20f, 2e-20f, 2e-20f));
    EXPECT_NEAR(tiny.x, 1.0f / 3.0f, 1e-6f);
}

TEST(Mesh, UvSphereMatchesTheBenchmarkLayout) {
    const Mesh m = makeUvSphere(46, 23, 1.0f);  // ../shared/bench: s = 23 gives 2,024 triangles
    EXPECT_EQ(m.triangleCount(), 2024u);
    EXPECT_EQ(m.positions.size(), size_t(24 * 47));
    expectConsistent(m);
    for (const auto& p : m.positions) EXPECT_NEAR(glm::length(p), 1.0f, 1e-5f);
    // Outward: the face normal points away from the centre.
    for (size_t t = 0; t < m.indices.size(); t += 3) {
        const glm::vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]], c = m.positions[m.indices[t + 2]];
        ASSERT_GT(glm::dot(faceNormal(a, b, c), a + b + c), 0.0f);
    }
}

TEST(Mesh, ProceduralShapesAreConsistentAndCountsAreRight) {
    const Mesh ico = makeIcoSphere(2, 2.0f);
    EXPECT_EQ(ico.triangleCount(), 20u * 16u);
    expectConsistent(ico);
    for (const auto& p : ico.positions) EXPECT_NEAR(glm::length(p), 2.0f, 1e-5f);
    const Mesh torus = makeTorus(1.0f, 0.25f, 12, 8);
    EXPECT_EQ(torus.triangleCount(), 2u * 12u * 8u);
    expectConsistent(torus);
    const Mesh cube = makeCube(2.0f);
    EXPECT_EQ(cube.triangleCount(), 12u);
    expectConsistent(cube);
    for (const auto& p : cube.positions) EXPECT_NEAR(std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}), 1.0f, 1e-6f);
    const Mesh plane = makePlane(4.0f, 3);
    EXPECT_EQ(plane.triangleCount(), 18u);
    expectConsistent(plane);
}

TEST(Mesh, FlatMeshGivesEachTriangleItsOwnProvokingVertex) {
    for (const Mesh& m : {makeIcoSphere(2, 1.0f), makeUvSphere(24, 12, 1.0f), makeCube(2.0f), makeTorus(1, 0.3f, 12, 8)}) {
        const FlatMesh f = makeFlatMesh(m);
        ASSERT_EQ(f.indices.size(), m.indices.size());
        std::vector<int> provokes(f.positions.size(), 0);
        for (size_t t = 0; t < m.triangleCount(); ++t) {
            const glm::vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                            c = m.positions[m.indices[3 * t + 2]];
            const glm::vec3 fa = f.positions[f.indices[3 * t]], fb = f.positions[f.indices[3 * t + 1]],
                            fc = f.positions[f.indices[3 * t + 2]];
            // The same triangle, its corners rotated (winding kept): (a,b,c), (b,c,a) or (c,a,b).
            const bool same = (fa == a && fb == b && fc == c) || (fa == b && fb == c && fc == a) ||
                              (fa == c && fb == a && fc == b);
            EXPECT_TRUE(same) << "triangle " << t;
            // Its last (provoking) vertex carries its face normal and centroid, and is nobody else's.
            const uint32_t p = f.indices[3 * t + 2];
            EXPECT_EQ(f.normals[p], faceNormal(a, b, c));
            EXPECT_NEAR(glm::distance(f.centroids[p], (a + b + c) / 3.0f), 0.0f, 1e-6f);
            ++provokes[p];
        }
        for (int count : provokes) EXPECT_LE(count, 1);
        // Far fewer vertices than one new vertex per triangle.
        EXPECT_LT(f.positions.size(), m.positions.size() + m.triangleCount());
    }
    const Mesh sphere = makeUvSphere(64, 32, 1.0f);
    EXPECT_LE(makeFlatMesh(sphere).positions.size(), size_t(1.1 * double(sphere.triangleCount())));
}

TEST(Mesh, WorldBoundsFollowTransforms) {
    const Mesh m = makeCube(2.0f);
    Transform t;
    t.translation = {10, 0, 0};
    t.scale = {2, 2, 2};
    const BoundingSphere b = worldBounds({&m}, {worldFromObject(t)});
    EXPECT_NEAR(b.center.x, 10.0f, 1e-5f);
    EXPECT_NEAR(b.radius, 2.0f * std::sqrt(3.0f), 1e-4f);
}

TEST(Camera, ComparePanesCoverTheImageExactly) {
    const auto panes = layoutPanes(Layout::Compare, ShadingMode::Phong, 100, 40);
    ASSERT_EQ(panes.size(), 3u);
    EXPECT_EQ(panes[0].mode, ShadingMode::Flat);
    EXPECT_EQ(panes[1].mode, ShadingMode::Gouraud);
    EXPECT_EQ(panes[2].mode, ShadingMode::Phong);
    EXPECT_EQ(panes[0].x, 0);
    EXPECT_EQ(panes[0].x + panes[0].width, panes[1].x);
    EXPECT_EQ(panes[1].x + panes[1].width, panes[2].x);
    EXPECT_EQ(panes[2].x + panes[2].width, 100);
    const auto single = layoutPanes(Layout::Single, ShadingMode::Gouraud, 100, 40);
    ASSERT_EQ(single.size(), 1u);
    EXPECT_EQ(single[0].mode, ShadingMode::Gouraud);
    EXPECT_EQ(single[0].width, 100);
}

// The status line's "triangles per frame": the scene is drawn once per pane but diff's difference pane.
TEST(Camera, ScenePanesLeaveOutTheDifference) {
    EXPECT_EQ(scenePaneCount(Layout::Single), 1u);
    EXPECT_EQ(scenePaneCount(Layout::Compare), 3u);
    EXPECT_EQ(scenePaneCount(Layout::Diff), 2u);
}

TEST(Camera, TransformAppliesScaleThenRotationXYZThenTranslation) {
    Transform t;
    t.translation = {1, 2, 3};
    t.rotationDeg = {0, 90, 0};
    t.scale = {2, 1, 1};
    const glm::vec4 p = worldFromObject(t) * glm::vec4(1, 0, 0, 1);  // scaled to (2,0,0), turned to (0,0,-2)
    EXPECT_NEAR(p.x, 1.0f, 1e-5f);
    EXPECT_NEAR(p.y, 2.0f, 1e-5f);
    EXPECT_NEAR(p.z, 1.0f, 1e-5f);
}

// sampleTexture: what GL reads from an sRGB texture at level 0 (texel centres at (i + 0.5) / size),
// worked out by hand for a 2 x 1 texture of sRGB 0 and 255 and one of sRGB 128.
TEST(Mesh, SampleTextureDecodesSrgbAndFiltersAndWrapsAsGl) {
    TextureImage t;
    t.width = 2, t.height = 1;
    t.rgba = {0, 0, 0, 255, 255, 255, 255, 255};
    t.wrapS = t.wrapT = 0x812F;  // CLAMP_TO_EDGE
    EXPECT_EQ(sampleTexture(t, {0.25f, 0.5f}), glm::vec3(0.0f));   // the first texel's centre
    EXPECT_EQ(sampleTexture(t, {0.75f, 0.5f}), glm::vec3(1.0f));
    EXPECT_NEAR(sampleTexture(t, {0.5f, 0.5f}).r, 0.5f, 1e-6f);    // halfway: linear values averaged
    EXPECT_EQ(sampleTexture(t, {-3.0f, 0.5f}), glm::vec3(0.0f));   // clamped
    EXPECT_EQ(sampleTexture(t, {7.0f, 0.5f}), glm::vec3(1.0f));
    t.wrapS = 0x2901;  // REPEAT: u = 1.25 is u = 0.25
    EXPECT_EQ(sampleTexture(t, {1.25f, 0.5f}), glm::vec3(0.0f));
    EXPECT_NEAR(sampleTexture(t, {1.0f, 0.5f}).r, 0.5f, 1e-6f);    // between the last and the first texel
    t.wrapS = 0x8370;  // MIRRORED_REPEAT: u = 1.25 is u = 0.75
    EXPECT_EQ(sampleTexture(t, {1.25f, 0.5f}), glm::vec3(1.0f));
    t.magFilter = 0x2600;  // NEAREST
    EXPECT_EQ(sampleTexture(t, {0.49f, 0.5f}), glm::vec3(0.0f));
    EXPECT_EQ(sampleTexture(t, {0.51f, 0.5f}), glm::vec3(1.0f));
    TextureImage grey;
    grey.width = grey.height = 1;
    grey.rgba = {128, 128, 128, 255};
    // Coordinates no int can index (a file may hold any float) read texel 0, without overflow.
    EXPECT_EQ(sampleTexture(t, {1e30f, 0.5f}), sampleTexture(t, {0.0f, 0.5f}));
    // sRGB 128 / 255 decodes to ((0.50196 + 0.055) / 1.055)^2.4 = 0.21586.
    EXPECT_NEAR(sampleTexture(grey, {0.3f, 0.9f}).g, 0.21586f, 1e-4f);
}
