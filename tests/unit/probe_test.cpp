// The pixel probe without GL (app/core/geometry/ray_cast.*, app/core/probe/probe.*): the ray cast against hand-placed
// triangles and against a brute-force loop written here, and the probe's evaluations against values
// worked out by hand. tests/gl/probe_test.cpp checks the probe's totals against rendered pixels.
#include "core/base/error.hpp"
#include "core/geometry/mesh.hpp"
#include "core/probe/probe.hpp"
#include "core/geometry/ray_cast.hpp"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <random>

using namespace shadelab;

namespace {

// The triangle (0,0,0), (2,0,0), (0,2,0): counter-clockwise seen from +z.
Mesh unitTriangle() {
    Mesh m;
    m.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
    m.normals.assign(3, glm::vec3(0, 0, 1));
    m.indices = {0, 1, 2};
    return m;
}

// A scene of `meshes` with the given transforms (the meshes are used as given, not built from specs).
struct TestScene {
    Scene scene;
    SceneGeometry geometry;
};
TestScene sceneOf(std::vector<Mesh> meshes, std::vector<Transform> transforms) {
    TestScene t;
    t.scene.objects.resize(meshes.size());
    for (std::size_t i = 0; i < meshes.size(); ++i) t.scene.objects[i].transform = transforms[i];
    t.geometry.meshes = std::move(meshes);
    return t;
}

constexpr float kInf = std::numeric_limits<float>::infinity();

}  // namespace

// Object 1 is the triangle halved and moved to z = 1 (corners (0,0,1), (1,0,1), (0,1,1)), in front of
// object 0 for a ray coming down the -z axis.
TEST(RayCast, NearestFrontFaceWithHandComputedBarycentrics) {
    Transform front;
    front.translation = {0, 0, 1};
    front.scale = glm::vec3(0.5f);
    const TestScene t = sceneOf({unitTriangle(), unitTriangle()}, {Transform{}, front});
    const SceneRayCaster caster(t.scene, t.geometry);
    EXPECT_EQ(caster.triangleCount(), 2u);

    // (0.5, 0.25) is inside both: the nearer, object 1, at t = 5 - 1. In object 1's own corners,
    // (0.5, 0.25) = 0.25 a + 0.5 b + 0.25 c.
    auto hit = caster.nearestFrontFace({0.5f, 0.25f, 5.0f}, {0, 0, -1}, 0.0f, kInf);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->object, 1u);
    EXPECT_EQ(hit->triangle, 0u);
    EXPECT_NEAR(hit->t, 4.0f, 1e-6f);
    EXPECT_NEAR(hit->barycentric.x, 0.25f, 1e-6f);
    EXPECT_NEAR(hit->barycentric.y, 0.5f, 1e-6f);
    EXPECT_NEAR(hit->barycentric.z, 0.25f, 1e-6f);

    // (1.5, 0.2) is outside the small triangle: object 0 at t = 5, weights 0.15, 0.75, 0.1.
    hit = caster.nearestFrontFace({1.5f, 0.2f, 5.0f}, {0, 0, -1}, 0.0f, kInf);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->object, 0u);
    EXPECT_NEAR(hit->t, 5.0f, 1e-6f);
    EXPECT_NEAR(hit->barycentric.x, 0.15f, 1e-6f);
    EXPECT_NEAR(hit->barycentric.y, 0.75f, 1e-6f);
    EXPECT_NEAR(hit->barycentric.z, 0.1f, 1e-6f);

    // The ray's range is respected: nothing before t = 3.
    EXPECT_FALSE(caster.nearestFrontFace({0.5f, 0.25f, 5.0f}, {0, 0, -1}, 0.0f, 3.0f));
    // From behind (+z direction) both are back faces, culled; an occlusion test sees them.
    EXPECT_FALSE(caster.nearestFrontFace({0.5f, 0.25f, -5.0f}, {0, 0, 1}, 0.0f, kInf));
    EXPECT_TRUE(caster.occluded({0.5f, 0.25f, -5.0f}, {0, 0, 1}, 0.0f, kInf));
    EXPECT_FALSE(caster.occluded({0.5f, 0.25f, -5.0f}, {0, 0, 1}, 0.0f, 4.9f));
    EXPECT_FALSE(caster.occluded({3.0f, 3.0f, -5.0f}, {0, 0, 1}, 0.0f, kInf));
}

