#pragma once
// CPU reference of the lecture's reflection model: the same inputs and the same result as
// shaders/lighting.glsl, used by the tests (and later the pixel probe).
//
//   L = k_a A C + sum_l L_l ( k_d C max(0, N.I_l) + k_s S spec_l ),  each channel clamped to [0, 1]
//   spec_l = max(0, R(I_l).V)^k_e (Phong) or max(0, H_l.N)^k_e (Blinn-Phong); 0 where N.I_l <= 0
//   R(I) = 2 (N.I) N - I,  H = normalize(I + V),  L_l = colour * intensity * attenuation
#include "core/scene.hpp"

#include <glm/vec3.hpp>

#include <vector>

namespace shadelab {

struct LightingEnvironment {
    ReflectionModel model = ReflectionModel::BlinnPhong;
    glm::vec3 ambient{1.0f};          // A
    std::vector<Light> lights;        // world space
    glm::vec3 eyeWorld{0.0f};
};

LightingEnvironment lightingEnvironment(const Scene& scene);

// Each addend of the formula before clamping, and the clamped total.
struct ShadingTerms {
    glm::vec3 ambient{0.0f};
    glm::vec3 diffuse{0.0f};
    glm::vec3 specular{0.0f};
    glm::vec3 total{0.0f};            // clamp(ambient + diffuse + specular, 0, 1)
};

// nrmWorld must be unit length.
ShadingTerms shadeTerms(const Material& m, const LightingEnvironment& env, const glm::vec3& posWorld,
                        const glm::vec3& nrmWorld);
inline glm::vec3 shade(const Material& m, const LightingEnvironment& env, const glm::vec3& posWorld,
                       const glm::vec3& nrmWorld) {
    return shadeTerms(m, env, posWorld, nrmWorld).total;
}

// The sRGB transfer curve (IEC 61966-2-1) applied to a linear value in [0, 1].
float encodeSrgb(float linear);

}  // namespace shadelab
