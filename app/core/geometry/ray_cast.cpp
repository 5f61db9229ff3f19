#include "core/geometry/ray_cast.hpp"

#include "core/geometry/camera.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadelab {
namespace {

constexpr std::uint32_t kLeafSize = 4;  // triangles per leaf: below this a box test costs about a triangle test
constexpr float kInf = std::numeric_limits<float>::infinity();

// Where a ray enters a box, clipped to [tMin, tMax]; +inf when it misses. `inv` is 1 / direction.
float boxEntry(const glm::vec3& lo, const glm::vec3& hi, const glm::vec3& origin, const glm::vec3& inv, float tMin,
               float tMax) {
    const glm::vec3 t0 = (lo - origin) * inv, t1 = (hi - origin) * inv;
    const glm::vec3 tNear = glm::min(t0, t1), tFar = glm::max(t0, t1);
    const float enter = std::max({tNear.x, tNear.y, tNear.z, tMin});
    const float leave = std::min({tFar.x, tFar.y, tFar.z, tMax});
    return enter <= leave ? enter : kInf;
}

struct RayTriangle {
    float t, u, v;  // the point origin + t * direction = (1 - u - v) a + u b + v c
    float det;      // > 0: the counter-clockwise side faces the ray's origin
};

// Möller-Trumbore against the triangle a, a + edge1, a + edge2. det = -dot(direction, edge1 x edge2)
// is positive when the counter-clockwise side faces the ray's origin: with frontSign +1 (or -1, for a
// mirroring transform) only that front face counts, with 0 both faces do.
bool intersect(const glm::vec3& a, const glm::vec3& edge1, const glm::vec3& edge2, const glm::vec3& origin,
               const glm::vec3& direction, float frontSign, RayTriangle& out) {
    const glm::vec3 p = glm::cross(direction, edge2);
    const float det = glm::dot(edge1, p);
    if (det == 0.0f || det * frontSign < 0.0f) return false;  // edge-on, or a culled back face
    out.det = det;
    // The bounds give a millionth of slack: without it, rounding lets a ray through a shared edge or
    // vertex miss both triangles (Möller-Trumbore is not watertight).
    constexpr float slack = 1e-6f;
    const glm::vec3 s = origin - a;
    out.u = glm::dot(s, p) / det;
    if (out.u < -slack || out.u > 1.0f + slack) return false;
    const glm::vec3 q = glm::cross(s, edge1);
    out.v = glm::dot(direction, q) / det;
    if (out.v < -slack || out.u + out.v > 1.0f + slack) return false;
    out.t = glm::dot(edge2, q) / det;
    return true;
}

// Per triangle of the mesh: whether its part is double-sided (both faces drawn).
std::vector<bool> doubleSidedTriangles(const Mesh& mesh) {
    std::vector<bool> out(mesh.triangleCount(), false);
    for (const MeshPart& part : mesh.parts) {
        if (!part.doubleSided) continue;
        const std::size_t end = std::min(out.size(), (std::size_t(part.firstIndex) + part.indexCount) / 3);
        for (std::size_t t = part.firstIndex / 3; t < end; ++t) out[t] = true;
    }
    return out;
}

}  // namespace

SceneRayCaster::SceneRayCaster(const Scene& scene, const SceneGeometry& geometry) {
    addTriangles(scene, geometry);
    if (!triangles_.empty()) buildTree();
}

void SceneRayCaster::addTriangles(const Scene& scene, const SceneGeometry& geometry) {
    const std::size_t objects = std::min(scene.objects.size(), geometry.meshes.size());
    for (std::size_t o = 0; o < objects; ++o) {
        const Mesh& mesh = geometry.meshes[o];
        const glm::mat4 world = worldFromObject(scene.objects[o].transform);
        const float frontSign = glm::determinant(glm::mat3(world)) < 0.0f ? -1.0f : 1.0f;
        const std::vector<bool> doubleSided = doubleSidedTriangles(mesh);
        std::vector<glm::vec3> posWorld(mesh.positions.size());
        for (std::size_t i = 0; i < posWorld.size(); ++i)
            posWorld[i] = glm::vec3(world * glm::vec4(mesh.positions[i], 1.0f));
        for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
            const glm::vec3& a = posWorld[mesh.indices[3 * t]];
            const glm::vec3& b = posWorld[mesh.indices[3 * t + 1]];
            const glm::vec3& c = posWorld[mesh.indices[3 * t + 2]];
            triangles_.push_back(
                {a, b - a, c - a, std::uint32_t(o), std::uint32_t(t), frontSign, bool(doubleSided[t])});
        }
    }
}

