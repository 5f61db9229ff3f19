// Issue 30, part 2: anisotropic reflection. Ashikhmin and Shirley's exponent against the formula as the
// lecture would write it, k_t = k_b = k_e against Blinn-Phong, the energy factor, the tangent frames
// (glTF's TANGENT: gltf_import_test.cpp; texture coordinates; the up axis), and the scene field and
// option with their refusals.
#include "options/options.hpp"
#include "core/base/error.hpp"
#include "core/geometry/ray_cast.hpp"
#include "core/geometry/scene_geometry.hpp"
#include "core/probe/probe.hpp"
#include "core/geometry/mesh.hpp"
#include "core/scene/scene_json.hpp"
#include "core/shading/lighting.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <random>

using namespace shadelab;

namespace {

// A unit vector in the upper hemisphere of +z, from a fixed-seed generator.
glm::vec3 randomAbove(std::mt19937& rng) {
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    for (;;) {
        const glm::vec3 v(u(rng), u(rng), std::fabs(u(rng)));
        const float l = glm::length(v);
        if (l > 0.1f && l <= 1.0f && v.z > 0.05f * l) return v / l;
    }
}

// The frame of the xy plane: N = +z, T = +x, B = +y.
const glm::vec3 kN(0, 0, 1);
const TangentFrame kFrame{{1, 0, 0}, {0, 1, 0}};

}  // namespace

// The exponent is the issue's formula, (k_t (H.T)^2 + k_b (H.B)^2) / (1 - (H.N)^2), at many H; spec is
// (H.N) to that power; where H = N, spec is 1.
TEST(Anisotropy, ExponentIsAshikhminShirleys) {
    std::mt19937 rng(30);
    LightingEnvironment env;
    const glm::vec2 k(8.0f, 256.0f);
    for (int n = 0; n < 500; ++n) {
        const glm::vec3 i = randomAbove(rng), v = randomAbove(rng);
        const glm::vec3 h = glm::normalize(i + v);
        const double ht = h.x, hb = h.y, hn = h.z;
        const double expected = (k.x * ht * ht + k.y * hb * hb) / (1.0 - hn * hn);
        EXPECT_NEAR(anisotropicExponent(k, h, kFrame), expected, 1e-3 * expected + 1e-3) << n;
        EXPECT_NEAR(anisotropicSpecularTerm(env, k, kN, i, v, kFrame), std::pow(hn, expected), 3e-5) << n;  // float against double
    }
    const glm::vec3 straight = glm::normalize(glm::vec3(0.3f, 0.2f, 1.0f)), mirrored(-straight.x, -straight.y, straight.z);
    EXPECT_FLOAT_EQ(anisotropicSpecularTerm(env, k, kN, straight, mirrored, kFrame), 1.0f);  // H = N
    // Across T the highlight is wide (k_t = 8), along B narrow (k_b = 256): at the same angle from N.
    const float along = anisotropicExponent(k, glm::normalize(glm::vec3(0.1f, 0, 1)), kFrame);
    const float across = anisotropicExponent(k, glm::normalize(glm::vec3(0, 0.1f, 1)), kFrame);
    EXPECT_NEAR(along, 8.0f, 1e-3f);
    EXPECT_NEAR(across, 256.0f, 1e-2f);
}

// k_t = k_b = k_e is Blinn-Phong's lobe, with and without Fresnel, whatever the frame.
TEST(Anisotropy, EqualExponentsAreBlinnPhong) {
    std::mt19937 rng(31);
    for (FresnelMode fresnel : {FresnelMode::None, FresnelMode::Schlick}) {
        LightingEnvironment env;
        env.fresnel = fresnel;
        for (int n = 0; n < 300; ++n) {
            const glm::vec3 i = randomAbove(rng), v = randomAbove(rng);
            const TangentFrame frame = tangentFrame(kN, randomAbove(rng) + glm::vec3(0, 0, -0.5f), n % 2 ? 1.0f : -1.0f);
            for (float ke : {1.0f, 32.0f, 500.0f})
                EXPECT_NEAR(anisotropicSpecularTerm(env, glm::vec2(ke), kN, i, v, frame), specularTerm(env, ke, kN, i, v), 1e-6f);
        }
    }
}

// "energy": sqrt((k_t + 1)(k_b + 1)) / 8pi, relative to k_t = k_b = 32 (1 there, as the isotropic lobe at 32).
TEST(Anisotropy, EnergyNormalisationIsTheirFactor) {
    const double eightPi = 8.0 * 3.14159265358979;
    EXPECT_NEAR(anisotropicEnergyScale({8, 256}), (std::sqrt(9.0 * 257.0) / eightPi) / (33.0 / eightPi), 1e-5);
    EXPECT_FLOAT_EQ(anisotropicEnergyScale({32, 32}), 1.0f);
    LightingEnvironment env;
    env.normalization = SpecularNormalization::Energy;
    const glm::vec3 i = glm::normalize(glm::vec3(0.2f, 0.1f, 1)), v = glm::normalize(glm::vec3(-0.1f, 0.0f, 1));
    LightingEnvironment none;
    EXPECT_NEAR(anisotropicSpecularTerm(env, {8, 256}, kN, i, v, kFrame),
                anisotropicSpecularTerm(none, {8, 256}, kN, i, v, kFrame) * anisotropicEnergyScale({8, 256}), 1e-6f);
}

