// Everything the shading programs evaluate besides the lecture's sum, and shade(), which every
// shading mode calls. The sum itself, L = k_a A C + sum_l L_l (k_d C max(0, N.I_l) + k_s S spec_l),
// is shaders/lecture.glsl; this file is what this program adds around it, each part named:
//
//   L = E + k_a A C + sum_l v_l L_l ( k_d C max(0, N.I_l) + k_s S spec_l ),   clamped to [0, 1]
//
//   - L_l arrives weakened: by the distance (inverse square), across a spot light's cone, and by
//     shadows, v_l (how much of light l reaches the point; arriving());
//   - spec_l may be normalised for constant energy and weighted by Fresnel's reflectance (lobeFactor());
//   - spec_l's exponent may differ along the surface's tangent and bitangent: anisotropic reflection,
//     Ashikhmin and Shirley's (lobeExponent(), SL_ANISOTROPY);
//   - an area light is a sum of point lights, its samples (areaLights());
//   - mirror and glass: k_r F env(R) + k_t (1 - F) env(T) added after the sum (mirrorAndGlass(),
//     SL_ENVIRONMENT);
//   - "show" keeps one term of the sum (termsShown()); E is the light a glTF material gives off
//     (shaders/object_color.glsl); a textured flat or Gouraud surface splits the sum (shadeLectureTermsOfC,
//     shaders/vertex_shading.glsl).
//
// Mirrors shadeTerms() in app/core/shading/lighting.cpp, which the tests compare against. The values
// (the material, A, L_l, the eye and the lights' places) come from shaders/values_from_blocks.glsl,
// or, in Phong's interpolated-inputs variant, from shaders/phong_interpolated.frag.
#include "lecture.glsl"
#include "uniforms.glsl"
#include "encoding.glsl"

Material objectMaterial(vec3 texel);  // the object's material, C times texel (1, or a texture's colour)
vec3 ambientLight();                  // A
vec3 toEye(vec3 P);                   // from P towards the eye (not unit length)
vec3 shownEmission();                 // E at this point, where "show" keeps it (shaders/object_color.glsl)

// ==== What this program adds to the lecture's sum (lecture.glsl, included above) ====

// ---- L_l arriving: distance, spot cone, shadow ----

// The distance falloff at squared distance r2 (core/shading/lighting.cpp, attenuationFactor).
float distanceFalloff(int l, float r2) {
    int attenuation = c_lightAttenuation[l];
    if (attenuation == SL_ATTENUATION_INVERSE_SQUARE) return 1.0 / r2;
    if (attenuation == SL_ATTENUATION_INVERSE_SQUARE_RANGE) {
        float q = r2 * u_lights[l].falloff.x;  // (r / range)^2
        float window = clamp(1.0 - q * q, 0.0, 1.0);
        return window * window / r2;
    }
    return 1.0;
}

// A spot light's cone (core/shading/lighting.cpp, spotFalloff): full inside the inner half-angle, none
// outside the outer one, glTF's smooth t^2 between. I points from the surface to the light.
float spotFalloff(int l, vec3 I) {
    float cd = dot(u_lights[l].spot.xyz, -I);
    float t = clamp((cd - u_lights[l].spot.w) * u_lights[l].falloff.w, 0.0, 1.0);
    return t * t;
}

#include "shadows.glsl"

// How much of light l's L_l arrives at P from direction I: 1 for the lecture's lights; less with the
// distance (inverse square), outside a spot light's cone, in shadow (v_l); 0 for a light "show" hides
// and for an area light, whose samples areaLights() sums.
float arriving(int l, vec3 P, vec3 N, vec3 I) {
    bool shown = SL_SHOW != SL_SHOW_LIGHT || l == SL_SHOW_LIGHT_INDEX;  // "show" may keep one light
    if (!shown || c_lightKind[l] == SL_LIGHT_AREA) return 0.0;
    float a = 1.0;
    if (c_lightKind[l] != SL_LIGHT_DIRECTIONAL) {
        vec3 d = toLight(l, P);
        a = distanceFalloff(l, dot(d, d));
    }
    if (c_lightKind[l] == SL_LIGHT_SPOT) a *= spotFalloff(l, I);
    if (SL_SHADOWS == 1) a *= visibility(l, P, N);  // v_l
    return a;
}

