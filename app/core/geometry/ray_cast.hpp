#pragma once
// Rays against the scene's triangles on the CPU, for the pixel probe (core/probe/probe.hpp): which surface
// point a pixel sees, and whether a light sample is hidden from a point (the lecture's "trace ray to
// light source and test for occlusion"). The triangles of every object are put in world space once,
// in a bounding-volume hierarchy, so a ray against a 200k-triangle model costs microseconds (a plain
// loop over the triangles costs milliseconds, and a probe with shadows casts thousands of rays).
#include "core/geometry/scene_geometry.hpp"
#include "core/scene/scene.hpp"

#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <vector>

namespace shadelab {

struct TriangleHit {
    std::size_t object = 0;       // index into Scene::objects
    std::size_t triangle = 0;     // triangle of that object's mesh: indices[3t], [3t+1], [3t+2]
    float t = 0.0f;               // ray parameter: the point is origin + t * direction
    glm::vec3 barycentric{0.0f};  // weights of those three corners (sum 1)
    bool backFace = false;        // the ray hit the back of a double-sided part (MeshPart::doubleSided)
};

class SceneRayCaster {
public:
    SceneRayCaster() = default;  // no triangles: every ray misses
    // Takes each object's mesh to world space with its transform (objects past the geometry's meshes,
    // as the renderer does, are skipped). Rebuild it when a mesh or a transform changes.
    SceneRayCaster(const Scene& scene, const SceneGeometry& geometry);

    // The nearest triangle the rasteriser draws along the ray: its front face toward the ray (back
    // faces are culled; a mirroring transform flips which side is the front, as in the renderer), or
    // either face of a double-sided part (not culled; TriangleHit::backFace says which), at a ray
    // parameter in [tMin, tMax].
    std::optional<TriangleHit> nearestFrontFace(const glm::vec3& origin, const glm::vec3& direction, float tMin,
                                                float tMax) const;
    // True when any triangle, either face (the shadow pass draws both), is hit at t in (tMin, tMax).
    bool occluded(const glm::vec3& origin, const glm::vec3& direction, float tMin, float tMax) const;

    // How many triangles nearestFrontFace() tests for this ray: the hierarchy's work, which tests
    // measure instead of wall-clock time.
    std::size_t trianglesTested(const glm::vec3& origin, const glm::vec3& direction, float tMin, float tMax) const;

    std::size_t triangleCount() const { return triangles_.size(); }
    // Half the diagonal of the box around every triangle, world units (0 when empty): a length scale
    // for offsets that must be small against the scene.
    float radius() const { return radius_; }

private:
    struct Triangle {
        glm::vec3 a, edge1, edge2;  // world space: corners a, a + edge1, a + edge2 in index order
        std::uint32_t object, triangle;
        float frontSign;   // +1: counter-clockwise corners face the viewer; -1 under a mirroring transform
        bool doubleSided;  // its part is double-sided: both faces are hit
    };
    struct Node {
        glm::vec3 lo, hi;         // bounds of everything below
        std::uint32_t first = 0;  // leaf: first of `count` triangles; inner: index of the left child (right = +1)
        std::uint32_t count = 0;  // 0 for an inner node
    };
    template <typename Visit>
    void traverse(const glm::vec3& origin, const glm::vec3& direction, float tMin, float& tMax, Visit&& visit) const;
    // The constructor's steps: every object's triangles in world space, then the tree over them.
    void addTriangles(const Scene& scene, const SceneGeometry& geometry);
    void buildTree();

    std::vector<Triangle> triangles_;  // reordered so each leaf's triangles are contiguous
    std::vector<Node> nodes_;          // nodes_[0] is the root
    float radius_ = 0.0f;
};

}  // namespace shadelab
