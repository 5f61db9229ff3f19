#pragma once
// Mirror and glass: what this program adds after the lecture's sum for a material with k_r ("mirror")
// or k_t ("transmission") and a scene with an "environment" (the lecture's "At the Intersection" and
// "Reflection and Refraction" slides). At the shaded point, with V the unit vector to the eye and N
// the unit normal,
//
//   L += k_r F env(R) + k_t (1 - F) env(T)
//
//   R = reflect(-V, N) = 2 (N.V) N - V                       the mirror direction
//   T = refract(-V, N, eta) = -eta V + (eta cos_i - cos_t) N  Snell's law, eta_i sin_i = eta_t sin_t,
//       eta = eta_i / eta_t,  cos_i = max(N.V, 0),  cos_t = sqrt(1 - eta^2 (1 - cos_i^2))
//   F   the Fresnel reflectance at cos_i in the scene's mode: "exact" (R_par + R_perp) / 2, "schlick"
//       R0 + (1 - R0)(1 - cos_i)^5; "none": no F, the weights k_r and k_t as they are.
//   Past the critical angle (eta > 1: light from inside the glass, --ior < 1) there is no T: total
//   internal reflection, F = 1.
//
// One interface only, the slide's picture: T leaves this surface and reads the environment at once; it
// is not traced through the object and out of its far side, and nothing in the scene is reflected but
// the environment (a rasterizer's environment mapping). env(d) is a function of direction alone, the
// environment infinitely far away. shaders/environment.glsl evaluates the same functions.
#include "core/scene/scene.hpp"

#include <glm/vec3.hpp>

namespace shadelab {

struct LightingEnvironment;

// The procedural environments as functions of a unit direction (world space), linear RGB (the sun
// brighter than 1). shaders/environment.glsl has the same functions with the same constants.
glm::vec3 roomRadiance(const glm::vec3& d);  // a room: coloured walls, a light ceiling, a checker floor
glm::vec3 skyRadiance(const glm::vec3& d);   // a sky gradient over a dark ground, with a sun
// The sun of the sky environment: the unit direction towards it.
glm::vec3 skySunDirection();
// An equirectangular image at direction d: longitude u = 1/2 + atan2(d.x, -d.z) / 2pi (the image's
// centre straight ahead along -z, the default camera's view), v = acos(d.y) / pi (the top row the
// zenith), read bilinearly between texel centres (wrapping in u, clamped in v), as the shader reads
// the same texels with texelFetch.
glm::vec3 imageRadiance(const EnvironmentImage& image, const glm::vec3& d);
// env(d) of the scene's environment (black for none).
glm::vec3 environmentRadiance(const EnvironmentSpec& env, const glm::vec3& d);

// Whether a material gets the term: it has k_r or k_t, and the scene an environment.
bool mirrorOrGlass(const Material& m, const EnvironmentSpec& env);

// The indices of refraction on either side of the surface for the scene's ior = eta_t / eta_i: from
// air into the glass (eta_i = 1, eta_t = ior) for ior >= 1; from inside the glass into air for ior < 1
// (eta_i = 1 / ior, eta_t = 1). Only their ratio enters the formula.
struct Interface {
    float etaI = 1.0f;
    float etaT = 1.5f;
};
Interface interfaceOf(float ior);

// The term at one point, every quantity the probe and the intersection diagram show.
struct EnvironmentTerm {
    glm::vec3 reflectedDirection{0.0f};    // R, unit
    glm::vec3 transmittedDirection{0.0f};  // T, unit (zero when totalInternal)
    bool totalInternal = false;
    float cosThetaI = 1.0f;  // cos_i = max(N.V, 0)
    float cosThetaT = 1.0f;  // cos_t (0 when totalInternal)
    Interface eta;
    float fresnel = 1.0f;         // F of the scene's mode (1 past the critical angle); 1 under "none"
    bool weighted = false;        // F weighs the two terms (fresnel != none)
    glm::vec3 reflected{0.0f};    // k_r F env(R)
    glm::vec3 transmitted{0.0f};  // k_t (1 - F) env(T)
    glm::vec3 total() const { return reflected + transmitted; }
};
// n and v unit (the normal and the direction to the eye). Zero weights give zero terms (the
// directions and F are filled in all the same).
EnvironmentTerm environmentTerm(const Material& m, const LightingEnvironment& env, const glm::vec3& n,
                                const glm::vec3& v);

}  // namespace shadelab
