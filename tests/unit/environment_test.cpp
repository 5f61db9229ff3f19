// Issue 30, part 1: mirror and glass with an environment, on the CPU (core/shading/environment.hpp).
// R, T, Snell's law and F against the lecture's formulas over many directions; total internal
// reflection; "none" keeping k_r and k_t as they are; the procedural environments' continuity and the
// image lookup's texels; the scene field, the options and the probe's "environment" at many pixels.
#include "options/options.hpp"
#include "core/base/error.hpp"
#include "core/geometry/ray_cast.hpp"
#include "core/figures/intersection_image.hpp"
#include "core/geometry/scene_geometry.hpp"
#include "core/probe/probe.hpp"
#include "core/scene/scene_json.hpp"
#include "core/shading/environment.hpp"
#include "core/shading/lighting.hpp"
#include "../../shaders/shared_defs.glsl"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <memory>
#include <random>

using namespace shadelab;

namespace {

glm::vec3 randomUnit(std::mt19937& rng) {
    std::normal_distribution<float> g;
    return glm::normalize(glm::vec3(g(rng), g(rng), g(rng)));
}

LightingEnvironment withEnvironment(FresnelMode fresnel, float ior, EnvironmentKind kind = EnvironmentKind::Room) {
    LightingEnvironment env;
    env.fresnel = fresnel;
    env.ior = ior;
    env.environment.kind = kind;
    return env;
}

glm::vec3 rgb(double r, double g, double b) { return {float(r), float(g), float(b)}; }

Material glass(float kr, float kt) {
    Material m;
    m.mirror = kr;
    m.transmission = kt;
    return m;
}

}  // namespace

// R = 2 (N.V) N - V; T unit, in the plane of N and V, into the surface, with eta_i sin_i = eta_t sin_t;
// F the exact average (R_par + R_perp) / 2 at cos_i = N.V; the terms k_r F env(R) and k_t (1 - F) env(T).
TEST(Environment, ReflectionRefractionAndFresnelAreTheFormulas) {
    std::mt19937 rng(7);
    int checked = 0;
    for (float ior : {1.33f, 1.5f, 2.4f}) {
        const LightingEnvironment env = withEnvironment(FresnelMode::Exact, ior);
        for (int k = 0; k < 400; ++k) {
            const glm::vec3 n = randomUnit(rng);
            glm::vec3 v = randomUnit(rng);
            if (glm::dot(n, v) < 0.0f) v = -v;
            const EnvironmentTerm t = environmentTerm(glass(0.7f, 0.9f), env, n, v);
            const float cosI = glm::dot(n, v);
            EXPECT_NEAR(glm::distance(t.reflectedDirection, 2.0f * cosI * n - v), 0.0f, 1e-5f);
            ASSERT_FALSE(t.totalInternal);
            const glm::vec3 tr = t.transmittedDirection;
            EXPECT_NEAR(glm::length(tr), 1.0f, 1e-5f);
            EXPECT_NEAR(glm::dot(tr, glm::cross(n, v)), 0.0f, 1e-5f);  // in the plane of incidence
            EXPECT_LE(glm::dot(tr, n), 0.0f);                          // into the surface
            const float sinI = glm::length(glm::cross(n, v)), sinT = glm::length(glm::cross(n, tr));
            EXPECT_NEAR(1.0f * sinI, ior * sinT, 1e-5f) << "Snell";
            // T bends towards -N: on the far side of -N from V's tangential part.
            EXPECT_LE(glm::dot(tr - glm::dot(tr, n) * n, v - cosI * n), 1e-6f);
            EXPECT_NEAR(t.eta.etaI, 1.0f, 0.0f);
            EXPECT_NEAR(t.eta.etaT, ior, 0.0f);
            // The lecture's Fresnel formulas, in tangents and sines, at theta_i and theta_t.
            const double ti = std::acos(double(std::min(cosI, 1.0f))), tt = std::asin(double(sinT));
            if (ti > 1e-3) {
                const double par = std::pow(std::tan(ti - tt) / std::tan(ti + tt), 2.0);
                const double perp = std::pow(std::sin(ti - tt) / std::sin(ti + tt), 2.0);
                EXPECT_NEAR(t.fresnel, 0.5 * (par + perp), 2e-4) << ti;
            }
            EXPECT_NEAR(glm::distance(t.reflected, 0.7f * t.fresnel * roomRadiance(t.reflectedDirection)), 0.0f, 1e-5f);
            EXPECT_NEAR(glm::distance(t.transmitted, 0.9f * (1.0f - t.fresnel) * roomRadiance(tr)), 0.0f, 1e-5f);
            ++checked;
        }
    }
    EXPECT_EQ(checked, 1200);
}

