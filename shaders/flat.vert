// Flat shading: the colour is evaluated once per triangle, at its centroid with its face normal.
// Only the provoking (last) vertex of each triangle carries those (see FlatMesh in app/core/mesh.hpp);
// `flat` makes the whole triangle take that vertex's colour.
#include "lighting.glsl"

layout(location = SL_ATTRIB_POSITION) in vec3 a_posObject;
layout(location = SL_ATTRIB_NORMAL) in vec3 a_nrmObject;
layout(location = SL_ATTRIB_CENTROID) in vec3 a_centroidObject;

flat out vec3 v_color;

void main() {
    vec3 centroidWorld = (u_worldFromObject * vec4(a_centroidObject, 1.0)).xyz;
    vec3 faceNrmWorld = normalize(mat3(u_normalWorldFromObject) * a_nrmObject);
    v_color = shadeLecture(centroidWorld, faceNrmWorld);
    gl_Position = u_clipFromWorld * (u_worldFromObject * vec4(a_posObject, 1.0));
}
