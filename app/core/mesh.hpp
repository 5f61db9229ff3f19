#pragma once
// Triangle meshes in object space, and the procedural shapes of the scene format.
// All meshes are indexed triangle lists, counter-clockwise seen from outside, with unit vertex normals.
#include "core/scene.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace shadelab {

// A run of triangles with a colour of its own (a glTF primitive's base colour factor). The scene's
// material colour overrides it when the scene sets one.
struct MeshPart {
    std::uint32_t firstIndex = 0;
    std::uint32_t indexCount = 0;
    bool hasBaseColor = false;
    glm::vec3 baseColor{1.0f};
};

struct Mesh {
    std::vector<glm::vec3> positions;   // object space
    std::vector<glm::vec3> normals;     // object space, unit length, one per position
    std::vector<std::uint32_t> indices; // three per triangle, counter-clockwise from outside
    std::vector<MeshPart> parts;        // empty: the whole mesh is one part with the scene's colour

    std::size_t triangleCount() const { return indices.size() / 3; }
};

// `v` scaled to unit length, or `fallback` when that is not possible (zero, not finite, or so small
// that its direction is lost to rounding). Rescales by the largest component first, so huge and
// tiny (denormal) vectors normalise accurately. Input files can hold any such normal.
glm::vec3 safeNormalize(const glm::vec3& v, const glm::vec3& fallback = glm::vec3(0.0f, 1.0f, 0.0f));

// The lecture's face normal of a counter-clockwise triangle a, b, c: normalize((c - b) x (a - b)).
glm::vec3 faceNormal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);

// UV sphere laid out exactly like ../shared/bench (seam column duplicated, one triangle per pole quad):
// (stacks + 1) * (slices + 1) vertices, 2 * slices * (stacks - 1) triangles.
Mesh makeUvSphere(int slices, int stacks, float radius);
Mesh makeIcoSphere(int subdivisions, float radius);            // 20 * 4^n triangles
Mesh makeTorus(float majorRadius, float minorRadius, int majorSegments, int minorSegments);
Mesh makeCube(float size);                                     // 24 vertices, one normal per face
Mesh makePlane(float size, int subdivisions);                  // x-z square at y = 0, facing +y

// Builds a procedural mesh (not glTF: see gltf_import.hpp).
Mesh makeProceduralMesh(const MeshSpec& spec);

// Vertex data for flat shading. GL takes a `flat` varying from the provoking (last) vertex of each
// triangle, so every triangle needs a vertex of its own in that slot, carrying its face normal and
// centroid. Each triangle is rotated (which keeps its winding) so that a corner no other triangle has
// claimed comes last; only triangles whose three corners are all taken get a new vertex. On a closed
// mesh (T = 2V) that is about T vertices instead of the V + T of one new vertex per triangle, and a
// third fewer vertex-shader runs. The colour is still evaluated once per triangle, at its centroid.
struct FlatMesh {
    std::vector<glm::vec3> positions;   // object space
    std::vector<glm::vec3> normals;     // face normal at each provoking vertex (vertex normal elsewhere)
    std::vector<glm::vec3> centroids;   // triangle centroid at each provoking vertex (position elsewhere)
    std::vector<std::uint32_t> indices; // per triangle, its corners rotated so the provoking one is last
};
FlatMesh makeFlatMesh(const Mesh& mesh);

struct BoundingSphere {
    glm::vec3 center{0.0f};
    float radius = 0.0f;
};
// Bounding sphere of all meshes after their object-to-world transforms (centre of the box, radius
// to the farthest vertex). Empty input gives radius 0.
BoundingSphere worldBounds(const std::vector<const Mesh*>& meshes, const std::vector<glm::mat4>& worldFromObject);

}  // namespace shadelab
