// Gouraud shading: the colour is evaluated at each vertex with its vertex normal; the rasterizer
// interpolates the colours (perspective-correct) across the triangle (shaders/vertex_shading.glsl).
#include "lighting.glsl"
#include "values_from_blocks.glsl"
#include "instancing.glsl"
#include "vertex_shading.glsl"

layout(location = SL_ATTRIB_POSITION) in vec3 a_posObject;
layout(location = SL_ATTRIB_NORMAL) in vec3 a_nrmObject;

void main() {
    vec4 posWorld = worldFromObject() * vec4(a_posObject, 1.0);
    vec3 nrmWorld = normalize(normalToWorld(a_nrmObject));
    shadeAndPass(posWorld.xyz, nrmWorld);  // shade() at this vertex, interpolated across the triangle
    gl_Position = u_clipFromWorld * posWorld;
}