// ---- spec_l: energy normalisation and Fresnel ----

// Fresnel reflectance from air onto ior (core/shading/lighting.cpp, fresnelSchlick and fresnelExact).
float fresnelSchlick(float cosVH) {  // R0 + (1 - R0)(1 - cos)^5
    float r0 = u_modelSettings.y;
    float m = 1.0 - clamp(cosVH, 0.0, 1.0);
    float m2 = m * m;
    return r0 + (1.0 - r0) * m2 * m2 * m;
}
float fresnelExact(float cosVH) {  // unpolarised (R_par + R_perp) / 2; no total internal reflection from air
    float eta = u_modelSettings.x;
    float c1 = clamp(cosVH, 0.0, 1.0);
    float sin3Sq = (1.0 - c1 * c1) / (eta * eta);
    float c3 = sqrt(max(1.0 - sin3Sq, 0.0));
    float perp = (c1 - eta * c3) / (c1 + eta * c3);
    float par = (c3 - eta * c1) / (c3 + eta * c1);
    return 0.5 * (par * par + perp * perp);
}

// ---- spec_l's exponent: anisotropic reflection (SL_ANISOTROPY) ----

#if SL_ANISOTROPY
// Brushed metal: Ashikhmin and Shirley's exponent, k_t along the surface's tangent T and k_b along its
// bitangent B (core/shading/lighting.cpp, anisotropicExponent):
//
//   spec_l = max(0, H.N)^k(H),   k(H) = (k_t (H.T)^2 + k_b (H.B)^2) / (1 - (H.N)^2)
//
// 1 - (H.N)^2 is (H.T)^2 + (H.B)^2 for the orthonormal frame below, and computed so (no cancellation as
// H nears N, where spec_l is 1 whatever k is). k_t = k_b = k_e gives Blinn-Phong's lobe exactly.
//
// The tangent where the point is shaded: the vertex's (gouraud.vert), the triangle's (flat.vert, the
// same attribute: FlatMesh::tangents), interpolated (phong.vert passes v_tanWorld to phong.frag,
// tangent.glsl).
#ifdef SL_VERTEX_STAGE
layout(location = SL_ATTRIB_TANGENT) in vec4 a_tanObject;  // xyz the tangent, w the handedness
vec3 tangentToWorld(vec3 tanObject);                       // shaders/instancing.glsl
vec4 tangentHere() { return vec4(tangentToWorld(a_tanObject.xyz), a_tanObject.w); }
#else
in vec4 v_tanWorld;
vec4 tangentHere() { return v_tanWorld; }
#endif
// The frame of the point being shaded, T and B (unit, orthogonal to N): shadeMaterial() sets it first.
vec3 s_tangentWorld, s_bitangentWorld;
void useTangentFrame(vec3 N) {
    vec4 tanWorld = tangentHere();
    vec3 T = tanWorld.xyz - N * dot(N, tanWorld.xyz);  // Gram-Schmidt against N
    if (dot(T, T) < 1e-12) T = cross(vec3(0.0, 1.0, 0.0), N);  // nothing left: around the up axis
    if (dot(T, T) < 1e-12) T = vec3(1.0, 0.0, 0.0) - N * N.x;
    s_tangentWorld = normalize(T);
    s_bitangentWorld = (tanWorld.w < 0.0 ? -1.0 : 1.0) * cross(N, s_tangentWorld);
}
float lobeExponent(vec3 H, float k_e) {
    float ht = dot(H, s_tangentWorld), hb = dot(H, s_bitangentWorld);
    float sinSq = ht * ht + hb * hb;  // 1 - (H.N)^2
    return sinSq > 0.0 ? (u_anisotropy.x * ht * ht + u_anisotropy.y * hb * hb) / sinSq : u_anisotropy.x;
}
// "energy": Ashikhmin and Shirley's sqrt((k_t + 1)(k_b + 1)) / 8pi, relative to k_t = k_b = 32.
float lobeNormalization(float k_e) {
    return sqrt((u_anisotropy.x + 1.0) * (u_anisotropy.y + 1.0)) / (SL_ENERGY_REFERENCE_EXPONENT + 1.0);
}
#else
void useTangentFrame(vec3 N) {}                        // no frame to set
float lobeExponent(vec3 H, float k_e) { return k_e; }  // the lecture's: one exponent all round
// "energy": n(k_e) / n(32), n = (k_e + 2) / 2pi (Phong) or (k_e + 8) / 8pi (Blinn-Phong).
float lobeNormalization(float k_e) {
    float n = SL_REFLECTION == SL_REFLECTION_PHONG ? 2.0 : 8.0;
    return (k_e + n) / (SL_ENERGY_REFERENCE_EXPONENT + n);
}
#endif

