// env(d): the environment mirrors and glass see, as a function of a unit direction d in world space
// (core/shading/environment.cpp has the same functions; the constants are shared_defs.glsl's).
// SL_ENVIRONMENT says which: the procedural room or sky, or an equirectangular image. Included by
// lighting.glsl (the mirror and glass term) and background.frag (the background).
#include "shared_defs.glsl"

// A room [-1, 1]^3 around the scene: a red wall at +x, a green one at -x, a blue one behind (+z), a
// warm white one ahead (-z), a light ceiling and a checker floor. Faces meet over SL_ROOM_EDGE, the
// tiles' edges are SL_ROOM_TILE_EDGE wide: no jumps, so a reflected direction a little off gives a
// colour a little off.
float tileStripe(float x) { return smoothstep(-SL_ROOM_TILE_EDGE, SL_ROOM_TILE_EDGE, abs(fract(x) - 0.5) - 0.25); }
vec3 roomRadiance(vec3 d) {
    vec3 a = abs(d);
    vec3 wallX = d.x > 0.0 ? vec3(SL_ROOM_WALL_RIGHT) : vec3(SL_ROOM_WALL_LEFT);
    vec3 wallZ = d.z > 0.0 ? vec3(SL_ROOM_WALL_BACK) : vec3(SL_ROOM_WALL_FRONT);
    vec3 walls = mix(wallZ, wallX, smoothstep(-SL_ROOM_EDGE, SL_ROOM_EDGE, a.x - a.z));
    float reach = SL_ROOM_TILES / max(a.y, 1e-4);  // where d meets the floor y = -1, in checker periods
    float sx = tileStripe(d.x * reach), sz = tileStripe(d.z * reach);
    vec3 floorColor = mix(vec3(SL_ROOM_TILE_DARK), vec3(SL_ROOM_TILE_LIGHT), sx + sz - 2.0 * sx * sz);
    vec3 below = d.y < 0.0 ? floorColor : vec3(SL_ROOM_CEILING);
    return mix(walls, below, smoothstep(-SL_ROOM_EDGE, SL_ROOM_EDGE, a.y - max(a.x, a.z)));
}

// A sky from the horizon's pale blue to the zenith's deep one over a dark ground, and a sun.
vec3 skyRadiance(vec3 d) {
    vec3 sky = mix(vec3(SL_SKY_HORIZON), vec3(SL_SKY_ZENITH), smoothstep(0.0, 1.0, d.y));
    vec3 ground = mix(0.5 * vec3(SL_SKY_HORIZON), vec3(SL_SKY_GROUND), smoothstep(0.0, 0.2, -d.y));
    vec3 around = mix(ground, sky, smoothstep(-0.01, 0.01, d.y));
    float sun = smoothstep(SL_SKY_SUN_OUTER_COS, SL_SKY_SUN_INNER_COS, dot(d, normalize(vec3(SL_SKY_SUN_DIRECTION))));
    return around + sun * vec3(SL_SKY_SUN);
}

#if SL_ENVIRONMENT == SL_ENVIRONMENT_IMAGE
// An equirectangular image (linear RGB floats): longitude u from atan(d.x, -d.z), latitude v from the
// zenith; bilinear between texel centres, wrapping in u, clamped in v. texelFetch and the weights
// here, not the sampler's filtering, so that core/shading/environment.cpp reads the same texels.
uniform sampler2D u_environmentMap;  // on unit SL_TEXTURE_ENVIRONMENT
vec3 imageTexel(ivec2 size, int i, int j) {
    i = ((i % size.x) + size.x) % size.x;
    j = clamp(j, 0, size.y - 1);
    return texelFetch(u_environmentMap, ivec2(i, j), 0).rgb;
}
vec3 imageRadiance(vec3 d) {
    ivec2 size = textureSize(u_environmentMap, 0);
    float u = 0.5 + atan(d.x, -d.z) / (2.0 * 3.14159265358979);
    float v = acos(clamp(d.y, -1.0, 1.0)) / 3.14159265358979;
    vec2 xy = vec2(u * float(size.x), v * float(size.y)) - 0.5;
    vec2 xy0 = floor(xy), f = xy - xy0;
    int i = int(xy0.x), j = int(xy0.y);
    return mix(mix(imageTexel(size, i, j), imageTexel(size, i + 1, j), f.x),
               mix(imageTexel(size, i, j + 1), imageTexel(size, i + 1, j + 1), f.x), f.y);
}
#endif

// env(d), unit d.
vec3 environment(vec3 d) {
#if SL_ENVIRONMENT == SL_ENVIRONMENT_ROOM
    return roomRadiance(d);
#elif SL_ENVIRONMENT == SL_ENVIRONMENT_SKY
    return skyRadiance(d);
#elif SL_ENVIRONMENT == SL_ENVIRONMENT_IMAGE
    return imageRadiance(d);
#else
    return vec3(0.0);
#endif
}
