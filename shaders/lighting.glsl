// The lecture's reflection model, evaluated wherever a shading mode chooses to evaluate it:
// once per triangle (flat), per vertex (gouraud) or per fragment (phong). Mirrors shadeTerms() in
// app/core/lighting.cpp, which the tests compare against.
//
//   L = k_a A C + sum_l L_l ( k_d C max(0, N.I_l) + k_s S spec_l ),   clamped to [0, 1]
//   spec_l = max(0, R(I_l).V)^k_e (Phong) or max(0, H_l.N)^k_e (Blinn-Phong), 0 where N.I_l <= 0
//
// Programs are specialised (app/render/renderer.cpp, programDefines): the number of lights, each
// light's kind and attenuation (and an area light's sample counts), the reflection model, the output
// encoding, and whether shadows are on (with the PCF radius) are compile-time constants. On llvmpipe a loop over a uniform light count with per-light branches made Phong
// shading ~50% slower than the same formula with constants (bench/README.md); light positions,
// colours and all material values stay uniforms, so dragging a slider never recompiles.
#include "uniforms.glsl"
#include "encoding.glsl"

#ifndef SL_LIGHT_COUNT
#define SL_LIGHT_COUNT 0
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
// With SL_LIGHT_COUNT = n the renderer also defines SL_LIGHT_KIND_l and SL_LIGHT_ATTENUATION_l for
// l < n, and SL_LIGHT_SAMPLES_X_l, SL_LIGHT_SAMPLES_Y_l for area lights; blocks for lights past the
// count are skipped by the preprocessor and never expanded.

// Where the per-object products and the vectors to the eye and the lights come from: the fragment
// inputs of shaders/phong_interface.glsl when the including stage has them, else the uniform blocks.
#ifdef SL_INTERPOLATED_INPUTS
#define SL_AMBIENT_TERM v_ambientTermExponent.rgb
#define SL_EXPONENT v_ambientTermExponent.w
#define SL_TO_EYE(posWorld) v_toEyeWorld
#else
#define SL_AMBIENT_TERM u_ambientTerm.rgb
#define SL_EXPONENT u_coefficients.w
#define SL_TO_EYE(posWorld) (u_eyeWorld.xyz - (posWorld))
#endif
#if defined(SL_INTERPOLATED_INPUTS) && SL_LIGHT_COUNT > 0
#define SL_LIGHT_DIFFUSE(l) v_lightDiffuse[l]
#define SL_LIGHT_SPECULAR(l) v_lightSpecular[l]
#define SL_TO_LIGHT(l, posWorld) v_toLightWorld[l]
#define SL_DIRECTION_TO_LIGHT(l) v_toLightWorld[l]
#else
#define SL_LIGHT_DIFFUSE(l) u_lightDiffuse[l].rgb
#define SL_LIGHT_SPECULAR(l) u_lightSpecular[l].rgb
#define SL_TO_LIGHT(l, posWorld) (u_lights[l].positionOrDirection.xyz - (posWorld))
#define SL_DIRECTION_TO_LIGHT(l) (-u_lights[l].positionOrDirection.xyz)
#endif

// Shadows (SL_SHADOWS = 1) are the lecture's occlusion term v(p, I): each light has a depth texture
// array (core/shadow_projection.hpp says what its layers see), and v multiplies that light's (or
// sample's) share. Without shadows the macros below are empty and the code is what it was before.
#if SL_SHADOWS && SL_LIGHT_COUNT > 0
uniform sampler2DArrayShadow u_shadowMaps[SL_LIGHT_COUNT];  // unit SL_TEXTURE_SHADOW_BASE + l
#define SL_SHADOW_PARAM sampler2DArrayShadow shadowMap,
#define SL_SHADOW_ARG(l) u_shadowMaps[l],
#else
#define SL_SHADOW_PARAM
#define SL_SHADOW_ARG(l)
#endif