// A mirroring transform turns the triangle clockwise seen from +z; the renderer flips the front face
// with it (glFrontFace), so the ray from +z still hits, and from -z it is still culled.
TEST(RayCast, MirroredObjectKeepsItsFrontFace) {
    Transform mirror;
    mirror.scale = {-1, 1, 1};  // corners (0,0,0), (-2,0,0), (0,2,0)
    const TestScene t = sceneOf({unitTriangle()}, {mirror});
    const SceneRayCaster caster(t.scene, t.geometry);
    const auto hit = caster.nearestFrontFace({-1.5f, 0.2f, 5.0f}, {0, 0, -1}, 0.0f, kInf);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->barycentric.y, 0.75f, 1e-6f);
    EXPECT_NEAR(hit->barycentric.z, 0.1f, 1e-6f);
    EXPECT_FALSE(caster.nearestFrontFace({-1.5f, 0.2f, -5.0f}, {0, 0, 1}, 0.0f, kInf));
}

// A double-sided part (glTF's doubleSided) is drawn from both sides: a ray from behind hits it and
// says so, mirrored or not; a single-sided object beside it is still culled from behind.
TEST(RayCast, DoubleSidedPartsAreHitFromBehind) {
    Mesh twoSided = unitTriangle();
    MeshPart part;
    part.indexCount = 3;
    part.doubleSided = true;
    twoSided.parts = {part};
    Transform beside, mirror;
    beside.translation = {5, 0, 0};
    mirror.scale = {-1, 1, 1};
    mirror.translation = {-5, 0, 0};  // corners (-5,0,0), (-7,0,0), (-5,2,0)
    const TestScene t = sceneOf({twoSided, unitTriangle(), twoSided}, {Transform{}, beside, mirror});
    const SceneRayCaster caster(t.scene, t.geometry);
    auto hit = caster.nearestFrontFace({0.5f, 0.25f, 5.0f}, {0, 0, -1}, 0.0f, kInf);
    ASSERT_TRUE(hit);
    EXPECT_FALSE(hit->backFace);
    hit = caster.nearestFrontFace({0.5f, 0.25f, -5.0f}, {0, 0, 1}, 0.0f, kInf);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->object, 0u);
    EXPECT_TRUE(hit->backFace);
    EXPECT_NEAR(hit->t, 5.0f, 1e-6f);
    EXPECT_NEAR(hit->barycentric.y, 0.25f, 1e-6f);
    EXPECT_FALSE(caster.nearestFrontFace({5.5f, 0.25f, -5.0f}, {0, 0, 1}, 0.0f, kInf));  // single-sided: culled
    hit = caster.nearestFrontFace({-5.5f, 0.25f, -5.0f}, {0, 0, 1}, 0.0f, kInf);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->object, 2u);
    EXPECT_TRUE(hit->backFace);  // mirrored: the front still faces +z
    hit = caster.nearestFrontFace({-5.5f, 0.25f, 5.0f}, {0, 0, -1}, 0.0f, kInf);
    ASSERT_TRUE(hit);
    EXPECT_FALSE(hit->backFace);
}

