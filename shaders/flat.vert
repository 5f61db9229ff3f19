// Flat shading: the colour is evaluated once per triangle, at its centroid with its face normal,
// carried by the triangle's provoking vertex (shaders/flat_inputs.glsl); every fragment of the
// triangle takes that one colour (`flat`, shaders/vertex_shading.glsl).
#define SL_ONE_PER_TRIANGLE 1
#include "lighting.glsl"
#include "values_from_blocks.glsl"
#include "instancing.glsl"
#include "flat_inputs.glsl"
#include "vertex_shading.glsl"

void main() {
    vec3 centroidWorld = (worldFromObject() * vec4(a_centroidObject, 1.0)).xyz;
    vec3 faceNrmWorld = normalize(normalToWorld(a_faceNrmObject));
    faceNrmWorld = facingNormal(faceNrmWorld, centroidWorld);  // flipped where the eye sees a double-sided back
    shadeAndPass(centroidWorld, faceNrmWorld);                 // shade() once, for the whole triangle
    gl_Position = u_clipFromWorld * (worldFromObject() * vec4(a_posObject, 1.0));
}
