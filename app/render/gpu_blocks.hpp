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
    std::int32_t kind[4];
};
static_assert(sizeof(LightGpu) == 48, "LightGpu must match std140");

struct FrameBlock {
    float clipFromWorld[16];
    float eyeWorld[4];
    float ambient[4];
    std::int32_t settings[4];  // light count, reflection model, output encoding
    LightGpu lights[SL_MAX_LIGHTS];
};
static_assert(offsetof(FrameBlock, eyeWorld) == 64, "std140 offset");
static_assert(offsetof(FrameBlock, ambient) == 80, "std140 offset");
static_assert(offsetof(FrameBlock, settings) == 96, "std140 offset");
static_assert(offsetof(FrameBlock, lights) == 112, "std140 offset");
static_assert(sizeof(FrameBlock) == 112 + 48 * SL_MAX_LIGHTS, "std140 size");

struct ObjectBlock {
    float worldFromObject[16];
    float normalWorldFromObject[16];
    float color[4];
    float specularColor[4];
    float coefficients[4];  // ka, kd, ks, ke
};
static_assert(offsetof(ObjectBlock, normalWorldFromObject) == 64, "std140 offset");
static_assert(offsetof(ObjectBlock, color) == 128, "std140 offset");
static_assert(offsetof(ObjectBlock, specularColor) == 144, "std140 offset");
static_assert(offsetof(ObjectBlock, coefficients) == 160, "std140 offset");
static_assert(sizeof(ObjectBlock) == 176, "std140 size");

}  // namespace shadelab::gpu
