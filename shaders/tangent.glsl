// Anisotropic reflection's tangent (SL_ANISOTROPY, lighting.glsl's lobeExponent): Phong's vertex
// stage hands it to the fragments in world space, with its handedness (passTangent). Every other draw
// has no tangent, and passTangent() does nothing. (Flat and Gouraud read the attribute where they
// shade, in the vertex stage: lighting.glsl, tangentHere.)
#include "specialisation.glsl"
#include "instancing.glsl"

#if SL_ANISOTROPY
layout(location = SL_ATTRIB_TANGENT) in vec4 a_tanObject;
out vec4 v_tanWorld;  // xyz: the tangent (made orthogonal to N again where shaded), w: the handedness
void passTangent() { v_tanWorld = vec4(tangentToWorld(a_tanObject.xyz), a_tanObject.w); }
#else
void passTangent() {}
#endif
