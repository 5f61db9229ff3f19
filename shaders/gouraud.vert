// Gouraud shading: the colour is evaluated at each vertex with its vertex normal; the rasterizer
// interpolates the colours (perspective-correct) across the triangle.
#include "lighting.glsl"

layout(location = SL_ATTRIB_POSITION) in vec3 a_posObject;
layout(location = SL_ATTRIB_NORMAL) in vec3 a_nrmObject;

out vec3 v_color;

void main() {
    vec4 posWorld = u_worldFromObject * vec4(a_posObject, 1.0);
    vec3 nrmWorld = normalize(mat3(u_normalWorldFromObject) * a_nrmObject);
    v_color = shadeLecture(posWorld.xyz, nrmWorld);
    gl_Position = u_clipFromWorld * posWorld;
}