#if SL_FRESNEL == SL_FRESNEL_SCHLICK
// Schlick: R0 + (1 - R0)(1 - cos)^5 (core/lighting.cpp, fresnelSchlick), from air onto ior.
float fresnelWeight(float cosVH) {
    float r0 = u_modelSettings.y;
    float m = 1.0 - clamp(cosVH, 0.0, 1.0);
    float m2 = m * m;
    return r0 + (1.0 - r0) * m2 * m2 * m;
}
#elif SL_FRESNEL == SL_FRESNEL_EXACT
// The unpolarised Fresnel reflectance (R_par + R_perp) / 2 from air (eta1 = 1) onto eta2 = ior
// (core/lighting.cpp, fresnelExact). No total internal reflection from the air side.
float fresnelWeight(float cosVH) {
    float eta = u_modelSettings.x;
    float c1 = clamp(cosVH, 0.0, 1.0);
    float sin3Sq = (1.0 - c1 * c1) / (eta * eta);
    float c3 = sqrt(max(1.0 - sin3Sq, 0.0));
    float perp = (c1 - eta * c3) / (c1 + eta * c3);
    float par = (c3 - eta * c1) / (c3 + eta * c1);
    return 0.5 * (par * par + perp * perp);
}
#endif

// L_l (k_d C (N.I) + k_s S spec) for light l from direction I with N.I > 0 (the products with L_l,
// k_d C and k_s S come folded from the ObjectBlock; `texel` and `specularShare`: see sumOfTerms).
vec3 reflected(int l, vec3 I, float NdotI, vec3 N, vec3 V, vec3 texel, float specularShare) {
#if SL_REFLECTION == SL_REFLECTION_PHONG
    vec3 R = 2.0 * NdotI * N - I;
    float cosLobe = dot(R, V);
#else
    float cosLobe = dot(normalize(I + V), N);
#endif
    float spec = pow(max(cosLobe, 0.0), SL_EXPONENT);
#if SL_SPECULAR_NORMALIZATION == SL_NORMALIZATION_ENERGY
    // n(k_e) / n(32): constant reflected energy, the same look as "none" at k_e = 32.
#if SL_REFLECTION == SL_REFLECTION_PHONG
    spec *= (SL_EXPONENT + 2.0) / (SL_ENERGY_REFERENCE_EXPONENT + 2.0);
#else
    spec *= (SL_EXPONENT + 8.0) / (SL_ENERGY_REFERENCE_EXPONENT + 8.0);
#endif
#endif
#if SL_FRESNEL != SL_FRESNEL_NONE
    spec *= fresnelWeight(dot(V, normalize(I + V)));
#endif
    spec *= specularShare;
#if SL_SHOW == SL_SHOW_DIFFUSE
    return SL_LIGHT_DIFFUSE(l) * texel * NdotI;               // L_l k_d C (N.I)
#elif SL_SHOW == SL_SHOW_SPECULAR
    return SL_LIGHT_SPECULAR(l) * spec;                       // L_l k_s S spec
#else
    return SL_LIGHT_DIFFUSE(l) * texel * NdotI + SL_LIGHT_SPECULAR(l) * spec;
#endif
}

// The distance falloff at squared distance r2 (core/lighting.cpp, attenuationFactor).
float distanceFalloff(int l, int attenuation, float r2) {
    float falloff = 1.0;
    if (attenuation == SL_ATTENUATION_INVERSE_SQUARE) falloff = 1.0 / r2;
    if (attenuation == SL_ATTENUATION_INVERSE_SQUARE_RANGE) {
        float q = r2 * u_lights[l].falloff.x;  // (r / range)^2
        float window = clamp(1.0 - q * q, 0.0, 1.0);
        falloff = window * window / r2;
    }
    return falloff;
}

// A spot light's cone (core/lighting.cpp, spotFalloff): full inside the inner half-angle, none
// outside the outer one, glTF's smooth t^2 between. I points from the surface to the light.
float spotFalloff(int l, vec3 I) {
    float cd = dot(u_lights[l].spot.xyz, -I);
    float t = clamp((cd - u_lights[l].spot.w) * u_lights[l].falloff.w, 0.0, 1.0);
    return t * t;
}

