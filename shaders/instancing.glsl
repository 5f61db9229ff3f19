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
// Normals take the inverse transpose of the whole transform, per vertex here (an instance's own).
mat3 normalWorldFromObject() { return transpose(inverse(mat3(worldFromObject()))); }
#else
mat4 worldFromObject() { return u_worldFromObject; }
mat3 normalWorldFromObject() { return mat3(u_normalWorldFromObject); }
#endif
