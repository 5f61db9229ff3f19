// The output encoding, shared by the shading programs and shaders/resolve.frag.
#include "shared_defs.glsl"

#ifndef SL_ENCODING
#define SL_ENCODING SL_ENCODING_LINEAR
#endif
#ifndef SL_ACCUMULATE
#define SL_ACCUMULATE 0
#endif

// What the framebuffer gets: the value itself, or its sRGB encoding when the scene asks for it. A
// progressive pass (SL_ACCUMULATE) writes linear values; the resolve pass encodes their mean.
vec3 encodeOutput(vec3 linear) {
#if SL_ENCODING == SL_ENCODING_SRGB && !SL_ACCUMULATE
    vec3 lo = 12.92 * linear;
    vec3 hi = 1.055 * pow(linear, vec3(1.0 / 2.4)) - 0.055;
    return mix(hi, lo, vec3(lessThanEqual(linear, vec3(0.0031308))));
#else
    return linear;
#endif
}
