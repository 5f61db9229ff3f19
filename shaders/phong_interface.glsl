// What phong.vert hands to phong.frag. Both include this file: the vertex stage defines
// SL_STAGE_IO as `out`, the fragment stage as `in`.
//
// SL_INTERPOLATED_INPUTS (defined by the renderer for a draw whose triangles are large on screen,
// with at most SL_MAX_INTERPOLATED_LIGHTS lights): everything the formula needs besides N is an input
// of the fragment stage rather than a uniform-block read: the vectors to the eye and to each light
// (affine in the world position, so perspective-correct interpolation reproduces them) and, as `flat`
// inputs, the per-object products k_a A C, k_e, L_l k_d C and L_l k_s S. On llvmpipe (Mesa 22.3)
// each scalar uniform read in a fragment shader costs ~35 instructions per 8 fragments (callgrind),
// while an input costs set-up work per triangle: on the 2k-triangle sphere the inputs remove 46% of
// the fragment code's instructions, on the 200k one they add 30% to the frame (bench/README.md),
// hence the choice per draw (Renderer::interpolatesInputs). Without the define the programs read the
// blocks, as flat and Gouraud do.
#include "uniforms.glsl"

#ifndef SL_LIGHT_COUNT
#define SL_LIGHT_COUNT 0
#endif
#if defined(SL_INTERPOLATED_INPUTS) && SL_LIGHT_COUNT > SL_MAX_INTERPOLATED_LIGHTS
#error "SL_INTERPOLATED_INPUTS with more than SL_MAX_INTERPOLATED_LIGHTS lights: past GL 3.3's 60 varying components"
#endif

SL_STAGE_IO vec3 v_posWorld;
SL_STAGE_IO vec3 v_nrmWorld;
#ifdef SL_INTERPOLATED_INPUTS
SL_STAGE_IO vec3 v_toEyeWorld;                           // eye - p
flat SL_STAGE_IO vec4 v_ambientTermExponent;             // rgb: k_a A C, w: k_e
#if SL_LIGHT_COUNT > 0
SL_STAGE_IO vec3 v_toLightWorld[SL_LIGHT_COUNT];         // light - p, or -direction for a directional light
flat SL_STAGE_IO vec3 v_lightDiffuse[SL_LIGHT_COUNT];    // L_l k_d C
flat SL_STAGE_IO vec3 v_lightSpecular[SL_LIGHT_COUNT];   // L_l k_s S
#endif
#endif
