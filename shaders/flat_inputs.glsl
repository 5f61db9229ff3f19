// Flat shading's vertex attributes (FlatMesh in app/core/geometry/mesh.hpp): each triangle's provoking
// (last) vertex carries the triangle's centroid and its face normal besides its own position.
// shaders/flat_packed.vert, a faster variant, declares these three itself, unpacked from two vec4s.
#include "shared_defs.glsl"

#ifndef SL_FLAT_PACKED
layout(location = SL_ATTRIB_POSITION) in vec3 a_posObject;
layout(location = SL_ATTRIB_CENTROID) in vec3 a_centroidObject;  // the triangle's centroid
layout(location = SL_ATTRIB_NORMAL) in vec3 a_faceNrmObject;     // and its face normal
#endif