// Area-light sample (i, j) of an nx x ny grid as an offset in [-0.5, 0.5]^2 of the rectangle: the
// same stratified, fixed-seed jitter as areaSampleOffset() in core/lighting.cpp.
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

#if SL_SHADOWS
// Shadow-map lookups compare depths in hardware (GL_COMPARE_REF_TO_TEXTURE, bilinear: 2 x 2
// texels per lookup); percentage-closer filtering averages (2 SL_SHADOW_PCF + 1)^2 of them a texel
// apart. Returns the visible fraction in [0, 1].
float shadowLookup(sampler2DArrayShadow map, vec2 st, float layer, float depth, float texel) {
#if SL_SHADOW_PCF == 0
    return texture(map, vec4(st, layer, depth));
#else
    float sum = 0.0;
    for (int y = -SL_SHADOW_PCF; y <= SL_SHADOW_PCF; ++y)
        for (int x = -SL_SHADOW_PCF; x <= SL_SHADOW_PCF; ++x)
            sum += texture(map, vec4(st + vec2(x, y) * texel, layer, depth));
    return sum / float((2 * SL_SHADOW_PCF + 1) * (2 * SL_SHADOW_PCF + 1));
#endif
}

// Normal-offset bias: the point looked up moves along its normal by u_shadowSettings.x texels (a
// texel's world size grows with the distance from a point or area light), so a lit surface does not
// shadow itself; the depth pass adds a slope-scaled offset (ShadowSettings::depthBias).

// Point light: six cube faces in layers 0..5, picked by the major axis of p - light.
float pointVisibility(sampler2DArrayShadow map, int l, vec3 posWorld, vec3 N) {
    vec4 sh = u_lights[l].shadow;
    vec3 d = posWorld - u_lights[l].positionOrDirection.xyz;
    d += N * (u_shadowSettings.x * sh.x * length(d));
    vec3 a = abs(d);
    float ma, face;
    vec2 uv;
    if (a.x >= a.y && a.x >= a.z) {
        ma = a.x, uv = d.yz, face = d.x >= 0.0 ? 0.0 : 1.0;
    } else if (a.y >= a.z) {
        ma = a.y, uv = d.zx, face = d.y >= 0.0 ? 2.0 : 3.0;
    } else {
        ma = a.z, uv = d.xy, face = d.z >= 0.0 ? 4.0 : 5.0;
    }
    vec2 st = 0.5 + 0.5 * uv / (ma * sh.w);
    return shadowLookup(map, st, face, sh.y - sh.z / ma, u_lights[l].falloff.z);
}

// Spot light: one perspective map down its axis; the normal offset grows with the distance, as a
// texel does.
float spotVisibility(sampler2DArrayShadow map, int l, vec3 posWorld, vec3 N) {
    float distance = length(posWorld - u_lights[l].positionOrDirection.xyz);
    vec3 pos = posWorld + N * (u_shadowSettings.x * u_lights[l].shadow.x * distance);
    vec4 clip = u_lights[l].shadowClipFromWorld * vec4(pos, 1.0);
    vec3 c = clip.xyz / clip.w * 0.5 + 0.5;
    return shadowLookup(map, c.xy, 0.0, c.z, u_lights[l].falloff.z);
}

// Directional light: one orthographic map.
float directionalVisibility(sampler2DArrayShadow map, int l, vec3 posWorld, vec3 N) {
    vec3 pos = posWorld + N * (u_shadowSettings.x * u_lights[l].shadow.x);
    vec3 c = (u_lights[l].shadowClipFromWorld * vec4(pos, 1.0)).xyz * 0.5 + 0.5;
    return shadowLookup(map, c.xy, 0.0, c.z, u_lights[l].falloff.z);
}
#endif