// Schlick's R0 + (1 - R0)(1 - cos_i)^5; "none": both weights 1 (F reported as 1, not weighting).
TEST(Environment, SchlickAndNone) {
    const glm::vec3 n(0, 1, 0), v = glm::normalize(glm::vec3(1, 1, 0));
    const EnvironmentTerm s = environmentTerm(glass(1, 1), withEnvironment(FresnelMode::Schlick, 1.5f), n, v);
    const float c = std::sqrt(0.5f), r0 = 0.04f;
    EXPECT_NEAR(s.fresnel, r0 + (1 - r0) * std::pow(1 - c, 5.0f), 1e-6f);
    const EnvironmentTerm none = environmentTerm(glass(0.5f, 0.25f), withEnvironment(FresnelMode::None, 1.5f, EnvironmentKind::Sky), n, v);
    EXPECT_FALSE(none.weighted);
    EXPECT_NEAR(glm::distance(none.reflected, 0.5f * skyRadiance(none.reflectedDirection)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(none.transmitted, 0.25f * skyRadiance(none.transmittedDirection)), 0.0f, 1e-6f);
}

// From inside the glass (ior < 1): past the critical angle asin(ior) no T, F = 1 in every mode, the
// mirror term alone; before it, Snell's law with eta_i = 1/ior, eta_t = 1.
TEST(Environment, TotalInternalReflection) {
    const float ior = 1.0f / 1.5f;
    const double critical = std::asin(double(ior));
    const glm::vec3 n(0, 0, 1);
    for (FresnelMode mode : {FresnelMode::None, FresnelMode::Schlick, FresnelMode::Exact})
        for (double deg = 1.0; deg < 89.0; deg += 2.0) {
            const double a = deg * 3.14159265358979 / 180.0;
            const glm::vec3 v(float(std::sin(a)), 0.0f, float(std::cos(a)));
            const EnvironmentTerm t = environmentTerm(glass(0.5f, 1.0f), withEnvironment(mode, ior), n, v);
            EXPECT_NEAR(t.eta.etaI, 1.5f, 1e-6f);
            EXPECT_NEAR(t.eta.etaT, 1.0f, 1e-6f);
            if (std::fabs(a - critical) < 1e-3) continue;
            EXPECT_EQ(t.totalInternal, a > critical) << deg;
            if (t.totalInternal) {
                EXPECT_EQ(t.fresnel, 1.0f);
                EXPECT_EQ(t.transmitted, glm::vec3(0.0f));
                EXPECT_NEAR(glm::distance(t.reflected, 0.5f * roomRadiance(t.reflectedDirection)), 0.0f, 1e-6f);
            } else {
                EXPECT_NEAR(1.5 * std::sin(a), std::sqrt(1.0 - double(t.cosThetaT * t.cosThetaT)), 1e-5);
            }
        }
}

// The procedural environments have no jumps (so GL and the CPU agree wherever a direction is a little
// off), and show what they promise: the walls' colours, light and dark tiles, the sun.
TEST(Environment, ProceduralEnvironmentsAreContinuous) {
    std::mt19937 rng(3);
    float worst = 0.0f;
    for (int k = 0; k < 20000; ++k) {
        const glm::vec3 d = randomUnit(rng);
        const glm::vec3 e = glm::normalize(d + 1e-5f * randomUnit(rng));
        worst = std::max({worst, glm::distance(roomRadiance(d), roomRadiance(e)) / glm::distance(d, e),
                          glm::distance(skyRadiance(d), skyRadiance(e)) / glm::distance(d, e) / 8.0f});
    }
    EXPECT_LT(worst, 2000.0f);  // a 1e-5 change moves a colour by less than 0.02 (sun: 0.16 of its 8)
    EXPECT_NEAR(glm::distance(roomRadiance({1, 0, 0}), rgb(SL_ROOM_WALL_RIGHT)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(roomRadiance({-1, 0, 0}), rgb(SL_ROOM_WALL_LEFT)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(roomRadiance({0, 0, -1}), rgb(SL_ROOM_WALL_FRONT)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(roomRadiance({0, 1, 0}), rgb(SL_ROOM_CEILING)), 0.0f, 1e-6f);
    // The floor under d = (x, -1, z): tiles 1/(2 SL_ROOM_TILES) wide centred on multiples of that; a tile
    // and its neighbour differ, a tile and its diagonal neighbour do not.
    const float tile = 0.5f / float(SL_ROOM_TILES);
    const glm::vec3 a = roomRadiance(glm::normalize(glm::vec3(1.0f * tile, -1, 2.0f * tile)));
    const glm::vec3 b = roomRadiance(glm::normalize(glm::vec3(2.0f * tile, -1, 2.0f * tile)));
    const glm::vec3 c = roomRadiance(glm::normalize(glm::vec3(2.0f * tile, -1, 3.0f * tile)));
    EXPECT_GT(std::fabs(a.r - b.r), 0.8f);
    EXPECT_NEAR(a.r, c.r, 1e-5f);
    EXPECT_GT(skyRadiance(skySunDirection()).r, 8.0f);  // the sun: its disc on the sky
    EXPECT_LT(skyRadiance(glm::normalize(glm::vec3(0, 1, 1))).r, 1.0f);
}

// The image lookup: at a texel's centre its own value; halfway between two, their mean; across the
// longitude seam, the first and last columns blend.
TEST(Environment, ImageTexelsAndTheSeam) {
    EnvironmentImage img{4, 2, std::vector<float>(4 * 2 * 3, 0.0f)};
    for (int i = 0; i < 8; ++i) img.rgb[std::size_t(3 * i)] = float(i);  // red = texel index
    auto dir = [](float u, float v) {  // the inverse of imageRadiance's mapping
        const float lon = (u - 0.5f) * 2.0f * 3.14159265f, lat = v * 3.14159265f;
        return glm::vec3(std::sin(lat) * std::sin(lon), std::cos(lat), -std::sin(lat) * std::cos(lon));
    };
    EXPECT_NEAR(imageRadiance(img, dir(1.5f / 4, 0.25f)).r, 1.0f, 1e-4f);
    EXPECT_NEAR(imageRadiance(img, dir(2.5f / 4, 0.75f)).r, 6.0f, 1e-4f);
    EXPECT_NEAR(imageRadiance(img, dir(2.0f / 4, 0.25f)).r, 1.5f, 1e-4f);
    EXPECT_NEAR(imageRadiance(img, dir(0.999f, 0.25f)).r, 1.5f, 0.02f);  // between column 3 and column 0
}

// "environment" and the material's "mirror" and "transmission": read, written back, refused where wrong.
TEST(Environment, SceneFieldAndOptions) {
    const Scene s = parseScene(R"({"environment": "sky", "material": {"mirror": 0.5, "transmission": 0.25}})", "a.json", "/s");
    EXPECT_EQ(s.environment.kind, EnvironmentKind::Sky);
    EXPECT_EQ(s.objects[0].material.mirror, 0.5f);
    EXPECT_EQ(s.objects[0].material.transmission, 0.25f);
    const Scene back = parseScene(sceneToJson(s, "/s"), "b.json", "/s");
    EXPECT_EQ(back.environment.kind, EnvironmentKind::Sky);
    EXPECT_EQ(back.objects[0].material.mirror, 0.5f);
    EXPECT_EQ(back.objects[0].material.transmission, 0.25f);
    EXPECT_EQ(parseScene("{}", "a.json", "/s").environment.kind, EnvironmentKind::None);
    EXPECT_THROW(parseScene(R"({"material": {"mirror": 1.5}})", "a.json", "/s"), InputError);
    EXPECT_THROW(parseScene(R"({"environment": 3})", "a.json", "/s"), InputError);
    EXPECT_THROW(parseScene(R"({"environment": "missing.hdr"})", "a.json", "/nowhere"), InputError);
    EXPECT_THROW(parseScene(R"({"environment": "room.txt"})", "a.json", "/nowhere"), InputError);

    Scene d = defaultScene();
    applyOverrides(d, parseOptions({"--environment", "room", "--mirror", "0.8", "--transmission", "0.1", "--ior", "0.7"}));
    EXPECT_EQ(d.environment.kind, EnvironmentKind::Room);
    EXPECT_EQ(d.objects[0].material.mirror, 0.8f);
    EXPECT_EQ(d.objects[0].material.transmission, 0.1f);
    EXPECT_EQ(d.ior, 0.7f);
    for (const char* bad : {"-0.1", "1.1", "x"}) {
        Scene p = defaultScene();
        EXPECT_THROW(applyOverrides(p, parseOptions({"--mirror", bad})), InputError) << bad;
    }
    EXPECT_THROW(parseOptions({"--environment", "nowhere.png"}), InputError);
}

// The probe's "environment" at many pixels of the three modes: R and T from that evaluation's own N
// and V by the formulas, the angles, the indices and F, and the terms adding up to what the sum got.
TEST(Environment, ProbeReportsTheIntersection) {
    Scene s = defaultScene();
    s.environment.kind = EnvironmentKind::Room;
    s.fresnel = FresnelMode::Exact;
    s.objects[0].material.mirror = 0.6f;
    s.objects[0].material.transmission = 0.8f;
    s.layout = Layout::Compare;
    s.width = 3 * 64;
    s.height = 64;
    const SceneGeometry g = buildSceneGeometry(s);
    const SceneRayCaster caster(s, g);
    int checked = 0;
    for (int y = 1; y < s.height; y += 3)
        for (int x = 1; x < s.width; x += 3) {
            const ProbeResult r = probePixel(s, g, caster, x, y);
            if (r.miss) continue;
            const nlohmann::json j = nlohmann::json::parse(probeToJson(s, r));
            for (std::size_t k = 0; k < r.modes[0].evaluations.size(); ++k) {
                const ProbeEvaluation& e = r.modes[0].evaluations[k];
                const nlohmann::json& env = j["evaluations"][k]["environment"];
                ASSERT_TRUE(env.is_object()) << j.dump();
                const glm::vec3 n = e.nrmWorld, v = e.viewWorld;
                auto vec = [](const nlohmann::json& a) { return glm::vec3(a[0].get<float>(), a[1].get<float>(), a[2].get<float>()); };
                const float cosI = std::max(glm::dot(n, v), 0.0f);
                EXPECT_NEAR(glm::distance(vec(env["R"]), 2.0f * glm::dot(n, v) * n - v), 0.0f, 1e-4f);
                const float eta = 1.0f / 1.5f, cosT = std::sqrt(1.0f - eta * eta * (1.0f - cosI * cosI));
                EXPECT_NEAR(glm::distance(vec(env["T"]), -eta * v + (eta * cosI - cosT) * n), 0.0f, 1e-4f);
                EXPECT_NEAR(env["theta_i_deg"].get<double>(), std::acos(cosI) * 180.0 / 3.14159265358979, 1e-2);
                EXPECT_NEAR(std::sin(env["theta_i_deg"].get<double>() * 3.14159265358979 / 180.0),
                            1.5 * std::sin(env["theta_t_deg"].get<double>() * 3.14159265358979 / 180.0), 1e-3);
                EXPECT_EQ(env["eta_i"].get<double>(), 1.0);
                EXPECT_EQ(env["eta_t"].get<double>(), 1.5);
                EXPECT_NEAR(env["F"].get<double>(), fresnelExact(cosI, 1.0f, 1.5f).average, 1e-4);
                const glm::vec3 sum = vec(env["reflected"]) + vec(env["transmitted"]);
                EXPECT_NEAR(glm::distance(sum, e.terms.environment), 0.0f, 1e-4f);
                EXPECT_NEAR(glm::distance(e.terms.shown, e.terms.ambient + e.terms.diffuse + e.terms.specular + e.terms.environment),
                            0.0f, 1e-5f);
                ++checked;
            }
        }
    EXPECT_GT(checked, 300);
}

// The intersection diagram's numbers: Snell's law between its angles, R the mean of R_par and R_perp,
// the lecture's tan^2 and sin^2 quotients; past the critical angle (from inside) no theta_t and R = 1.
TEST(Environment, IntersectionDiagramNumbers) {
    Scene s = defaultScene();
    s.camera.eye = {0.0f, 2.0f, 2.0f};  // 45 degrees onto the point at the origin with N = +y
    IntersectionPoint at;
    at.posWorld = glm::vec3(0.0f);
    at.nrmWorld = glm::vec3(0.0f, 1.0f, 0.0f);
    const IntersectionNumbers n = intersectionNumbers(s, at);
    EXPECT_NEAR(n.thetaIDeg, 45.0f, 1e-3f);
    const double ti = double(n.thetaIDeg) * 3.14159265358979 / 180.0, tt = double(n.thetaTDeg) * 3.14159265358979 / 180.0;
    EXPECT_NEAR(std::sin(ti), 1.5 * std::sin(tt), 1e-5);
    EXPECT_NEAR(n.rParallel, std::pow(std::tan(ti - tt) / std::tan(ti + tt), 2.0), 1e-5);
    EXPECT_NEAR(n.rPerpendicular, std::pow(std::sin(ti - tt) / std::sin(ti + tt), 2.0), 1e-5);
    EXPECT_NEAR(n.r, 0.5f * (n.rParallel + n.rPerpendicular), 1e-6f);
    s.ior = 1.0f / 1.5f;  // from inside the glass: 45 degrees is past the critical angle (41.8)
    const IntersectionNumbers inside = intersectionNumbers(s, at);
    EXPECT_TRUE(inside.totalInternal);
    EXPECT_EQ(inside.r, 1.0f);
    EXPECT_NEAR(inside.etaI, 1.5f, 1e-6f);
}
