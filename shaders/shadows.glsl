// The occlusion term v_l of shaders/lighting.glsl: how much of light l reaches the point, from the
// light's shadow maps (SL_SHADOWS = 1; render/cpu/shadow_projection.hpp says what each layer sees). Every
// point, spot and directional light's layers are in one depth texture array, every area light's in a
// second (area maps have their own size); light l's first layer is c_shadowLayer[l], so a loop over
// the lights needs no array of samplers.
//   point        six cube faces, picked by the major axis of p - light
//   spot         one perspective view down its axis
//   directional  one orthographic view
//   area         one perspective view per sample
uniform sampler2DArrayShadow u_shadowMaps;      // texture unit SL_TEXTURE_SHADOW_MAPS
uniform sampler2DArrayShadow u_areaShadowMaps;  // texture unit SL_TEXTURE_AREA_SHADOW_MAPS

#ifndef SL_SHADOW_LAYERS
#define SL_SHADOW_LAYERS 0
#endif
const int c_shadowLayer[] = int[](SL_SHADOW_LAYERS);  // light l's first layer in its array

// Shadow-map lookups compare depths in hardware (GL_COMPARE_REF_TO_TEXTURE, bilinear: 2 x 2 texels
// per lookup); percentage-closer filtering averages (2 SL_SHADOW_PCF + 1)^2 of them a texel apart.
// SL_SHADOW_PCF is the scene's radius ("shadow_settings": "pcf"); the viewer's moving frames on a
// software rasterizer (dragging, an animation) are compiled with 0, one lookup, and the still view
// with the scene's again (Renderer::setMovingFrames). Returns the visible fraction in [0, 1].
float shadowLookup(vec2 st, float layer, float depth, float texel) {
    float sum = 0.0;
    for (int y = -SL_SHADOW_PCF; y <= SL_SHADOW_PCF; ++y)
        for (int x = -SL_SHADOW_PCF; x <= SL_SHADOW_PCF; ++x)
            sum += texture(u_shadowMaps, vec4(st + vec2(x, y) * texel, layer, depth));
    return sum / float((2 * SL_SHADOW_PCF + 1) * (2 * SL_SHADOW_PCF + 1));
}

// Normal-offset bias: the point looked up moves along its normal by u_shadowSettings.x texels (a
// texel's world size grows with the distance from a point, spot or area light), so a lit surface does
// not shadow itself; the depth pass adds a slope-scaled offset (ShadowSettings::depthBias).
float pointVisibility(int l, vec3 posWorld, vec3 N) {
    vec4 sh = u_lights[l].shadow;
    vec3 d = posWorld - u_lights[l].positionOrDirection.xyz;
    d += N * (u_shadowSettings.x * sh.x * length(d));
    vec3 a = abs(d);
    float ma, face;
    vec2 uv;
    if (a.x >= a.y && a.x >= a.z) {
        ma = a.x, uv = d.yz, face = d.x >= 0.0 ? 0.0 : 1.0;
    } else if (a.y >= a.z) {
        ma = a.y, uv = d.zx, face = d.y >= 0.0 ? 2.0 : 3.0;
    } else {
        ma = a.z, uv = d.xy, face = d.z >= 0.0 ? 4.0 : 5.0;
    }
    vec2 st = 0.5 + 0.5 * uv / (ma * sh.w);
    return shadowLookup(st, float(c_shadowLayer[l]) + face, sh.y - sh.z / ma, u_lights[l].falloff.z);
}

float spotVisibility(int l, vec3 posWorld, vec3 N) {
    float distance = length(posWorld - u_lights[l].positionOrDirection.xyz);
    vec3 pos = posWorld + N * (u_shadowSettings.x * u_lights[l].shadow.x * distance);
    vec4 clip = u_lights[l].shadowClipFromWorld * vec4(pos, 1.0);
    vec3 c = clip.xyz / clip.w * 0.5 + 0.5;
    return shadowLookup(c.xy, float(c_shadowLayer[l]), c.z, u_lights[l].falloff.z);
}

float directionalVisibility(int l, vec3 posWorld, vec3 N) {
    vec3 pos = posWorld + N * (u_shadowSettings.x * u_lights[l].shadow.x);
    vec3 c = (u_lights[l].shadowClipFromWorld * vec4(pos, 1.0)).xyz * 0.5 + 0.5;
    return shadowLookup(c.xy, float(c_shadowLayer[l]), c.z, u_lights[l].falloff.z);
}

// v_l for a point, spot or directional light.
float visibility(int l, vec3 posWorld, vec3 N) {
    if (c_lightKind[l] == SL_LIGHT_DIRECTIONAL) return directionalVisibility(l, posWorld, N);
    if (c_lightKind[l] == SL_LIGHT_SPOT) return spotVisibility(l, posWorld, N);
    return pointVisibility(l, posWorld, N);
}

// v for sample `sampleIndex` of area light l, at offset ab of the rectangle: that sample's view is the
// centre's (clipP, of the point, clipN of its normal) moved by the edges' clip-space images
// (render/cpu/shadow_projection.hpp).
float areaSampleVisibility(int l, vec2 ab, int sampleIndex, vec4 clipP, vec4 clipN) {
    vec4 clip = clipP - ab.x * u_lights[l].shadowU - ab.y * u_lights[l].shadowV;
    clip += clipN * (u_shadowSettings.x * u_lights[l].shadow.x * clip.w);
    vec3 c = clip.xyz / clip.w * 0.5 + 0.5;
    return texture(u_areaShadowMaps, vec4(c.xy, float(c_shadowLayer[l] + sampleIndex), c.z));
}
