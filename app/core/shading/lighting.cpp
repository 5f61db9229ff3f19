#include "core/shading/lighting.hpp"

#include "core/shading/environment.hpp"

#include "../../../shaders/shared_defs.glsl"

#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

namespace shadelab {
namespace {

constexpr float kPi = 3.14159265358979f;

// One light sample's addend: radiance * (k_d C (N.I) + k_s S spec), nothing when N.I <= 0 (lecture.glsl's
// oneLight()).
// `frame`: the tangent frame, for an anisotropic lobe (else unused).
void addSample(LightShare& t, const Material& m, const LightingEnvironment& env, const glm::vec3& n, const glm::vec3& v,
               const glm::vec3& i, const glm::vec3& radiance, const TangentFrame& frame) {
    const float nDotI = glm::dot(n, i);
    if (nDotI <= 0.0f) return;  // light behind the surface: no diffuse, no specular
    t.diffuse += radiance * m.kd * m.color * nDotI;
    t.specular += radiance * m.ks * m.specularColor * lobeTerm(m, env, n, i, v, frame);
}

}  // namespace

LightingEnvironment lightingEnvironment(const Scene& s) {
    LightingEnvironment env;
    env.model = s.reflection;
    env.normalization = s.specularNormalization;
    env.fresnel = s.fresnel;
    env.ior = s.ior;
    env.show = s.show;
    env.ambient = s.ambient;
    env.lights = s.lights;
    env.eyeWorld = s.camera.eye;
    env.environment = s.environment;
    return env;
}

float lobeNormalization(ReflectionModel model, float ke) {
    return model == ReflectionModel::Phong ? (ke + 2.0f) / (2.0f * kPi) : (ke + 8.0f) / (8.0f * kPi);
}

float energySpecularScale(ReflectionModel model, float ke) {
    return lobeNormalization(model, ke) / lobeNormalization(model, kEnergyReferenceExponent);
}

FresnelTerms fresnelExact(float cosTheta1, float eta1, float eta2) {
    FresnelTerms f;
    const float c1 = glm::clamp(cosTheta1, 0.0f, 1.0f);
    const float sin1 = std::sqrt(std::max(0.0f, 1.0f - c1 * c1));
    const float sin3 = eta1 / eta2 * sin1;  // Snell: eta1 sin theta1 = eta2 sin theta3
    if (sin3 >= 1.0f) {
        f.parallel = f.perpendicular = f.average = 1.0f;
        f.totalInternal = true;
        return f;
    }
    const float c3 = std::sqrt(1.0f - sin3 * sin3);
    // The cosine forms of the lecture's tan^2/sin^2 quotients (equal to them, and finite at normal incidence).
    const float perp = (eta1 * c1 - eta2 * c3) / (eta1 * c1 + eta2 * c3);
    const float par = (eta1 * c3 - eta2 * c1) / (eta1 * c3 + eta2 * c1);
    f.parallel = par * par;
    f.perpendicular = perp * perp;
    f.average = 0.5f * (f.parallel + f.perpendicular);
    return f;
}

float fresnelR0(float eta1, float eta2) {
    const float r = (eta1 - eta2) / (eta1 + eta2);
    return r * r;
}

float fresnelSchlick(float cosTheta1, float eta1, float eta2) {
    const float r0 = fresnelR0(eta1, eta2);
    const float m = 1.0f - glm::clamp(cosTheta1, 0.0f, 1.0f);
    return r0 + (1.0f - r0) * m * m * m * m * m;
}

float fresnelWeight(FresnelMode mode, float cosVH, float ior) {
    switch (mode) {
    case FresnelMode::None: return 1.0f;
    case FresnelMode::Schlick: return fresnelSchlick(cosVH, 1.0f, ior);
    case FresnelMode::Exact: return fresnelExact(cosVH, 1.0f, ior).average;
    }
    return 1.0f;
}

float specularTerm(const LightingEnvironment& env, float ke, const glm::vec3& n, const glm::vec3& i,
                   const glm::vec3& v) {
    const float nDotI = glm::dot(n, i);
    if (nDotI <= 0.0f) return 0.0f;  // light behind the surface
    float cosLobe;
    const glm::vec3 h = glm::normalize(i + v);
    if (env.model == ReflectionModel::Phong) {
        const glm::vec3 r = 2.0f * nDotI * n - i;
        cosLobe = glm::dot(r, v);
    } else {
        cosLobe = glm::dot(h, n);
    }
    float spec = std::pow(std::max(cosLobe, 0.0f), ke);
    if (env.normalization == SpecularNormalization::Energy) spec *= energySpecularScale(env.model, ke);
    if (env.fresnel != FresnelMode::None) spec *= fresnelWeight(env.fresnel, std::max(glm::dot(v, h), 0.0f), env.ior);
    return spec;
}

glm::vec3 orthogonalTangent(const glm::vec3& t, const glm::vec3& n, const glm::vec3& fallback) {
    const glm::vec3 g = t - n * glm::dot(n, t);
    const float len = glm::length(g);
    return len > 1e-6f * std::max(glm::length(t), 1e-30f) && std::isfinite(len) ? g / len : fallback;
}

glm::vec4 tangentAroundUp(const glm::vec3& n) {
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    const glm::vec3 t = orthogonalTangent(
        glm::cross(up, n), n, orthogonalTangent(glm::vec3(1.0f, 0.0f, 0.0f), n, glm::vec3(0.0f, 0.0f, 1.0f)));
    return glm::vec4(t, 1.0f);
}

TangentFrame tangentFrame(const glm::vec3& n, const glm::vec3& t, float w) {
    TangentFrame f;
    f.tangent = orthogonalTangent(t, n, glm::vec3(tangentAroundUp(n)));
    f.bitangent = (w < 0.0f ? -1.0f : 1.0f) * glm::cross(n, f.tangent);
    return f;
}

bool anisotropicLobe(const Material& m, const LightingEnvironment& env) {
    return m.anisotropic && env.model == ReflectionModel::BlinnPhong;
}

float anisotropicExponent(const glm::vec2& k, const glm::vec3& h, const TangentFrame& f) {
    const float ht = glm::dot(h, f.tangent), hb = glm::dot(h, f.bitangent);
    const float sinSq = ht * ht + hb * hb;  // 1 - (H.N)^2
    return sinSq > 0.0f ? (k.x * ht * ht + k.y * hb * hb) / sinSq : k.x;
}

float anisotropicEnergyScale(const glm::vec2& k) {
    return std::sqrt((k.x + 1.0f) * (k.y + 1.0f)) / (kEnergyReferenceExponent + 1.0f);
}

float anisotropicSpecularTerm(const LightingEnvironment& env, const glm::vec2& k, const glm::vec3& n,
                              const glm::vec3& i, const glm::vec3& v, const TangentFrame& frame) {
    if (glm::dot(n, i) <= 0.0f) return 0.0f;  // light behind the surface
    const glm::vec3 h = glm::normalize(i + v);
    float spec = std::pow(std::max(glm::dot(h, n), 0.0f), anisotropicExponent(k, h, frame));
    if (env.normalization == SpecularNormalization::Energy) spec *= anisotropicEnergyScale(k);
    if (env.fresnel != FresnelMode::None) spec *= fresnelWeight(env.fresnel, std::max(glm::dot(v, h), 0.0f), env.ior);
    return spec;
}

float lobeTerm(const Material& m, const LightingEnvironment& env, const glm::vec3& n, const glm::vec3& i,
               const glm::vec3& v, const TangentFrame& frame) {
    return anisotropicLobe(m, env) ? anisotropicSpecularTerm(env, m.anisotropy, n, i, v, frame)
                                   : specularTerm(env, m.ke, n, i, v);
}

BrdfValue brdf(const Material& m, const LightingEnvironment& env, const glm::vec3& n, const glm::vec3& i,
               const glm::vec3& v, const TangentFrame& frame) {
    const float nDotI = glm::dot(n, i);
    if (nDotI <= 0.0f) return {};  // light behind the surface
    return {m.kd, m.ks * lobeTerm(m, env, n, i, v, frame) / nDotI};
}

float attenuationFactor(const Light& light, float r2) {
    if (light.attenuation != Attenuation::InverseSquare) return 1.0f;
    float f = 1.0f / r2;
    if (light.range > 0.0f) {
        const float q = r2 / (light.range * light.range);  // (r/range)^2
        const float w = glm::clamp(1.0f - q * q, 0.0f, 1.0f);
        f *= w * w;
    }
    return f;
}

glm::vec2 spotCone(const Light& l) {
    const float cosOuter = std::cos(glm::radians(l.outerConeDeg)), cosInner = std::cos(glm::radians(l.innerConeDeg));
    return {cosOuter, 1.0f / std::max(cosInner - cosOuter, 1e-3f)};
}

float spotFalloff(const Light& l, const glm::vec3& towardLight) {
    if (l.type != LightType::Spot) return 1.0f;
    const glm::vec2 cone = spotCone(l);
    const float cd = glm::dot(glm::normalize(l.direction), -towardLight);
    const float t = glm::clamp((cd - cone.x) * cone.y, 0.0f, 1.0f);
    return t * t;
}

AreaFrame areaFrame(const Light& l) {
    AreaFrame f;
    f.n = glm::normalize(l.normal);
    const glm::vec3 ref = std::fabs(f.n.y) > 0.999f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    const glm::vec3 u = glm::normalize(glm::cross(ref, f.n));
    f.u = l.size.x * u;
    f.v = l.size.y * glm::cross(f.n, u);
    return f;
}

std::uint32_t jitterHash(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

glm::vec2 areaSampleOffset(int i, int j, const glm::ivec2& n) {
    const auto k = std::uint32_t(j * n.x + i);
    // 24 bits of the hash as a float in [0, 1): exact in float, the same in GLSL.
    auto unit = [](std::uint32_t h) { return float(h >> 8) * (1.0f / 16777216.0f); };
    const float jx = n.x == 1 ? 0.5f : unit(jitterHash(2u * k + SL_AREA_JITTER_SEED));
    const float jy = n.y == 1 ? 0.5f : unit(jitterHash(2u * k + 1u + SL_AREA_JITTER_SEED));
    return {(float(i) + jx) / float(n.x) - 0.5f, (float(j) + jy) / float(n.y) - 0.5f};
}

glm::vec3 areaSamplePosition(const Light& l, int i, int j) {
    const AreaFrame f = areaFrame(l);
    const glm::vec2 o = areaSampleOffset(i, j, l.samples);
    return l.position + o.x * f.u + o.y * f.v;
}

namespace {

// The point being shaded, as each light's samples reach it: P, its unit normal N, the unit vector V
// towards the eye, the tangent frame (for an anisotropic lobe) and the caller's occlusion test.
struct ShadedPoint {
    const Material& m;
    const LightingEnvironment& env;
    glm::vec3 p, n, v;
    TangentFrame frame;
    const Visibility& visibility;

    // v(p, I) of the sample towards `i`: 1 without a Visibility, and where N.I <= 0 (it adds nothing anyway).
    float visible(std::size_t light, int sample, const glm::vec3& i, float distance) const {
        if (!visibility || glm::dot(n, i) <= 0.0f) return 1.0f;
        return visibility(p, LightRay{light, sample, i, distance});
    }
    // One light sample arriving from `i` with `radiance`, reflected into `share`.
    void reflect(LightShare& share, const glm::vec3& i, const glm::vec3& radiance) const {
        addSample(share, m, env, n, v, i, radiance, frame);
    }
};

// ---- What this program adds to L_l: distance, spot cone, shadow; area lights (lighting.glsl) ----

// A point or spot light: L_l weakened by the distance (attenuationFactor) and the spot cone
// (spotFalloff), and v where the cone lets any light through.
LightShare pointLight(const ShadedPoint& at, std::size_t li) {
    const Light& light = at.env.lights[li];
    LightShare share;
    const glm::vec3 d = light.position - at.p;
    const float r2 = glm::dot(d, d), r = std::sqrt(r2);
    const glm::vec3 i = d / r;
    const float cone = spotFalloff(light, i);
    const glm::vec3 power = light.color * light.intensity;
    at.reflect(share, i,
               power * (attenuationFactor(light, r2) * cone) * (cone > 0.0f ? at.visible(li, 0, i, r) : 1.0f));
    return share;
}

// An area light: nx * ny point lights, its samples, each weighted by its share of the area, the
// cosine at the light (|cos| when two-sided; nothing from behind the emitting side) and its own v.
LightShare areaLight(const ShadedPoint& at, std::size_t li) {
    const Light& light = at.env.lights[li];
    LightShare share;
    const glm::vec3 power = light.color * light.intensity;
    const glm::vec3 front = glm::normalize(light.normal);
    const float area = 1.0f / float(light.samples.x * light.samples.y);
    for (int sj = 0; sj < light.samples.y; ++sj)
        for (int si = 0; si < light.samples.x; ++si) {
            const glm::vec3 d = areaSamplePosition(light, si, sj) - at.p;
            const float r2 = glm::dot(d, d), r = std::sqrt(r2);
            const glm::vec3 i = d / r;
            float cosLight = -glm::dot(front, i);
            if (light.twoSided) cosLight = std::fabs(cosLight);
            if (cosLight <= 0.0f) continue;  // behind the emitting side
            const float vis = at.visible(li, sj * light.samples.x + si, i, r);
            at.reflect(share, i, power * (attenuationFactor(light, r2) * cosLight * area * vis));
        }
    return share;
}

// ---- The lecture's sum, one light at a time (lecture.glsl's loop in lecture()) ----

// Light l's share of the sum: v L_l (k_d C max(0, N.I) + k_s S spec); a directional light's I is the
// same everywhere and its L_l arrives whole.
LightShare lightShare(const ShadedPoint& at, std::size_t li) {
    const Light& light = at.env.lights[li];
    switch (light.type) {
    case LightType::Directional: {
        LightShare share;
        const glm::vec3 i = glm::normalize(-light.direction);
        const glm::vec3 power = light.color * light.intensity;
        at.reflect(share, i, power * at.visible(li, 0, i, std::numeric_limits<float>::infinity()));
        return share;
    }
    case LightType::Point:
    case LightType::Spot: return pointLight(at, li);
    case LightType::Area: return areaLight(at, li);
    }
    return {};
}

// ---- "show": one term of the sum alone ----

// The term drawn (all of them by default), before the clamp.
glm::vec3 termsShown(const ShadingTerms& t, const Material& m, const TermView& show) {
    switch (show.term) {
    case ShowTerm::All: return t.emissive + t.ambient + t.diffuse + t.specular + t.environment;
    case ShowTerm::Emissive: return t.emissive;
    case ShowTerm::Ambient: return t.ambient;
    case ShowTerm::Diffuse: return t.diffuse;
    case ShowTerm::Specular: return t.specular;
    case ShowTerm::Light:
        if (show.light >= 0 && std::size_t(show.light) < t.lights.size())
            return t.lights[std::size_t(show.light)].diffuse + t.lights[std::size_t(show.light)].specular;
        return glm::vec3(0.0f);
    case ShowTerm::Unlit: return m.color;
    }
    return glm::vec3(0.0f);
}

}  // namespace

ShadingTerms shadeTerms(const Material& m, const LightingEnvironment& env, const glm::vec3& p, const glm::vec3& n,
                        const Visibility& visibility, const TangentFrame* tangents) {
    const TangentFrame frame = tangents ? *tangents : tangentFrame(n, glm::vec3(tangentAroundUp(n)), 1.0f);
    const ShadedPoint at{m, env, p, n, glm::normalize(env.eyeWorld - p), frame, visibility};
    ShadingTerms t;
    // The lecture's sum: k_a A C + sum_l L_l (k_d C max(0, N.I_l) + k_s S spec_l), each light's share kept.
    t.ambient = m.ka * env.ambient * m.color;
    for (std::size_t li = 0; li < env.lights.size(); ++li) t.lights.push_back(lightShare(at, li));
    for (const LightShare& share : t.lights) {
        t.diffuse += share.diffuse;
        t.specular += share.specular;
    }
    // What this program adds: E before the sum, mirror and glass after it, and "show" keeping one term.
    t.emissive = m.emissive;
    if (mirrorOrGlass(m, env.environment)) t.environment = environmentTerm(m, env, n, at.v).total();
    t.shown = termsShown(t, m, env.show);
    t.total = glm::clamp(t.shown, 0.0f, 1.0f);
    return t;
}

float encodeSrgb(float c) { return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f; }

}  // namespace shadelab