// spec_l's factor besides the lobe: 1 for the lecture's model; with "energy", n(k_e) / n(32): constant
// reflected energy, the same look as "none" at k_e = 32; with Fresnel, the reflectance at V.H.
float lobeFactor(vec3 I, vec3 V, float k_e) {
    float factor = 1.0;
    if (SL_SPECULAR_NORMALIZATION == SL_NORMALIZATION_ENERGY) factor *= lobeNormalization(k_e);
    if (SL_FRESNEL == SL_FRESNEL_SCHLICK) factor *= fresnelSchlick(dot(V, normalize(I + V)));
    if (SL_FRESNEL == SL_FRESNEL_EXACT) factor *= fresnelExact(dot(V, normalize(I + V)));
    return factor;
}

// ---- Area lights: sums of point lights ----

// Area-light sample (i, j) of an nx x ny grid as an offset in [-0.5, 0.5]^2 of the rectangle: the
// same stratified, fixed-seed jitter as areaSampleOffset() in core/shading/lighting.cpp.
uint jitterHash(uint x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}
vec2 areaSampleOffset(int i, int j, int nx, int ny) {
    uint k = uint(j * nx + i);
    float jx = nx == 1 ? 0.5 : float(jitterHash(2u * k + SL_AREA_JITTER_SEED) >> 8) * (1.0 / 16777216.0);
    float jy = ny == 1 ? 0.5 : float(jitterHash(2u * k + 1u + SL_AREA_JITTER_SEED) >> 8) * (1.0 / 16777216.0);
    return vec2((float(i) + jx) / float(nx) - 0.5, (float(j) + jy) / float(ny) - 0.5);
}

