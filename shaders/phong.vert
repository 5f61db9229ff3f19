// Phong shading: position and normal are interpolated; the fragment shader evaluates the colour.
#include "object_color.glsl"
#include "instancing.glsl"

layout(location = SL_ATTRIB_POSITION) in vec3 a_posObject;
layout(location = SL_ATTRIB_NORMAL) in vec3 a_nrmObject;

out vec3 v_posWorld;
out vec3 v_nrmWorld;  // not unit length once interpolated: phong.frag renormalises it
#if SL_ANISOTROPY
layout(location = SL_ATTRIB_TANGENT) in vec4 a_tanObject;
out vec4 v_tanWorld;  // xyz: the tangent (phong.frag makes it orthogonal to N again), w: the handedness
#endif

void main() {
    vec4 posWorld = worldFromObject() * vec4(a_posObject, 1.0);
    v_posWorld = posWorld.xyz;
    v_nrmWorld = normalToWorld(a_nrmObject);
#if SL_ANISOTROPY
    v_tanWorld = vec4(tangentToWorld(a_tanObject.xyz), a_tanObject.w);
#endif
    gl_Position = u_clipFromWorld * posWorld;
    passObjectColor();
}