namespace {

// The plain loop the hierarchy must agree with: Möller-Trumbore on every triangle, culling back faces
// (no mirroring transforms here).
std::optional<TriangleHit> bruteForce(const Scene& scene, const SceneGeometry& g, const glm::vec3& o, const glm::vec3& d) {
    std::optional<TriangleHit> best;
    for (std::size_t obj = 0; obj < g.meshes.size(); ++obj) {
        const glm::mat4 w = worldFromObject(scene.objects[obj].transform);
        const Mesh& m = g.meshes[obj];
        for (std::size_t t = 0; t < m.triangleCount(); ++t) {
            glm::vec3 c[3];
            for (int k = 0; k < 3; ++k) c[k] = glm::vec3(w * glm::vec4(m.positions[m.indices[3 * t + std::size_t(k)]], 1.0f));
            const glm::vec3 e1 = c[1] - c[0], e2 = c[2] - c[0];
            if (glm::dot(glm::cross(e1, e2), d) >= 0.0f) continue;  // back face
            const glm::vec3 p = glm::cross(d, e2);
            const float det = glm::dot(e1, p);
            const glm::vec3 s = o - c[0];
            const float u = glm::dot(s, p) / det, v = glm::dot(d, glm::cross(s, e1)) / det;
            const float dist = glm::dot(e2, glm::cross(s, e1)) / det;
            if (u < 0 || v < 0 || u + v > 1 || dist < 0) continue;
            if (!best || dist < best->t) best = TriangleHit{obj, t, dist, {1 - u - v, u, v}};
        }
    }
    return best;
}

}  // namespace

TEST(RayCast, HierarchyAgreesWithABruteForceLoop) {
    Transform moved;
    moved.translation = {0.4f, -0.3f, 0.2f};
    moved.rotationDeg = {30, 10, 0};
    moved.scale = {1.2f, 0.6f, 1.0f};
    const TestScene t = sceneOf({makeIcoSphere(4, 1.0f), makeTorus(1.2f, 0.3f, 40, 16)}, {Transform{}, moved});
    const SceneRayCaster caster(t.scene, t.geometry);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    int hits = 0;
    for (int i = 0; i < 400; ++i) {
        const glm::vec3 origin = 4.0f * glm::normalize(glm::vec3(unit(rng), unit(rng), unit(rng)));
        const glm::vec3 aim(1.3f * unit(rng), 1.3f * unit(rng), 1.3f * unit(rng));
        const glm::vec3 dir = glm::normalize(aim - origin);
        const auto expected = bruteForce(t.scene, t.geometry, origin, dir);
        const auto got = caster.nearestFrontFace(origin, dir, 0.0f, kInf);
        ASSERT_EQ(bool(got), bool(expected)) << "ray " << i;
        if (!got) continue;
        ++hits;
        EXPECT_NEAR(got->t, expected->t, 1e-4f) << "ray " << i;
        // Where two triangles share an edge either may answer; elsewhere it is the same triangle.
        if (got->object != expected->object || got->triangle != expected->triangle) {
            EXPECT_LT(std::min({got->barycentric.x, got->barycentric.y, got->barycentric.z}), 1e-3f) << "ray " << i;
        }
    }
    EXPECT_GT(hits, 250);
}

// 262,144 triangles: a loop over every triangle tests all of them per ray (~4 ms a ray on the 2-core
// development machine); the hierarchy tests a few dozen. Measured as triangles tested, not as time:
// tests never assert wall-clock times (a loaded CI machine or an unoptimised build is slower).
TEST(RayCast, LargeMeshTestsFewTrianglesPerRay) {
    const TestScene t = sceneOf({makeUvSphere(512, 257, 1.0f)}, {Transform{}});
    const SceneRayCaster caster(t.scene, t.geometry);
    EXPECT_EQ(caster.triangleCount(), 262144u);
    int hits = 0;
    std::size_t tested = 0, most = 0;
    constexpr int kRays = 2000;
    for (int i = 0; i < kRays; ++i) {
        const float a = 0.01f * float(i);
        const glm::vec3 origin(3.0f * std::cos(a), 0.5f * std::sin(3.0f * a), 3.0f * std::sin(a));
        const glm::vec3 direction = glm::normalize(-origin);
        const auto hit = caster.nearestFrontFace(origin, direction, 0.0f, kInf);
        // The ray aims at the centre: it meets the sphere ~1 unit before it.
        if (hit && std::fabs(hit->t - (glm::length(origin) - 1.0f)) < 1e-3f) ++hits;
        const std::size_t n = caster.trianglesTested(origin, direction, 0.0f, kInf);
        tested += n;
        most = std::max(most, n);
    }
    EXPECT_EQ(hits, kRays);
    // Without the hierarchy every ray would test all 262,144; with it the mean is a few dozen.
    EXPECT_LT(double(tested) / kRays, 200.0);
    EXPECT_LT(most, 2000u);
    RecordProperty("mean_triangles_tested", std::to_string(double(tested) / kRays));
}

