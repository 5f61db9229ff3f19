// glTF accessors: an accessor's elements checked against its buffer view and buffer, sparse ones
// materialised, integer types dequantized (KHR_mesh_quantization), indices widened and checked; and
// the vertex attributes read through them (POSITION, NORMAL, TEXCOORD_n, COLOR_0, TANGENT).
#include "core/geometry/gltf_import_parts.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cstring>
#include <limits>

namespace shadelab::gltf_import_parts {

void GltfReader::checkRange(int bvIndex, std::size_t byteOffset, std::size_t elementSize, std::size_t stride,
                            std::size_t count, const std::string& where, std::size_t* strideOut,
                            const unsigned char** baseOut) const {
    if (bvIndex < 0 || std::size_t(bvIndex) >= model_.bufferViews.size())
        fail(where, "bufferView " + std::to_string(bvIndex) + " does not exist");
    const tinygltf::BufferView& bv = model_.bufferViews[std::size_t(bvIndex)];
    const std::string bvName = "bufferView " + std::to_string(bvIndex);
    if (bv.buffer < 0 || std::size_t(bv.buffer) >= model_.buffers.size())
        fail(bvName, "buffer " + std::to_string(bv.buffer) + " does not exist");
    const tinygltf::Buffer& buf = model_.buffers[std::size_t(bv.buffer)];
    if (bv.byteOffset > buf.data.size() || bv.byteLength > buf.data.size() - bv.byteOffset)
        fail(bvName, "range " + std::to_string(bv.byteOffset) + "+" + std::to_string(bv.byteLength) +
                         " lies outside buffer " + std::to_string(bv.buffer) + " (" + std::to_string(buf.data.size()) +
                         " bytes)");
    const std::size_t s = stride ? stride : (bv.byteStride ? bv.byteStride : elementSize);
    if (s < elementSize) fail(bvName, "byteStride " + std::to_string(s) + " is smaller than an element");
    if (count > 0) {
        // last byte read = byteOffset + s * (count - 1) + elementSize, computed without overflow
        if (byteOffset > bv.byteLength || (count - 1) > (bv.byteLength - byteOffset) / s ||
            s * (count - 1) + elementSize > bv.byteLength - byteOffset)
            fail(where, std::to_string(count) + " elements at offset " + std::to_string(byteOffset) +
                            " do not fit in " + bvName + " (" + std::to_string(bv.byteLength) + " bytes)");
    }
    *strideOut = s;
    *baseOut = buf.data.data() + bv.byteOffset + byteOffset;
}

GltfReader::View GltfReader::view(int ai, const std::string& where, const std::vector<int>& types,
                                  const std::vector<int>& componentTypes) const {
    const std::string name = where + " (accessor " + std::to_string(ai) + ")";
    if (ai < 0 || std::size_t(ai) >= model_.accessors.size())
        fail(where, "accessor " + std::to_string(ai) + " does not exist");
    const tinygltf::Accessor& a = model_.accessors[std::size_t(ai)];
    bool typeOk = false, ctOk = false;
    for (int t : types) typeOk = typeOk || a.type == t;
    for (int t : componentTypes) ctOk = ctOk || a.componentType == t;
    if (!typeOk || !ctOk) fail(name, "unsupported type/componentType for this attribute");
    View v;
    v.componentType = a.componentType;
    v.components = tinygltf::GetNumComponentsInType(std::uint32_t(a.type));
    v.normalized = a.normalized;
    v.count = a.count;
    const int componentSize = tinygltf::GetComponentSizeInBytes(std::uint32_t(a.componentType));
    if (v.components <= 0 || componentSize <= 0) fail(name, "bad type");
    if (v.count > 3 * kMaxTriangles) fail(name, "count " + std::to_string(v.count) + " is too large");
    const std::size_t elementSize = std::size_t(v.components) * std::size_t(componentSize);
    if (a.bufferView >= 0) {
        checkRange(a.bufferView, a.byteOffset, elementSize, 0, v.count, name, &v.stride, &v.base);
    } else if (!a.sparse.isSparse) {
        fail(name, "has neither a bufferView nor sparse values");
    }
    if (a.bufferView < 0) checkZeroBackedCount(v.count, name);
    if (a.sparse.isSparse) materialiseSparse(a, elementSize, name, v);
    return v;
}

// Sparse values over zeros: the count is backed by no bytes. It may not exceed the bytes the file's
// buffers hold (a real one, a morph target's deltas, matches a mesh stored beside it).
void GltfReader::checkZeroBackedCount(std::size_t count, const std::string& name) const {
    std::size_t present = 0;
    for (const tinygltf::Buffer& b : model_.buffers) present += b.data.size();
    if (count > std::max<std::size_t>(present, std::size_t(1) << 20))
        fail(name, "sparse accessor of " + std::to_string(count) + " elements without a bufferView: more than the " +
                       std::to_string(present) + " bytes of the file's buffers");
}

// Materialise: the base values (or zeros), then the sparse ones written over them, byte for byte.
void GltfReader::materialiseSparse(const tinygltf::Accessor& a, std::size_t elementSize, const std::string& name,
                                   View& v) const {
    auto bytes = std::make_shared<std::vector<unsigned char>>(v.count * elementSize, 0);
    if (v.base)
        for (std::size_t i = 0; i < v.count; ++i)
            std::memcpy(bytes->data() + i * elementSize, v.base + i * v.stride, elementSize);
    const std::size_t n = std::size_t(a.sparse.count);
    if (a.sparse.count < 0 || n > v.count) fail(name, "sparse count out of range");
    View idx;
    idx.componentType = a.sparse.indices.componentType;
    idx.components = 1;
    const int idxSize = tinygltf::GetComponentSizeInBytes(std::uint32_t(idx.componentType));
    if (idx.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        idx.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        idx.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        fail(name, "sparse indices must be unsigned integers");
    checkRange(a.sparse.indices.bufferView, std::size_t(a.sparse.indices.byteOffset), std::size_t(idxSize),
               std::size_t(idxSize), n, name + " sparse indices", &idx.stride, &idx.base);
    std::size_t valuesStride = 0;
    const unsigned char* values = nullptr;
    checkRange(a.sparse.values.bufferView, std::size_t(a.sparse.values.byteOffset), elementSize, elementSize, n,
               name + " sparse values", &valuesStride, &values);
    for (std::size_t k = 0; k < n; ++k) {
        const std::uint32_t target = unsignedInteger(idx, k);
        if (target >= v.count) fail(name, "sparse index " + std::to_string(target) + " out of range");
        std::memcpy(bytes->data() + std::size_t(target) * elementSize, values + k * valuesStride, elementSize);
    }
    v.materialised = std::move(bytes);
    v.base = v.materialised->data();
    v.stride = elementSize;
}

GltfReader::View GltfReader::vertexAttribute(int ai, const std::string& where, const std::vector<int>& types,
                                             const std::vector<int>& componentTypes, std::size_t count,
                                             const char* integers) const {
    View v = view(ai, where, types, componentTypes);  // returned: moved, not copied
    const std::string name = where + " (accessor " + std::to_string(ai) + ")";
    if (integers && v.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !v.normalized)
        fail(name, std::string("integer ") + integers + " must be normalized");
    if (v.count != count)
        fail(name, "count " + std::to_string(v.count) + " differs from POSITION's " + std::to_string(count));
    return v;
}

namespace {
// One integer component as glTF reads it (KHR_mesh_quantization): as it is, or normalized, signed
// types as max(c / (2^(b-1) - 1), -1) and unsigned as c / (2^b - 1) (glTF 2.0, 3.11).
template <typename T>
float dequantize(const unsigned char* p, bool normalized) {
    T c;
    std::memcpy(&c, p, sizeof c);
    if (!normalized) return float(c);
    constexpr float largest = float(std::numeric_limits<T>::max());
    return std::max(float(c) / largest, -1.0f);
}

template <typename T>
void readVec3As(const unsigned char* base, std::size_t stride, std::size_t count, bool normalized,
                std::vector<glm::vec3>& out) {
    for (std::size_t i = 0; i < count; ++i) {
        const unsigned char* p = base + i * stride;
        out[i] = glm::vec3(dequantize<T>(p, normalized), dequantize<T>(p + sizeof(T), normalized),
                           dequantize<T>(p + 2 * sizeof(T), normalized));
    }
}

// Smooth vertex normals: the face normals around each vertex weighted by the corner angle, so a
// vertex's normal does not depend on how the surface around it happens to be split into triangles.
void angleWeightedNormals(const std::vector<glm::vec3>& pos, const std::vector<std::uint32_t>& idx,
                          std::vector<glm::vec3>& nrm) {
    nrm.assign(pos.size(), glm::vec3(0.0f));
    for (std::size_t t = 0; t + 2 < idx.size(); t += 3) {
        const std::uint32_t v[3] = {idx[t], idx[t + 1], idx[t + 2]};
        const glm::vec3 n = faceNormal(pos[v[0]], pos[v[1]], pos[v[2]]);
        for (int k = 0; k < 3; ++k) {
            const glm::vec3 e1 = pos[v[(k + 1) % 3]] - pos[v[k]], e2 = pos[v[(k + 2) % 3]] - pos[v[k]];
            const float l1 = glm::length(e1), l2 = glm::length(e2);
            if (l1 <= 0.0f || l2 <= 0.0f) continue;
            const float angle = std::acos(glm::clamp(glm::dot(e1, e2) / (l1 * l2), -1.0f, 1.0f));
            nrm[v[k]] += angle * n;
        }
    }
    for (auto& n : nrm) {
        n = safeNormalize(n);
    }
}
}  // namespace

std::vector<glm::vec3> GltfReader::readVec3(const View& v) {
    std::vector<glm::vec3> out(v.count);
    switch (v.componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: readVec3As<std::int8_t>(v.base, v.stride, v.count, v.normalized, out); break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        readVec3As<std::uint8_t>(v.base, v.stride, v.count, v.normalized, out);
        break;
    case TINYGLTF_COMPONENT_TYPE_SHORT: readVec3As<std::int16_t>(v.base, v.stride, v.count, v.normalized, out); break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        readVec3As<std::uint16_t>(v.base, v.stride, v.count, v.normalized, out);
        break;
    default:  // FLOAT: copied as it is
        if (v.stride == sizeof(glm::vec3)) {
            if (v.count) std::memcpy(out.data(), v.base, v.count * sizeof(glm::vec3));
        } else {
            for (std::size_t i = 0; i < v.count; ++i) std::memcpy(&out[i], v.base + i * v.stride, sizeof(glm::vec3));
        }
    }
    return out;
}

std::uint32_t GltfReader::unsignedInteger(const View& v, std::size_t i) {
    const unsigned char* p = v.base + i * v.stride;
    switch (v.componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return p[0];
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t u;
        std::memcpy(&u, p, 2);
        return u;
    }
    default: {
        std::uint32_t u;
        std::memcpy(&u, p, 4);
        return u;
    }
    }
}

std::vector<std::uint32_t> GltfReader::indices(int ai, std::size_t vertexCount, const std::string& where) const {
    const View v = view(ai, where + " indices", {TINYGLTF_TYPE_SCALAR},
                        {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                         TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT});
    std::vector<std::uint32_t> out(v.count);
    const std::uint32_t restart = v.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? 0xffu
                                  : v.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 0xffffu
                                                                                              : 0xffffffffu;
    // Widen to 32 bits first (a loop per type, so the compiler vectorises it), then check.
    if (v.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
        for (std::size_t i = 0; i < v.count; ++i) out[i] = v.base[i * v.stride];
    } else if (v.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
        for (std::size_t i = 0; i < v.count; ++i) {
            std::uint16_t x;
            std::memcpy(&x, v.base + i * v.stride, 2);
            out[i] = x;
        }
    } else if (v.stride == 4) {
        if (v.count) std::memcpy(out.data(), v.base, v.count * 4);
    } else {
        for (std::size_t i = 0; i < v.count; ++i) std::memcpy(&out[i], v.base + i * v.stride, 4);
    }
    std::uint32_t largest = 0;
    bool restartSeen = false;
    for (std::uint32_t x : out) {
        largest = std::max(largest, x);
        restartSeen = restartSeen || x == restart;
    }
    if (!restartSeen && largest < vertexCount) return out;
    for (std::size_t i = 0; i < v.count; ++i) {  // name the first offending index
        const std::uint32_t x = out[i];
        if (x == restart)
            fail(where + " indices (accessor " + std::to_string(ai) + ")",
                 "index " + std::to_string(i) + " is the primitive-restart value " + std::to_string(x) +
                     ", which glTF forbids");
        if (x >= vertexCount)
            fail(where + " indices (accessor " + std::to_string(ai) + ")",
                 "index " + std::to_string(x) + " is out of range (" + std::to_string(vertexCount) + " vertices)");
    }
    return out;
}

float GltfReader::scalarAt(const View& v, std::size_t i, int c) {
    const unsigned char* p = v.base + i * v.stride;
    switch (v.componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return dequantize<std::int8_t>(p + c, v.normalized);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return dequantize<std::uint8_t>(p + c, v.normalized);
    case TINYGLTF_COMPONENT_TYPE_SHORT: return dequantize<std::int16_t>(p + 2 * c, v.normalized);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return dequantize<std::uint16_t>(p + 2 * c, v.normalized);
    default: {
        float f;
        std::memcpy(&f, p + 4 * c, 4);
        return f;
    }
    }
}

// POSITION: FLOAT, or any 8- or 16-bit integer type (KHR_mesh_quantization; the node transform dequantizes).
std::vector<glm::vec3> GltfReader::readPositions(int accessor, const std::string& where) const {
    const View pos =
        view(accessor, where + " POSITION", {TINYGLTF_TYPE_VEC3},
             {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
              TINYGLTF_COMPONENT_TYPE_SHORT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT});
    std::vector<glm::vec3> positions = readVec3(pos);
    for (std::size_t i = 0; i < pos.count; ++i) {
        if (!isFinite(positions[i]))
            fail(where + " POSITION (accessor " + std::to_string(accessor) + ")",
                 "vertex " + std::to_string(i) + " is not finite");
    }
    return positions;
}

// NORMAL (FLOAT, or normalized BYTE or SHORT: KHR_mesh_quantization), normalised; generated from the
// triangles (angleWeightedNormals) when the primitive has none.
std::vector<glm::vec3> GltfReader::readNormals(const tinygltf::Primitive& p, const std::vector<glm::vec3>& positions,
                                               const std::vector<std::uint32_t>& tris, const std::string& where) {
    std::vector<glm::vec3> normals;
    const auto nrmIt = p.attributes.find("NORMAL");
    if (nrmIt == p.attributes.end()) {
        angleWeightedNormals(positions, tris, normals);
        info_.generatedNormals += normals.size();
        return normals;
    }
    const std::string name = where + " NORMAL (accessor " + std::to_string(nrmIt->second) + ")";
    const View nv =
        vertexAttribute(nrmIt->second, where + " NORMAL", {TINYGLTF_TYPE_VEC3},
                        {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT},
                        positions.size(), "normals");
    normals = readVec3(nv);
    for (std::size_t i = 0; i < normals.size(); ++i) {
        glm::vec3& n = normals[i];
        if (!isFinite(n)) fail(name, "normal " + std::to_string(i) + " is not finite");
        n = safeNormalize(n);
    }
    return normals;
}

// The primitive's texture coordinates for its base colour texture (TEXCOORD_n, transformed): FLOAT,
// normalized UNSIGNED_BYTE / UNSIGNED_SHORT, and with KHR_mesh_quantization every 8- and 16-bit type.
// Empty (with a warning) when the primitive lacks that set.
std::vector<glm::vec2> GltfReader::texcoords(const tinygltf::Primitive& p, const MaterialTexture& t, std::size_t count,
                                             const std::string& where) const {
    const std::string name = "TEXCOORD_" + std::to_string(t.texCoord);
    const auto it = p.attributes.find(name);
    if (it == p.attributes.end()) {
        info_.warnings.push_back(where + ": its " + t.role + " texture reads " + name +
                                 ", which it does not have; drawn in its " + t.role + " factor");
        return {};
    }
    const View v = vertexAttribute(
        it->second, where + " " + name, {TINYGLTF_TYPE_VEC2},
        {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
         TINYGLTF_COMPONENT_TYPE_SHORT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
        count, nullptr);
    std::vector<glm::vec2> out(count);
    for (std::size_t i = 0; i < count; ++i) {
        const glm::vec3 uv = t.transform * glm::vec3(scalarAt(v, i, 0), scalarAt(v, i, 1), 1.0f);
        if (!std::isfinite(uv.x) || !std::isfinite(uv.y))
            fail(where + " " + name + " (accessor " + std::to_string(it->second) + ")",
                 "coordinate " + std::to_string(i) + " is not finite");
        out[i] = glm::vec2(uv);
    }
    return out;
}

// COLOR_0 as linear RGBA in [0, 1] (alpha 1 for a VEC3 accessor); empty when the primitive has none.
std::vector<glm::vec4> GltfReader::vertexColors(const tinygltf::Primitive& p, std::size_t count,
                                                const std::string& where) const {
    const auto it = p.attributes.find("COLOR_0");
    if (it == p.attributes.end()) return {};
    const std::string name = where + " COLOR_0 (accessor " + std::to_string(it->second) + ")";
    const View v = vertexAttribute(
        it->second, where + " COLOR_0", {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4},
        {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
         TINYGLTF_COMPONENT_TYPE_SHORT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
        count, "colours");
    const bool rgba = v.components == 4;
    std::vector<glm::vec4> out(count);
    for (std::size_t i = 0; i < count; ++i) {
        const glm::vec4 c(scalarAt(v, i, 0), scalarAt(v, i, 1), scalarAt(v, i, 2), rgba ? scalarAt(v, i, 3) : 1.0f);
        if (!isFinite(glm::vec3(c)) || !std::isfinite(c.w))
            fail(name, "colour " + std::to_string(i) + " is not finite");
        out[i] = glm::clamp(c, 0.0f, 1.0f);
    }
    return out;
}

std::vector<glm::vec4> GltfReader::readTangents(const tinygltf::Primitive& p, std::size_t count,
                                                const std::string& where) const {
    const auto it = p.attributes.find("TANGENT");
    if (it == p.attributes.end()) return {};
    const std::string name = where + " TANGENT (accessor " + std::to_string(it->second) + ")";
    const View v =
        vertexAttribute(it->second, where + " TANGENT", {TINYGLTF_TYPE_VEC4},
                        {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT},
                        count, "tangents");
    std::vector<glm::vec4> out(count);
    for (std::size_t i = 0; i < count; ++i) {
        const glm::vec4 t(scalarAt(v, i, 0), scalarAt(v, i, 1), scalarAt(v, i, 2), scalarAt(v, i, 3));
        if (!isFinite(glm::vec3(t)) || !std::isfinite(t.w))
            fail(name, "tangent " + std::to_string(i) + " is not finite");
        out[i] = glm::vec4(glm::vec3(t), t.w < 0.0f ? -1.0f : 1.0f);
    }
    return out;
}

}  // namespace shadelab::gltf_import_parts