// Light l's share: L_l (k_d C (N.I) + k_s S spec). `kind` and `attenuation` are constants, so the
// compiler drops the branches that do not apply.
vec3 lightTerm(int l, int kind, int attenuation, SL_SHADOW_PARAM vec3 posWorld, vec3 N, vec3 V, vec3 texel,
               float specularShare) {
    vec3 I;
    float falloff = 1.0;
    if (kind == SL_LIGHT_DIRECTIONAL) {
        I = normalize(SL_DIRECTION_TO_LIGHT(l));
    } else {
        vec3 toLight = SL_TO_LIGHT(l, posWorld);
        float r2 = dot(toLight, toLight);
        I = toLight * inversesqrt(r2);
        falloff = distanceFalloff(l, attenuation, r2);
        if (kind == SL_LIGHT_SPOT) falloff *= spotFalloff(l, I);
    }
    float NdotI = dot(N, I);
    if (NdotI <= 0.0) return vec3(0.0);  // light behind the surface: no diffuse and no highlight
#if SL_SHADOWS
    if (kind == SL_LIGHT_DIRECTIONAL) falloff *= directionalVisibility(shadowMap, l, posWorld, N);
    else if (kind == SL_LIGHT_SPOT) falloff *= spotVisibility(shadowMap, l, posWorld, N);
    else falloff *= pointVisibility(shadowMap, l, posWorld, N);
#endif
    return falloff * reflected(l, I, NdotI, N, V, texel, specularShare);
}

// Area light l: nx * ny point-light samples, each weighted by its share of the area (1 / (nx ny))
// and the cosine at the light (|cos| when two-sided; nothing from behind the emitting side). With
// shadows, one occlusion test per sample, in that sample's own layer of the light's map.
vec3 areaLightTerm(int l, int attenuation, int nx, int ny, SL_SHADOW_PARAM vec3 posWorld, vec3 N, vec3 V, vec3 texel,
                   float specularShare) {
    vec3 centre = u_lights[l].positionOrDirection.xyz;
    vec3 edgeU = u_lights[l].areaU.xyz, edgeV = u_lights[l].areaV.xyz, front = u_lights[l].areaNormal.xyz;
    float twoSided = u_lights[l].falloff.y;
#if SL_SHADOWS
    vec4 clipP = u_lights[l].shadowClipFromWorld * vec4(posWorld, 1.0);
    vec4 clipN = u_lights[l].shadowClipFromWorld * vec4(N, 0.0);
    float bias = u_shadowSettings.x * u_lights[l].shadow.x;
#endif
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
            vec3 toLight = centre + ab.x * edgeU + ab.y * edgeV - posWorld;
            float r2 = dot(toLight, toLight);
            vec3 I = toLight * inversesqrt(r2);
            float cosLight = -dot(front, I);
            cosLight = mix(cosLight, abs(cosLight), twoSided);
            float NdotI = dot(N, I);
            if (cosLight <= 0.0 || NdotI <= 0.0) continue;
            float weight = cosLight * distanceFalloff(l, attenuation, r2);
#if SL_SHADOWS
            vec4 clip = clipP - ab.x * u_lights[l].shadowU - ab.y * u_lights[l].shadowV;
            clip += clipN * (bias * clip.w);
            vec3 c = clip.xyz / clip.w * 0.5 + 0.5;
            weight *= texture(shadowMap, vec4(c.xy, float(j * nx + i), c.z));
#endif
            sum += weight * reflected(l, I, NdotI, N, V, texel, specularShare);
        }
#if SL_ACCUMULATE
    sum *= float(u_areaPass.z * u_areaPass.w);
#endif
    return sum / float(nx * ny);
}

