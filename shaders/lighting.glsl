// The lecture's reflection model, evaluated wherever a shading mode chooses to evaluate it:
// once per triangle (flat), per vertex (gouraud) or per fragment (phong). Mirrors shadeTerms() in
// app/core/lighting.cpp, which the tests compare against.
//
//   L = k_a A C + sum_l L_l ( k_d C max(0, N.I_l) + k_s S spec_l ),   clamped to [0, 1]
//   spec_l = max(0, R(I_l).V)^k_e (Phong) or max(0, H_l.N)^k_e (Blinn-Phong), 0 where N.I_l <= 0
#include "uniforms.glsl"

// posWorld: the point being shaded; nrmWorld: its unit normal. Returns linear RGB in [0, 1].
vec3 shadeLecture(vec3 posWorld, vec3 nrmWorld) {
    vec3 N = nrmWorld;
    vec3 V = normalize(u_eyeWorld.xyz - posWorld);
    float ka = u_coefficients.x, kd = u_coefficients.y, ks = u_coefficients.z, ke = u_coefficients.w;
    vec3 L = ka * u_ambient.rgb * u_color.rgb;
    for (int l = 0; l < u_settings.x; ++l) {
        vec3 I;
        float attenuation = 1.0;
        if (u_lights[l].kind.x == SL_LIGHT_DIRECTIONAL) {
            I = normalize(-u_lights[l].positionOrDirection.xyz);
        } else {
            vec3 toLight = u_lights[l].positionOrDirection.xyz - posWorld;
            float r2 = dot(toLight, toLight);
            I = toLight * inversesqrt(r2);
            if (u_lights[l].kind.y == SL_ATTENUATION_INVERSE_SQUARE) attenuation = 1.0 / r2;
        }
        float NdotI = dot(N, I);
        if (NdotI <= 0.0) continue;  // light behind the surface: no diffuse and no highlight
        float cosLobe;
        if (u_settings.y == SL_REFLECTION_PHONG) {
            vec3 R = 2.0 * NdotI * N - I;
            cosLobe = dot(R, V);
        } else {
            cosLobe = dot(normalize(I + V), N);
        }
        float spec = pow(max(cosLobe, 0.0), ke);
        vec3 radiance = u_lights[l].radiance.rgb * attenuation;
        L += radiance * (kd * u_color.rgb * NdotI + ks * u_specularColor.rgb * spec);
    }
    return clamp(L, 0.0, 1.0);
}

// What the framebuffer gets: the value itself, or its sRGB encoding when the scene asks for it.
vec3 encodeOutput(vec3 linear) {
    if (u_settings.z != SL_ENCODING_SRGB) return linear;
    vec3 lo = 12.92 * linear;
    vec3 hi = 1.055 * pow(linear, vec3(1.0 / 2.4)) - 0.055;
    return mix(hi, lo, vec3(lessThanEqual(linear, vec3(0.0031308))));
}
