// The lecture's reflection model, evaluated wherever a shading mode chooses to evaluate it:
// once per triangle (flat), per vertex (gouraud) or per fragment (phong). Mirrors shadeTerms() in
// app/core/shading/lighting.cpp, which the tests compare against.
//
//   L = E + k_a A C + sum_l v_l L_l ( k_d C max(0, N.I_l) + k_s S spec_l ),   clamped to [0, 1]
//   spec_l = max(0, R(I_l).V)^k_e (Phong) or max(0, H_l.N)^k_e (Blinn-Phong), 0 where N.I_l <= 0
//   v_l: how much of light l reaches the point (1, or its shadow-map test with shadows on)
//   E: the light a glTF material gives off (0 for the lecture's own materials; shaders/object_color.glsl)
//
// sumOfTerms() at the end of this file is that line. The programs are specialised
// (app/render/program_cache.cpp, programDefines): the number of lights and each light's kind, attenuation
// and area samples are constant arrays, and the reflection model, the output encoding, the options
// and "show" are constants, so the compiler unrolls the loop over the lights and drops every branch
// that does not apply: on llvmpipe a loop over a uniform light count with per-light branches made
// Phong ~50% slower (bench/README.md). Positions, colours and material values stay uniforms, so
// dragging a slider never recompiles.
#include "uniforms.glsl"
#include "encoding.glsl"

#ifndef SL_LIGHT_COUNT
#define SL_LIGHT_COUNT 0
#endif
#ifndef SL_AREA_LIGHTS
#define SL_AREA_LIGHTS 0  // 1 when a light is an area light (the loop over lights then has its branch)
#endif
#ifndef SL_REFLECTION
#define SL_REFLECTION SL_REFLECTION_BLINN_PHONG
#endif
#ifndef SL_SHADOWS
#define SL_SHADOWS 0
#endif
#ifndef SL_SHADOW_PCF
#define SL_SHADOW_PCF 0
#endif
#ifndef SL_SPECULAR_NORMALIZATION
#define SL_SPECULAR_NORMALIZATION SL_NORMALIZATION_NONE
#endif
#ifndef SL_FRESNEL
#define SL_FRESNEL SL_FRESNEL_NONE
#endif
#ifndef SL_SHOW
#define SL_SHOW SL_SHOW_ALL
#endif
#ifndef SL_SHOW_LIGHT_INDEX
#define SL_SHOW_LIGHT_INDEX -1
#endif
// SL_ACCUMULATE = 1: a pass of progressive area-light sampling (Renderer::renderProgressive). Each
// area light evaluates only the samples u_areaPass selects, and the programs write linear values that
// the renderer sums over the passes in a float buffer, then clamps and encodes in shaders/resolve.frag.
#ifndef SL_ACCUMULATE
#define SL_ACCUMULATE 0
#endif
#ifndef SL_EMISSIVE
#define SL_EMISSIVE 0  // 1: the draw gives off light, E > 0 (only such draws get the define)
#endif
vec3 objectEmission();  // E at this point (shaders/object_color.glsl)
// SL_DOUBLE_SIDED = 1: a draw of a glTF material with "doubleSided": true, drawn without back-face
// culling. glTF's rule: the back of a surface is lit as a surface facing the other way, with its
// normal flipped. Each mode flips where it knows which side the eye sees: phong.frag per fragment,
// flat.vert per triangle, gouraud.vert evaluates both sides and gouraud.frag picks one.
#ifndef SL_DOUBLE_SIDED
#define SL_DOUBLE_SIDED 0
#endif

// Per light, from the renderer's lists (comma-separated, one entry per light; a scene without lights
// gets one placeholder entry that the loop over the lights never reads).
#ifndef SL_LIGHT_KINDS
#define SL_LIGHT_KINDS SL_LIGHT_POINT
#define SL_LIGHT_ATTENUATIONS SL_ATTENUATION_NONE
#define SL_AREA_SAMPLES_X 1
#define SL_AREA_SAMPLES_Y 1
#endif
const int c_lightKind[] = int[](SL_LIGHT_KINDS);                // SL_LIGHT_*
const int c_lightAttenuation[] = int[](SL_LIGHT_ATTENUATIONS);  // SL_ATTENUATION_*
const int c_areaSamplesX[] = int[](SL_AREA_SAMPLES_X);          // area lights: nx x ny samples (1 for others)
const int c_areaSamplesY[] = int[](SL_AREA_SAMPLES_Y);

