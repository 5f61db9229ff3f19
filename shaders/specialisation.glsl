// What the renderer compiles each shading program for (app/render/program_cache.cpp, programDefines),
// with the defaults a program gets when a define is missing. The number of lights and each light's
// kind, attenuation and area samples are constant arrays, and the reflection model, the output
// encoding, the options and "show" are constants, so the compiler unrolls the loop over the lights
// and drops every branch that does not apply: on llvmpipe a loop over a uniform light count with
// per-light branches made Phong ~50% slower (bench/README.md). Positions, colours and material values
// stay uniforms, so dragging a slider never recompiles.
#include "shared_defs.glsl"

#ifndef SL_LIGHT_COUNT
#define SL_LIGHT_COUNT 0
#endif
#ifndef SL_AREA_LIGHTS
#define SL_AREA_LIGHTS 0  // 1 when a light is an area light (lighting.glsl then has its loop)
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
// SL_DOUBLE_SIDED = 1: a draw of a glTF material with "doubleSided": true, drawn without back-face
// culling. glTF's rule: the back of a surface is lit as a surface facing the other way, with its
// normal flipped. Each mode flips where it knows which side the eye sees: phong.frag per fragment,
// flat.vert per triangle (object_color.glsl, facingNormal); Gouraud's vertex stage evaluates both
// sides and its fragments pick one (vertex_shading.glsl).
// SL_ANISOTROPY = 1: a draw of an anisotropic material under Blinn-Phong (Ashikhmin and Shirley's
// exponent, lighting.glsl): its vertices carry a tangent (SL_ATTRIB_TANGENT). Only such draws get the
// define, and their own vertex arrays: every other draw compiles to the programs it always did.
#ifndef SL_ANISOTROPY
#define SL_ANISOTROPY 0
#endif
// SL_ENVIRONMENT = SL_ENVIRONMENT_ROOM, _SKY or _IMAGE: a draw of a material with k_r or k_t in a scene
// with an environment (mirror and glass, lighting.glsl). Only such draws get it.
#ifndef SL_ENVIRONMENT
#define SL_ENVIRONMENT SL_ENVIRONMENT_NONE
#endif
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
