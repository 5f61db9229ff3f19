#include "core/shading/environment.hpp"

#include "../../../shaders/shared_defs.glsl"
#include "core/shading/lighting.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace shadelab {
namespace {

constexpr float kPi = 3.14159265358979f;

// GLSL's smoothstep and fract, as shaders/environment.glsl calls them.
float smoothStep(float e0, float e1, float x) {
    const float t = glm::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}
float fract(float x) { return x - std::floor(x); }

// shared_defs.glsl's constants are GLSL literals (doubles to C++): as floats, as the shaders take them.
constexpr float kRoomEdge = float(SL_ROOM_EDGE), kTileEdge = float(SL_ROOM_TILE_EDGE), kTiles = float(SL_ROOM_TILES);
constexpr float kSunInnerCos = float(SL_SKY_SUN_INNER_COS), kSunOuterCos = float(SL_SKY_SUN_OUTER_COS);
glm::vec3 rgb(double r, double g, double b) { return {float(r), float(g), float(b)}; }

// 1 on one half of each period of x, 0 on the other, with soft edges SL_ROOM_TILE_EDGE wide.
float tileStripe(float x) { return smoothStep(-kTileEdge, kTileEdge, std::fabs(fract(x) - 0.5f) - 0.25f); }

}  // namespace

glm::vec3 roomRadiance(const glm::vec3& d) {
    const glm::vec3 a = glm::abs(d);
    const glm::vec3 wallX = d.x > 0.0f ? rgb(SL_ROOM_WALL_RIGHT) : rgb(SL_ROOM_WALL_LEFT);
    const glm::vec3 wallZ = d.z > 0.0f ? rgb(SL_ROOM_WALL_BACK) : rgb(SL_ROOM_WALL_FRONT);
    const glm::vec3 walls = glm::mix(wallZ, wallX, smoothStep(-kRoomEdge, kRoomEdge, a.x - a.z));
    // The floor y = -1 of the room [-1, 1]^3 around the scene: the point d reaches there, in checker periods.
    const float reach = kTiles / std::max(a.y, 1e-4f);
    const float sx = tileStripe(d.x * reach), sz = tileStripe(d.z * reach);
    const glm::vec3 floorColor = glm::mix(rgb(SL_ROOM_TILE_DARK), rgb(SL_ROOM_TILE_LIGHT), sx + sz - 2.0f * sx * sz);
    const glm::vec3 below = d.y < 0.0f ? floorColor : rgb(SL_ROOM_CEILING);
    return glm::mix(walls, below, smoothStep(-kRoomEdge, kRoomEdge, a.y - std::max(a.x, a.z)));
}

glm::vec3 skySunDirection() { return glm::normalize(rgb(SL_SKY_SUN_DIRECTION)); }

glm::vec3 skyRadiance(const glm::vec3& d) {
    const glm::vec3 sky = glm::mix(rgb(SL_SKY_HORIZON), rgb(SL_SKY_ZENITH), smoothStep(0.0f, 1.0f, d.y));
    const glm::vec3 ground = glm::mix(0.5f * rgb(SL_SKY_HORIZON), rgb(SL_SKY_GROUND), smoothStep(0.0f, 0.2f, -d.y));
    const glm::vec3 around = glm::mix(ground, sky, smoothStep(-0.01f, 0.01f, d.y));
    const float sun = smoothStep(kSunOuterCos, kSunInnerCos, glm::dot(d, skySunDirection()));
    return around + sun * rgb(SL_SKY_SUN);
}

glm::vec3 imageRadiance(const EnvironmentImage& img, const glm::vec3& d) {
    if (img.width < 1 || img.height < 1) return glm::vec3(0.0f);
    const float u = 0.5f + std::atan2(d.x, -d.z) / (2.0f * kPi);
    const float v = std::acos(glm::clamp(d.y, -1.0f, 1.0f)) / kPi;
    const float x = u * float(img.width) - 0.5f, y = v * float(img.height) - 0.5f;
    const float x0 = std::floor(x), y0 = std::floor(y);
    const float fx = x - x0, fy = y - y0;
    auto texel = [&](int i, int j) {
        i = ((i % img.width) + img.width) % img.width;  // around the longitude
        j = std::clamp(j, 0, img.height - 1);           // not over the poles
        const float* p = &img.rgb[(std::size_t(j) * std::size_t(img.width) + std::size_t(i)) * 3];
        return glm::vec3(p[0], p[1], p[2]);
    };
    const int i = int(x0), j = int(y0);
    return glm::mix(glm::mix(texel(i, j), texel(i + 1, j), fx), glm::mix(texel(i, j + 1), texel(i + 1, j + 1), fx), fy);
}

glm::vec3 environmentRadiance(const EnvironmentSpec& env, const glm::vec3& d) {
    switch (env.kind) {
    case EnvironmentKind::None: return glm::vec3(0.0f);
    case EnvironmentKind::Room: return roomRadiance(d);
    case EnvironmentKind::Sky: return skyRadiance(d);
    case EnvironmentKind::Image: return env.image ? imageRadiance(*env.image, d) : glm::vec3(0.0f);
    }
    return glm::vec3(0.0f);
}

bool mirrorOrGlass(const Material& m, const EnvironmentSpec& env) {
    return env.kind != EnvironmentKind::None && (m.mirror > 0.0f || m.transmission > 0.0f);
}

Interface interfaceOf(float ior) { return ior >= 1.0f ? Interface{1.0f, ior} : Interface{1.0f / ior, 1.0f}; }

EnvironmentTerm environmentTerm(const Material& m, const LightingEnvironment& env, const glm::vec3& n,
                                const glm::vec3& v) {
    EnvironmentTerm t;
    t.eta = interfaceOf(env.ior);
    const float nDotV = glm::dot(n, v);
    t.reflectedDirection = 2.0f * nDotV * n - v;
    t.cosThetaI = std::max(nDotV, 0.0f);
    const float eta = 1.0f / env.ior;  // eta_i / eta_t
    const float sinTSq = eta * eta * (1.0f - t.cosThetaI * t.cosThetaI);
    t.totalInternal = sinTSq > 1.0f;
    if (!t.totalInternal) {
        t.cosThetaT = std::sqrt(1.0f - sinTSq);
        t.transmittedDirection = -eta * v + (eta * t.cosThetaI - t.cosThetaT) * n;
    } else {
        t.cosThetaT = 0.0f;
    }
    t.weighted = env.fresnel != FresnelMode::None;
    t.fresnel = t.totalInternal ? 1.0f : fresnelWeight(env.fresnel, t.cosThetaI, env.ior);
    const float reflectedWeight = t.weighted ? t.fresnel : 1.0f;
    const float transmittedWeight = t.totalInternal ? 0.0f : t.weighted ? 1.0f - t.fresnel : 1.0f;
    if (m.mirror > 0.0f)
        t.reflected = m.mirror * reflectedWeight * environmentRadiance(env.environment, t.reflectedDirection);
    if (m.transmission > 0.0f && transmittedWeight > 0.0f)
        t.transmitted =
            m.transmission * transmittedWeight * environmentRadiance(env.environment, t.transmittedDirection);
    return t;
}

}  // namespace shadelab
