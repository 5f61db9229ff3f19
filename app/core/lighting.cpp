#include "core/lighting.hpp"

#include "../../shaders/shared_defs.glsl"

#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>

#include <cmath>

namespace shadelab {
namespace {

// One light sample's addend: radiance * (k_d C (N.I) + k_s S spec), nothing when N.I <= 0.
void addSample(ShadingTerms& t, const Material& m, ReflectionModel model, const glm::vec3& n, const glm::vec3& v,
               const glm::vec3& i, const glm::vec3& radiance) {
    const float nDotI = glm::dot(n, i);
    if (nDotI <= 0.0f) return;  // light behind the surface: no diffuse, no specular
    float cosLobe;
    if (model == ReflectionModel::Phong) {
        const glm::vec3 r = 2.0f * nDotI * n - i;
        cosLobe = glm::dot(r, v);
    } else {
        cosLobe = glm::dot(glm::normalize(i + v), n);
    }
    const float spec = std::pow(std::max(cosLobe, 0.0f), m.ke);
    t.diffuse += radiance * m.kd * m.color * nDotI;
    t.specular += radiance * m.ks * m.specularColor * spec;
}

}  // namespace

LightingEnvironment lightingEnvironment(const Scene& s) {
    return LightingEnvironment{s.reflection, s.ambient, s.lights, s.camera.eye};
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

ShadingTerms shadeTerms(const Material& m, const LightingEnvironment& env, const glm::vec3& p, const glm::vec3& n,
                        const Visibility& visibility) {
    ShadingTerms t;
    const glm::vec3 v = glm::normalize(env.eyeWorld - p);
    t.ambient = m.ka * env.ambient * m.color;
    auto visible = [&](std::size_t light, int sample, const glm::vec3& i, float distance) {
        if (!visibility || glm::dot(n, i) <= 0.0f) return 1.0f;  // N.I <= 0 adds nothing anyway
        return visibility(p, LightRay{light, sample, i, distance});
    };
    for (std::size_t li = 0; li < env.lights.size(); ++li) {
        const Light& light = env.lights[li];
        const glm::vec3 power = light.color * light.intensity;
        switch (light.type) {
        case LightType::Directional: {
            const glm::vec3 i = glm::normalize(-light.direction);
            addSample(t, m, env.model, n, v, i, power * visible(li, 0, i, std::numeric_limits<float>::infinity()));
            break;
        }
        case LightType::Point: {
            const glm::vec3 d = light.position - p;
            const float r2 = glm::dot(d, d), r = std::sqrt(r2);
            const glm::vec3 i = d / r;
            addSample(t, m, env.model, n, v, i, power * attenuationFactor(light, r2) * visible(li, 0, i, r));
            break;
        }
        case LightType::Area: {
            const glm::vec3 front = glm::normalize(light.normal);
            const float share = 1.0f / float(light.samples.x * light.samples.y);
            for (int sj = 0; sj < light.samples.y; ++sj)
                for (int si = 0; si < light.samples.x; ++si) {
                    const glm::vec3 d = areaSamplePosition(light, si, sj) - p;
                    const float r2 = glm::dot(d, d), r = std::sqrt(r2);
                    const glm::vec3 i = d / r;
                    float cosLight = -glm::dot(front, i);
                    if (light.twoSided) cosLight = std::fabs(cosLight);
                    if (cosLight <= 0.0f) continue;  // behind the emitting side
                    const float vis = visible(li, sj * light.samples.x + si, i, r);
                    addSample(t, m, env.model, n, v, i, power * (attenuationFactor(light, r2) * cosLight * share * vis));
                }
            break;
        }
        }
    }
    t.total = glm::clamp(t.ambient + t.diffuse + t.specular, 0.0f, 1.0f);
    return t;
}

float encodeSrgb(float c) {
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

}  // namespace shadelab
