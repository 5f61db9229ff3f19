// Vertex-cache orders compared (issue 15: "the vertex-cache order comes from meshoptimizer if it keeps
// the frame times"): what shadelab uploads (render/cpu/vertex_order: Tipsify through Debian's meshoptimizer
// 0.18, meshopt_optimizeVertexCacheFifo with a cache of 32, per mesh part) against meshoptimizer's
// other order (meshopt_optimizeVertexCache) and the rows as generated, on the benchmark's UV spheres. For each: the time to order, and the vertex-shader runs per triangle Mesa's draw module
// makes (vertexShaderRuns: segments of 1023 indices, a direct-mapped table of 256), for the smooth
// mesh and for the flat mesh built from it. Figures in bench/README.md ("Vertex order: meshoptimizer").
//
//   cmake --build build --target bench_vertex_order && build/bench_vertex_order
#include "core/geometry/mesh.hpp"
#include "render/cpu/vertex_order.hpp"

#include <meshoptimizer.h>

#include <chrono>
#include <cstdio>
#include <functional>
#include <limits>

using namespace shadelab;

namespace {

// `mesh` with `indices` as its triangle order and its vertices numbered by first use.
Mesh withOrder(const Mesh& mesh, const std::vector<std::uint32_t>& indices) {
    Mesh out;
    std::vector<std::uint32_t> newFromOld(mesh.positions.size(), std::numeric_limits<std::uint32_t>::max());
    for (std::uint32_t i : indices)
        if (newFromOld[i] == std::numeric_limits<std::uint32_t>::max()) {
            newFromOld[i] = std::uint32_t(out.positions.size());
            out.positions.push_back(mesh.positions[i]);
            out.normals.push_back(mesh.normals[i]);
        }
    for (std::uint32_t i : indices) out.indices.push_back(newFromOld[i]);
    return out;
}

void report(const char* name, const Mesh& mesh, const std::function<Mesh()>& order) {
    const auto t0 = std::chrono::steady_clock::now();
    const Mesh ordered = order();
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    const FlatMesh flat = makeOrderedFlatMesh(ordered);
    const double tris = double(mesh.triangleCount());
    std::printf("| %s | %.1f | %.3f | %.3f |\n", name, ms, double(vertexShaderRuns(ordered.indices)) / tris,
                double(vertexShaderRuns(flat.indices)) / tris);
}

}  // namespace

int main() {
    for (const int stacks : {23, 224, 708}) {
        const Mesh sphere = makeUvSphere(2 * stacks, stacks, 1.0f);
        std::printf("\n%zu triangles\n\n| order | ms to order | runs per triangle, smooth | flat |\n| --- | --- | --- | --- |\n",
                    sphere.triangleCount());
        report("as generated (rows)", sphere, [&] { return withOrder(sphere, sphere.indices); });
        report("shadelab (orderedForVertexCache)", sphere, [&] { return orderedForVertexCache(sphere); });
        report("meshopt_optimizeVertexCache", sphere, [&] {
            std::vector<std::uint32_t> out(sphere.indices.size());
            meshopt_optimizeVertexCache(out.data(), sphere.indices.data(), out.size(), sphere.positions.size());
            return withOrder(sphere, out);
        });
        report("meshopt_optimizeVertexCacheFifo, 32", sphere, [&] {
            std::vector<std::uint32_t> out(sphere.indices.size());
            meshopt_optimizeVertexCacheFifo(out.data(), sphere.indices.data(), out.size(), sphere.positions.size(), 32);
            return withOrder(sphere, out);
        });
    }
}