namespace {

// A 2 x 2 plane (corners x, z = +-1 at y = 0, normal +y) lit by a point light at (1, 1, 1) with no
// falloff, seen straight from above; no specular term, so every value is worked out by hand:
//   corner (1, 0, 1):   I = (0, 1, 0), N.I = 1
//   corners (1, 0, -1) and (-1, 0, 1): I = (0, 1, 2)/sqrt 5 or (2, 1, 0)/sqrt 5, N.I = 1/sqrt 5
//   colour = k_a A C + k_d C N.I = C (0.1 + N.I)
Scene planeScene(ShadingMode mode) {
    Scene s;
    s.objects[0].mesh.type = MeshSpec::Type::Plane;
    s.objects[0].mesh.size = 2.0f;
    s.objects[0].mesh.planeSubdivisions = 1;
    s.objects[0].material.color = {0.8f, 0.4f, 0.2f};
    s.objects[0].material.ka = 0.1f;
    s.objects[0].material.kd = 1.0f;
    s.objects[0].material.ks = 0.0f;
    s.ambient = glm::vec3(1.0f);
    Light light;
    light.position = {1, 1, 1};
    s.lights = {light};
    s.camera.eye = {0, 5, 0};
    s.camera.target = {0, 0, 0};
    s.camera.up = {0, 0, -1};  // image right = +x, image down = +z
    s.camera.fovYDeg = 45.0f;
    s.width = s.height = 101;
    s.shading = mode;
    return s;
}

// Pixel (65, 40) of the 101 x 101 image, worked out by hand: NDC (2 * 65.5 / 101 - 1, 1 - 2 * 40.5 / 101),
// times 5 tan(22.5 deg) on the plane 5 below the eye.
glm::vec3 planePoint() {
    const float half = 5.0f * std::tan(glm::radians(22.5f));
    return {(2.0f * 65.5f / 101.0f - 1.0f) * half, 0.0f, -(1.0f - 2.0f * 40.5f / 101.0f) * half};
}

// x + z > 0 there: the triangle (1, 0, -1), (-1, 0, 1), (1, 0, 1). Barycentrics in x-z by hand.
struct Corner {
    glm::vec3 pos;
    glm::vec3 color;
    float weight;
};
std::vector<Corner> planeCorners() {
    const glm::vec3 c(0.8f, 0.4f, 0.2f);
    const glm::vec3 p = planePoint();
    // p = wA (1,-1) + wB (-1,1) + wC (1,1) in (x, z): wB = (1 - x) / 2, wA = (1 - z) / 2, wC = 1 - wA - wB.
    const float wB = (1.0f - p.x) / 2.0f, wA = (1.0f - p.z) / 2.0f;
    const float side = 1.0f / std::sqrt(5.0f);
    return {{{1, 0, -1}, c * (0.1f + side), wA}, {{-1, 0, 1}, c * (0.1f + side), wB}, {{1, 0, 1}, c * 1.1f, 1.0f - wA - wB}};
}

ProbeResult probePlane(const Scene& s, int x = 65, int y = 40) {
    const SceneGeometry g = buildSceneGeometry(s);
    return probePixel(s, g, SceneRayCaster(s, g), x, y);
}

}  // namespace

