#include "core/lighting.hpp"

#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>

#include <cmath>

namespace shadelab {

LightingEnvironment lightingEnvironment(const Scene& s) {
    return LightingEnvironment{s.reflection, s.ambient, s.lights, s.camera.eye};
}

ShadingTerms shadeTerms(const Material& m, const LightingEnvironment& env, const glm::vec3& p, const glm::vec3& n) {
    ShadingTerms t;
    const glm::vec3 v = glm::normalize(env.eyeWorld - p);
    t.ambient = m.ka * env.ambient * m.color;
    for (const Light& light : env.lights) {
        glm::vec3 i;
        float attenuation = 1.0f;
        if (light.type == LightType::Directional) {
            i = glm::normalize(-light.direction);
        } else {
            const glm::vec3 d = light.position - p;
            const float r2 = glm::dot(d, d);
            i = d / std::sqrt(r2);
            if (light.attenuation == Attenuation::InverseSquare) attenuation = 1.0f / r2;
        }
        const float nDotI = glm::dot(n, i);
        if (nDotI <= 0.0f) continue;  // light behind the surface: no diffuse, no specular
        float cosLobe;
        if (env.model == ReflectionModel::Phong) {
            const glm::vec3 r = 2.0f * nDotI * n - i;
            cosLobe = glm::dot(r, v);
        } else {
            cosLobe = glm::dot(glm::normalize(i + v), n);
        }
        const float spec = std::pow(std::max(cosLobe, 0.0f), m.ke);
        const glm::vec3 radiance = light.color * light.intensity * attenuation;
        t.diffuse += radiance * m.kd * m.color * nDotI;
        t.specular += radiance * m.ks * m.specularColor * spec;
    }
    t.total = glm::clamp(t.ambient + t.diffuse + t.specular, 0.0f, 1.0f);
    return t;
}

float encodeSrgb(float c) {
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

}  // namespace shadelab