// posWorld: the point being shaded; nrmWorld: its unit normal. Returns linear RGB before the clamp.
// `texel` multiplies the material's C where it varies over the surface (a texture and vertex colours,
// shaders/object_color.glsl; 1 elsewhere), so it scales the terms C is in, ambient and diffuse, and
// not the specular; `specularShare` (1, or 0) keeps or drops the specular. The functions below call
// this with constants, which the compiler folds away.
vec3 sumOfTerms(vec3 posWorld, vec3 nrmWorld, vec3 texel, float specularShare) {
    vec3 N = nrmWorld;
    vec3 V = normalize(SL_TO_EYE(posWorld));
#if SL_SHOW == SL_SHOW_UNLIT
    return clamp(u_color.rgb * texel, 0.0, 1.0);
#endif
#if SL_SHOW == SL_SHOW_ALL || SL_SHOW == SL_SHOW_AMBIENT
    vec3 L = SL_AMBIENT_TERM * texel;  // k_a A C
#else
    vec3 L = vec3(0.0);
#endif
#if SL_LIGHT_COUNT > 0 && SL_SHOW != SL_SHOW_AMBIENT && SL_SHOW != SL_SHOW_UNLIT && (SL_SHOW != SL_SHOW_LIGHT || SL_SHOW_LIGHT_INDEX == 0)
#if SL_LIGHT_KIND_0 == SL_LIGHT_AREA
    L += areaLightTerm(0, SL_LIGHT_ATTENUATION_0, SL_LIGHT_SAMPLES_X_0, SL_LIGHT_SAMPLES_Y_0, SL_SHADOW_ARG(0) posWorld, N, V, texel, specularShare);
#else
    L += lightTerm(0, SL_LIGHT_KIND_0, SL_LIGHT_ATTENUATION_0, SL_SHADOW_ARG(0) posWorld, N, V, texel, specularShare);
#endif
#endif
#if SL_LIGHT_COUNT > 1 && SL_SHOW != SL_SHOW_AMBIENT && SL_SHOW != SL_SHOW_UNLIT && (SL_SHOW != SL_SHOW_LIGHT || SL_SHOW_LIGHT_INDEX == 1)
#if SL_LIGHT_KIND_1 == SL_LIGHT_AREA
    L += areaLightTerm(1, SL_LIGHT_ATTENUATION_1, SL_LIGHT_SAMPLES_X_1, SL_LIGHT_SAMPLES_Y_1, SL_SHADOW_ARG(1) posWorld, N, V, texel, specularShare);
#else
    L += lightTerm(1, SL_LIGHT_KIND_1, SL_LIGHT_ATTENUATION_1, SL_SHADOW_ARG(1) posWorld, N, V, texel, specularShare);
#endif
#endif
#if SL_LIGHT_COUNT > 2 && SL_SHOW != SL_SHOW_AMBIENT && SL_SHOW != SL_SHOW_UNLIT && (SL_SHOW != SL_SHOW_LIGHT || SL_SHOW_LIGHT_INDEX == 2)
#if SL_LIGHT_KIND_2 == SL_LIGHT_AREA
    L += areaLightTerm(2, SL_LIGHT_ATTENUATION_2, SL_LIGHT_SAMPLES_X_2, SL_LIGHT_SAMPLES_Y_2, SL_SHADOW_ARG(2) posWorld, N, V, texel, specularShare);
#else
    L += lightTerm(2, SL_LIGHT_KIND_2, SL_LIGHT_ATTENUATION_2, SL_SHADOW_ARG(2) posWorld, N, V, texel, specularShare);
#endif
#endif
#if SL_LIGHT_COUNT > 3 && SL_SHOW != SL_SHOW_AMBIENT && SL_SHOW != SL_SHOW_UNLIT && (SL_SHOW != SL_SHOW_LIGHT || SL_SHOW_LIGHT_INDEX == 3)
#if SL_LIGHT_KIND_3 == SL_LIGHT_AREA
    L += areaLightTerm(3, SL_LIGHT_ATTENUATION_3, SL_LIGHT_SAMPLES_X_3, SL_LIGHT_SAMPLES_Y_3, SL_SHADOW_ARG(3) posWorld, N, V, texel, specularShare);
#else
    L += lightTerm(3, SL_LIGHT_KIND_3, SL_LIGHT_ATTENUATION_3, SL_SHADOW_ARG(3) posWorld, N, V, texel, specularShare);
#endif
#endif
#if SL_LIGHT_COUNT > 4 && SL_SHOW != SL_SHOW_AMBIENT && SL_SHOW != SL_SHOW_UNLIT && (SL_SHOW != SL_SHOW_LIGHT || SL_SHOW_LIGHT_INDEX == 4)
#if SL_LIGHT_KIND_4 == SL_LIGHT_AREA
    L += areaLightTerm(4, SL_LIGHT_ATTENUATION_4, SL_LIGHT_SAMPLES_X_4, SL_LIGHT_SAMPLES_Y_4, SL_SHADOW_ARG(4) posWorld, N, V, texel, specularShare);
#else
    L += lightTerm(4, SL_LIGHT_KIND_4, SL_LIGHT_ATTENUATION_4, SL_SHADOW_ARG(4) posWorld, N, V, texel, specularShare);
#endif
#endif
#if SL_LIGHT_COUNT > 5 && SL_SHOW != SL_SHOW_AMBIENT && SL_SHOW != SL_SHOW_UNLIT && (SL_SHOW != SL_SHOW_LIGHT || SL_SHOW_LIGHT_INDEX == 5)
#if SL_LIGHT_KIND_5 == SL_LIGHT_AREA
    L += areaLightTerm(5, SL_LIGHT_ATTENUATION_5, SL_LIGHT_SAMPLES_X_5, SL_LIGHT_SAMPLES_Y_5, SL_SHADOW_ARG(5) posWorld, N, V, texel, specularShare);
#else
    L += lightTerm(5, SL_LIGHT_KIND_5, SL_LIGHT_ATTENUATION_5, SL_SHADOW_ARG(5) posWorld, N, V, texel, specularShare);
#endif
#endif
#if SL_LIGHT_COUNT > 6 && SL_SHOW != SL_SHOW_AMBIENT && SL_SHOW != SL_SHOW_UNLIT && (SL_SHOW != SL_SHOW_LIGHT || SL_SHOW_LIGHT_INDEX == 6)
#if SL_LIGHT_KIND_6 == SL_LIGHT_AREA
    L += areaLightTerm(6, SL_LIGHT_ATTENUATION_6, SL_LIGHT_SAMPLES_X_6, SL_LIGHT_SAMPLES_Y_6, SL_SHADOW_ARG(6) posWorld, N, V, texel, specularShare);
#else
    L += lightTerm(6, SL_LIGHT_KIND_6, SL_LIGHT_ATTENUATION_6, SL_SHADOW_ARG(6) posWorld, N, V, texel, specularShare);
#endif
#endif
#if SL_LIGHT_COUNT > 7 && SL_SHOW != SL_SHOW_AMBIENT && SL_SHOW != SL_SHOW_UNLIT && (SL_SHOW != SL_SHOW_LIGHT || SL_SHOW_LIGHT_INDEX == 7)
#if SL_LIGHT_KIND_7 == SL_LIGHT_AREA
    L += areaLightTerm(7, SL_LIGHT_ATTENUATION_7, SL_LIGHT_SAMPLES_X_7, SL_LIGHT_SAMPLES_Y_7, SL_SHADOW_ARG(7) posWorld, N, V, texel, specularShare);
#else
    L += lightTerm(7, SL_LIGHT_KIND_7, SL_LIGHT_ATTENUATION_7, SL_SHADOW_ARG(7) posWorld, N, V, texel, specularShare);
#endif
#endif
#if SL_LIGHT_COUNT > 8 && SL_SHOW != SL_SHOW_AMBIENT && SL_SHOW != SL_SHOW_UNLIT && (SL_SHOW != SL_SHOW_LIGHT || SL_SHOW_LIGHT_INDEX == 8)
#if SL_LIGHT_KIND_8 == SL_LIGHT_AREA
    L += areaLightTerm(8, SL_LIGHT_ATTENUATION_8, SL_LIGHT_SAMPLES_X_8, SL_LIGHT_SAMPLES_Y_8, SL_SHADOW_ARG(8) posWorld, N, V, texel, specularShare);
#else
    L += lightTerm(8, SL_LIGHT_KIND_8, SL_LIGHT_ATTENUATION_8, SL_SHADOW_ARG(8) posWorld, N, V, texel, specularShare);
#endif
#endif
#if SL_LIGHT_COUNT > 9 && SL_SHOW != SL_SHOW_AMBIENT && SL_SHOW != SL_SHOW_UNLIT && (SL_SHOW != SL_SHOW_LIGHT || SL_SHOW_LIGHT_INDEX == 9)
#if SL_LIGHT_KIND_9 == SL_LIGHT_AREA
    L += areaLightTerm(9, SL_LIGHT_ATTENUATION_9, SL_LIGHT_SAMPLES_X_9, SL_LIGHT_SAMPLES_Y_9, SL_SHADOW_ARG(9) posWorld, N, V, texel, specularShare);
#else
    L += lightTerm(9, SL_LIGHT_KIND_9, SL_LIGHT_ATTENUATION_9, SL_SHADOW_ARG(9) posWorld, N, V, texel, specularShare);
#endif
#endif
#if SL_LIGHT_COUNT > 10 && SL_SHOW != SL_SHOW_AMBIENT && SL_SHOW != SL_SHOW_UNLIT && (SL_SHOW != SL_SHOW_LIGHT || SL_SHOW_LIGHT_INDEX == 10)
#if SL_LIGHT_KIND_10 == SL_LIGHT_AREA
    L += areaLightTerm(10, SL_LIGHT_ATTENUATION_10, SL_LIGHT_SAMPLES_X_10, SL_LIGHT_SAMPLES_Y_10, SL_SHADOW_ARG(10) posWorld, N, V, texel, specularShare);
#else
    L += lightTerm(10, SL_LIGHT_KIND_10, SL_LIGHT_ATTENUATION_10, SL_SHADOW_ARG(10) posWorld, N, V, texel, specularShare);
#endif
#endif
#if SL_LIGHT_COUNT > 11 && SL_SHOW != SL_SHOW_AMBIENT && SL_SHOW != SL_SHOW_UNLIT && (SL_SHOW != SL_SHOW_LIGHT || SL_SHOW_LIGHT_INDEX == 11)
#if SL_LIGHT_KIND_11 == SL_LIGHT_AREA
    L += areaLightTerm(11, SL_LIGHT_ATTENUATION_11, SL_LIGHT_SAMPLES_X_11, SL_LIGHT_SAMPLES_Y_11, SL_SHADOW_ARG(11) posWorld, N, V, texel, specularShare);
#else
    L += lightTerm(11, SL_LIGHT_KIND_11, SL_LIGHT_ATTENUATION_11, SL_SHADOW_ARG(11) posWorld, N, V, texel, specularShare);
#endif
#endif
#if SL_LIGHT_COUNT > 12 && SL_SHOW != SL_SHOW_AMBIENT && SL_SHOW != SL_SHOW_UNLIT && (SL_SHOW != SL_SHOW_LIGHT || SL_SHOW_LIGHT_INDEX == 12)
#if SL_LIGHT_KIND_12 == SL_LIGHT_AREA
    L += areaLightTerm(12, SL_LIGHT_ATTENUATION_12, SL_LIGHT_SAMPLES_X_12, SL_LIGHT_SAMPLES_Y_12, SL_SHADOW_ARG(12) posWorld, N, V, texel, specularShare);
#else
    L += lightTerm(12, SL_LIGHT_KIND_12, SL_LIGHT_ATTENUATION_12, SL_SHADOW_ARG(12) posWorld, N, V, texel, specularShare);
#endif
#endif
#if SL_LIGHT_COUNT > 13 && SL_SHOW != SL_SHOW_AMBIENT && SL_SHOW != SL_SHOW_UNLIT && (SL_SHOW != SL_SHOW_LIGHT || SL_SHOW_LIGHT_INDEX == 13)
#if SL_LIGHT_KIND_13 == SL_LIGHT_AREA
    L += areaLightTerm(13, SL_LIGHT_ATTENUATION_13, SL_LIGHT_SAMPLES_X_13, SL_LIGHT_SAMPLES_Y_13, SL_SHADOW_ARG(13) posWorld, N, V, texel, specularShare);
#else
    L += lightTerm(13, SL_LIGHT_KIND_13, SL_LIGHT_ATTENUATION_13, SL_SHADOW_ARG(13) posWorld, N, V, texel, specularShare);
#endif
#endif
#if SL_LIGHT_COUNT > 14 && SL_SHOW != SL_SHOW_AMBIENT && SL_SHOW != SL_SHOW_UNLIT && (SL_SHOW != SL_SHOW_LIGHT || SL_SHOW_LIGHT_INDEX == 14)
#if SL_LIGHT_KIND_14 == SL_LIGHT_AREA
    L += areaLightTerm(14, SL_LIGHT_ATTENUATION_14, SL_LIGHT_SAMPLES_X_14, SL_LIGHT_SAMPLES_Y_14, SL_SHADOW_ARG(14) posWorld, N, V, texel, specularShare);
#else
    L += lightTerm(14, SL_LIGHT_KIND_14, SL_LIGHT_ATTENUATION_14, SL_SHADOW_ARG(14) posWorld, N, V, texel, specularShare);
#endif
#endif
#if SL_LIGHT_COUNT > 15 && SL_SHOW != SL_SHOW_AMBIENT && SL_SHOW != SL_SHOW_UNLIT && (SL_SHOW != SL_SHOW_LIGHT || SL_SHOW_LIGHT_INDEX == 15)
#if SL_LIGHT_KIND_15 == SL_LIGHT_AREA
    L += areaLightTerm(15, SL_LIGHT_ATTENUATION_15, SL_LIGHT_SAMPLES_X_15, SL_LIGHT_SAMPLES_Y_15, SL_SHADOW_ARG(15) posWorld, N, V, texel, specularShare);
#else
    L += lightTerm(15, SL_LIGHT_KIND_15, SL_LIGHT_ATTENUATION_15, SL_SHADOW_ARG(15) posWorld, N, V, texel, specularShare);
#endif
#endif
    return L;
}

