// Flat shading: the colour is evaluated once per triangle, at its centroid with its face normal.
// Each triangle's provoking (last) vertex carries those (FlatMesh in app/core/geometry/mesh.hpp); `flat` makes
// the whole triangle take that vertex's colour.
#include "lighting.glsl"
#include "values_from_blocks.glsl"
#include "object_color.glsl"
#include "instancing.glsl"

#ifndef SL_FLAT_PACKED  // shaders/flat_packed.vert, a faster variant, declares these itself
layout(location = SL_ATTRIB_POSITION) in vec3 a_posObject;
layout(location = SL_ATTRIB_CENTROID) in vec3 a_centroidObject;  // the triangle's centroid
layout(location = SL_ATTRIB_NORMAL) in vec3 a_faceNrmObject;     // and its face normal
#endif

#if SL_TEXTURED
// C varies across the triangle (the texture is read per fragment): the formula's two parts, once per
// triangle, combined in flat.frag.
flat out vec3 v_termsOfC;  // k_a A C + sum v L_l k_d C (N.I), with the material's C
flat out vec3 v_specular;  // sum v L_l k_s S spec_l
#else
flat out vec3 v_color;
#endif

void main() {
    vec3 centroidWorld = (worldFromObject() * vec4(a_centroidObject, 1.0)).xyz;
    vec3 faceNrmWorld = normalize(normalToWorld(a_faceNrmObject));
#if SL_DOUBLE_SIDED
    // glTF's doubleSided: the eye sees the triangle's back when it is behind the triangle's plane
    // (for a planar triangle, exactly what gl_FrontFacing says); the back is lit with -N.
    if (dot(faceNrmWorld, u_eyeWorld.xyz - centroidWorld) < 0.0) faceNrmWorld = -faceNrmWorld;
#endif
#if SL_TEXTURED
    v_termsOfC = shadeLectureTermsOfC(centroidWorld, faceNrmWorld);
    v_specular = shadeLectureSpecular(centroidWorld, faceNrmWorld);
    passObjectColor();
#else
    v_color = shadeLecture(centroidWorld, faceNrmWorld);
#endif
    gl_Position = u_clipFromWorld * (worldFromObject() * vec4(a_posObject, 1.0));
}
