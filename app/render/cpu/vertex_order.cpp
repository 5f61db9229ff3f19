#include "render/cpu/vertex_order.hpp"

#if SHADELAB_HAVE_MESHOPT
#include <meshoptimizer.h>
#endif

#include <algorithm>
#include <limits>

namespace shadelab {

namespace {
constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
// Tipsify's cache size: 32 gave the fewest runs in Mesa's model on UV spheres (16: +6%, 64: +3%,
// 128: +27%): it keeps the fans compact enough for a 341-triangle segment.
constexpr std::uint32_t kCacheSize = 32;

// Tipsify on `triangles` triangles whose corners are all below vertexCount, in place: Debian's
// meshoptimizer (meshopt_optimizeVertexCacheFifo is Sander et al.'s algorithm). bench/vertex_order.cpp
// compares it with meshoptimizer's own order and with the Tipsify shadelab wrote before. A build
// without meshoptimizer (SHADELAB_MESHOPT off: the Windows build) keeps the triangles' order.
void tipsify(std::uint32_t* in, std::size_t triangles, std::size_t vertexCount, std::uint32_t cacheSize) {
#if SHADELAB_HAVE_MESHOPT
    if (triangles < 2) return;
    std::vector<std::uint32_t> out(3 * triangles);
    meshopt_optimizeVertexCacheFifo(out.data(), in, out.size(), vertexCount, cacheSize);
    std::copy(out.begin(), out.end(), in);
#else
    (void)in, (void)triangles, (void)vertexCount, (void)cacheSize;
#endif
}

// New vertex numbers in order of first use in `indices` (vertices no index uses keep their relative
// order after them). Rewrites `indices` and returns oldFromNew, for permuted().
std::vector<std::uint32_t> renumberVerticesByFirstUse(std::vector<std::uint32_t>& indices, std::size_t vertexCount) {
    std::vector<std::uint32_t> newFromOld(vertexCount, kNone), oldFromNew;
    oldFromNew.reserve(vertexCount);
    for (std::uint32_t& i : indices) {
        if (newFromOld[i] == kNone) {
            newFromOld[i] = std::uint32_t(oldFromNew.size());
            oldFromNew.push_back(i);
        }
        i = newFromOld[i];
    }
    for (std::size_t v = 0; v < vertexCount; ++v)
        if (newFromOld[v] == kNone) oldFromNew.push_back(std::uint32_t(v));
    return oldFromNew;
}

template <typename T>
std::vector<T> permuted(const std::vector<T>& attribute, const std::vector<std::uint32_t>& oldFromNew) {
    std::vector<T> out(oldFromNew.size());
    for (std::size_t i = 0; i < oldFromNew.size(); ++i) out[i] = attribute[oldFromNew[i]];
    return out;
}

}  // namespace

Mesh orderedForVertexCache(const Mesh& mesh) {
    Mesh out;
    out.indices = mesh.indices;
    out.parts = mesh.parts;
    const std::size_t vertexCount = mesh.positions.size();
    const bool onePart = out.parts.empty() || (out.parts.size() == 1 && out.parts[0].firstIndex == 0 &&
                                               out.parts[0].indexCount == out.indices.size());
    if (onePart) {
        tipsify(out.indices.data(), out.indices.size() / 3, vertexCount, kCacheSize);
    } else {
        // Each part on its own, its vertices numbered locally (a file can have thousands of small
        // parts over a large vertex array: no per-part work proportional to the whole array).
        std::vector<std::uint32_t> localFromMesh(vertexCount, kNone), meshFromLocal, local;
        for (const MeshPart& part : out.parts) {
            std::uint32_t* range = out.indices.data() + part.firstIndex;
            meshFromLocal.clear();
            local.resize(part.indexCount);
            for (std::size_t i = 0; i < part.indexCount; ++i) {
                std::uint32_t& l = localFromMesh[range[i]];
                if (l == kNone) {
                    l = std::uint32_t(meshFromLocal.size());
                    meshFromLocal.push_back(range[i]);
                }
                local[i] = l;
            }
            tipsify(local.data(), local.size() / 3, meshFromLocal.size(), kCacheSize);
            for (std::size_t i = 0; i < part.indexCount; ++i) range[i] = meshFromLocal[local[i]];
            for (std::uint32_t v : meshFromLocal) localFromMesh[v] = kNone;
        }
    }
    const std::vector<std::uint32_t> oldFromNew = renumberVerticesByFirstUse(out.indices, vertexCount);
    out.positions = permuted(mesh.positions, oldFromNew);
    out.normals = permuted(mesh.normals, oldFromNew);
    if (!mesh.tangents.empty()) out.tangents = permuted(mesh.tangents, oldFromNew);
    if (mesh.variesColor()) {
        out.texcoords = permuted(mesh.texcoords, oldFromNew);
        out.colors = permuted(mesh.colors, oldFromNew);
        if (mesh.hasEmissiveTexture()) out.emissiveTexcoords = permuted(mesh.emissiveTexcoords, oldFromNew);
    }
    out.textures = mesh.textures;  // shared, not copied
    return out;
}

FlatMesh makeOrderedFlatMesh(const Mesh& orderedMesh) {
    FlatMesh flat = makeFlatMesh(orderedMesh);
    const std::vector<std::uint32_t> oldFromNew = renumberVerticesByFirstUse(flat.indices, flat.positions.size());
    flat.positions = permuted(flat.positions, oldFromNew);
    flat.normals = permuted(flat.normals, oldFromNew);
    flat.centroids = permuted(flat.centroids, oldFromNew);
    if (!flat.tangents.empty()) flat.tangents = permuted(flat.tangents, oldFromNew);
    if (!flat.texcoords.empty()) {
        flat.texcoords = permuted(flat.texcoords, oldFromNew);
        flat.colors = permuted(flat.colors, oldFromNew);
        if (!flat.emissiveTexcoords.empty()) flat.emissiveTexcoords = permuted(flat.emissiveTexcoords, oldFromNew);
    }
    return flat;
}

std::size_t vertexShaderRuns(const std::vector<std::uint32_t>& indices, std::size_t segmentIndices,
                             std::size_t tableSize) {
    std::size_t runs = 0;
    std::vector<std::uint32_t> table(tableSize);
    for (std::size_t s = 0; s < indices.size(); s += segmentIndices) {
        std::fill(table.begin(), table.end(), kNone);
        const std::size_t end = std::min(indices.size(), s + segmentIndices);
        for (std::size_t i = s; i < end; ++i) {
            std::uint32_t& slot = table[indices[i] % tableSize];
            if (slot != indices[i]) {
                slot = indices[i];
                ++runs;
            }
        }
    }
    return runs;
}

}  // namespace shadelab