// Where the per-object products and the vectors to the eye and the lights come from: the fragment
// inputs of shaders/phong_interface.glsl when the including stage has them, else the uniform blocks.
#ifdef SL_INTERPOLATED_INPUTS
vec3 ambientTerm() { return v_ambientTermExponent.rgb; }      // k_a A C
float specularExponent() { return v_ambientTermExponent.w; }  // k_e
vec3 toEye(vec3 posWorld) { return v_toEyeWorld; }            // eye - p
#else
vec3 ambientTerm() { return u_ambientTerm.rgb; }
float specularExponent() { return u_coefficients.w; }
vec3 toEye(vec3 posWorld) { return u_eyeWorld.xyz - posWorld; }
#endif
#if defined(SL_INTERPOLATED_INPUTS) && SL_LIGHT_COUNT > 0
vec3 lightDiffuse(int l) { return v_lightDiffuse[l]; }            // L_l k_d C
vec3 lightSpecular(int l) { return v_lightSpecular[l]; }          // L_l k_s S
vec3 toLight(int l, vec3 posWorld) { return v_toLightWorld[l]; }  // light - p; -direction for a directional light
#else
vec3 lightDiffuse(int l) { return u_lightDiffuse[l].rgb; }
vec3 lightSpecular(int l) { return u_lightSpecular[l].rgb; }
vec3 toLight(int l, vec3 posWorld) {
    vec3 p = u_lights[l].positionOrDirection.xyz;
    return c_lightKind[l] == SL_LIGHT_DIRECTIONAL ? -p : p - posWorld;
}
#endif

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

// spec_l for a light from direction I (N.I > 0), with the options the scene turned on.
float specularLobe(vec3 I, float NdotI, vec3 N, vec3 V) {
    float cosLobe = SL_REFLECTION == SL_REFLECTION_PHONG ? dot(2.0 * NdotI * N - I, V)  // R(I).V
                                                         : dot(normalize(I + V), N);    // H.N
    float spec = pow(max(cosLobe, 0.0), specularExponent());
    // "energy": n(k_e) / n(32), constant reflected energy, the same look as "none" at k_e = 32.
    float n = SL_REFLECTION == SL_REFLECTION_PHONG ? 2.0 : 8.0;
    if (SL_SPECULAR_NORMALIZATION == SL_NORMALIZATION_ENERGY)
        spec *= (specularExponent() + n) / (SL_ENERGY_REFERENCE_EXPONENT + n);
    if (SL_FRESNEL == SL_FRESNEL_SCHLICK) spec *= fresnelSchlick(dot(V, normalize(I + V)));
    if (SL_FRESNEL == SL_FRESNEL_EXACT) spec *= fresnelExact(dot(V, normalize(I + V)));
    return spec;
}

// L_l (k_d C (N.I) + k_s S spec_l) for light l from direction I with N.I > 0. The products L_l k_d C
// and L_l k_s S come folded from the ObjectBlock; `texel` and `specularShare`: see sumOfTerms.
vec3 reflected(int l, vec3 I, float NdotI, vec3 N, vec3 V, vec3 texel, float specularShare) {
    vec3 diffuse = lightDiffuse(l) * texel * NdotI;                                   // L_l k_d C (N.I)
    vec3 specular = lightSpecular(l) * (specularLobe(I, NdotI, N, V) * specularShare);  // L_l k_s S spec_l
    if (SL_SHOW == SL_SHOW_DIFFUSE) return diffuse;
    if (SL_SHOW == SL_SHOW_SPECULAR) return specular;
    return diffuse + specular;
}

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

#include "shadows.glsl"

// Light l's share, v_l L_l (k_d C (N.I) + k_s S spec_l), for a point, spot or directional light.
vec3 lightTerm(int l, vec3 posWorld, vec3 N, vec3 V, vec3 texel, float specularShare) {
    vec3 d = toLight(l, posWorld);
    float r2 = dot(d, d);
    vec3 I = d * inversesqrt(r2);
    float NdotI = dot(N, I);
    if (NdotI <= 0.0) return vec3(0.0);  // light behind the surface: no diffuse and no highlight
    float falloff = 1.0;  // part of L_l: with the distance, and across a spot light's cone
    if (c_lightKind[l] != SL_LIGHT_DIRECTIONAL) falloff = distanceFalloff(l, r2);
    if (c_lightKind[l] == SL_LIGHT_SPOT) falloff *= spotFalloff(l, I);
    float v = SL_SHADOWS == 1 ? visibility(l, posWorld, N) : 1.0;
    return v * falloff * reflected(l, I, NdotI, N, V, texel, specularShare);
}

