#pragma once
// CPU reference of the lecture's reflection model: the same inputs and the same result as
// shaders/lighting.glsl, used by the tests (and later the pixel probe).
//
//   L = E + k_a A C + sum_l sum_k v(p, I_lk) L_lk ( k_d C max(0, N.I_lk) + k_s S spec_lk ),  each channel clamped to
//   [0, 1] (E: the light a glTF material gives off, Material::emissive; 0 for the lecture's own materials) spec =
//   max(0, R(I).V)^k_e (Phong) or max(0, H.N)^k_e (Blinn-Phong); 0 where N.I <= 0 R(I) = 2 (N.I) N - I,  H =
//   normalize(I + V)
//
// Point and directional lights are one sample k, with L = colour * intensity * attenuation; a spot light
// is a point light times its cone's falloff (spotFalloff: glTF KHR_lights_punctual's). An area
// light is nx * ny point-light samples (areaSamplePosition), each with
//   L_k = colour * intensity * attenuation(r_k) * cos_k / (nx * ny),   cos_k = n_light . (-I_k)
// (its share of the area, and the cosine at the light; |cos_k| when two-sided, 0 behind the light).
// v(p, I) is the lecture's occlusion term: 1 unless the caller supplies a Visibility.
//
// Beyond the heuristic model (scene fields; the GLSL is specialised for each, see lighting.glsl):
// - "specular_normalization": "energy" replaces the lobe cos^k_e by the energy-normalised lobe
//   n(k_e) cos^k_e, n = (k_e + 2) / 2pi (Phong) or (k_e + 8) / 8pi (Blinn-Phong), and the diffuse
//   term k_d C (N.I) by k_d C/pi (N.I). The lights' radiance is scaled by pi (so the diffuse term is
//   unchanged) and k_s is read relative to k_e = 32 (divided by pi n(32)), so that the default scene
//   looks the same at k_e = 32. Net effect, exactly: spec is multiplied by
//   energySpecularScale = n(k_e) / n(32) = (k_e + 2) / 34 (Phong) or (k_e + 8) / 40 (Blinn-Phong),
//   and the energy the lobe reflects stays constant as k_e changes (instead of the highlight dimming).
// - "fresnel": spec is multiplied by F(V.H), the reflectance of a surface of relative index of
//   refraction `ior` (= eta2/eta1, light arriving from eta1 = air): Schlick's R0 + (1 - R0)(1 - cos)^5,
//   or the exact unpolarised Fresnel average (R_par + R_perp) / 2.
// - "anisotropy": [k_t, k_b] (Blinn-Phong only): Ashikhmin and Shirley's exponent replaces k_e,
//     spec = max(0, H.N)^k(H),  k(H) = (k_t (H.T)^2 + k_b (H.B)^2) / (1 - (H.N)^2)   (spec = 1 where H = N)
//   with T, B the surface's unit tangent and bitangent (TangentFrame). k_t = k_b = k_e is Blinn-Phong's
//   lobe exactly. With "energy", their normalisation sqrt((k_t + 1)(k_b + 1)) / 8pi, read relative to
//   k_t = k_b = 32 like the isotropic lobe: spec is multiplied by sqrt((k_t + 1)(k_b + 1)) / 33.
// - "mirror" and "transmission" with an "environment": k_r F env(R) + k_t (1 - F) env(T) added after
//   the sum (core/shading/environment.hpp); drawn with show = all only.
// - "show": only one addend is drawn (ambient, diffuse, specular, one light's diffuse + specular) or
//   the unlit colour C; the total is that addend clamped to [0, 1].
#include "core/scene/scene.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

