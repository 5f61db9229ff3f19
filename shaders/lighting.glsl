// The lecture's reflection model, evaluated wherever a shading mode chooses to evaluate it:
// once per triangle (flat), per vertex (gouraud) or per fragment (phong). Mirrors shadeTerms() in
// app/core/lighting.cpp, which the tests compare against.
//
//   L = k_a A C + sum_l L_l ( k_d C max(0, N.I_l) + k_s S spec_l ),   clamped to [0, 1]
//   spec_l = max(0, R(I_l).V)^k_e (Phong) or max(0, H_l.N)^k_e (Blinn-Phong), 0 where N.I_l <= 0
//
// Programs are specialised (app/render/renderer.cpp, programDefines): the number of lights, each
// light's kind and attenuation, the reflection model and the output encoding are compile-time
// constants. On llvmpipe a loop over a uniform light count with per-light branches made Phong
// shading ~50% slower than the same formula with constants (bench/README.md); light positions,
// colours and all material values stay uniforms, so dragging a slider never recompiles.
#include "uniforms.glsl"

#ifndef SL_LIGHT_COUNT
#define SL_LIGHT_COUNT 0
#endif
#ifndef SL_REFLECTION
#define SL_REFLECTION SL_REFLECTION_BLINN_PHONG
#endif
#ifndef SL_ENCODING
#define SL_ENCODING SL_ENCODING_LINEAR
#endif
// With SL_LIGHT_COUNT = n the renderer also defines SL_LIGHT_KIND_l and SL_LIGHT_ATTENUATION_l for
// l < n; blocks for lights past the count are skipped by the preprocessor and never expanded.

// Light l's share: L_l (k_d C (N.I) + k_s S spec). `kind` and `attenuation` are constants, so the
// compiler drops the branches that do not apply.
vec3 lightTerm(int l, int kind, int attenuation, vec3 posWorld, vec3 N, vec3 V) {
    vec3 I;
    float falloff = 1.0;
    if (kind == SL_LIGHT_DIRECTIONAL) {
        I = normalize(-u_lights[l].positionOrDirection.xyz);
    } else {
        vec3 toLight = u_lights[l].positionOrDirection.xyz - posWorld;
        float r2 = dot(toLight, toLight);
        I = toLight * inversesqrt(r2);
        if (attenuation == SL_ATTENUATION_INVERSE_SQUARE) falloff = 1.0 / r2;
    }
    float NdotI = dot(N, I);
    if (NdotI <= 0.0) return vec3(0.0);  // light behind the surface: no diffuse and no highlight
#if SL_REFLECTION == SL_REFLECTION_PHONG
    vec3 R = 2.0 * NdotI * N - I;
    float cosLobe = dot(R, V);
#else
    float cosLobe = dot(normalize(I + V), N);
#endif
    float spec = pow(max(cosLobe, 0.0), u_coefficients.w);
    float kd = u_coefficients.y, ks = u_coefficients.z;
    return u_lights[l].radiance.rgb * falloff * (kd * u_color.rgb * NdotI + ks * u_specularColor.rgb * spec);
}

// posWorld: the point being shaded; nrmWorld: its unit normal. Returns linear RGB in [0, 1].
vec3 shadeLecture(vec3 posWorld, vec3 nrmWorld) {
    vec3 N = nrmWorld;
    vec3 V = normalize(u_eyeWorld.xyz - posWorld);
    vec3 L = u_coefficients.x * u_ambient.rgb * u_color.rgb;
#if SL_LIGHT_COUNT > 0
    L += lightTerm(0, SL_LIGHT_KIND_0, SL_LIGHT_ATTENUATION_0, posWorld, N, V);
#endif
#if SL_LIGHT_COUNT > 1
    L += lightTerm(1, SL_LIGHT_KIND_1, SL_LIGHT_ATTENUATION_1, posWorld, N, V);
#endif
#if SL_LIGHT_COUNT > 2
    L += lightTerm(2, SL_LIGHT_KIND_2, SL_LIGHT_ATTENUATION_2, posWorld, N, V);
#endif
#if SL_LIGHT_COUNT > 3
    L += lightTerm(3, SL_LIGHT_KIND_3, SL_LIGHT_ATTENUATION_3, posWorld, N, V);
#endif
#if SL_LIGHT_COUNT > 4
    L += lightTerm(4, SL_LIGHT_KIND_4, SL_LIGHT_ATTENUATION_4, posWorld, N, V);
#endif
#if SL_LIGHT_COUNT > 5
    L += lightTerm(5, SL_LIGHT_KIND_5, SL_LIGHT_ATTENUATION_5, posWorld, N, V);
#endif
#if SL_LIGHT_COUNT > 6
    L += lightTerm(6, SL_LIGHT_KIND_6, SL_LIGHT_ATTENUATION_6, posWorld, N, V);
#endif
#if SL_LIGHT_COUNT > 7
    L += lightTerm(7, SL_LIGHT_KIND_7, SL_LIGHT_ATTENUATION_7, posWorld, N, V);
#endif
#if SL_LIGHT_COUNT > 8
    L += lightTerm(8, SL_LIGHT_KIND_8, SL_LIGHT_ATTENUATION_8, posWorld, N, V);
#endif
#if SL_LIGHT_COUNT > 9
    L += lightTerm(9, SL_LIGHT_KIND_9, SL_LIGHT_ATTENUATION_9, posWorld, N, V);
#endif
#if SL_LIGHT_COUNT > 10
    L += lightTerm(10, SL_LIGHT_KIND_10, SL_LIGHT_ATTENUATION_10, posWorld, N, V);
#endif
#if SL_LIGHT_COUNT > 11
    L += lightTerm(11, SL_LIGHT_KIND_11, SL_LIGHT_ATTENUATION_11, posWorld, N, V);
#endif
#if SL_LIGHT_COUNT > 12
    L += lightTerm(12, SL_LIGHT_KIND_12, SL_LIGHT_ATTENUATION_12, posWorld, N, V);
#endif
#if SL_LIGHT_COUNT > 13
    L += lightTerm(13, SL_LIGHT_KIND_13, SL_LIGHT_ATTENUATION_13, posWorld, N, V);
#endif
#if SL_LIGHT_COUNT > 14
    L += lightTerm(14, SL_LIGHT_KIND_14, SL_LIGHT_ATTENUATION_14, posWorld, N, V);
#endif
#if SL_LIGHT_COUNT > 15
    L += lightTerm(15, SL_LIGHT_KIND_15, SL_LIGHT_ATTENUATION_15, posWorld, N, V);
#endif
    return clamp(L, 0.0, 1.0);
}

// What the framebuffer gets: the value itself, or its sRGB encoding when the scene asks for it.
vec3 encodeOutput(vec3 linear) {
#if SL_ENCODING == SL_ENCODING_SRGB
    vec3 lo = 12.92 * linear;
    vec3 hi = 1.055 * pow(linear, vec3(1.0 / 2.4)) - 0.055;
    return mix(hi, lo, vec3(lessThanEqual(linear, vec3(0.0031308))));
#else
    return linear;
#endif
}