// The lecture's L before the clamp (progressive Phong sums these over passes and clamps the mean).
vec3 shadeLectureUnclamped(vec3 posWorld, vec3 nrmWorld, vec3 texel) { return sumOfTerms(posWorld, nrmWorld, texel, 1.0); }

// The lecture's L, clamped to [0, 1]: linear RGB.
vec3 shadeLecture(vec3 posWorld, vec3 nrmWorld, vec3 texel) { return clamp(shadeLectureUnclamped(posWorld, nrmWorld, texel), 0.0, 1.0); }

// The formula in two parts, for flat and Gouraud shading of a textured surface: they evaluate it per
// face or vertex, before the fragment knows its texel, and the fragment stage combines them
// (shaders/object_color.glsl, combineTerms):  L = clamp(texel * termsOfC + specular, 0, 1).
vec3 shadeLectureTermsOfC(vec3 posWorld, vec3 nrmWorld) { return sumOfTerms(posWorld, nrmWorld, vec3(1.0), 0.0); }  // k_a A C + sum v L_l k_d C (N.I)
vec3 shadeLectureSpecular(vec3 posWorld, vec3 nrmWorld) { return sumOfTerms(posWorld, nrmWorld, vec3(0.0), 1.0); }  // sum v L_l k_s S spec_l
