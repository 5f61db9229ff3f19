// Flat and Gouraud shading evaluate the formula in the vertex stage, flat once per triangle
// (flat.vert), Gouraud once per vertex (gouraud.vert), and hand the result to the fragments:
//
//   shadeAndPass(P, N)   vertex stage: lighting.glsl's shade() at P with unit normal N, clamped
//   shadedColor()        fragment stage: the L that reached this fragment
//
// What is handed on, decided here by the draw's defines:
//   - the lecture's L, clamped (v_color);
//   - where C varies over the surface (SL_TEXTURED, shaders/object_color.glsl), the formula's two
//     parts instead, which the fragment combines with its texel: L = clamp(texel * termsOfC +
//     specular + E, 0, 1) (v_termsOfC, v_specular, combineTerms);
//   - glTF's doubleSided under Gouraud (SL_DOUBLE_SIDED): a vertex cannot know which side of its
//     triangles the eye sees, so, as OpenGL's fixed-function two-sided lighting did
//     (GL_LIGHT_MODEL_TWO_SIDE), the same for -N as well, and the fragment picks by gl_FrontFacing.
//     Flat shading knows the side per triangle and flips N itself (object_color.glsl, facingNormal).
//
// How it reaches the fragments: a file that defines SL_ONE_PER_TRIANGLE 1 before including this one
// (flat.vert, flat.frag) hands it on `flat`: every fragment of a triangle takes the value of its
// provoking vertex. Otherwise (Gouraud) it is interpolated across the triangle (perspective-correct).
#include "object_color.glsl"

#ifndef SL_ONE_PER_TRIANGLE
#define SL_ONE_PER_TRIANGLE 0
#endif
#if SL_ONE_PER_TRIANGLE
#define SL_HANDED_ON flat  // the provoking vertex's value for the whole triangle
#else
#define SL_HANDED_ON       // interpolated: the default, smooth
#endif
// Both sides evaluated per vertex: Gouraud's double-sided surfaces.
#define SL_BOTH_SIDES (SL_DOUBLE_SIDED == 1 && SL_ONE_PER_TRIANGLE == 0)

#ifdef SL_VERTEX_STAGE
// A vertex stage includes lighting.glsl before this file: shadeLecture() (shade(), clamped) and, for a
// textured surface, its two parts, shadeLectureTermsOfC() and shadeLectureSpecular().

#if SL_TEXTURED
SL_HANDED_ON out vec3 v_termsOfC;  // k_a A C + sum v L_l k_d C (N.I), with the material's C
SL_HANDED_ON out vec3 v_specular;  // sum v L_l k_s S spec_l
#else
SL_HANDED_ON out vec3 v_color;
#endif
#if SL_BOTH_SIDES && SL_TEXTURED
SL_HANDED_ON out vec3 v_termsOfCBack;  // the same with -N
SL_HANDED_ON out vec3 v_specularBack;
#elif SL_BOTH_SIDES
SL_HANDED_ON out vec3 v_colorBack;
#endif

void shadeAndPass(vec3 P, vec3 N) {
#if SL_TEXTURED
    v_termsOfC = shadeLectureTermsOfC(P, N);
    v_specular = shadeLectureSpecular(P, N);
    passObjectColor();
#else
    v_color = shadeLecture(P, N);
#endif
#if SL_BOTH_SIDES && SL_TEXTURED
    v_termsOfCBack = shadeLectureTermsOfC(P, -N);
    v_specularBack = shadeLectureSpecular(P, -N);
#elif SL_BOTH_SIDES
    v_colorBack = shadeLecture(P, -N);
#endif
}

#else  // the fragment stage

#if SL_TEXTURED
SL_HANDED_ON in vec3 v_termsOfC;
SL_HANDED_ON in vec3 v_specular;
#else
SL_HANDED_ON in vec3 v_color;
#endif
#if SL_BOTH_SIDES && SL_TEXTURED
SL_HANDED_ON in vec3 v_termsOfCBack;  // the vertex stage's values with -N, for the back of the surface
SL_HANDED_ON in vec3 v_specularBack;
#elif SL_BOTH_SIDES
SL_HANDED_ON in vec3 v_colorBack;
#endif

vec3 shadedColor() {
#if SL_TEXTURED
    vec3 termsOfC = v_termsOfC, specular = v_specular;
#if SL_BOTH_SIDES
    if (!gl_FrontFacing) {  // glTF's doubleSided: the back side, lit with -N
        termsOfC = v_termsOfCBack;
        specular = v_specularBack;
    }
#endif
    return combineTerms(termsOfC, specular);
#else
    vec3 color = v_color;
#if SL_BOTH_SIDES
    if (!gl_FrontFacing) color = v_colorBack;  // glTF's doubleSided: the back side, lit with -N
#endif
    return color;
#endif
}
#endif
