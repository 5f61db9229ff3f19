// A glTF primitive into the mesh: its triangles as a list (strips and fans unrolled), its vertices
// baked with the node's transform, its colour inputs, tangents and indices appended, then its part.
#include "core/geometry/gltf_import_parts.hpp"

#include "core/shading/lighting.hpp"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>

namespace shadelab::gltf_import_parts {

namespace {

// The triangles of a strip or a fan (or a list, its last partial triangle dropped) as a triangle list.
std::vector<std::uint32_t> triangleList(int mode, std::vector<std::uint32_t> order) {
    std::vector<std::uint32_t> tris;
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        order.resize(order.size() / 3 * 3);
        tris = std::move(order);
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        for (std::size_t i = 2; i < order.size(); ++i) {
            // Every other strip triangle is flipped to keep counter-clockwise winding (glTF spec 3.7.2.1).
            if (i % 2 == 0) tris.insert(tris.end(), {order[i - 2], order[i - 1], order[i]});
            else tris.insert(tris.end(), {order[i - 1], order[i - 2], order[i]});
        }
    } else {
        for (std::size_t i = 2; i < order.size(); ++i) tris.insert(tris.end(), {order[i - 1], order[i], order[0]});
    }
    return tris;
}

}  // namespace

// The order: read, check and triangulate the primitive; bake its vertices into *out_; then its
// colour inputs, its indices and its part.
void GltfReader::addPrimitive(const tinygltf::Primitive& p, const glm::mat4& world, const std::string& where,
                              const std::vector<glm::mat4>& instances) {
    const int mode = p.mode < 0 ? TINYGLTF_MODE_TRIANGLES : p.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        static const char* kNames[] = {"POINTS", "LINES", "LINE_LOOP", "LINE_STRIP"};
        info_.warnings.push_back(where + ": " + (mode >= 0 && mode < 4 ? kNames[mode] : "unknown-mode") +
                                 " primitive skipped (only triangles are shaded)");
        return;
    }
    const auto posIt = p.attributes.find("POSITION");
    // The validator only warns about this, but a triangle primitive without positions cannot be drawn,
    // and its indices (if any) point at nothing: refuse the file rather than guess.
    if (posIt == p.attributes.end()) fail(where, "has no POSITION attribute");
    std::vector<glm::vec3> positions = readPositions(posIt->second, where);
    std::vector<std::uint32_t> tris = triangles(p, mode, positions.size(), where);
    std::vector<glm::vec3> normals = readNormals(p, positions, tris, where);

    // C where it varies over the surface: the base colour texture's coordinates and COLOR_0.
    const std::size_t vertexCount = positions.size();
    const MaterialTexture texture = baseColorTexture(p.material);
    std::vector<glm::vec2> uvs =
        texture.slot >= 0 ? texcoords(p, texture, vertexCount, where) : std::vector<glm::vec2>();
    const int textureSlot = uvs.empty() ? -1 : texture.slot;
    const std::vector<glm::vec4> colors = vertexColors(p, vertexCount, where);
    const std::vector<glm::vec4> tangents = readTangents(p, vertexCount, where);
    // E where it varies: the emissive texture at its own coordinates.
    const MaterialTexture emissive = emissiveTexture(p.material);
    std::vector<glm::vec2> emissiveUvs =
        emissive.slot >= 0 ? texcoords(p, emissive, vertexCount, where) : std::vector<glm::vec2>();
    const int emissiveSlot = emissiveUvs.empty() ? -1 : emissive.slot;

    const auto base = std::uint32_t(out_->positions.size());
    bakeVertices(std::move(positions), std::move(normals), world, posIt->second, where);
    appendColorInputs(base, vertexCount, uvs, colors, emissiveUvs);
    appendTangents(base, vertexCount, tangents, world);
    // A mirroring transform (negative determinant) turns counter-clockwise triangles clockwise, so
    // their winding is flipped back.
    const bool mirrored = glm::determinant(glm::mat3(world)) < 0.0f;
    const std::uint32_t firstIndex = appendIndices(std::move(tris), base, mirrored);
    addPart(p.material, firstIndex, textureSlot, emissiveSlot, instances);
    info_.primitives += 1;
    info_.triangles += (out_->indices.size() - firstIndex) / 3;
}

// The primitive's triangles as a list (its indices, or its vertices in order), within kMaxTriangles.
std::vector<std::uint32_t> GltfReader::triangles(const tinygltf::Primitive& p, int mode, std::size_t vertexCount,
                                                 const std::string& where) const {
    std::vector<std::uint32_t> order;
    if (p.indices >= 0) {
        order = indices(p.indices, vertexCount, where);
    } else {
        order.resize(vertexCount);
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = std::uint32_t(i);
    }
    std::vector<std::uint32_t> tris = triangleList(mode, std::move(order));
    if (info_.triangles + tris.size() / 3 > kMaxTriangles)
        fail(where, "more than " + std::to_string(kMaxTriangles) + " triangles in total");
    return tris;
}

