// Where an object's vertices go: the ObjectBlock's object-to-world transform, and with SL_INSTANCED
// (a glTF node drawn once per EXT_mesh_gpu_instancing instance, all in one instanced draw) each
// instance's own transform before it, read once per instance from the attributes at
// SL_ATTRIB_INSTANCE. Vertex stages only.
#include "uniforms.glsl"

#ifndef SL_INSTANCED
#define SL_INSTANCED 0
#endif

#if SL_INSTANCED
layout(location = SL_ATTRIB_INSTANCE) in mat4 a_instanceFromPart;
mat4 worldFromObject() { return u_worldFromObject * a_instanceFromPart; }
// A normal of the part: through the instance's inverse transpose (per vertex here) and renormalised,
// as if the instance had been baked into the mesh, then through the object's.
vec3 normalToWorld(vec3 nrmObject) {
    vec3 nrmInstance = normalize(transpose(inverse(mat3(a_instanceFromPart))) * nrmObject);
    return mat3(u_normalWorldFromObject) * nrmInstance;
}
#else
mat4 worldFromObject() { return u_worldFromObject; }
// A normal in world space: the inverse transpose of the object's transform (not renormalised here).
vec3 normalToWorld(vec3 nrmObject) { return mat3(u_normalWorldFromObject) * nrmObject; }
#endif
// A tangent lies in the surface: it goes with the transform itself, not its inverse transpose.
vec3 tangentToWorld(vec3 tanObject) { return mat3(worldFromObject()) * tanObject; }