void SceneRayCaster::buildTree() {
    // Top-down build: split each node's triangles at the median centroid along the longest axis of the
    // centroids' box. Median splits keep the tree balanced (depth ~ log2(n / 4)) at any mesh density.
    const std::size_t n = triangles_.size();
    std::vector<glm::vec3> lo(n), hi(n), centre(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Triangle& tri = triangles_[i];
        const glm::vec3 b = tri.a + tri.edge1, c = tri.a + tri.edge2;
        lo[i] = glm::min(tri.a, glm::min(b, c));
        hi[i] = glm::max(tri.a, glm::max(b, c));
        centre[i] = (tri.a + b + c) / 3.0f;
    }
    std::vector<std::uint32_t> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = std::uint32_t(i);
    nodes_.reserve(2 * (n / kLeafSize + 1));
    nodes_.push_back(Node{});
    struct Range {
        std::uint32_t node, begin, end;
    };
    std::vector<Range> todo{{0, 0, std::uint32_t(n)}};
    while (!todo.empty()) {
        const Range r = todo.back();
        todo.pop_back();
        glm::vec3 boxLo(kInf), boxHi(-kInf), centreLo(kInf), centreHi(-kInf);
        for (std::uint32_t i = r.begin; i < r.end; ++i) {
            boxLo = glm::min(boxLo, lo[order[i]]);
            boxHi = glm::max(boxHi, hi[order[i]]);
            centreLo = glm::min(centreLo, centre[order[i]]);
            centreHi = glm::max(centreHi, centre[order[i]]);
        }
        nodes_[r.node].lo = boxLo;
        nodes_[r.node].hi = boxHi;
        const glm::vec3 extent = centreHi - centreLo;
        const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
        if (r.end - r.begin <= kLeafSize || !(extent[axis] > 0.0f)) {
            nodes_[r.node].first = r.begin;
            nodes_[r.node].count = r.end - r.begin;
            continue;
        }
        const std::uint32_t mid = r.begin + (r.end - r.begin) / 2;
        std::nth_element(order.begin() + r.begin, order.begin() + mid, order.begin() + r.end,
                         [&](std::uint32_t x, std::uint32_t y) { return centre[x][axis] < centre[y][axis]; });
        const auto left = std::uint32_t(nodes_.size());
        nodes_[r.node].first = left;
        nodes_.push_back(Node{});
        nodes_.push_back(Node{});
        todo.push_back({left, r.begin, mid});
        todo.push_back({left + 1, mid, r.end});
    }
    std::vector<Triangle> sorted;
    sorted.reserve(n);
    for (std::uint32_t i : order) sorted.push_back(triangles_[i]);
    triangles_.swap(sorted);
    radius_ = 0.5f * glm::length(nodes_[0].hi - nodes_[0].lo);
}

template <typename Visit>
void SceneRayCaster::traverse(const glm::vec3& origin, const glm::vec3& direction, float tMin, float& tMax,
                              Visit&& visit) const {
    if (nodes_.empty()) return;
    // A zero component becomes a tiny one of the same sign: the slab test then needs no special case
    // (0 * inf would be NaN for a ray starting exactly on a box face).
    glm::vec3 inv;
    for (int k = 0; k < 3; ++k)
        inv[k] = 1.0f / (direction[k] != 0.0f ? direction[k] : std::copysign(1e-30f, direction[k]));
    std::uint32_t stack[64];  // depth ~ log2(n / 4) + 1: 64 holds any mesh that fits in memory
    int top = 0;
    if (boxEntry(nodes_[0].lo, nodes_[0].hi, origin, inv, tMin, tMax) == kInf) return;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[stack[--top]];
        if (node.count > 0) {
            for (std::uint32_t i = node.first; i < node.first + node.count; ++i)
                if (visit(triangles_[i])) return;
            continue;
        }
        // Nearer child on top of the stack, so the nearest hit shortens tMax early.
        const float enterLeft = boxEntry(nodes_[node.first].lo, nodes_[node.first].hi, origin, inv, tMin, tMax);
        const float enterRight =
            boxEntry(nodes_[node.first + 1].lo, nodes_[node.first + 1].hi, origin, inv, tMin, tMax);
        const bool leftFirst = enterLeft <= enterRight;
        const float enter[2] = {leftFirst ? enterRight : enterLeft, leftFirst ? enterLeft : enterRight};
        const std::uint32_t child[2] = {leftFirst ? node.first + 1 : node.first,
                                        leftFirst ? node.first : node.first + 1};
        for (int k = 0; k < 2; ++k)
            if (enter[k] != kInf && top < 64) stack[top++] = child[k];
    }
}

std::optional<TriangleHit> SceneRayCaster::nearestFrontFace(const glm::vec3& origin, const glm::vec3& direction,
                                                            float tMin, float tMax) const {
    std::optional<TriangleHit> best;
    traverse(origin, direction, tMin, tMax, [&](const Triangle& tri) {
        RayTriangle h;
        if (!intersect(tri.a, tri.edge1, tri.edge2, origin, direction, tri.doubleSided ? 0.0f : tri.frontSign, h) ||
            h.t < tMin || h.t > tMax)
            return false;
        tMax = h.t;
        best = TriangleHit{tri.object, tri.triangle, h.t, glm::vec3(1.0f - h.u - h.v, h.u, h.v),
                           h.det * tri.frontSign < 0.0f};
        return false;  // a nearer one may follow
    });
    return best;
}

std::size_t SceneRayCaster::trianglesTested(const glm::vec3& origin, const glm::vec3& direction, float tMin,
                                            float tMax) const {
    std::size_t tested = 0;
    traverse(origin, direction, tMin, tMax, [&](const Triangle& tri) {
        ++tested;
        RayTriangle h;
        if (intersect(tri.a, tri.edge1, tri.edge2, origin, direction, tri.doubleSided ? 0.0f : tri.frontSign, h) &&
            h.t >= tMin && h.t <= tMax)
            tMax = h.t;  // as nearestFrontFace: a nearer hit prunes the boxes behind it
        return false;
    });
    return tested;
}

bool SceneRayCaster::occluded(const glm::vec3& origin, const glm::vec3& direction, float tMin, float tMax) const {
    bool hit = false;
    traverse(origin, direction, tMin, tMax, [&](const Triangle& tri) {
        RayTriangle h;
        hit = intersect(tri.a, tri.edge1, tri.edge2, origin, direction, 0.0f, h) && h.t > tMin && h.t < tMax;
        return hit;  // any hit will do
    });
    return hit;
}

}  // namespace shadelab