// Area light l: nx * ny point-light samples, each weighted by its share of the area (1 / (nx ny))
// and the cosine at the light (|cos| when two-sided; nothing from behind the emitting side). With
// shadows, one occlusion test per sample, in that sample's own layer of the light's map.
vec3 areaLightTerm(int l, vec3 posWorld, vec3 N, vec3 V, vec3 texel, float specularShare) {
    int nx = c_areaSamplesX[l], ny = c_areaSamplesY[l];
    vec3 centre = u_lights[l].positionOrDirection.xyz;
    vec3 edgeU = u_lights[l].areaU.xyz, edgeV = u_lights[l].areaV.xyz, front = u_lights[l].areaNormal.xyz;
    float twoSided = u_lights[l].falloff.y;
    vec4 clipP = u_lights[l].shadowClipFromWorld * vec4(posWorld, 1.0);  // shadows: seen from the centre
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
            vec3 toSample = centre + ab.x * edgeU + ab.y * edgeV - posWorld;
            float r2 = dot(toSample, toSample);
            vec3 I = toSample * inversesqrt(r2);
            float cosLight = -dot(front, I);
            cosLight = mix(cosLight, abs(cosLight), twoSided);
            float NdotI = dot(N, I);
            if (cosLight <= 0.0 || NdotI <= 0.0) continue;
            float weight = cosLight * distanceFalloff(l, r2);
            if (SL_SHADOWS == 1) weight *= areaSampleVisibility(l, ab, j * nx + i, clipP, clipN);
            sum += weight * reflected(l, I, NdotI, N, V, texel, specularShare);
        }
#if SL_ACCUMULATE
    sum *= float(u_areaPass.z * u_areaPass.w);
#endif
    return sum / float(nx * ny);
}

// posWorld: the point being shaded; nrmWorld: its unit normal. Returns linear RGB before the clamp:
// the lecture's formula, with "show" keeping one of its terms.
// `texel` multiplies the material's C where it varies over the surface (a texture and vertex colours,
// shaders/object_color.glsl; 1 elsewhere), so it scales the terms C is in, ambient and diffuse, and
// not the specular; `specularShare` (1, or 0) keeps or drops the specular. The functions below call
// this with constants, which the compiler folds away.
vec3 sumOfTerms(vec3 posWorld, vec3 nrmWorld, vec3 texel, float specularShare) {
    if (SL_SHOW == SL_SHOW_UNLIT) return u_color.rgb * texel;  // C, no lighting
    vec3 N = nrmWorld;
    vec3 V = normalize(toEye(posWorld));
    vec3 L = vec3(0.0);
    if (SL_EMISSIVE == 1 && (SL_SHOW == SL_SHOW_ALL || SL_SHOW == SL_SHOW_EMISSIVE)) L += objectEmission();  // E
    if (SL_SHOW == SL_SHOW_EMISSIVE) return L;
    if (SL_SHOW == SL_SHOW_ALL || SL_SHOW == SL_SHOW_AMBIENT) L += ambientTerm() * texel;  // k_a A C
    if (SL_SHOW == SL_SHOW_AMBIENT) return L;
    for (int l = 0; l < SL_LIGHT_COUNT; ++l) {
        bool shown = SL_SHOW != SL_SHOW_LIGHT || l == SL_SHOW_LIGHT_INDEX;  // "show" may keep one light
        if (shown && c_lightKind[l] != SL_LIGHT_AREA) L += lightTerm(l, posWorld, N, V, texel, specularShare);
#if SL_AREA_LIGHTS
        // Only scenes with an area light get this branch: the loops over its samples would keep the
        // compiler from unrolling the loop over the lights.
        if (shown && c_lightKind[l] == SL_LIGHT_AREA) L += areaLightTerm(l, posWorld, N, V, texel, specularShare);
#endif
    }
    return L;
}

// The lecture's L before the clamp (progressive Phong sums these over passes and clamps the mean).
vec3 shadeLectureUnclamped(vec3 posWorld, vec3 nrmWorld, vec3 texel) { return sumOfTerms(posWorld, nrmWorld, texel, 1.0); }

// The lecture's L, clamped to [0, 1]: linear RGB.
vec3 shadeLecture(vec3 posWorld, vec3 nrmWorld, vec3 texel) { return clamp(shadeLectureUnclamped(posWorld, nrmWorld, texel), 0.0, 1.0); }

// The formula in two parts, for flat and Gouraud shading of a textured surface: they evaluate it per
// face or vertex, before the fragment knows its texel, and the fragment stage combines them
// (shaders/object_color.glsl, combineTerms):  L = clamp(texel * termsOfC + specular + E, 0, 1).
vec3 shadeLectureTermsOfC(vec3 posWorld, vec3 nrmWorld) { return sumOfTerms(posWorld, nrmWorld, vec3(1.0), 0.0); }  // k_a A C + sum v L_l k_d C (N.I)
vec3 shadeLectureSpecular(vec3 posWorld, vec3 nrmWorld) { return sumOfTerms(posWorld, nrmWorld, vec3(0.0), 1.0); }  // sum v L_l k_s S spec_l