// The lobe is Blinn-Phong's: a material's anisotropy applies under blinn-phong only.
TEST(Anisotropy, AppliesToBlinnPhongOnly) {
    Material m;
    m.anisotropic = true;
    LightingEnvironment env;
    EXPECT_TRUE(anisotropicLobe(m, env));
    env.model = ReflectionModel::Phong;
    EXPECT_FALSE(anisotropicLobe(m, env));
    m.anisotropic = false;
    env.model = ReflectionModel::BlinnPhong;
    EXPECT_FALSE(anisotropicLobe(m, env));
}

// Around the up axis: on the sphere T runs along the parallels (eastward, horizontal), B towards the
// north pole; at the poles T = +x. Every frame is orthonormal.
TEST(TangentFrames, AroundTheUpAxisOnTheSphere) {
    const Mesh sphere = makeProceduralMesh(MeshSpec{});
    ASSERT_EQ(sphere.tangents.size(), sphere.positions.size());
    for (std::size_t v = 0; v < sphere.positions.size(); ++v) {
        const glm::vec3 n = sphere.normals[v], t(sphere.tangents[v]);
        EXPECT_EQ(sphere.tangents[v].w, 1.0f);
        EXPECT_NEAR(glm::length(t), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(t, n), 0.0f, 1e-5f);
        EXPECT_NEAR(t.y, 0.0f, 1e-5f);  // along a parallel
        const TangentFrame f = tangentFrame(n, t, 1.0f);
        if (std::fabs(n.y) < 0.99f) {
            EXPECT_NEAR(glm::distance(t, glm::normalize(glm::cross(glm::vec3(0, 1, 0), n))), 0.0f, 1e-5f);
            EXPECT_GT(f.bitangent.y, 0.0f);  // towards the north pole
        }
    }
    EXPECT_EQ(tangentAroundUp(glm::vec3(0, 1, 0)), glm::vec4(1, 0, 0, 1));
    EXPECT_EQ(tangentAroundUp(glm::vec3(0, -1, 0)), glm::vec4(1, 0, 0, 1));
}

// From texture coordinates: on the plane (N = +y) with u along +x and v along -z, T = +x and
// N x T = -z is dP/dv's direction, so w = +1; with v along +z, w = -1. Coordinates rotated by 90 degrees turn T.
// A vertex the file gave a tangent (w != 0) keeps it.
TEST(TangentFrames, FromTextureCoordinates) {
    MeshSpec spec;
    spec.type = MeshSpec::Type::Plane;
    spec.planeSubdivisions = 2;
    Mesh plane = makeProceduralMesh(spec);
    ASSERT_EQ(plane.tangents.size(), plane.positions.size());
    auto withUv = [&](auto uvOf) {
        Mesh m = plane;
        m.tangents.clear();
        m.texcoords.clear();
        m.colors.assign(m.positions.size(), glm::vec4(1.0f));
        for (const glm::vec3& p : m.positions) m.texcoords.push_back(uvOf(p));
        EXPECT_EQ(completeTangents(m), TangentSource::Texcoords);
        return m;
    };
    const Mesh a = withUv([](const glm::vec3& p) { return glm::vec2(p.x, -p.z); });
    for (const glm::vec4& t : a.tangents) EXPECT_EQ(t, glm::vec4(1, 0, 0, 1));
    const Mesh b = withUv([](const glm::vec3& p) { return glm::vec2(p.x, p.z); });
    for (const glm::vec4& t : b.tangents) EXPECT_EQ(t, glm::vec4(1, 0, 0, -1));
    const Mesh c = withUv([](const glm::vec3& p) { return glm::vec2(p.z, p.x); });
    for (const glm::vec4& t : c.tangents) EXPECT_NEAR(glm::distance(glm::vec3(t), glm::vec3(0, 0, 1)), 0.0f, 1e-6f);

    Mesh given = plane;
    given.tangents.assign(given.positions.size(), glm::vec4(0.0f));
    given.tangents[0] = glm::vec4(0, 0, 1, -1);
    EXPECT_EQ(completeTangents(given), TangentSource::UpAxis);
    EXPECT_EQ(given.tangents[0], glm::vec4(0, 0, 1, -1));
    EXPECT_EQ(given.tangents[1], tangentAroundUp(given.normals[1]));
    EXPECT_EQ(completeTangents(given), TangentSource::Given);
}

// Flat shading's tangent: the corners' averaged, orthogonal to the face normal.
TEST(TangentFrames, FlatMeshCarriesTheFaceTangent) {
    const Mesh sphere = makeProceduralMesh(MeshSpec{});
    const FlatMesh flat = makeFlatMesh(sphere);
    ASSERT_EQ(flat.tangents.size(), flat.positions.size());
    for (std::size_t t = 0; t < flat.indices.size(); t += 3) {
        const std::uint32_t p = flat.indices[t + 2];
        EXPECT_NEAR(glm::dot(glm::vec3(flat.tangents[p]), flat.normals[p]), 0.0f, 1e-5f);
        EXPECT_NEAR(glm::length(glm::vec3(flat.tangents[p])), 1.0f, 1e-5f);
    }
}