// Appends the vertices to *out_ baked with the node transform `world` (normals with its inverse
// transpose); the first untransformed primitive's arrays are taken as they are.
void GltfReader::bakeVertices(std::vector<glm::vec3>&& positions, std::vector<glm::vec3>&& normals,
                              const glm::mat4& world, int positionAccessor, const std::string& where) {
    if (world == glm::mat4(1.0f) && out_->positions.empty()) {
        // One untransformed primitive (most models): take the arrays as they are.
        out_->positions = std::move(positions);
        out_->normals = std::move(normals);
        return;
    }
    // Room for this primitive, growing geometrically: an exact reserve per primitive copied the
    // whole mesh every time (quadratic in the number of node instances).
    const std::size_t needed = out_->positions.size() + positions.size();
    // Every instance is baked: the vertices the file asks for, not its size, set the memory.
    if (needed > kMaxBakedVertices)
        fail(where, "the scene bakes to more than " + std::to_string(kMaxBakedVertices) + " vertices");
    if (needed > out_->positions.capacity()) {
        out_->positions.reserve(std::max(needed, 2 * out_->positions.capacity()));
        out_->normals.reserve(std::max(needed, 2 * out_->normals.capacity()));
    }
    const glm::mat3 nrmWorld = glm::transpose(glm::inverse(glm::mat3(world)));
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const glm::vec3 baked = glm::vec3(world * glm::vec4(positions[i], 1.0f));
        // Finite positions times a finite matrix can still overflow.
        if (!isFinite(baked))
            fail(where + " POSITION (accessor " + std::to_string(positionAccessor) + ")",
                 "vertex " + std::to_string(i) + " is not finite after node " + std::to_string(currentNode_) +
                     "'s transform");
        out_->positions.push_back(baked);
        const glm::vec3 n = nrmWorld * normals[i];
        out_->normals.push_back(safeNormalize(n));
    }
}

// The texture coordinates and vertex colours of the `count` vertices from `base` on, once any
// primitive has them.
void GltfReader::appendColorInputs(std::uint32_t base, std::size_t count, const std::vector<glm::vec2>& uvs,
                                   const std::vector<glm::vec4>& colors, const std::vector<glm::vec2>& emissiveUvs) {
    if (uvs.empty() && colors.empty() && emissiveUvs.empty() && !out_->variesColor()) return;
    // Defaults for the vertices before (the first primitive that varies) and for this one where
    // it has no texture or no COLOR_0: coordinates 0 (an untextured part samples no texture) and white.
    if (!out_->variesColor()) {
        out_->texcoords.assign(base, glm::vec2(0.0f));
        out_->colors.assign(base, glm::vec4(1.0f));
    }
    out_->texcoords.reserve(out_->positions.capacity());
    out_->colors.reserve(out_->positions.capacity());
    if (uvs.empty()) out_->texcoords.resize(base + count, glm::vec2(0.0f));
    else out_->texcoords.insert(out_->texcoords.end(), uvs.begin(), uvs.end());
    if (colors.empty()) out_->colors.resize(base + count, glm::vec4(1.0f));
    else out_->colors.insert(out_->colors.end(), colors.begin(), colors.end());
    // The emissive coordinates likewise, from the first primitive with an emissive texture on.
    if (emissiveUvs.empty() && !out_->hasEmissiveTexture()) return;
    if (!out_->hasEmissiveTexture()) out_->emissiveTexcoords.assign(base, glm::vec2(0.0f));
    if (emissiveUvs.empty()) out_->emissiveTexcoords.resize(base + count, glm::vec2(0.0f));
    else out_->emissiveTexcoords.insert(out_->emissiveTexcoords.end(), emissiveUvs.begin(), emissiveUvs.end());
}

// Appends the triangles to *out_'s indices, offset by the vertices before them (`base`) and flipped
// when `mirrored`; returns where they start.
std::uint32_t GltfReader::appendIndices(std::vector<std::uint32_t>&& tris, std::uint32_t base, bool mirrored) {
    const auto firstIndex = std::uint32_t(out_->indices.size());
    if (firstIndex == 0 && base == 0 && !mirrored) {
        out_->indices = std::move(tris);  // the first primitive, winding kept: its indices as they are
        return firstIndex;
    }
    out_->indices.resize(firstIndex + tris.size());  // tris holds whole triangles
    std::uint32_t* out = out_->indices.data() + firstIndex;
    for (std::size_t t = 0; t + 2 < tris.size(); t += 3, out += 3) {
        out[0] = base + tris[t];
        out[1] = base + tris[t + (mirrored ? 2 : 1)];
        out[2] = base + tris[t + (mirrored ? 1 : 2)];
    }
    return firstIndex;
}

// Tangents go with the node transform (not its inverse transpose); a mirroring one flips the handedness.
void GltfReader::appendTangents(std::uint32_t base, std::size_t count, const std::vector<glm::vec4>& tangents,
                                const glm::mat4& world) {
    if (tangents.empty() && out_->tangents.empty()) return;
    out_->tangents.resize(base, glm::vec4(0.0f));
    const glm::mat3 m(world);
    const float handedness = glm::determinant(m) < 0.0f ? -1.0f : 1.0f;
    for (std::size_t i = 0; i < count; ++i) {
        if (tangents.empty()) {
            out_->tangents.push_back(glm::vec4(0.0f));
            continue;
        }
        const glm::vec3& n = out_->normals[base + i];
        const glm::vec3 t = orthogonalTangent(m * glm::vec3(tangents[i]), n, glm::vec3(0.0f));
        out_->tangents.push_back(t == glm::vec3(0.0f) ? glm::vec4(0.0f) : glm::vec4(t, tangents[i].w * handedness));
    }
}

}  // namespace shadelab::gltf_import_parts
