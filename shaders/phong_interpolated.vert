// A speed variant of phong.vert for software rasterizers: besides position and normal it hands the
// fragment stage everything else the formula reads, computed once per vertex from the uniform blocks
// (shaders/values_from_blocks.glsl): the vectors to the eye and to each light (affine in the world
// position, so perspective-correct interpolation reproduces them) and, as `flat` inputs, the material,
// A and each light's L_l. On llvmpipe (Mesa 22.3) each scalar uniform read in a fragment shader costs
// ~35 instructions per 8 fragments, while an input costs set-up work per triangle: where triangles are
// large on screen the inputs are faster, where they are small the blocks (bench/README.md), hence the
// renderer's choice per draw (Renderer::interpolatesInputs). The viewer draws phong.vert and
// phong.frag, the files a lecturer reads and edits; a test checks that both draw the same picture.
#include "lighting.glsl"
#include "values_from_blocks.glsl"

#if SL_LIGHT_COUNT > SL_MAX_INTERPOLATED_LIGHTS
#error "phong_interpolated with more than SL_MAX_INTERPOLATED_LIGHTS lights: past GL 3.3's 60 varying components"
#endif
#define SL_INPUT_LIGHTS (SL_LIGHT_COUNT > 0 ? SL_LIGHT_COUNT : 1)  // no array of size 0

out vec3 v_toEyeWorld;                          // eye - p
out vec3 v_toLightWorld[SL_INPUT_LIGHTS];       // toLight(l, p)
flat out vec3 v_C, v_S, v_A;                    // the material's C and S, the ambient light A
flat out vec4 v_k;                              // k_a, k_d, k_s, k_e
flat out vec3 v_lightColor[SL_INPUT_LIGHTS];    // L_l

#define main phongMain
#include "phong.vert"
#undef main

void main() {
    phongMain();
    v_toEyeWorld = toEye(v_posWorld);
    Material m = objectMaterial(vec3(1.0));
    v_C = m.C, v_S = m.S, v_A = ambientLight();
    v_k = vec4(m.k_a, m.k_d, m.k_s, m.k_e);
    for (int l = 0; l < SL_LIGHT_COUNT; ++l) {
        v_toLightWorld[l] = toLight(l, v_posWorld);
        v_lightColor[l] = lightColor(l);
    }
}
