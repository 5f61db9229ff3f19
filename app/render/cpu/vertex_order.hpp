#pragma once
// Triangle and vertex order for the GL driver's post-transform vertex cache.
//
// A vertex shader runs once per vertex the driver cannot find in its cache of recently shaded
// vertices, so the same mesh in another order can cost up to twice the vertex-shader runs. Mesa's
// draw module (llvmpipe, and every driver without hardware vertex processing) cuts an indexed draw into
// segments of 1023 indices (341 triangles) and, inside a segment, keeps a vertex found by a
// direct-mapped table of 256 entries (index mod 256); the table starts empty in every segment. A UV
// sphere in row order, as ../shared/bench draws it, shades ~1 vertex per triangle that way: each
// segment is one thin band of the sphere. Compact patches shade ~0.6, and the flat mesh (a provoking
// vertex per triangle, see FlatMesh) goes from ~1.5 to ~1.1 (bench/README.md, "Vertex order").
//
// Only the order changes: every triangle keeps its corners in the same rotation (winding and
// provoking vertex), every vertex its attributes, every MeshPart its index range and its triangles.
#include "core/geometry/mesh.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace shadelab {

// The order: Tipsify (Sander, Nehab and Barczak, "Fast triangle reordering for vertex locality and
// reduced overdraw", SIGGRAPH 2007) on each mesh part, which fans around one vertex at a time and moves
// on to the neighbour that stays longest in a FIFO cache, linear in the triangle count (Debian's
// meshoptimizer, meshopt_optimizeVertexCacheFifo; its other order, meshopt_optimizeVertexCache, makes
// ~11% more runs in this model: bench/README.md); then vertices numbered by first use, so that
// consecutive new vertices land in consecutive slots of the table.

// `mesh` with the triangles of each part reordered for the vertex cache and its vertices renumbered
// by first use. Draws the same picture (a closed mesh has no two triangles on one pixel at one depth).
Mesh orderedForVertexCache(const Mesh& mesh);

// The flat-shading vertices of a mesh already ordered by orderedForVertexCache(): makeFlatMesh(), whose
// added provoking vertices go at the end, renumbered by first use so that they sit beside their
// triangles' other corners.
FlatMesh makeOrderedFlatMesh(const Mesh& orderedMesh);

// The vertex-shader runs Mesa's draw module makes for a triangle list with these indices: the model
// above (segments of `segmentIndices`, a direct-mapped table of `tableSize` per segment). For tests: the
// driver is the authority, this only mirrors it.
std::size_t vertexShaderRuns(const std::vector<std::uint32_t>& indices, std::size_t segmentIndices = 1023,
                             std::size_t tableSize = 256);

}  // namespace shadelab
