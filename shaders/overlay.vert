// Overlay lines drawn over the shaded surface: wireframe edges, vertex and face normals, light markers.
// Unlit: the colour is a uniform. Normal lines are built here, in world space, so that a non-uniform
// scale tilts them the way it tilts the shading normals (the inverse transpose), and their length does
// not depend on the object's scale.
#include "uniforms.glsl"

layout(location = SL_ATTRIB_POSITION) in vec3 a_posObject;
// Zero for a point on the surface (wireframe, normal bases, markers); the unit object-space normal for
// the tip of a normal line, which is moved u_normalLength world units along the world-space normal.
layout(location = SL_ATTRIB_NORMAL) in vec3 a_nrmObject;

uniform float u_normalLength;  // world units
uniform float u_depthBias;     // NDC depth units pulled towards the viewer, so lines win over the surface
uniform float u_tangentTips;   // 1: the tips are tangents (the tangents overlay), which go with the transform itself

void main() {
    vec3 posWorld = (u_worldFromObject * vec4(a_posObject, 1.0)).xyz;
    if (dot(a_nrmObject, a_nrmObject) > 0.25)
        posWorld += u_normalLength * normalize(u_tangentTips > 0.5 ? mat3(u_worldFromObject) * a_nrmObject
                                                                   : mat3(u_normalWorldFromObject) * a_nrmObject);
    gl_Position = u_clipFromWorld * vec4(posWorld, 1.0);
    gl_Position.z -= u_depthBias * gl_Position.w;
}
