#pragma once
// C++ mirrors of the std140 uniform blocks in shaders/uniforms.glsl. The static_asserts pin every
// offset to std140's rules (vec4 = 16 bytes, mat4 = 64, array elements padded to 16), so a change on
// one side that is not made on the other fails to compile.
#include "../../shaders/shared_defs.glsl"

#include <cstddef>
#include <cstdint>

namespace shadelab::gpu {

struct LightGpu {
    float positionOrDirection[4];
    float radiance[4];
    std::int32_t kind[4];  // kind, attenuation, area samples nx, ny
    float falloff[4];      // 1 / range^2, two-sided, 1 / shadow-map size, spot: 1 / (cos inner - cos outer)
    float areaU[4];
    float areaV[4];
    float areaNormal[4];
    float shadowClipFromWorld[16];
    float shadowU[4];
    float shadowV[4];
    float shadow[4];  // texel world size, depth = y - z / distance, tan(half fov)
    float spot[4];    // spot: unit axis, cos outer
};
static_assert(offsetof(LightGpu, falloff) == 48, "std140 offset");
static_assert(offsetof(LightGpu, shadowClipFromWorld) == 112, "std140 offset");
static_assert(offsetof(LightGpu, shadow) == 208, "std140 offset");
static_assert(offsetof(LightGpu, spot) == 224, "std140 offset");
static_assert(sizeof(LightGpu) == 240, "LightGpu must match std140");

struct FrameBlock {
    float clipFromWorld[16];
    float eyeWorld[4];
    float ambient[4];
    std::int32_t settings[4];  // light count, reflection model, output encoding
    LightGpu lights[SL_MAX_LIGHTS];
    float shadowSettings[4];   // normal bias (texels)
    float modelSettings[4];    // ior, R0
    std::int32_t areaPass[4];  // progressive sampling: first sample (i, j), stride (i, j)
};
static_assert(offsetof(FrameBlock, eyeWorld) == 64, "std140 offset");
static_assert(offsetof(FrameBlock, ambient) == 80, "std140 offset");
static_assert(offsetof(FrameBlock, settings) == 96, "std140 offset");
static_assert(offsetof(FrameBlock, lights) == 112, "std140 offset");
static_assert(offsetof(FrameBlock, shadowSettings) == 112 + 240 * SL_MAX_LIGHTS, "std140 offset");
static_assert(offsetof(FrameBlock, modelSettings) == 128 + 240 * SL_MAX_LIGHTS, "std140 offset");
static_assert(offsetof(FrameBlock, areaPass) == 144 + 240 * SL_MAX_LIGHTS, "std140 offset");
static_assert(sizeof(FrameBlock) == 160 + 240 * SL_MAX_LIGHTS, "std140 size");

struct ObjectBlock {
    float worldFromObject[16];
    float normalWorldFromObject[16];
    float color[4];
    float specularColor[4];
    float coefficients[4];  // ka, kd, ks, ke
    float emissive[4];      // E's factor
    float alphaCutoff[4];   // MASK's cutoff
    float anisotropy[4];    // k_t, k_b (SL_ANISOTROPY)
    float mirrorGlass[4];   // k_r, k_t (SL_ENVIRONMENT)
};
static_assert(offsetof(ObjectBlock, normalWorldFromObject) == 64, "std140 offset");
static_assert(offsetof(ObjectBlock, color) == 128, "std140 offset");
static_assert(offsetof(ObjectBlock, specularColor) == 144, "std140 offset");
static_assert(offsetof(ObjectBlock, coefficients) == 160, "std140 offset");
static_assert(offsetof(ObjectBlock, emissive) == 176, "std140 offset");
static_assert(offsetof(ObjectBlock, alphaCutoff) == 192, "std140 offset");
static_assert(offsetof(ObjectBlock, anisotropy) == 208, "std140 offset");
static_assert(offsetof(ObjectBlock, mirrorGlass) == 224, "std140 offset");
static_assert(sizeof(ObjectBlock) == 240, "std140 size");

}  // namespace shadelab::gpu
