// What a glTF material adds to the lecture's C: where C varies over the surface (SL_TEXTURED), its
// alpha (SL_ALPHA_MODE) and the light it gives off, E (SL_EMISSIVE).
//
// C: a glTF model's base colour texture and its vertex colours (COLOR_0). The material's own C (the
// base colour factor) is in the ObjectBlock's products already (u_color, k_a A C, L_l k_d C); what
// varies is the factor
//
//     texel = texture(u_baseColorTexture, uv).rgb * COLOR_0,    C = u_color * texel,
//
// read per fragment in every shading mode: the vertex stage passes the texture coordinates and the
// vertex colour on (passObjectColor), the fragment stage samples (objectTexel). Without SL_TEXTURED
// the texel is 1 and the programs are the ones they always were.
//
// Alpha: the same product of the base colour factor's, the texel's and COLOR_0's alphas (objectAlpha).
// E: emissiveFactor x strength (u_emissive) times the emissive texture at its own coordinates
// (objectEmission), added to the lecture's sum: L = E + k_a A C + sum ... (shaders/lighting.glsl).
// And the colour a fragment writes (fragmentColor) and glTF's double-sided surfaces (facingNormal:
// per fragment in the fragment stage, per triangle in the vertex stage).
#include "specialisation.glsl"
#include "uniforms.glsl"
#include "encoding.glsl"

#ifndef SL_TEXTURED
#define SL_TEXTURED 0
#endif
#ifndef SL_ALPHA_MODE
#define SL_ALPHA_MODE SL_ALPHA_OPAQUE
#endif
#ifndef SL_EMISSIVE
#define SL_EMISSIVE 0          // 1: the draw gives off light (E > 0)
#endif
#ifndef SL_EMISSIVE_TEXTURE
#define SL_EMISSIVE_TEXTURE 0  // 1 (with SL_TEXTURED): E varies by the emissive texture
#endif

#if SL_TEXTURED && defined(SL_VERTEX_STAGE)
layout(location = SL_ATTRIB_TEXCOORD) in vec2 a_texcoord;  // the texture's TEXCOORD_n, transformed
layout(location = SL_ATTRIB_COLOR) in vec4 a_color;        // COLOR_0, linear (white where there is none)
out vec2 v_texcoord;
out vec4 v_vertexColor;
#if SL_EMISSIVE_TEXTURE
layout(location = SL_ATTRIB_EMISSIVE_TEXCOORD) in vec2 a_emissiveTexcoord;
out vec2 v_emissiveTexcoord;
#endif
void passObjectColor() {
    v_texcoord = a_texcoord;
    v_vertexColor = a_color;
#if SL_EMISSIVE_TEXTURE
    v_emissiveTexcoord = a_emissiveTexcoord;
#endif
}
// E varies per fragment here: the fragment stage adds it (combineTerms), not this stage's sum.
vec3 objectEmission() { return vec3(0.0); }
#elif SL_TEXTURED
in vec2 v_texcoord;
in vec4 v_vertexColor;
uniform sampler2D u_baseColorTexture;  // on unit SL_TEXTURE_BASE_COLOR; an sRGB texture: samples are linear
vec3 objectTexel() { return texture(u_baseColorTexture, v_texcoord).rgb * v_vertexColor.rgb; }
float objectAlpha() { return u_color.a * texture(u_baseColorTexture, v_texcoord).a * v_vertexColor.a; }
#if SL_EMISSIVE_TEXTURE
in vec2 v_emissiveTexcoord;
uniform sampler2D u_emissiveTexture;   // on unit SL_TEXTURE_EMISSIVE; sRGB, like the base colour
vec3 objectEmission() { return u_emissive.rgb * texture(u_emissiveTexture, v_emissiveTexcoord).rgb; }
#else
vec3 objectEmission() { return u_emissive.rgb; }
#endif
#else
void passObjectColor() {}
vec3 objectTexel() { return vec3(1.0); }
float objectAlpha() { return u_color.a; }
vec3 objectEmission() { return u_emissive.rgb; }
#endif

// E as the formula adds it: where "show" keeps it (all terms, or E alone), and where the draw gives off light.
vec3 shownEmission() {
    return SL_EMISSIVE == 1 && (SL_SHOW == SL_SHOW_ALL || SL_SHOW == SL_SHOW_EMISSIVE) ? objectEmission() : vec3(0.0);
}

#ifndef SL_VERTEX_STAGE
// Flat and Gouraud with SL_TEXTURED: L = clamp(texel * termsOfC + specular + E, 0, 1), the two sums
// from the vertex stage (shaders/vertex_shading.glsl) and E, which varies per fragment.
vec3 combineTerms(vec3 termsOfC, vec3 specular) {
    return clamp(objectTexel() * termsOfC + specular + shownEmission(), 0.0, 1.0);
}
// The fragment's alpha as written: the object's with BLEND (blended over what is behind), else 1.
float outputAlpha() { return SL_ALPHA_MODE == SL_ALPHA_BLEND ? objectAlpha() : 1.0; }
// glTF's MASK: a fragment whose alpha is below the cutoff is not there (a cut-out).
bool cutOut() { return SL_ALPHA_MODE == SL_ALPHA_MASK && objectAlpha() < u_alphaCutoff.x; }
// glTF's doubleSided (SL_DOUBLE_SIDED): a fragment on the back of its triangle is lit as a surface
// facing the other way, with N flipped; every other surface keeps N.
vec3 facingNormal(vec3 N) { return SL_DOUBLE_SIDED == 1 && !gl_FrontFacing ? -N : N; }
// What a fragment writes for the linear L before the clamp: L clamped to [0, 1] and encoded, with the
// object's alpha. A pass of progressive sampling (SL_ACCUMULATE) writes L itself, summed with the
// other passes' in a float buffer; shaders/resolve.frag clamps and encodes the mean.
vec4 fragmentColor(vec3 L) {
    if (SL_ACCUMULATE == 1) return vec4(L, 1.0);
    return vec4(encodeOutput(clamp(L, 0.0, 1.0)), outputAlpha());
}
#else
// glTF's doubleSided for a whole triangle (flat.vert): the eye sees the triangle's back when it is
// behind the triangle's plane through P (for a planar triangle, exactly what gl_FrontFacing says), and
// the back is lit with N flipped; every other surface keeps N.
vec3 facingNormal(vec3 N, vec3 P) {
#if SL_DOUBLE_SIDED
    if (dot(N, u_eyeWorld.xyz - P) < 0.0) return -N;
#endif
    return N;
}
#endif