// The scene field [k_t, k_b], its round trip and refusals (the one-line messages: tests/bad-inputs).
TEST(Anisotropy, SceneFieldAndOption) {
    const Scene s = parseScene(R"({"material": {"anisotropy": [8, 256]}})", "a.json", "/scenes");
    EXPECT_TRUE(s.objects[0].material.anisotropic);
    EXPECT_EQ(s.objects[0].material.anisotropy, glm::vec2(8, 256));
    EXPECT_FALSE(parseScene("{}", "a.json", "/scenes").objects[0].material.anisotropic);
    const Scene back = parseScene(sceneToJson(s, "/scenes"), "b.json", "/scenes");
    EXPECT_TRUE(back.objects[0].material.anisotropic);
    EXPECT_EQ(back.objects[0].material.anisotropy, glm::vec2(8, 256));
    EXPECT_THROW(parseScene(R"({"material": {"anisotropy": [8, 0]}})", "a.json", "/scenes"), InputError);
    EXPECT_THROW(parseScene(R"({"reflection": "phong", "material": {"anisotropy": [8, 9]}})", "a.json", "/scenes"), InputError);

    const Options o = parseOptions({"--anisotropy", "8,256"});
    ASSERT_TRUE(o.anisotropy);
    Scene d = defaultScene();
    applyOverrides(d, o);
    for (const SceneObject& obj : d.objects) {
        EXPECT_TRUE(obj.material.anisotropic);
        EXPECT_EQ(obj.material.anisotropy, glm::vec2(8, 256));
    }
    for (const char* bad : {"8", "8,", "8,256,3", "0,8", "8,1e9"}) EXPECT_THROW(parseOptions({"--anisotropy", bad}), InputError) << bad;
    Scene p = defaultScene();
    EXPECT_THROW(applyOverrides(p, parseOptions({"--anisotropy", "8,256", "--reflection", "phong"})), InputError);
}

// The probe's light entries: "tangent", "bitangent" and "exponent" at every evaluation of every mode,
// against the formula: T and B unit and orthogonal to N and to each other, B = N x T (the sphere's
// handedness is +1), on the untransformed sphere T along the parallels (Gouraud: exactly, at the
// corner; Phong: to a few degrees), and the exponent (k_t (H.T)^2 + k_b (H.B)^2) / (1 - (H.N)^2) from the probe's own H and N.
TEST(Anisotropy, ProbeReportsTheFrameAndTheExponent) {
    Scene s = defaultScene();
    s.objects[0].material.anisotropic = true;
    s.objects[0].material.anisotropy = {8.0f, 256.0f};
    s.layout = Layout::Compare;
    s.width = 3 * 64;
    s.height = 64;
    const SceneGeometry g = buildSceneGeometry(s);
    const SceneRayCaster caster(s, g);
    int checked = 0;
    for (int y = 1; y < s.height; y += 4)
        for (int x = 1; x < s.width; x += 4) {
            const ProbeResult r = probePixel(s, g, caster, x, y);
            if (r.miss) continue;
            for (const ProbeEvaluation& e : r.modes[0].evaluations) {
                const glm::vec3 n = e.nrmWorld, t = e.frame.tangent, b = e.frame.bitangent;
                ASSERT_TRUE(e.anisotropic);
                EXPECT_NEAR(glm::length(t), 1.0f, 1e-5f);
                EXPECT_NEAR(glm::dot(t, n), 0.0f, 1e-5f);
                EXPECT_NEAR(glm::distance(b, glm::cross(n, t)), 0.0f, 1e-5f);
                // Gouraud: the vertex's own frame. Phong: the corners' tangents interpolated, a few degrees
                // off the parallel through the point itself (their weights are not the normal's).
                const ShadingMode mode = r.modes[0].mode;
                if (mode != ShadingMode::Flat && std::fabs(n.y) < 0.95f) {
                    EXPECT_NEAR(glm::distance(t, glm::normalize(glm::cross(glm::vec3(0, 1, 0), n))), 0.0f,
                                mode == ShadingMode::Gouraud ? 1e-5f : 0.05f);
                }
                for (const ProbeLight& l : e.lights) {
                    const double ht = glm::dot(l.halfway, t), hb = glm::dot(l.halfway, b), hn = l.hDotN;
                    if (1.0 - hn * hn < 1e-4) continue;  // near H = N the quotient is rounding
                    const double expected = (8.0 * ht * ht + 256.0 * hb * hb) / (1.0 - hn * hn);
                    EXPECT_NEAR(l.exponent, expected, 1e-3 * expected) << x << "," << y;
                    ++checked;
                }
            }
            const nlohmann::json j = nlohmann::json::parse(probeToJson(s, r));
            const nlohmann::json& light = j["evaluations"][0]["lights"][0];
            EXPECT_TRUE(light.contains("tangent") && light.contains("bitangent") && light.contains("exponent")) << light.dump();
        }
    EXPECT_GT(checked, 200);
}
