// Uniform blocks shared by every program. std140; mirrored by FrameBlock and ObjectBlock in
// app/render/gpu_blocks.hpp, whose static_asserts pin every offset.
#include "shared_defs.glsl"

struct LightGpu {
    vec4 positionOrDirection;  // xyz: world-space position (point) or travel direction (directional)
    vec4 radiance;             // rgb: colour * intensity
    ivec4 kind;                // x: SL_LIGHT_*, y: SL_ATTENUATION_*
};

layout(std140) uniform FrameBlock {
    mat4 u_clipFromWorld;
    vec4 u_eyeWorld;           // xyz
    vec4 u_ambient;            // rgb: A
    ivec4 u_settings;          // x: light count, y: SL_REFLECTION_*, z: SL_ENCODING_* (the programs'
                               // specialisation, as data: for tools that read the block)
    LightGpu u_lights[SL_MAX_LIGHTS];
};

layout(std140) uniform ObjectBlock {
    mat4 u_worldFromObject;
    mat4 u_normalWorldFromObject;  // inverse transpose in the upper 3x3 (mat4 sidesteps std140's mat3 padding)
    vec4 u_color;                  // rgb: C
    vec4 u_specularColor;          // rgb: S
    vec4 u_coefficients;           // k_a, k_d, k_s, k_e
};