// Area light l: nx * ny point lights, its samples, each weighted by its share of the area (1 / (nx ny))
// and the cosine at the light (|cos| when two-sided; nothing from behind the emitting side), then
// reflected as lecture.glsl's oneLight() reflects a light. With shadows, one occlusion test per
// sample, in that sample's own layer of the light's map.
vec3 areaLight(Material m, int l, vec3 P, vec3 N, vec3 V) {
    int nx = c_areaSamplesX[l], ny = c_areaSamplesY[l];
    vec3 L_l = lightColor(l);
    vec3 centre = u_lights[l].positionOrDirection.xyz;
    vec3 edgeU = u_lights[l].areaU.xyz, edgeV = u_lights[l].areaV.xyz, front = u_lights[l].areaNormal.xyz;
    float twoSided = u_lights[l].falloff.y;
    vec4 clipP = u_lights[l].shadowClipFromWorld * vec4(P, 1.0);  // shadows: seen from the centre
    vec4 clipN = u_lights[l].shadowClipFromWorld * vec4(N, 0.0);
    vec3 sum = vec3(0.0);
#if SL_ACCUMULATE
    // This pass's share of the grid: every stride-th sample from an offset, weighted by the number of
    // passes (stride.x * stride.y). Each sample lies in exactly one pass, so the mean of all passes
    // is the full sum below, whatever nx and ny are.
    for (int j = u_areaPass.y; j < ny; j += u_areaPass.w)
        for (int i = u_areaPass.x; i < nx; i += u_areaPass.z) {
#else
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
#endif
            vec2 ab = areaSampleOffset(i, j, nx, ny);
            vec3 toSample = centre + ab.x * edgeU + ab.y * edgeV - P;
            float r2 = dot(toSample, toSample);
            vec3 I = toSample * inversesqrt(r2);
            float cosLight = -dot(front, I);
            cosLight = mix(cosLight, abs(cosLight), twoSided);
            if (cosLight <= 0.0 || dot(N, I) <= 0.0) continue;
            float weight = cosLight * distanceFalloff(l, r2);
            if (SL_SHADOWS == 1) weight *= areaSampleVisibility(l, ab, j * nx + i, clipP, clipN);
            sum += oneLight(m, weight * L_l, N, I, V);
        }
#if SL_ACCUMULATE
    sum *= float(u_areaPass.z * u_areaPass.w);
#endif
    return sum / float(nx * ny);
}

// Every area light's share. Only scenes with an area light get the loop (SL_AREA_LIGHTS): the loops
// over its samples would keep the compiler from unrolling lecture()'s loop over the lights.
vec3 areaLights(Material m, vec3 P, vec3 N, vec3 V) {
    vec3 sum = vec3(0.0);
#if SL_AREA_LIGHTS
    for (int l = 0; l < SL_LIGHT_COUNT; ++l)
        if (c_lightKind[l] == SL_LIGHT_AREA && (SL_SHOW != SL_SHOW_LIGHT || l == SL_SHOW_LIGHT_INDEX))
            sum += areaLight(m, l, P, N, V);
#endif
    return sum;
}

// ---- Mirror and glass: the environment reflected and refracted (SL_ENVIRONMENT) ----

#if SL_ENVIRONMENT
#include "environment.glsl"
// The lecture's "Reflection and Refraction" at this one surface (core/shading/environment.hpp,
// environmentTerm): what a mirror (k_r) and glass (k_t) add after the sum, the environment seen along
//
//   R = reflect(-V, N) = 2 (N.V) N - V
//   T = refract(-V, N, eta) = -eta V + (eta cos_i - cos_t) N,   eta = eta_i / eta_t = 1 / ior
//
//   k_r F env(R) + k_t (1 - F) env(T)
//
// Snell's law eta_i sin_i = eta_t sin_t gives cos_t; past the critical angle (ior < 1: from inside the
// glass) there is no T, and F = 1. F is the Fresnel reflectance at cos_i = N.V in the scene's mode;
// without Fresnel (SL_FRESNEL_NONE) both weights are 1: the lecture's "without Fresnel" picture.
// T leaves this surface for the environment at once: one interface, as on the slide.
vec3 mirrorAndGlass(vec3 P, vec3 N) {
    if (SL_SHOW != SL_SHOW_ALL) return vec3(0.0);  // "show" draws one term of the sum, not this
    vec3 V = normalize(toEye(P));
    float cosI = max(dot(N, V), 0.0);
    vec3 R = 2.0 * dot(N, V) * N - V;
    float eta = 1.0 / u_modelSettings.x;
    float sinTSq = eta * eta * (1.0 - cosI * cosI);
    bool totalInternal = sinTSq > 1.0;
    float F = 1.0;
    if (SL_FRESNEL == SL_FRESNEL_SCHLICK && !totalInternal) F = fresnelSchlick(cosI);
    if (SL_FRESNEL == SL_FRESNEL_EXACT && !totalInternal) F = fresnelExact(cosI);
    float towardsR = SL_FRESNEL == SL_FRESNEL_NONE ? 1.0 : F;
    float towardsT = totalInternal ? 0.0 : SL_FRESNEL == SL_FRESNEL_NONE ? 1.0 : 1.0 - F;
    vec3 L = u_mirrorGlass.x * towardsR * environment(R);
    if (towardsT > 0.0) {
        vec3 T = -eta * V + (eta * cosI - sqrt(1.0 - sinTSq)) * N;
        L += u_mirrorGlass.y * towardsT * environment(T);
    }
    return L;
}
#else
vec3 mirrorAndGlass(vec3 P, vec3 N) { return vec3(0.0); }  // no environment, or neither k_r nor k_t
#endif

