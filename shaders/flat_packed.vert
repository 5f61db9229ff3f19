// flat.vert with its nine floats per vertex in two vec4s instead of three vec3s: a speed variant for
// software rasterizers, which fetch each attribute of each vertex on its own (llvmpipe: two fetches
// instead of three take ~7% off a flat frame at 200k triangles, bench/README.md). The renderer uses
// it where RendererOptions::packedFlatVertices asks (headless frames); the viewer, the docs and the
// probe use flat.vert, and a test checks that both draw the same pixels.
//
// The packing (MeshCache::gpuMesh): position xyz and centroid x; centroid yz, face normal x, and face
// normal y plus SL_FLAT_NORMAL_Z_NEGATIVE where its z is negative (z itself comes from the unit length).
#include "shared_defs.glsl"

#define SL_FLAT_PACKED 1  // flat_inputs.glsl: these declarations instead of its three attributes
layout(location = SL_ATTRIB_POSITION) in vec4 a_posCentroidXObject;
layout(location = SL_ATTRIB_CENTROID) in vec4 a_centroidYZNormalXYObject;
vec3 a_posObject, a_centroidObject, a_faceNrmObject;  // what flat.vert reads, unpacked below

#define main flatMain
#include "flat.vert"
#undef main

void main() {
    a_posObject = a_posCentroidXObject.xyz;
    a_centroidObject = vec3(a_posCentroidXObject.w, a_centroidYZNormalXYObject.xy);
    float nx = a_centroidYZNormalXYObject.z, ny = a_centroidYZNormalXYObject.w, zSign = 1.0;
    if (ny > 0.5 * SL_FLAT_NORMAL_Z_NEGATIVE) {
        ny -= SL_FLAT_NORMAL_Z_NEGATIVE;
        zSign = -1.0;
    }
    a_faceNrmObject = vec3(nx, ny, zSign * sqrt(max(1.0 - nx * nx - ny * ny, 0.0)));
    flatMain();
}
