// The lecture's reflection model, as on its slide (../shared/lecture/shading-lecture.txt, "Phong
// Reflection Model" and "Blinn-Phong Reflection Model"): the light L leaving a point towards the eye,
//
//   L = k_a A C + sum_l L_l ( k_d C max(0, N.I_l) + k_s S max(0, R(I_l).V)^k_e )
//
// Flat shading evaluates it once per triangle, Gouraud once per vertex, Phong once per fragment:
// the three modes reach lecture() below through lighting.glsl's shade() and differ only in where
// they call it. What this program adds around it
// (distance falloff, spot cones, shadows, area lights, Fresnel, anisotropy, showing one term) is in lighting.glsl.
#include "specialisation.glsl"

struct Material {
    vec3 C;     // the surface's colour: what the ambient and the diffuse term reflect
    vec3 S;     // the specular colour: what the highlight reflects (white for plastic)
    float k_a;  // ambient coefficient
    float k_d;  // diffuse coefficient
    float k_s;  // specular coefficient
    float k_e;  // specular exponent: the larger, the smaller and sharper the highlight
};

// Where light l is and how much of it arrives (values_from_blocks.glsl, lighting.glsl).
vec3 toLight(int l, vec3 P);                   // from P towards light l (not unit length)
vec3 lightColor(int l);                        // L_l: the light's colour times its intensity
float arriving(int l, vec3 P, vec3 N, vec3 I);  // 1, or less: falloff, cone and shadow (lighting.glsl)
float lobeFactor(vec3 I, vec3 V, float k_e);   // 1, or the lobe's normalisation and Fresnel (lighting.glsl)
float lobeExponent(vec3 H, float k_e);         // k_e, or anisotropic: k_t along T, k_b along B (lighting.glsl)

// One light's term: L_l (k_d C max(0, N.I) + k_s S max(0, R(I).V)^k_e). N: the surface's unit
// normal, I: the unit vector towards the light, V: the unit vector towards the eye.
vec3 oneLight(Material m, vec3 L_l, vec3 N, vec3 I, vec3 V) {
    vec3 R = 2.0 * dot(N, I) * N - I;  // I mirrored about N: where a mirror would send the light
    vec3 H = normalize(I + V);         // halfway between I and V (Blinn-Phong)
    float cosLobe = SL_REFLECTION == SL_REFLECTION_PHONG ? dot(R, V) : dot(H, N);
    float spec_l = pow(max(cosLobe, 0.0), lobeExponent(H, m.k_e)) * lobeFactor(I, V, m.k_e);
    vec3 diffuse = m.k_d * m.C * max(dot(N, I), 0.0);
    vec3 specular = m.k_s * m.S * spec_l;
    return L_l * (diffuse + specular);
}

// The sum at point P (world space). A: the ambient light; N: the unit normal; V: the unit vector to the eye.
vec3 lecture(Material m, vec3 A, vec3 P, vec3 N, vec3 V) {
    vec3 L = m.k_a * A * m.C;  // ambient
    for (int l = 0; l < SL_LIGHT_COUNT; ++l) {
        vec3 I = normalize(toLight(l, P));
        if (dot(N, I) > 0.0) {  // the light is in front of the surface (behind it: no diffuse, no highlight)
            vec3 L_l = lightColor(l) * arriving(l, P, N, I);
            L += oneLight(m, L_l, N, I, V);
        }
    }
    return L;
}