TEST(Probe, GouraudInterpolatesTheThreeVertexColours) {
    const Scene s = planeScene(ShadingMode::Gouraud);
    const ProbeResult r = probePlane(s);
    ASSERT_FALSE(r.miss);
    const glm::vec3 p = planePoint();
    EXPECT_NEAR(glm::length(r.posWorld - p), 0.0f, 1e-5f);
    ASSERT_EQ(r.modes.size(), 1u);
    const ModeProbe& m = r.modes[0];
    EXPECT_EQ(m.mode, ShadingMode::Gouraud);
    ASSERT_EQ(m.evaluations.size(), 3u);
    glm::vec3 expected(0.0f);
    for (const Corner& corner : planeCorners()) {
        expected += corner.weight * corner.color;
        int found = 0;
        for (int k = 0; k < 3; ++k) {
            const ProbeEvaluation& e = m.evaluations[std::size_t(k)];
            if (glm::length(e.posWorld - corner.pos) > 1e-6f) continue;
            ++found;
            EXPECT_EQ(e.site, ProbeEvaluation::Site::Vertex);
            EXPECT_NEAR(glm::length(e.nrmWorld - glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
            EXPECT_NEAR(glm::length(e.terms.total - corner.color), 0.0f, 1e-6f) << "corner " << corner.pos.x << "," << corner.pos.z;
            EXPECT_NEAR(r.anchor.barycentric[k], corner.weight, 1e-5f);
        }
        EXPECT_EQ(found, 1) << "corner " << corner.pos.x << "," << corner.pos.z;
    }
    EXPECT_NEAR(glm::length(m.color - expected), 0.0f, 1e-5f);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(m.output8[k], int(std::lround(expected[k] * 255.0f)));
    EXPECT_EQ(r.output8, m.output8);
}

TEST(Probe, PhongAndFlatEvaluateWhereTheirShadersDo) {
    const glm::vec3 c(0.8f, 0.4f, 0.2f), p = planePoint();
    // Phong: at the point itself, N = +y, N.I = (1 - 0) / |L - p|.
    const ProbeResult phong = probePlane(planeScene(ShadingMode::Phong));
    ASSERT_EQ(phong.modes[0].evaluations.size(), 1u);
    const ProbeEvaluation& e = phong.modes[0].evaluations[0];
    EXPECT_EQ(e.site, ProbeEvaluation::Site::Point);
    const float nDotI = 1.0f / glm::length(glm::vec3(1, 1, 1) - p);
    EXPECT_NEAR(e.lights[0].nDotI, nDotI, 1e-6f);
    EXPECT_NEAR(glm::length(phong.modes[0].color - c * (0.1f + nDotI)), 0.0f, 1e-6f);
    // Flat: at the centroid of (1,0,-1), (-1,0,1), (1,0,1) = (1/3, 0, 1/3), N.I = 1 / |(2/3, 1, 2/3)| = 3 / sqrt 17.
    const ProbeResult flat = probePlane(planeScene(ShadingMode::Flat));
    const ProbeEvaluation& f = flat.modes[0].evaluations[0];
    EXPECT_EQ(f.site, ProbeEvaluation::Site::Centroid);
    EXPECT_NEAR(glm::length(f.posWorld - glm::vec3(1.0f / 3, 0, 1.0f / 3)), 0.0f, 1e-6f);
    EXPECT_NEAR(f.lights[0].nDotI, 3.0f / std::sqrt(17.0f), 1e-6f);
    EXPECT_NEAR(glm::length(flat.modes[0].color - c * (0.1f + 3.0f / std::sqrt(17.0f))), 0.0f, 1e-6f);
}

// The lecture's vectors at the probed point, and the Blinn-Phong share k_s S (H.N)^k_e L.
TEST(Probe, VectorsAreTheLecturesDefinitions) {
    Scene s = planeScene(ShadingMode::Phong);
    s.objects[0].material.ks = 0.5f;
    s.objects[0].material.ke = 8.0f;
    s.objects[0].material.specularColor = {1.0f, 0.5f, 0.25f};
    s.lights[0].color = {1.0f, 0.8f, 0.6f};
    const ProbeResult r = probePlane(s);
    const ProbeEvaluation& e = r.modes[0].evaluations[0];
    const glm::vec3 p = planePoint(), n(0, 1, 0);
    const glm::vec3 i = glm::normalize(glm::vec3(1, 1, 1) - p), v = glm::normalize(glm::vec3(0, 5, 0) - p);
    const glm::vec3 refl = 2.0f * i.y * n - i, h = glm::normalize(i + v);
    const ProbeLight& l = e.lights[0];
    EXPECT_NEAR(glm::length(e.viewWorld - v), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(l.towardLight - i), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(l.reflected - refl), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(l.halfway - h), 0.0f, 1e-6f);
    EXPECT_NEAR(l.nDotI, i.y, 1e-6f);
    EXPECT_NEAR(l.rDotV, glm::dot(refl, v), 1e-6f);
    EXPECT_NEAR(l.hDotN, h.y, 1e-6f);
    const glm::vec3 spec = 0.5f * glm::vec3(1.0f, 0.5f, 0.25f) * glm::vec3(1.0f, 0.8f, 0.6f) * std::pow(h.y, 8.0f);
    EXPECT_NEAR(glm::length(l.specular - spec), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(l.diffuse - glm::vec3(0.8f, 0.4f, 0.2f) * glm::vec3(1.0f, 0.8f, 0.6f) * i.y), 0.0f, 1e-6f);
    EXPECT_FLOAT_EQ(l.visibility, 1.0f);
    EXPECT_EQ(l.samplesTested, 0);  // shadows off: no occlusion test
}

TEST(Probe, BackgroundPanesAndRange) {
    Scene s = planeScene(ShadingMode::Phong);
    s.background = {0.2f, 0.4f, 0.6f};
    // The image corner looks past the plane's edge (it reaches x = +-2.07 at the corners).
    const ProbeResult miss = probePlane(s, 0, 0);
    EXPECT_TRUE(miss.miss);
    EXPECT_EQ(miss.pane, 0);
    EXPECT_EQ(miss.output8, glm::ivec3(51, 102, 153));
    EXPECT_THROW(probePlane(s, 101, 5), InputError);
    EXPECT_THROW(probePlane(s, 5, -1), InputError);

    // Compare layout, 303 wide: panes of 101; pixel 65 + 202 is in the phong pane at the same place.
    s.layout = Layout::Compare;
    s.width = 303;
    const ProbeResult right = probePlane(s, 65 + 202, 40);
    EXPECT_EQ(right.pane, 2);
    EXPECT_EQ(right.modes[0].mode, ShadingMode::Phong);
    EXPECT_NEAR(glm::length(right.posWorld - planePoint()), 0.0f, 1e-5f);
    // Diff layout, 304 wide: the last column belongs to no pane; the difference pane evaluates both modes.
    s.layout = Layout::Diff;
    s.width = 304;
    const ProbeResult spare = probePlane(s, 303, 40);
    EXPECT_TRUE(spare.miss);
    EXPECT_EQ(spare.pane, -1);
    const ProbeResult diff = probePlane(s, 65 + 202, 40);
    ASSERT_EQ(diff.modes.size(), 2u);
    EXPECT_EQ(diff.modes[0].mode, ShadingMode::Gouraud);
    EXPECT_EQ(diff.modes[1].mode, ShadingMode::Phong);
    const glm::ivec3 d = glm::abs(diff.modes[0].output8 - diff.modes[1].output8) * 4;
    EXPECT_EQ(diff.output8, glm::min(d, glm::ivec3(255)));
}

// A small square hides the light from the plane's middle: v = 0 there (no diffuse), 1 elsewhere.
TEST(Probe, ShadowsAreARayCastTowardTheLight) {
    Scene s = planeScene(ShadingMode::Phong);
    s.lights[0].position = {0, 4, 0};
    s.camera.eye = {0, 8, 0.01f};
    s.shadows.enabled = true;
    SceneObject blocker;
    blocker.mesh.type = MeshSpec::Type::Plane;
    blocker.mesh.size = 0.5f;
    blocker.transform.translation = {0, 2, 0};
    s.objects.push_back(blocker);
    SceneGeometry g = buildSceneGeometry(s);
    const SceneRayCaster caster(s, g);
    // Anchors on triangle 0 of the plane, (-1,0,-1), (-1,0,1), (1,0,-1) as makePlane orders it; its
    // corner weights for a point (x, 0, z) solved here in x-z.
    const Mesh& plane = g.meshes[0];
    glm::vec2 c[3];
    for (int k = 0; k < 3; ++k) {
        const glm::vec3& q = plane.positions[plane.indices[std::size_t(k)]];
        c[k] = {q.x, q.z};
    }
    auto anchorAt = [&](float x, float z) {
        const glm::vec2 p(x, z);
        const float det = (c[1].x - c[0].x) * (c[2].y - c[0].y) - (c[2].x - c[0].x) * (c[1].y - c[0].y);
        const float w1 = ((p.x - c[0].x) * (c[2].y - c[0].y) - (c[2].x - c[0].x) * (p.y - c[0].y)) / det;
        const float w2 = ((c[1].x - c[0].x) * (p.y - c[0].y) - (p.x - c[0].x) * (c[1].y - c[0].y)) / det;
        ProbeAnchor a;
        a.barycentric = {1.0f - w1 - w2, w1, w2};
        EXPECT_GE(std::min({a.barycentric.x, a.barycentric.y, a.barycentric.z}), 0.0f) << x << "," << z << " not in triangle 0";
        return a;
    };
    // (-0.9, 0, -0.9): the ray to the light crosses y = 2 at (-0.45, -0.45), beside the blocker.
    const ProbeResult lit = probeAnchor(s, g, caster, anchorAt(-0.9f, -0.9f));
    EXPECT_EQ(lit.modes[0].evaluations[0].lights[0].samplesTested, 1);
    EXPECT_EQ(lit.modes[0].evaluations[0].lights[0].samplesVisible, 1);
    EXPECT_GT(lit.modes[0].evaluations[0].lights[0].diffuse.r, 0.1f);
    // (-0.05, 0, -0.05): it crosses y = 2 at (-0.025, -0.025), through the blocker.
    const ProbeAnchor a = anchorAt(-0.05f, -0.05f);
    const ProbeResult shaded = probeAnchor(s, g, caster, a);
    const ProbeLight& l = shaded.modes[0].evaluations[0].lights[0];
    EXPECT_EQ(l.samplesTested, 1);
    EXPECT_EQ(l.samplesVisible, 0);
    EXPECT_FLOAT_EQ(l.visibility, 0.0f);
    EXPECT_EQ(l.diffuse, glm::vec3(0.0f));
    // What is left is the ambient term alone: 0.1 C.
    EXPECT_NEAR(glm::length(shaded.modes[0].color - 0.1f * glm::vec3(0.8f, 0.4f, 0.2f)), 0.0f, 1e-6f);
}

// planeScene turned upside down: the eye and the light below the plane, which faces +y. Single-sided,
// its back is culled (the probe misses); double-sided, it is lit as a plane facing -y, in every mode:
// colour = C (0.1 + N.I) with N = (0, -1, 0), as planeScene's is with +y.
TEST(Probe, BackOfADoubleSidedPartIsEvaluatedWithTheNormalFlipped) {
    for (ShadingMode mode : {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong}) {
        SCOPED_TRACE(toString(mode));
        Scene s = planeScene(mode);
        s.camera.eye = {0, -5, 0};
        s.camera.up = {0, 0, 1};
        s.lights[0].position = {1, -1, 1};
        SceneGeometry g = buildSceneGeometry(s);
        EXPECT_TRUE(probePixel(s, g, SceneRayCaster(s, g), 65, 40).miss) << "single-sided: culled";
        MeshPart part;
        part.indexCount = std::uint32_t(g.meshes[0].indices.size());
        part.doubleSided = true;
        g.meshes[0].parts = {part};
        const ProbeResult r = probePixel(s, g, SceneRayCaster(s, g), 65, 40);
        ASSERT_FALSE(r.miss);
        EXPECT_TRUE(r.doubleSided);
        EXPECT_TRUE(r.backFace);
        const ModeProbe& m = r.modes[0];
        glm::vec3 expected(0.0f);
        for (std::size_t k = 0; k < m.evaluations.size(); ++k) {
            const ProbeEvaluation& e = m.evaluations[k];
            EXPECT_NEAR(glm::length(e.nrmWorld - glm::vec3(0, -1, 0)), 0.0f, 1e-6f);
            const float nDotI = glm::dot(glm::vec3(0, -1, 0), glm::normalize(s.lights[0].position - e.posWorld));
            EXPECT_NEAR(e.lights[0].nDotI, nDotI, 1e-6f);
            EXPECT_GT(nDotI, 0.3f);
            const glm::vec3 c = glm::vec3(0.8f, 0.4f, 0.2f) * (0.1f + nDotI);
            EXPECT_NEAR(glm::length(e.terms.total - c), 0.0f, 1e-6f);
            expected += (m.evaluations.size() == 3 ? r.anchor.barycentric[int(k)] : 1.0f) * c;
        }
        EXPECT_NEAR(glm::length(m.color - expected), 0.0f, 1e-5f);
        const auto j = nlohmann::json::parse(probeToJson(s, r));
        EXPECT_EQ(j["double_sided"], true);
        EXPECT_EQ(j["back_face"], true);
        // From above, the same part is seen from the front: nothing flipped.
        const Scene above = planeScene(mode);
        const ProbeResult front = probePixel(above, g, SceneRayCaster(above, g), 65, 40);
        EXPECT_FALSE(front.backFace);
        EXPECT_NEAR(glm::length(front.modes[0].evaluations[0].nrmWorld - glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
        EXPECT_EQ(nlohmann::json::parse(probeToJson(above, front))["back_face"], false);
    }
}

TEST(Probe, JsonHasTheTermsOfTheResult) {
    const Scene s = planeScene(ShadingMode::Gouraud);
    const ProbeResult r = probePlane(s);
    const auto j = nlohmann::json::parse(probeToJson(s, r));
    EXPECT_EQ(j["pixel"], nlohmann::json::array({65, 40}));
    EXPECT_EQ(j["mode"], "gouraud");
    EXPECT_EQ(j["miss"], false);
    EXPECT_EQ(j["object"], 0);
    EXPECT_EQ(j["triangle"], r.anchor.triangle);
    ASSERT_EQ(j["evaluations"].size(), 3u);
    float weights = 0.0f;
    for (const auto& e : j["evaluations"]) {
        EXPECT_EQ(e["at"], "vertex");
        weights += e["weight"].get<float>();
        ASSERT_EQ(e["lights"].size(), 1u);
        EXPECT_EQ(e["lights"][0]["type"], "point");
        for (const char* key : {"I", "N.I", "R", "R.V", "H", "H.N", "diffuse", "specular"})
            EXPECT_TRUE(e["lights"][0].contains(key)) << key;
        EXPECT_FALSE(e["lights"][0].contains("visibility"));  // shadows off
    }
    EXPECT_NEAR(weights, 1.0f, 1e-5f);
    const glm::vec3 p = planePoint();
    EXPECT_NEAR(j["position"][0].get<float>(), p.x, 1e-5f);
    EXPECT_NEAR(j["position"][2].get<float>(), p.z, 1e-5f);
    EXPECT_EQ(j["output_8bit"], nlohmann::json::array({r.output8.x, r.output8.y, r.output8.z}));
    EXPECT_FALSE(j.contains("back_face"));  // a single-sided part is always seen from the front

    Scene background = s;
    background.camera.eye = {0, 5, 100};  // far away and low: pixel (65, 40) looks over the plane
    background.camera.up = {0, 1, 0};
    const auto miss = nlohmann::json::parse(probeToJson(background, probePlane(background)));
    EXPECT_EQ(miss["miss"], true);
    EXPECT_FALSE(miss.contains("evaluations"));
}
