// Flat shading: the colour is evaluated once per triangle, at its centroid with its face normal.
// Only the provoking (last) vertex of each triangle carries those (see FlatMesh in app/core/mesh.hpp);
// `flat` makes the whole triangle take that vertex's colour.
#include "lighting.glsl"
#include "object_color.glsl"
#include "instancing.glsl"

// Nine floats in two vec4s (Renderer::gpuMesh): llvmpipe fetches each attribute of each vertex on its
// own, and two fetches cost less than three. The face normal's z comes from its unit length, its sign
// from y, which carries SL_FLAT_NORMAL_Z_NEGATIVE where z < 0.
layout(location = SL_ATTRIB_POSITION) in vec4 a_posCentroidXObject;
layout(location = SL_ATTRIB_FLAT_FACE) in vec4 a_centroidYZNormalXYObject;

#if SL_TEXTURED
// C varies across the triangle (the texture is read per fragment): the formula's two parts, once per
// triangle, combined in flat.frag.
flat out vec3 v_termsOfC;  // k_a A C + sum v L_l k_d C (N.I), with the material's C
flat out vec3 v_specular;  // sum v L_l k_s S spec_l
#else
flat out vec3 v_color;
#endif

void main() {
    vec3 posObject = a_posCentroidXObject.xyz;
    vec3 centroidObject = vec3(a_posCentroidXObject.w, a_centroidYZNormalXYObject.xy);
    float nx = a_centroidYZNormalXYObject.z, ny = a_centroidYZNormalXYObject.w, zSign = 1.0;
    if (ny > 0.5 * SL_FLAT_NORMAL_Z_NEGATIVE) {
        ny -= SL_FLAT_NORMAL_Z_NEGATIVE;
        zSign = -1.0;
    }
    vec3 faceNrmObject = vec3(nx, ny, zSign * sqrt(max(1.0 - nx * nx - ny * ny, 0.0)));
    vec3 centroidWorld = (worldFromObject() * vec4(centroidObject, 1.0)).xyz;
    vec3 faceNrmWorld = normalize(normalToWorld(faceNrmObject));
#if SL_TEXTURED
    v_termsOfC = shadeLectureTermsOfC(centroidWorld, faceNrmWorld);
    v_specular = shadeLectureSpecular(centroidWorld, faceNrmWorld);
    passObjectColor();
#else
    v_color = shadeLecture(centroidWorld, faceNrmWorld, vec3(1.0));
#endif
    gl_Position = u_clipFromWorld * (worldFromObject() * vec4(posObject, 1.0));
}
