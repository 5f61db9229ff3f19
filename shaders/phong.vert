// Phong shading: position and normal are interpolated; the fragment shader evaluates the colour.
#include "object_color.glsl"
#include "instancing.glsl"
#include "tangent.glsl"

layout(location = SL_ATTRIB_POSITION) in vec3 a_posObject;
layout(location = SL_ATTRIB_NORMAL) in vec3 a_nrmObject;

out vec3 v_posWorld;
out vec3 v_nrmWorld;  // not unit length once interpolated: phong.frag renormalises it

void main() {
    vec4 posWorld = worldFromObject() * vec4(a_posObject, 1.0);
    v_posWorld = posWorld.xyz;
    v_nrmWorld = normalToWorld(a_nrmObject);
    gl_Position = u_clipFromWorld * posWorld;
    passObjectColor();  // where C varies: its texture coordinates and vertex colour (object_color.glsl)
    passTangent();      // anisotropic reflection: the tangent (tangent.glsl)
}
