// Uniform blocks shared by every program. std140; mirrored by FrameBlock and ObjectBlock in
// app/render/gpu_blocks.hpp, whose static_asserts pin every offset.
#include "shared_defs.glsl"

struct LightGpu {
    vec4 positionOrDirection;  // xyz: world-space position (point, area centre) or travel direction (directional)
    vec4 radiance;             // rgb: colour * intensity
    ivec4 kind;                // x: SL_LIGHT_*, y: SL_ATTENUATION_*, z, w: area samples nx, ny
    vec4 falloff;              // x: 1 / range^2 (windowed inverse-square), y: 1 for a two-sided area light,
                               // z: 1 / shadow-map size (a texel in texture coordinates),
                               // w: spot lights: 1 / (cos(inner) - cos(outer)) (at most 1000)
    vec4 areaU;                // xyz: the area light's edge along its width (length = width)
    vec4 areaV;                // xyz: the edge along its height
    vec4 areaNormal;           // xyz: unit normal of the emitting side
    // Shadows (render/cpu/shadow_projection.hpp). Directional: the orthographic map. Area: the map of the
    // rectangle's centre; sample (a, b)'s map is shadowClipFromWorld * p - a shadowU - b shadowV.
    mat4 shadowClipFromWorld;
    vec4 shadowU;              // shadowClipFromWorld * vec4(areaU, 0)
    vec4 shadowV;              // shadowClipFromWorld * vec4(areaV, 0)
    vec4 shadow;               // x: a texel's world size (per unit of distance for point and area lights);
                               // point cube faces: y - z / distance is the stored depth, w: tan(half fov)
    vec4 spot;                 // spot lights: xyz the unit axis (the way the light points), w: cos(outer)
};

layout(std140) uniform FrameBlock {
    mat4 u_clipFromWorld;
    vec4 u_eyeWorld;           // xyz
    vec4 u_ambient;            // rgb: A
    ivec4 u_settings;          // x: light count, y: SL_REFLECTION_*, z: SL_ENCODING_* (the programs'
                               // specialisation, as data: for tools that read the block)
    LightGpu u_lights[SL_MAX_LIGHTS];
    vec4 u_shadowSettings;     // x: normal bias, in shadow-map texels
    vec4 u_modelSettings;      // x: ior = eta2 / eta1 (Fresnel), y: R0 = ((1 - ior) / (1 + ior))^2
    ivec4 u_areaPass;          // progressive sampling (SL_ACCUMULATE): this pass's first area-light
                               // sample (x: i, y: j) and the stride between samples (z: along i, w: j)
};

layout(std140) uniform ObjectBlock {
    mat4 u_worldFromObject;
    mat4 u_normalWorldFromObject;  // inverse transpose in the upper 3x3 (mat4 sidesteps std140's mat3 padding)
    vec4 u_color;                  // rgb: C; a: its alpha (glTF's base colour factor)
    vec4 u_specularColor;          // rgb: S
    vec4 u_coefficients;           // k_a, k_d, k_s, k_e
    // What a glTF material adds (shaders/object_color.glsl); u_color.a is the base colour factor's alpha.
    vec4 u_emissive;                         // rgb: E's factor (emissiveFactor x emissive strength)
    vec4 u_alphaCutoff;                      // x: MASK's cutoff
    vec4 u_anisotropy;                       // x: k_t, y: k_b (SL_ANISOTROPY: lighting.glsl, lobeExponent)
    vec4 u_mirrorGlass;                      // x: k_r, y: k_t (SL_ENVIRONMENT: lighting.glsl, mirrorAndGlass)
};