// ---- "show": one term of the sum alone ----

// The material with the coefficients of the terms "show" hides set to 0 (the compiler folds them away).
Material termsShown(Material m) {
    if (SL_SHOW != SL_SHOW_ALL && SL_SHOW != SL_SHOW_AMBIENT) m.k_a = 0.0;
    if (SL_SHOW == SL_SHOW_AMBIENT || SL_SHOW == SL_SHOW_SPECULAR) m.k_d = 0.0;
    if (SL_SHOW == SL_SHOW_AMBIENT || SL_SHOW == SL_SHOW_DIFFUSE) m.k_s = 0.0;
    return m;
}

// ---- L at a point ----

// P: the point being shaded (world space); N: its unit normal. Linear RGB before the clamp: E plus
// the lecture's sum over the lights, area lights included, with "show" keeping one of its terms.
vec3 shadeMaterial(Material m, vec3 P, vec3 N) {
    if (SL_SHOW == SL_SHOW_UNLIT) return m.C;  // C, no lighting
    vec3 E = shownEmission();
    if (SL_SHOW == SL_SHOW_EMISSIVE) return E;
    Material shown = termsShown(m);
    useTangentFrame(N);  // anisotropic reflection's T and B at P (nothing without SL_ANISOTROPY)
    vec3 V = normalize(toEye(P));
    return E + lecture(shown, ambientLight(), P, N, V) + areaLights(shown, P, N, V);
}

// L before the clamp: the sum (shadeMaterial) and mirror and glass after it, with C times `texel` where
// C varies over the surface (shaders/object_color.glsl; 1 elsewhere). Phong's fragments clamp it
// (progressive Phong sums these over passes and clamps the mean).
vec3 shade(vec3 P, vec3 N, vec3 texel) { return shadeMaterial(objectMaterial(texel), P, N) + mirrorAndGlass(P, N); }

// The lecture's L, clamped to [0, 1]: linear RGB (flat and Gouraud, per triangle or vertex, through
// shaders/vertex_shading.glsl's shadeAndPass).
vec3 shadeLecture(vec3 P, vec3 N) { return clamp(shade(P, N, vec3(1.0)), 0.0, 1.0); }

// The formula in two parts, for flat and Gouraud shading of a textured surface: they evaluate it per
// face or vertex, before the fragment knows its texel, and the fragment stage combines them
// (shaders/object_color.glsl, combineTerms):  L = clamp(texel * termsOfC + specular + E, 0, 1).
vec3 shadeLectureTermsOfC(vec3 P, vec3 N) {  // k_a A C + sum v L_l k_d C (N.I)
    Material m = objectMaterial(vec3(1.0));
    m.k_s = 0.0;
    return shadeMaterial(m, P, N);
}
// sum v L_l k_s S spec_l, and mirror and glass (which C does not colour)
vec3 shadeLectureSpecular(vec3 P, vec3 N) { return shadeMaterial(objectMaterial(vec3(0.0)), P, N) + mirrorAndGlass(P, N); }