namespace shadelab {

struct LightingEnvironment {
    ReflectionModel model = ReflectionModel::BlinnPhong;
    SpecularNormalization normalization = SpecularNormalization::None;
    FresnelMode fresnel = FresnelMode::None;
    float ior = 1.5f;  // eta2 / eta1
    TermView show;
    glm::vec3 ambient{1.0f};    // A
    std::vector<Light> lights;  // world space
    glm::vec3 eyeWorld{0.0f};
    EnvironmentSpec environment;  // what mirrors and glass see (core/shading/environment.hpp)
};

LightingEnvironment lightingEnvironment(const Scene& scene);

// One light's share (summed over an area light's samples), before clamping.
struct LightShare {
    glm::vec3 diffuse{0.0f};
    glm::vec3 specular{0.0f};
};

// Each addend of the formula before clamping, and the clamped total (of what `show` selects).
struct ShadingTerms {
    glm::vec3 emissive{0.0f};  // E (Material::emissive)
    glm::vec3 ambient{0.0f};
    glm::vec3 diffuse{0.0f};
    glm::vec3 specular{0.0f};
    // Mirror and glass, after the lecture's sum: k_r F env(R) + k_t (1 - F) env(T) (environment.hpp).
    glm::vec3 environment{0.0f};
    glm::vec3 shown{0.0f};           // what `show` selects before clamping: E + ambient + diffuse + specular
                                     // + environment with show = all
    glm::vec3 total{0.0f};           // clamp(shown, 0, 1)
    std::vector<LightShare> lights;  // per light, in the order of LightingEnvironment::lights
};

// The energy-normalisation of the lobe: (k_e + 2) / 2pi (Phong) or (k_e + 8) / 8pi (Blinn-Phong).
float lobeNormalization(ReflectionModel model, float ke);
// What "specular_normalization": "energy" multiplies spec by: lobeNormalization(k_e) / lobeNormalization(32).
float energySpecularScale(ReflectionModel model, float ke);
inline constexpr float kEnergyReferenceExponent = 32.0f;  // the default scene looks the same here

// Fresnel reflectance for light arriving from a medium eta1 onto eta2 at incidence angle theta1
// (cosTheta1 = cos theta1 in [0, 1]). Past the critical angle (eta1 > eta2) every term is 1.
struct FresnelTerms {
    float parallel = 0.0f;       // R_par: E field in the plane of incidence
    float perpendicular = 0.0f;  // R_perp
    float average = 0.0f;        // (R_par + R_perp) / 2: unpolarised light
    bool totalInternal = false;
};
FresnelTerms fresnelExact(float cosTheta1, float eta1, float eta2);
// R0 = ((eta1 - eta2) / (eta1 + eta2))^2, the reflectance at normal incidence.
float fresnelR0(float eta1, float eta2);
// Schlick: R0 + (1 - R0)(1 - cos theta)^5, as the lecture writes it (with cos theta1; it knows no TIR).
float fresnelSchlick(float cosTheta1, float eta1, float eta2);
// The weight the specular term gets in the scene's Fresnel mode: 1 (none), Schlick or the exact average,
// from air (eta1 = 1) onto `ior`, at cos = V.H.
float fresnelWeight(FresnelMode mode, float cosVH, float ior);

// spec of the formula above for one light direction, as the shaders compute it: the lobe
// max(0, R(I).V)^k_e or max(0, H.N)^k_e of env.model, times energySpecularScale with energy
// normalisation, times fresnelWeight(V.H) with Fresnel; 0 where N.I <= 0. n, i, v are unit vectors
// (normal, toward the light, toward the eye). The lobe plot (core/figures/plot.hpp) draws this function.
float specularTerm(const LightingEnvironment& env, float ke, const glm::vec3& n, const glm::vec3& i,
                   const glm::vec3& v);

// The frame around the model's up axis (+y in object space): T = normalize(up x N), along the
// parallels of a sphere (eastward), B = N x T towards the north pole; at a pole (N along +-y) T = +x.
// w = 1.
glm::vec4 tangentAroundUp(const glm::vec3& n);
// Gram-Schmidt: `t` made orthogonal to the unit normal `n` and unit length; `fallback` where nothing
// of it is left.
glm::vec3 orthogonalTangent(const glm::vec3& t, const glm::vec3& n, const glm::vec3& fallback);
// The tangent frame at a shaded point (world space, unit, both orthogonal to N): T along which k_t
// applies, B = w N x T along which k_b applies.
struct TangentFrame {
    glm::vec3 tangent{1.0f, 0.0f, 0.0f};
    glm::vec3 bitangent{0.0f, 0.0f, 1.0f};
};
// The frame from a tangent `t` (any length; w the handedness) at unit normal `n`: T = t made orthogonal to
// N (Gram-Schmidt; around the up axis where nothing is left), B = w N x T. The shaders do the same.
TangentFrame tangentFrame(const glm::vec3& n, const glm::vec3& t, float w);
// Whether the anisotropic lobe applies: the material asks for it and the lobe is Blinn-Phong's.
bool anisotropicLobe(const Material& m, const LightingEnvironment& env);
// Ashikhmin and Shirley's exponent at halfway vector `h`: (k_t (H.T)^2 + k_b (H.B)^2) / (1 - (H.N)^2),
// with 1 - (H.N)^2 computed as (H.T)^2 + (H.B)^2 (the same for an orthonormal frame, and without
// cancellation as H nears N); k_t where H = N, where spec is 1 whatever the exponent.
float anisotropicExponent(const glm::vec2& k, const glm::vec3& h, const TangentFrame& frame);
// What "energy" multiplies the anisotropic lobe by: sqrt((k_t + 1)(k_b + 1)) / sqrt(33 * 33).
float anisotropicEnergyScale(const glm::vec2& k);
// spec with the anisotropic lobe (as specularTerm, the exponent anisotropicExponent's).
float anisotropicSpecularTerm(const LightingEnvironment& env, const glm::vec2& k, const glm::vec3& n,
                              const glm::vec3& i, const glm::vec3& v, const TangentFrame& frame);

// The lobe a material gets from one light direction: anisotropicSpecularTerm where anisotropicLobe,
// else specularTerm at k_e. `frame` is used only by the anisotropic lobe. The renderer's spec.
float lobeTerm(const Material& m, const LightingEnvironment& env, const glm::vec3& n, const glm::vec3& i,
               const glm::vec3& v, const TangentFrame& frame);
// The BRDF of the formula above, f_r(I -> V) = dL(V) / dE(I), in the renderer's units: a light of
// radiance L (colour * intensity) gives the irradiance E = L (N.I) and the reflected radiance
// L (k_d (N.I) + k_s spec), so f_r = k_d + k_s spec / (N.I), for white C and S (the colours multiply
// it channel by channel). 0 where N.I <= 0. With energy normalisation the renderer's lights carry the
// factor pi, so this is pi times the physical k_d / pi + ...: the same picture. The BRDF plots
// (core/figures/plot.hpp: lobe3d, brdf-slice) draw this function.
struct BrdfValue {
    float diffuse = 0.0f;   // k_d
    float specular = 0.0f;  // k_s spec / (N.I)
    float total() const { return diffuse + specular; }
};
BrdfValue brdf(const Material& m, const LightingEnvironment& env, const glm::vec3& n, const glm::vec3& i,
               const glm::vec3& v, const TangentFrame& frame);

// The occlusion test toward one light sample: from the shaded point along `towardLight` (unit) for
// `distance` (infinite for directional lights). Returns v in [0, 1]: 1 visible, 0 occluded.
struct LightRay {
    std::size_t light = 0;  // index into LightingEnvironment::lights
    int sample = 0;         // area lights: j * nx + i; else 0
    glm::vec3 towardLight{0.0f};
    float distance = std::numeric_limits<float>::infinity();
};
using Visibility = std::function<float(const glm::vec3& posWorld, const LightRay& ray)>;

// nrmWorld must be unit length. Without a visibility every light sample is visible. `frame`: the
// tangent frame for an anisotropic material; null: the frame around world +y (tangentFrame(n, +y x n)),
// which is the procedural meshes' own where their transform does not rotate them.
ShadingTerms shadeTerms(const Material& m, const LightingEnvironment& env, const glm::vec3& posWorld,
                        const glm::vec3& nrmWorld, const Visibility& visibility = {},
                        const TangentFrame* frame = nullptr);
inline glm::vec3 shade(const Material& m, const LightingEnvironment& env, const glm::vec3& posWorld,
                       const glm::vec3& nrmWorld, const Visibility& visibility = {},
                       const TangentFrame* frame = nullptr) {
    return shadeTerms(m, env, posWorld, nrmWorld, visibility, frame).total;
}

// The distance falloff of a point or area light at squared distance r2: 1 (none), 1/r2
// (inverse-square), or 1/r2 * clamp(1 - (r/range)^4, 0, 1)^2 (inverse-square with a range).
float attenuationFactor(const Light& light, float r2);

// A spot light's share toward the unit vector `towardLight` (from the point to the light): with cd the
// cosine between the light's axis and -towardLight, t = clamp((cd - cos outer) / (cos inner - cos outer),
// 0, 1), the falloff is t^2 (glTF KHR_lights_punctual's; the span is at least 1e-3). 1 for other lights.
float spotFalloff(const Light& light, const glm::vec3& towardLight);
// The two numbers the shaders take: cos(outer) and 1 / max(cos(inner) - cos(outer), 1e-3).
glm::vec2 spotCone(const Light& light);

// An area light's rectangle: `u` and `v` are its edges (lengths size.x and size.y), `n` its unit front
// normal. u runs along normalize(cross(ref, n)) with ref = +y, or +z when n is within ~2.6 degrees of
// +-y; v = size.y * cross(n, u/|u|). A light facing down (n = -y) has u along +x and v along +z.
struct AreaFrame {
    glm::vec3 u{1.0f, 0.0f, 0.0f};
    glm::vec3 v{0.0f, 0.0f, 1.0f};
    glm::vec3 n{0.0f, -1.0f, 0.0f};
};
AreaFrame areaFrame(const Light& light);

// Sample (i, j) of an nx x ny grid as an offset (a, b) in [-0.5, 0.5]^2 of the rectangle: stratified
// (one sample per cell) and jittered inside its cell by a fixed integer hash of the sample index and
// SL_AREA_JITTER_SEED, so every render is the same. A side with one sample sits at the centre (so 1 x 1
// is the centre). shaders/lighting.glsl computes the same offsets with the same hash.
glm::vec2 areaSampleOffset(int i, int j, const glm::ivec2& samples);
// The world position of that sample: position + a u + b v.
glm::vec3 areaSamplePosition(const Light& light, int i, int j);
// The hash behind the jitter (lowbias32 by Chris Wellons), exposed for the test that pins it.
std::uint32_t jitterHash(std::uint32_t x);

// The sRGB transfer curve (IEC 61966-2-1) applied to a linear value in [0, 1].
float encodeSrgb(float linear);

}  // namespace shadelab
