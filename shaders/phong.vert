// Phong shading: position and normal are interpolated; the fragment shader evaluates the colour.
#define SL_STAGE_IO out
#include "phong_interface.glsl"
#include "object_color.glsl"
#include "instancing.glsl"

layout(location = SL_ATTRIB_POSITION) in vec3 a_posObject;
layout(location = SL_ATTRIB_NORMAL) in vec3 a_nrmObject;

void main() {
    vec4 posWorld = worldFromObject() * vec4(a_posObject, 1.0);
    v_posWorld = posWorld.xyz;
    v_nrmWorld = normalToWorld(a_nrmObject);
    gl_Position = u_clipFromWorld * posWorld;
    passObjectColor();
#ifdef SL_INTERPOLATED_INPUTS
    v_toEyeWorld = u_eyeWorld.xyz - posWorld.xyz;
    v_ambientTermExponent = vec4(u_ambientTerm.rgb, u_coefficients.w);
#if SL_LIGHT_COUNT > 0
    for (int l = 0; l < SL_LIGHT_COUNT; ++l) {
        vec3 p = u_lights[l].positionOrDirection.xyz;
        v_toLightWorld[l] = u_lights[l].kind.x == SL_LIGHT_DIRECTIONAL ? -p : p - posWorld.xyz;
        v_lightDiffuse[l] = u_lightDiffuse[l].rgb;
        v_lightSpecular[l] = u_lightSpecular[l].rgb;
    }
#endif
#endif
}
