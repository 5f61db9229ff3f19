#include "core/geometry/gltf_import.hpp"

#include "core/base/error.hpp"
#include "core/base/file_io.hpp"
#include "core/geometry/gltf_extensions.hpp"
#include "core/shading/lighting.hpp"
#include "core/base/json_depth.hpp"
#include "core/scene/scene_names.hpp"
#include "platform/platform.hpp"

#include <nlohmann/json.hpp>
#include <stb/stb_image.h>
#include <tiny_gltf.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string_view>

namespace shadelab {
namespace {
namespace fs = std::filesystem;

constexpr std::size_t kMaxTriangles = 50'000'000;

// External files are read only from inside the model's folder: a URI with a scheme (http:, file:),
// an absolute path elsewhere, or one that climbs out with ".." is refused before anything is opened.
bool insideFolder(const std::string& p, const fs::path& root) {
    if (p.find("://") != std::string::npos) return false;
    // tinygltf joins every URI onto the folder: an absolute URI arrives as "<folder>//etc/passwd".
    const std::string prefix = root.string() + "/";
    if (p.size() > prefix.size() && p.compare(0, prefix.size(), prefix) == 0 && p[prefix.size()] == '/') return false;
    std::error_code ec;
    const fs::path full = fs::absolute(fs::path(p), ec).lexically_normal();
    if (ec) return false;
    const fs::path rel = full.lexically_relative(root);
    return !rel.empty() && *rel.begin() != "..";
}  // ~1.8 GB of vertex data after baking: refuse beyond

// The same with symbolic links followed, in the URI and in the folder: a link inside the folder (or a
// linked subfolder) that leads outside it is outside. A path that cannot be resolved (missing, a loop,
// a name too long) is refused too.
bool insideFolderResolved(const std::string& p, const fs::path& root) {
    std::error_code ec;
    const fs::path real = fs::canonical(fs::path(p), ec);
    if (ec) return false;
    const fs::path realRoot = fs::canonical(root, ec);
    if (ec) return false;
    const fs::path rel = real.lexically_relative(realRoot);
    return !rel.empty() && *rel.begin() != "..";
}

bool isFinite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool isFinite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

// At most this many vertices after every node instance is baked (about 1.2 GB of positions and normals).
constexpr std::size_t kMaxBakedVertices = 50000000;

class GltfReader {
public:
    GltfReader(const std::string& path, const tinygltf::Model& model, GltfInfo& info)
        : path_(path), model_(model), info_(info) {}

    Mesh read();

private:
    [[noreturn]] void fail(const std::string& where, const std::string& what) const {
        throw InputError(path_ + ": " + where + ": " + what);
    }

    // A checked view of an accessor's elements in its buffer (or materialised, when it is sparse).
    struct View {
        const unsigned char* base = nullptr;
        std::size_t stride = 0;
        int componentType = 0;
        int components = 0;
        bool normalized = false;
        std::size_t count = 0;
        // A sparse accessor's elements, materialised in the accessor's own format (base values or
        // zeros, the sparse ones substituted); `base` points into it. Integers stay integers.
        std::shared_ptr<std::vector<unsigned char>> materialised;
    };
    View view(int accessorIndex, const std::string& where, const std::vector<int>& allowedTypes,
              const std::vector<int>& allowedComponentTypes) const;
    // view()'s steps for a sparse accessor: the count of one without a bufferView checked against the
    // file's bytes, and its elements materialised into v.
    void checkZeroBackedCount(std::size_t count, const std::string& name) const;
    void materialiseSparse(const tinygltf::Accessor& a, std::size_t elementSize, const std::string& name, View& v) const;
    // A vertex attribute's view beside POSITION: `count` elements, and where `integers` names them
    // ("colours"), integer values normalized. `where` names the attribute.
    View vertexAttribute(int accessorIndex, const std::string& where, const std::vector<int>& allowedTypes,
                         const std::vector<int>& allowedComponentTypes, std::size_t count, const char* integers) const;
    static std::uint32_t unsignedInteger(const View& v, std::size_t i);  // a SCALAR of an unsigned type
    // All elements of a VEC3 accessor (POSITION, NORMAL): floats copied, integer types dequantized.
    static std::vector<glm::vec3> readVec3(const View& v);
    static float scalarAt(const View& v, std::size_t i, int c);  // component c of element i, dequantized
    std::vector<glm::mat4> instances(int nodeIndex, const tinygltf::Node& n);
    void addCamera(int cameraIndex, const glm::mat4& world);
    void addLight(const tinygltf::Node& node, int nodeIndex, const glm::mat4& world);
    int lightsLeftOut_ = 0;
    std::vector<int> cameraIndices_;  // which file camera each info_.cameras entry is
    std::vector<std::uint32_t> indices(int accessorIndex, std::size_t vertexCount, const std::string& where) const;
    void checkRange(int bufferViewIndex, std::size_t byteOffset, std::size_t elementSize, std::size_t stride,
                    std::size_t count, const std::string& where, std::size_t* strideOut,
                    const unsigned char** baseOut) const;
    // Appends a primitive to *out_, baked with `worldFromObject`; `instances`: the instanced pass's
    // transforms of its copies relative to that (a part drawn with instances, see read()).
    void addPrimitive(const tinygltf::Primitive& p, const glm::mat4& worldFromObject, const std::string& where,
                      const std::vector<glm::mat4>& instances = {});
    // addPrimitive's steps.
    std::vector<glm::vec3> readPositions(int accessorIndex, const std::string& where) const;
    std::vector<std::uint32_t> triangles(const tinygltf::Primitive& p, int mode, std::size_t vertexCount,
                                         const std::string& where) const;
    std::vector<glm::vec3> readNormals(const tinygltf::Primitive& p, const std::vector<glm::vec3>& positions,
                                       const std::vector<std::uint32_t>& triangles, const std::string& where);
    void bakeVertices(std::vector<glm::vec3>&& positions, std::vector<glm::vec3>&& normals, const glm::mat4& worldFromObject,
                      int positionAccessor, const std::string& where);
    void appendColorInputs(std::uint32_t base, std::size_t count, const std::vector<glm::vec2>& uvs,
                           const std::vector<glm::vec4>& colors, const std::vector<glm::vec2>& emissiveUvs);
    std::uint32_t appendIndices(std::vector<std::uint32_t>&& triangles, std::uint32_t base, bool mirrored);
    void addPart(int materialIndex, std::uint32_t firstIndex, int textureSlot, int emissiveSlot,
                 const std::vector<glm::mat4>& instances);
    void visit(int nodeIndex, const glm::mat4& parent, int depth);
    // read()'s steps: the nodes the walk starts from, the instanced pass, and the counts and bounds of info_.
    std::vector<int> rootNodes() const;
    void readInstanced(const std::vector<int>& roots);
    void summarise();
    // A material's texture: the object texture of the lecture's C (baseColorTexture) or of E
    // (emissiveTexture), decoded once per image and sampler into Mesh::textures; -1 (with a warning)
    // where it cannot be drawn.
    struct MaterialTexture {
        int slot = -1;           // index into mesh_.textures
        int texCoord = 0;        // which TEXCOORD_n
        glm::mat3 transform{1.0f};  // KHR_texture_transform: uv' = transform * (uv, 1)
        const char* role = "base colour";
    };
    MaterialTexture materialTexture(const tinygltf::TextureInfo& info, const char* role);
    MaterialTexture baseColorTexture(int materialIndex);
    MaterialTexture emissiveTexture(int materialIndex);
    int textureSlot(int textureIndex);
    // textureSlot's step: the image decoded into `out` (its name set), or why it is not drawn.
    std::string decodeImage(const tinygltf::Image& image, TextureImage& out) const;
    std::vector<glm::vec2> texcoords(const tinygltf::Primitive& p, const MaterialTexture& t, std::size_t count,
                                     const std::string& where) const;
    std::vector<glm::vec4> vertexColors(const tinygltf::Primitive& p, std::size_t count, const std::string& where) const;
    // TANGENT (xyz, w the handedness), or empty; appended to *out_ baked with `world` (w = 0 where a
    // primitive has none: completeTangents fills those).
    std::vector<glm::vec4> readTangents(const tinygltf::Primitive& p, std::size_t count, const std::string& where) const;
    void appendTangents(std::uint32_t base, std::size_t count, const std::vector<glm::vec4>& tangents, const glm::mat4& world);
    std::map<std::pair<int, int>, int> textureSlots_;  // (image, sampler) -> slot, or -1

    const std::string& path_;
    const tinygltf::Model& model_;
    GltfInfo& info_;
    Mesh mesh_;
    Mesh* out_ = &mesh_;           // where addPrimitive appends: mesh_, or the instanced pass's mesh
    bool instancedPass_ = false;   // read()'s second walk (a file with EXT_mesh_gpu_instancing)
    bool instanced_ = false;       // a node drew more than one instance
    int currentNode_ = -1;  // the node whose meshes addPrimitive is baking
};

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
    if (ai < 0 || std::size_t(ai) >= model_.accessors.size()) fail(where, "accessor " + std::to_string(ai) + " does not exist");
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
        for (std::size_t i = 0; i < v.count; ++i) std::memcpy(bytes->data() + i * elementSize, v.base + i * v.stride, elementSize);
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
    const View v = view(ai, where, types, componentTypes);
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
}  // namespace

std::vector<glm::vec3> GltfReader::readVec3(const View& v) {
    std::vector<glm::vec3> out(v.count);
    switch (v.componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: readVec3As<std::int8_t>(v.base, v.stride, v.count, v.normalized, out); break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: readVec3As<std::uint8_t>(v.base, v.stride, v.count, v.normalized, out); break;
    case TINYGLTF_COMPONENT_TYPE_SHORT: readVec3As<std::int16_t>(v.base, v.stride, v.count, v.normalized, out); break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: readVec3As<std::uint16_t>(v.base, v.stride, v.count, v.normalized, out); break;
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

// The texture coordinate transform of KHR_texture_transform: translation * rotation * scale, with the
// rotation [[cos, sin], [-sin, cos]] by rows: counter-clockwise in uv with v pointing down, so the
// picture turns clockwise. That is the spec's example, three.js, Babylon.js and Blender; its GLSL
// listing read by columns is the transpose (KhronosGroup/glTF#1563; tests/unit/gltf_import_test.cpp).
glm::mat3 textureTransform(const tinygltf::Value& ext) {
    const auto number = [&](const char* key, int i, double fallback) {
        if (!ext.Has(key)) return fallback;
        const tinygltf::Value& v = ext.Get(key);
        if (i < 0) return v.IsNumber() ? v.GetNumberAsDouble() : fallback;
        return v.IsArray() && v.ArrayLen() > std::size_t(i) && v.Get(i).IsNumber() ? v.Get(i).GetNumberAsDouble() : fallback;
    };
    const float ox = float(number("offset", 0, 0.0)), oy = float(number("offset", 1, 0.0));
    const float r = float(number("rotation", -1, 0.0));
    const float sx = float(number("scale", 0, 1.0)), sy = float(number("scale", 1, 1.0));
    const glm::mat3 translation(1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, ox, oy, 1.0f);  // column-major
    const glm::mat3 rotation(std::cos(r), -std::sin(r), 0.0f, std::sin(r), std::cos(r), 0.0f, 0.0f, 0.0f, 1.0f);
    const glm::mat3 scale(sx, 0.0f, 0.0f, 0.0f, sy, 0.0f, 0.0f, 0.0f, 1.0f);
    return translation * rotation * scale;
}

// A sampler's GL enum, or glTF's default where the file gives none or one GL does not have.
int wrapMode(int mode) {
    return mode == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE || mode == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT ? mode
                                                                                                      : TINYGLTF_TEXTURE_WRAP_REPEAT;
}

// A sampler's wrap modes and filters on a texture; glTF's defaults (repeat, trilinear) where it gives none.
void useSampler(const tinygltf::Sampler& s, TextureImage& out) {
    out.wrapS = wrapMode(s.wrapS);
    out.wrapT = wrapMode(s.wrapT);
    if (s.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST) out.magFilter = s.magFilter;
    switch (s.minFilter) {
    case TINYGLTF_TEXTURE_FILTER_NEAREST:
    case TINYGLTF_TEXTURE_FILTER_LINEAR:
    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST:
    case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST:
    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR:
    case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR: out.minFilter = s.minFilter; break;
    default: break;  // none given: trilinear
    }
}

// Images larger than this on a side, or with more pixels, are not decoded (a 16k texture is 1 GiB),
// nor past kMaxModelTexturePixels in one model (a small PNG can decode to 256 MiB).
constexpr int kMaxTextureSide = 16384;
constexpr std::size_t kMaxTexturePixels = std::size_t(1) << 26;
constexpr std::size_t kMaxModelTexturePixels = std::size_t(1) << 28;

GltfReader::MaterialTexture GltfReader::materialTexture(const tinygltf::TextureInfo& info, const char* role) {
    MaterialTexture t;
    t.role = role;
    if (info.index < 0) return t;
    t.texCoord = info.texCoord;
    if (const auto e = info.extensions.find("KHR_texture_transform"); e != info.extensions.end()) {
        t.transform = textureTransform(e->second);
        if (e->second.Has("texCoord") && e->second.Get("texCoord").IsInt()) t.texCoord = e->second.Get("texCoord").GetNumberAsInt();
    }
    t.slot = textureSlot(info.index);
    return t;
}

GltfReader::MaterialTexture GltfReader::baseColorTexture(int mi) {
    if (mi < 0 || std::size_t(mi) >= model_.materials.size()) return {};
    return materialTexture(model_.materials[std::size_t(mi)].pbrMetallicRoughness.baseColorTexture, "base colour");
}

GltfReader::MaterialTexture GltfReader::emissiveTexture(int mi) {
    if (mi < 0 || std::size_t(mi) >= model_.materials.size()) return {};
    const tinygltf::Material& m = model_.materials[std::size_t(mi)];
    // No light given off (a zero factor): the texture would multiply nothing, and is not read.
    if (m.emissiveFactor.size() < 3 || (m.emissiveFactor[0] <= 0.0 && m.emissiveFactor[1] <= 0.0 && m.emissiveFactor[2] <= 0.0))
        return {};
    return materialTexture(m.emissiveTexture, "emissive");
}

int GltfReader::textureSlot(int ti) {
    const std::string where = "texture " + std::to_string(ti);
    if (std::size_t(ti) >= model_.textures.size()) fail(where, "does not exist");
    const tinygltf::Texture& texture = model_.textures[std::size_t(ti)];
    const auto key = std::make_pair(texture.source, texture.sampler);
    if (const auto known = textureSlots_.find(key); known != textureSlots_.end()) return known->second;
    int& slot = textureSlots_[key];
    slot = -1;
    const auto skip = [&](const std::string& why) {
        info_.warnings.push_back(where + ": " + why + "; drawn in its base colour");
        return -1;
    };
    if (texture.source < 0) return skip("no PNG or JPEG image (only an extension's)");
    if (std::size_t(texture.source) >= model_.images.size()) fail(where, "image " + std::to_string(texture.source) + " does not exist");
    const tinygltf::Image& image = model_.images[std::size_t(texture.source)];
    auto out = std::make_shared<TextureImage>();
    out->name = image.uri.empty() || image.uri.rfind("data:", 0) == 0 ? "image " + std::to_string(texture.source) : image.uri;
    if (const std::string why = decodeImage(image, *out); !why.empty()) return skip(why);
    if (texture.sampler >= 0 && std::size_t(texture.sampler) < model_.samplers.size())
        useSampler(model_.samplers[std::size_t(texture.sampler)], *out);
    slot = int(mesh_.textures.size());
    mesh_.textures.push_back(std::move(out));
    return slot;
}

std::string GltfReader::decodeImage(const tinygltf::Image& image, TextureImage& out) const {
    const unsigned char* bytes = image.image.data();
    std::size_t size = image.image.size();
    if (image.bufferView >= 0) {
        if (std::size_t(image.bufferView) >= model_.bufferViews.size())
            fail(out.name, "bufferView " + std::to_string(image.bufferView) + " does not exist");
        const std::size_t length = model_.bufferViews[std::size_t(image.bufferView)].byteLength;
        if (length == 0) return out.name + "'s bufferView is empty";
        std::size_t stride = 0;  // the view's bytes one by one: its byteStride does not apply to an image
        checkRange(image.bufferView, 0, 1, 1, length, out.name, &stride, &bytes);
        size = length;
    }
    if (size == 0) return out.name + " could not be read";
    if (size > std::size_t(std::numeric_limits<int>::max())) return out.name + " is too large";
    int w = 0, h = 0, channels = 0;
    if (!stbi_info_from_memory(bytes, int(size), &w, &h, &channels))
        return out.name + " is not an image shadelab decodes (PNG or JPEG)";
    if (w <= 0 || h <= 0 || w > kMaxTextureSide || h > kMaxTextureSide || std::size_t(w) * std::size_t(h) > kMaxTexturePixels)
        return out.name + " is " + std::to_string(w) + "x" + std::to_string(h) + " pixels, more than shadelab reads (" +
               std::to_string(kMaxTextureSide) + " on a side, 64 Mpixels)";
    std::size_t decoded = 0;
    for (const auto& t : mesh_.textures) decoded += std::size_t(t->width) * std::size_t(t->height);
    if (decoded + std::size_t(w) * std::size_t(h) > kMaxModelTexturePixels)
        return out.name + " would take the model's textures past 256 Mpixels";
    std::unique_ptr<unsigned char, void (*)(void*)> pixels(stbi_load_from_memory(bytes, int(size), &w, &h, &channels, 4),
                                                           &stbi_image_free);
    if (!pixels) return out.name + " does not decode (" + std::string(stbi_failure_reason()) + ")";
    out.width = w, out.height = h;
    out.rgba.assign(pixels.get(), pixels.get() + std::size_t(w) * std::size_t(h) * 4);
    return "";
}

// The primitive's texture coordinates for its base colour texture (TEXCOORD_n, transformed): FLOAT,
// normalized UNSIGNED_BYTE / UNSIGNED_SHORT, and with KHR_mesh_quantization every 8- and 16-bit type.
// Empty (with a warning) when the primitive lacks that set.
std::vector<glm::vec2> GltfReader::texcoords(const tinygltf::Primitive& p, const MaterialTexture& t, std::size_t count,
                                             const std::string& where) const {
    const std::string name = "TEXCOORD_" + std::to_string(t.texCoord);
    const auto it = p.attributes.find(name);
    if (it == p.attributes.end()) {
        info_.warnings.push_back(where + ": its " + t.role + " texture reads " + name + ", which it does not have; drawn in its " +
                                 t.role + " factor");
        return {};
    }
    const View v = vertexAttribute(it->second, where + " " + name, {TINYGLTF_TYPE_VEC2},
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
    const View v = vertexAttribute(it->second, where + " COLOR_0", {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4},
                                   {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                    TINYGLTF_COMPONENT_TYPE_SHORT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
                                   count, "colours");
    const bool rgba = v.components == 4;
    std::vector<glm::vec4> out(count);
    for (std::size_t i = 0; i < count; ++i) {
        const glm::vec4 c(scalarAt(v, i, 0), scalarAt(v, i, 1), scalarAt(v, i, 2), rgba ? scalarAt(v, i, 3) : 1.0f);
        if (!isFinite(glm::vec3(c)) || !std::isfinite(c.w)) fail(name, "colour " + std::to_string(i) + " is not finite");
        out[i] = glm::clamp(c, 0.0f, 1.0f);
    }
    return out;
}

std::vector<glm::vec4> GltfReader::readTangents(const tinygltf::Primitive& p, std::size_t count,
                                                const std::string& where) const {
    const auto it = p.attributes.find("TANGENT");
    if (it == p.attributes.end()) return {};
    const std::string name = where + " TANGENT (accessor " + std::to_string(it->second) + ")";
    const View v = vertexAttribute(it->second, where + " TANGENT", {TINYGLTF_TYPE_VEC4},
                                   {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT},
                                   count, "tangents");
    std::vector<glm::vec4> out(count);
    for (std::size_t i = 0; i < count; ++i) {
        const glm::vec4 t(scalarAt(v, i, 0), scalarAt(v, i, 1), scalarAt(v, i, 2), scalarAt(v, i, 3));
        if (!isFinite(glm::vec3(t)) || !std::isfinite(t.w)) fail(name, "tangent " + std::to_string(i) + " is not finite");
        out[i] = glm::vec4(glm::vec3(t), t.w < 0.0f ? -1.0f : 1.0f);
    }
    return out;
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
    std::vector<glm::vec2> uvs = texture.slot >= 0 ? texcoords(p, texture, vertexCount, where) : std::vector<glm::vec2>();
    const int textureSlot = uvs.empty() ? -1 : texture.slot;
    const std::vector<glm::vec4> colors = vertexColors(p, vertexCount, where);
    const std::vector<glm::vec4> tangents = readTangents(p, vertexCount, where);
    // E where it varies: the emissive texture at its own coordinates.
    const MaterialTexture emissive = emissiveTexture(p.material);
    std::vector<glm::vec2> emissiveUvs = emissive.slot >= 0 ? texcoords(p, emissive, vertexCount, where) : std::vector<glm::vec2>();
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

// POSITION: FLOAT, or any 8- or 16-bit integer type (KHR_mesh_quantization; the node transform dequantizes).
std::vector<glm::vec3> GltfReader::readPositions(int accessor, const std::string& where) const {
    const View pos = view(accessor, where + " POSITION", {TINYGLTF_TYPE_VEC3},
                          {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                           TINYGLTF_COMPONENT_TYPE_SHORT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT});
    std::vector<glm::vec3> positions = readVec3(pos);
    for (std::size_t i = 0; i < pos.count; ++i) {
        if (!isFinite(positions[i]))
            fail(where + " POSITION (accessor " + std::to_string(accessor) + ")", "vertex " + std::to_string(i) + " is not finite");
    }
    return positions;
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
    const View nv = vertexAttribute(nrmIt->second, where + " NORMAL", {TINYGLTF_TYPE_VEC3},
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

namespace {

// Parts that look the same: consecutive primitives like these share one draw.
bool sameLook(const MeshPart& a, const MeshPart& b) {
    return a.baseColor == b.baseColor && a.texture == b.texture && a.baseAlpha == b.baseAlpha && a.alphaMode == b.alphaMode &&
           a.alphaCutoff == b.alphaCutoff && a.emissive == b.emissive && a.emissiveTexture == b.emissiveTexture &&
           a.doubleSided == b.doubleSided;
}

// KHR_materials_emissive_strength's factor (1 without it; a negative or non-finite one is ignored).
float emissiveStrength(const tinygltf::Material& m) {
    const auto e = m.extensions.find("KHR_materials_emissive_strength");
    if (e == m.extensions.end() || !e->second.Has("emissiveStrength")) return 1.0f;
    const tinygltf::Value& v = e->second.Get("emissiveStrength");
    const double s = v.IsNumber() ? v.GetNumberAsDouble() : 1.0;
    return std::isfinite(s) && s >= 0.0 ? float(std::min(s, 1e6)) : 1.0f;
}

}  // namespace

// The part of the indices from `firstIndex` on, with the material's base colour (glTF's default is
// white), alpha, emission and sidedness; consecutive primitives that look the same share a part, so a
// many-primitive model does not cost a draw call per primitive.
void GltfReader::addPart(int materialIndex, std::uint32_t firstIndex, int textureSlot, int emissiveSlot,
                         const std::vector<glm::mat4>& instances) {
    MeshPart part;
    part.firstIndex = firstIndex;
    part.indexCount = std::uint32_t(out_->indices.size()) - firstIndex;
    part.hasBaseColor = true;
    if (materialIndex >= 0 && std::size_t(materialIndex) < model_.materials.size()) {
        const tinygltf::Material& m = model_.materials[std::size_t(materialIndex)];
        const auto& f = m.pbrMetallicRoughness.baseColorFactor;
        if (f.size() >= 3)
            part.baseColor = glm::clamp(glm::vec3(float(f[0]), float(f[1]), float(f[2])), 0.0f, 1.0f);
        if (f.size() >= 4 && std::isfinite(f[3])) part.baseAlpha = glm::clamp(float(f[3]), 0.0f, 1.0f);
        if (m.alphaMode == "MASK") part.alphaMode = AlphaMode::Mask;
        if (m.alphaMode == "BLEND") part.alphaMode = AlphaMode::Blend;
        if (std::isfinite(m.alphaCutoff)) part.alphaCutoff = glm::clamp(float(m.alphaCutoff), 0.0f, 1.0f);
        const auto& e = m.emissiveFactor;
        if (e.size() >= 3 && std::isfinite(e[0]) && std::isfinite(e[1]) && std::isfinite(e[2]))
            part.emissive = glm::clamp(glm::vec3(float(e[0]), float(e[1]), float(e[2])), 0.0f, 1.0f) * emissiveStrength(m);
        part.doubleSided = m.doubleSided;
    }
    part.texture = textureSlot;
    part.emissiveTexture = emissiveSlot;
    part.instances = instances;
    MeshPart* last = out_->parts.empty() ? nullptr : &out_->parts.back();
    if (last && sameLook(*last, part) && last->instances.empty() && part.instances.empty() &&
        last->firstIndex + last->indexCount == part.firstIndex)
        last->indexCount += part.indexCount;
    else if (part.indexCount > 0)
        out_->parts.push_back(part);
}

// A glTF camera looks down its node's -Z with +Y up (glTF 2.0, 3.10.1); only the first node using it counts.
void GltfReader::addCamera(int ci, const glm::mat4& world) {
    if (std::find(cameraIndices_.begin(), cameraIndices_.end(), ci) != cameraIndices_.end()) return;
    const tinygltf::Camera& c = model_.cameras[std::size_t(ci)];
    GltfCamera cam;
    cam.name = c.name.empty() ? "camera " + std::to_string(ci) : c.name;
    cam.perspective = c.type != "orthographic";
    cam.eye = glm::vec3(world[3]);
    const glm::vec3 forward = safeNormalize(glm::mat3(world) * glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 0.0f, -1.0f));
    cam.target = cam.eye + forward;  // moved onto the model once its bounds are known (read())
    cam.up = safeNormalize(glm::mat3(world) * glm::vec3(0.0f, 1.0f, 0.0f));
    if (cam.perspective) {
        cam.yfovDeg = float(glm::degrees(c.perspective.yfov));
        cam.znear = float(c.perspective.znear);
        cam.zfar = float(c.perspective.zfar);
    }
    cameraIndices_.push_back(ci);
    info_.cameras.push_back(cam);
}

// A node's KHR_lights_punctual light: at the node's origin, pointing down its -Z (glTF 2.0's
// convention for lights and cameras). Values the extension forbids are refused; a light past
// kMaxLights is left out with a warning.
void GltfReader::addLight(const tinygltf::Node& n, int ni, const glm::mat4& world) {
    const auto ext = n.extensions.find("KHR_lights_punctual");
    if (ext == n.extensions.end() || !ext->second.Has("light")) return;
    const std::string where = "node " + std::to_string(ni) + " KHR_lights_punctual";
    const tinygltf::Value& index = ext->second.Get("light");
    if (!index.IsInt() || index.GetNumberAsInt() < 0 || std::size_t(index.GetNumberAsInt()) >= model_.lights.size())
        fail(where, "light " + std::to_string(index.IsNumber() ? index.GetNumberAsInt() : -1) + " does not exist");
    const tinygltf::Light& src = model_.lights[std::size_t(index.GetNumberAsInt())];
    const std::string name = "light " + std::to_string(index.GetNumberAsInt());
    if (info_.lights.size() >= std::size_t(kMaxLights)) {
        if (lightsLeftOut_++ == 0)
            info_.warnings.push_back("more than " + std::to_string(kMaxLights) + " lights: only the first " +
                                     std::to_string(kMaxLights) + " the scene reaches are drawn");
        return;
    }
    GltfLight out;
    out.name = src.name.empty() ? name : src.name;
    Light& l = out.light;
    const std::optional<LightType> type = valueNamed(kPunctualLightTypeNames, src.type);
    if (!type) fail(name, "type \"" + src.type + "\" is not " + namesList(kPunctualLightTypeNames, ", ", " or "));
    l.type = *type;
    if (!std::isfinite(src.intensity) || src.intensity < 0.0) fail(name, "intensity must be a finite number >= 0");
    l.intensity = float(src.intensity);
    if (src.color.size() >= 3) {
        const glm::vec3 c(float(src.color[0]), float(src.color[1]), float(src.color[2]));
        if (!isFinite(c)) fail(name, "color is not finite");
        l.color = glm::clamp(c, 0.0f, 1.0f);
    } else {
        l.color = glm::vec3(1.0f);
    }
    l.position = glm::vec3(world[3]);
    l.direction = safeNormalize(glm::mat3(world) * glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 0.0f, -1.0f));
    if (l.type != LightType::Directional) {
        // Physical point lights fall off with 1/r^2, windowed to zero at the range when there is one
        // (the extension's recommendation, shadelab's "range").
        l.attenuation = Attenuation::InverseSquare;
        l.range = std::isfinite(src.range) && src.range > 0.0 ? float(src.range) : 0.0f;
    }
    if (l.type == LightType::Spot) {
        const double inner = src.spot.innerConeAngle, outer = src.spot.outerConeAngle;
        if (!std::isfinite(inner) || !std::isfinite(outer) || inner < 0.0 || outer <= inner || outer > 1.5707963268 + 1e-6)
            fail(name, "spot cone angles must satisfy 0 <= innerConeAngle < outerConeAngle <= pi/2");
        l.outerConeDeg = std::clamp(float(glm::degrees(outer)), float(kSpotOuterConeDegRange.lo), kSpotConeDegRange.hi);
        l.innerConeDeg = std::clamp(float(glm::degrees(inner)), 0.0f, std::max(l.outerConeDeg - 0.01f, 0.0f));
    }
    info_.lights.push_back(std::move(out));
}

// Every node drawn is a copy of its meshes in the baked mesh: at most this many, whatever the file's size.
constexpr int kMaxNodeInstances = 1000000;

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

// The node's own transform once, or once per instance of EXT_mesh_gpu_instancing: T * R * S from its
// TRANSLATION, ROTATION and SCALE accessors (each optional; quantized types as the extension allows).
std::vector<glm::mat4> GltfReader::instances(int ni, const tinygltf::Node& n) {
    const auto ext = n.extensions.find("EXT_mesh_gpu_instancing");
    if (ext == n.extensions.end()) return {glm::mat4(1.0f)};
    const std::string where = "node " + std::to_string(ni) + " EXT_mesh_gpu_instancing";
    if (!ext->second.Has("attributes") || !ext->second.Get("attributes").IsObject()) fail(where, "has no attributes");
    const tinygltf::Value& attributes = ext->second.Get("attributes");
    std::optional<View> translation, rotation, scale;
    std::size_t count = 0;
    bool counted = false;
    const auto read = [&](const char* name, int type, const std::vector<int>& componentTypes, std::optional<View>& out) {
        if (!attributes.Has(name)) return;
        out = view(attributes.Get(name).GetNumberAsInt(), where + " " + name, {type}, componentTypes);
        if (counted && out->count != count) fail(where, std::string(name) + " counts differ from the other attributes");
        count = out->count, counted = true;
    };
    read("TRANSLATION", TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT}, translation);
    read("ROTATION", TINYGLTF_TYPE_VEC4, {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT},
         rotation);
    read("SCALE", TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT}, scale);
    if (!counted) fail(where, "has none of TRANSLATION, ROTATION and SCALE");
    if (count == 0) fail(where, "has no instances");
    if (std::size_t(info_.nodes) + count > std::size_t(kMaxNodeInstances))
        fail(where, "more than " + std::to_string(kMaxNodeInstances) + " instances in the scene");
    info_.nodes += int(count) - 1;  // the node itself is already counted
    std::vector<glm::mat4> out(count, glm::mat4(1.0f));
    for (std::size_t i = 0; i < count; ++i) {
        glm::mat4& m = out[i];
        if (translation) m = glm::translate(m, glm::vec3(scalarAt(*translation, i, 0), scalarAt(*translation, i, 1), scalarAt(*translation, i, 2)));
        if (rotation)  // x, y, z, w as in a node's rotation
            m *= glm::mat4_cast(glm::normalize(glm::quat(scalarAt(*rotation, i, 3), scalarAt(*rotation, i, 0),
                                                         scalarAt(*rotation, i, 1), scalarAt(*rotation, i, 2))));
        if (scale) m = glm::scale(m, glm::vec3(scalarAt(*scale, i, 0), scalarAt(*scale, i, 1), scalarAt(*scale, i, 2)));
    }
    return out;
}

void GltfReader::visit(int ni, const glm::mat4& parent, int depth) {
    if (ni < 0 || std::size_t(ni) >= model_.nodes.size()) fail("node " + std::to_string(ni), "does not exist");
    if (depth > 256) fail("node " + std::to_string(ni), "node hierarchy deeper than 256 (a cycle?)");
    const tinygltf::Node& n = model_.nodes[std::size_t(ni)];
    glm::mat4 local(1.0f);
    if (n.matrix.size() == 16) {
        local = glm::make_mat4(n.matrix.data());
    } else {
        if (n.translation.size() == 3)
            local = glm::translate(local, glm::vec3(float(n.translation[0]), float(n.translation[1]), float(n.translation[2])));
        if (n.rotation.size() == 4)  // glTF stores x, y, z, w
            local *= glm::mat4_cast(glm::quat(float(n.rotation[3]), float(n.rotation[0]), float(n.rotation[1]),
                                              float(n.rotation[2])));
        if (n.scale.size() == 3) local = glm::scale(local, glm::vec3(float(n.scale[0]), float(n.scale[1]), float(n.scale[2])));
    }
    const glm::mat4 world = parent * local;
    // A translation of 1e39 is +inf as a float; finite scales can multiply past the float range.
    if (!isFinite(world)) fail("node " + std::to_string(ni), "its transform (with its parents') is not finite");
    // The depth limit does not bound the work: a child listed twice at each of 40 levels is 2^40 visits.
    if (info_.nodes >= kMaxNodeInstances)
        fail("node " + std::to_string(ni), "more than " + std::to_string(kMaxNodeInstances) +
                                               " node instances in the scene (children listed many times?)");
    info_.nodes += 1;
    if (!instancedPass_) {
        if (n.camera >= 0 && std::size_t(n.camera) < model_.cameras.size()) addCamera(n.camera, world);
        addLight(n, ni, world);
    }
    if (n.mesh >= 0) {
        if (std::size_t(n.mesh) >= model_.meshes.size()) fail("node " + std::to_string(ni), "mesh " + std::to_string(n.mesh) + " does not exist");
        const tinygltf::Mesh& m = model_.meshes[std::size_t(n.mesh)];
        currentNode_ = ni;
        const std::vector<glm::mat4> copies = instances(ni, n);
        instanced_ = instanced_ || copies.size() > 1;
        if (instancedPass_ && copies.size() > 1) {
            // Once, baked with the first instance's transform; the others relative to it.
            const glm::mat4 first = world * copies[0];
            const glm::mat4 firstInverse = glm::inverse(first);
            std::vector<glm::mat4> relative;
            for (const glm::mat4& instance : copies) relative.push_back(world * instance * firstInverse);
            relative[0] = glm::mat4(1.0f);
            for (std::size_t k = 0; k < m.primitives.size(); ++k)
                addPrimitive(m.primitives[k], first, "mesh " + std::to_string(n.mesh) + " primitive " + std::to_string(k), relative);
        } else {
            for (const glm::mat4& instance : copies) {
                const glm::mat4 instanceWorld = world * instance;
                if (!isFinite(instanceWorld)) fail("node " + std::to_string(ni), "an instance's transform is not finite");
                for (std::size_t k = 0; k < m.primitives.size(); ++k)
                    addPrimitive(m.primitives[k], instanceWorld, "mesh " + std::to_string(n.mesh) + " primitive " + std::to_string(k));
            }
        }
    }
    for (int child : n.children) visit(child, world, depth + 1);
}

// Whether every instance transform of the instanced pass is finite and invertible (a zero scale is
// not): otherwise the baked mesh is drawn as it is.
bool instancesInvertible(const Mesh& m) {
    for (const MeshPart& part : m.parts)
        for (const glm::mat4& t : part.instances)
            if (!isFinite(t) || !(std::fabs(glm::determinant(glm::mat3(t))) > 1e-12f)) return false;
    return true;
}

Mesh GltfReader::read() {
    const std::vector<int> roots = rootNodes();
    for (int r : roots) visit(r, glm::mat4(1.0f), 0);
    if (instanced_) readInstanced(roots);
    summarise();
    if (mesh_.indices.empty()) info_.warnings.push_back("nothing to draw: the default scene has no triangles");
    completeTangents(mesh_);  // TANGENT where given, else from the texture coordinates or the up axis
    return std::move(mesh_);
}

// The default scene's nodes (the first scene's where none is named); with no scene, every node that
// is nobody's child.
std::vector<int> GltfReader::rootNodes() const {
    std::vector<int> roots;
    if (!model_.scenes.empty()) {
        const int si = model_.defaultScene >= 0 ? model_.defaultScene : 0;
        if (std::size_t(si) >= model_.scenes.size()) fail("scene", std::to_string(si) + " does not exist");
        return model_.scenes[std::size_t(si)].nodes;
    }
    std::vector<bool> isChild(model_.nodes.size(), false);
    for (const auto& n : model_.nodes)
        for (int c : n.children)
            if (c >= 0 && std::size_t(c) < isChild.size()) isChild[std::size_t(c)] = true;
    for (std::size_t i = 0; i < model_.nodes.size(); ++i)
        if (!isChild[i]) roots.push_back(int(i));
    return roots;
}

// GPU instancing: the same scene again with each instanced node's primitives once and its instances
// as transforms (MeshPart::instances), for the renderer's instanced draws. The baked mesh of the first
// walk stays what everything else reads (bounds, the probe, overlays).
void GltfReader::readInstanced(const std::vector<int>& roots) {
    const GltfInfo baked = info_;
    auto compact = std::make_shared<Mesh>();
    out_ = compact.get();
    instancedPass_ = true;
    info_.nodes = 0, info_.triangles = 0, info_.primitives = 0, info_.generatedNormals = 0;  // limits count one walk
    for (int r : roots) visit(r, glm::mat4(1.0f), 0);
    out_ = &mesh_;
    instancedPass_ = false;
    info_ = baked;
    compact->textures = mesh_.textures;
    completeTangents(*compact);
    if (instancesInvertible(*compact)) mesh_.instanced = std::move(compact);
}

// What the file holds and what was drawn (info_'s counts and bounds), and each camera's target.
void GltfReader::summarise() {
    info_.meshes = int(model_.meshes.size());
    info_.materials = int(model_.materials.size());
    info_.doubleSidedMaterials = int(std::count_if(model_.materials.begin(), model_.materials.end(),
                                                   [](const tinygltf::Material& m) { return m.doubleSided; }));
    info_.vertices = mesh_.positions.size();
    info_.textures = int(mesh_.textures.size());
    // TRIANGLES primitives of every mesh, each counted once (what the file holds, drawn or not).
    for (const tinygltf::Mesh& m : model_.meshes)
        for (const tinygltf::Primitive& p : m.primitives) {
            if (p.mode >= 0 && p.mode != TINYGLTF_MODE_TRIANGLES) continue;
            const int counted = p.indices >= 0 ? p.indices : (p.attributes.count("POSITION") ? p.attributes.at("POSITION") : -1);
            if (counted >= 0 && std::size_t(counted) < model_.accessors.size())
                info_.fileTriangles += model_.accessors[std::size_t(counted)].count / 3;
        }
    if (!mesh_.positions.empty()) {
        info_.boundsMin = info_.boundsMax = mesh_.positions.front();
        for (const glm::vec3& p : mesh_.positions) {
            info_.boundsMin = glm::min(info_.boundsMin, p);
            info_.boundsMax = glm::max(info_.boundsMax, p);
        }
    }
    // Each camera's target: the point of its view axis nearest the model's centre (at least its near plane
    // ahead), so the viewer orbits about the model as the file's camera sees it.
    const glm::vec3 centre = 0.5f * (info_.boundsMin + info_.boundsMax);
    for (GltfCamera& c : info_.cameras) {
        const glm::vec3 forward = c.target - c.eye;
        c.target = c.eye + forward * std::max(glm::dot(centre - c.eye, forward), std::max(c.znear, 1e-3f) * 2.0f);
    }
}

}  // namespace

namespace {

// A .glb: a 12-byte header, a JSON chunk and an optional BIN chunk that holds buffer 0. tinygltf's own
// .glb loader copies the BIN chunk out of the file's bytes, so a large model was in memory twice; here
// the chunks are found first, tinygltf parses the JSON, and buffer 0 is read from its range of the file
// (or of the bytes in memory) straight into tinygltf's buffer, once.
struct GlbLayout {
    std::string json;
    bool hasBin = false;
    std::uint64_t binOffset = 0, binLength = 0;
};

using ByteReader = std::function<void(std::uint64_t offset, std::size_t length, unsigned char* out)>;

std::uint32_t readU32(const unsigned char* b) {
    return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[3]) << 24;
}

GlbLayout splitGlb(std::uint64_t available, const ByteReader& read, const std::string& label) {
    auto bad = [&](const std::string& why) { return InputError(label + ": not a valid .glb: " + why); };
    if (available < 20) throw bad("shorter than its 12-byte header and first chunk header");
    unsigned char head[20];
    read(0, sizeof head, head);
    const std::uint32_t version = readU32(head + 4), total = readU32(head + 8);
    const std::uint32_t jsonLength = readU32(head + 12), jsonType = readU32(head + 16);
    if (version != 2) throw bad("version " + std::to_string(version) + " (only glTF 2.0 is read)");
    if (total > available)
        throw bad("the header says " + std::to_string(total) + " bytes, the file has " + std::to_string(available));
    // Before any length is taken from it: `total - 20` must not wrap.
    if (total < 20) throw bad("the header says " + std::to_string(total) + " bytes, less than its own headers");
    if (jsonType != 0x4E4F534Au) throw bad("the first chunk is not JSON");
    if (std::uint64_t(jsonLength) > std::uint64_t(total) - 20)
        throw bad("the JSON chunk's length " + std::to_string(jsonLength) + " runs past the end");
    GlbLayout g;
    g.json.resize(jsonLength);
    read(20, jsonLength, reinterpret_cast<unsigned char*>(g.json.data()));
    const std::uint64_t next = 20 + std::uint64_t(jsonLength);
    if (next + 8 <= total) {
        unsigned char chunk[8];
        read(next, sizeof chunk, chunk);
        const std::uint32_t binLength = readU32(chunk), binType = readU32(chunk + 4);
        if (binType == 0x004E4942u) {
            if (std::uint64_t(binLength) > total - next - 8)
                throw bad("the BIN chunk's length " + std::to_string(binLength) + " runs past the end");
            g.hasBin = true;
            g.binOffset = next + 8;
            g.binLength = binLength;
        }
    }
    return g;
}

// What the file-system callbacks need: the folder URIs are confined to and, for a .glb, where buffer 0
// is (tinygltf asks for it by a URI that names no file: kGlbBinUri joined onto the folder).
constexpr const char* kGlbBinUri = "<GLB BIN chunk>";
struct LoadContext {
    fs::path folder;
    // The path tinygltf asks the callbacks for when it looks for `uri`: joined onto the folder with
    // '/' as its JoinPath does, whatever the platform's separator ('\\' in the folder on Windows).
    std::string pathOf(const std::string& uri) const {
        std::string out = folder.string();
        if (out.empty()) return uri;
        if (out.back() != '/') out += '/';
        return out + uri;
    }
    std::string binPath;  // pathOf(kGlbBinUri); empty unless a .glb's buffer 0 is its BIN chunk
    std::uint64_t binOffset = 0, binLength = 0;
    const ByteReader* read = nullptr;
    std::string* release = nullptr;  // bytes to free once tinygltf has parsed (it keeps what it needs)
    // A .gltf's base64 buffers, decoded by decodeDataUris(), by the path tinygltf asks for them by
    // (pathOf("<data URI i>")).
    std::map<std::string, std::vector<unsigned char>> decoded;
    GltfPrepass extensions;  // what the JSON step found (core/geometry/gltf_extensions)
};

// Standard base64 (RFC 4648, '=' padding); false on any other character.
bool decodeBase64(std::string_view in, std::vector<unsigned char>& out) {
    static const std::array<std::int8_t, 256> kValue = [] {
        std::array<std::int8_t, 256> t{};
        t.fill(-1);
        for (int i = 0; i < 26; ++i) t[std::size_t('A' + i)] = std::int8_t(i), t[std::size_t('a' + i)] = std::int8_t(26 + i);
        for (int i = 0; i < 10; ++i) t[std::size_t('0' + i)] = std::int8_t(52 + i);
        t[std::size_t('+')] = 62, t[std::size_t('/')] = 63;
        return t;
    }();
    std::size_t n = in.size();
    while (n > 0 && in.size() - n < 2 && in[n - 1] == '=') --n;
    if (n % 4 == 1) return false;
    out.resize(n / 4 * 3 + (n % 4 == 0 ? 0 : n % 4 - 1));
    std::uint32_t bits = 0;
    int count = 0;
    std::size_t o = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const std::int8_t v = kValue[static_cast<unsigned char>(in[i])];
        if (v < 0) return false;
        bits = (bits << 6) | std::uint32_t(v);
        if (++count == 4) {
            out[o++] = static_cast<unsigned char>(bits >> 16);
            out[o++] = static_cast<unsigned char>(bits >> 8);
            out[o++] = static_cast<unsigned char>(bits);
            bits = 0, count = 0;
        }
    }
    if (count == 2) out[o++] = static_cast<unsigned char>(bits >> 4);
    if (count == 3) {
        out[o++] = static_cast<unsigned char>(bits >> 10);
        out[o++] = static_cast<unsigned char>(bits >> 2);
    }
    return o == out.size();
}

// A .gltf's buffers embedded as base64 data: URIs, decoded here and handed to tinygltf through the
// file callbacks: its own decoder takes ~15 ns a character (the 200k sphere's 6.4 MB: ~100 ms of a
// 0.2 s --output), and its JSON parser then skips a few bytes instead of megabytes. Anything this
// does not recognise is left as it is, for tinygltf to read or to report.
bool decodeDataUris(nlohmann::json& doc, LoadContext& context, const std::string& label) {
    const auto buffers = doc.find("buffers");
    if (buffers == doc.end() || !buffers->is_array()) return false;
    bool changed = false;
    for (std::size_t i = 0; i < buffers->size(); ++i) {
        nlohmann::json& buffer = (*buffers)[i];
        if (!buffer.is_object()) continue;
        const auto uri = buffer.find("uri");
        if (uri == buffer.end() || !uri->is_string()) continue;
        const std::string& text = uri->get_ref<const std::string&>();
        std::string_view data;
        for (const char* prefix : {"data:application/octet-stream;base64,", "data:application/gltf-buffer;base64,"})
            if (text.rfind(prefix, 0) == 0) data = std::string_view(text).substr(std::strlen(prefix));
        if (data.empty()) continue;
        const std::string sentinel = "<data URI " + std::to_string(i) + ">";
        std::vector<unsigned char>& bytes = context.decoded[context.pathOf(sentinel)];
        if (!decodeBase64(data, bytes))
            throw InputError(label + ": buffer " + std::to_string(i) + ": its data: URI is not valid base64");
        buffer["uri"] = sentinel;
        changed = true;
    }
    return changed;
}

// The JSON of a .glb with buffer 0 pointed at the BIN chunk (kGlbBinUri) when it is stored there.
bool pointBufferAtBin(nlohmann::json& doc, const GlbLayout& g, const std::string& label, LoadContext& context,
                      const ByteReader& read) {
    const auto buffers = doc.find("buffers");
    if (buffers == doc.end() || !buffers->is_array() || buffers->empty() || !(*buffers)[0].is_object() ||
        (*buffers)[0].contains("uri"))
        return false;  // buffer 0 is external or embedded as a data: URI, or there is none
    nlohmann::json& buffer = (*buffers)[0];
    if (!g.hasBin) throw InputError(label + ": buffer 0 has no uri and the .glb has no BIN chunk");
    const auto length = buffer.find("byteLength");
    if (length == buffer.end() || !length->is_number_unsigned())
        throw InputError(label + ": buffer 0: byteLength is missing or not a non-negative integer");
    if (length->get<std::uint64_t>() > g.binLength)
        throw InputError(label + ": buffer 0: byteLength " + std::to_string(length->get<std::uint64_t>()) +
                         " is more than the BIN chunk's " + std::to_string(g.binLength) + " bytes");
    context.binPath = context.pathOf(kGlbBinUri);
    context.binOffset = g.binOffset;
    context.binLength = length->get<std::uint64_t>();
    context.read = &read;
    buffer["uri"] = kGlbBinUri;
    return true;
}

// The JSON as tinygltf will read it: extensions checked and prepared (core/geometry/gltf_extensions), a .glb's
// buffer 0 pointed at its BIN chunk, base64 buffers decoded here. Parsed once; text that does not
// parse is handed on as it is, for tinygltf to say what is wrong with it.
std::string prepareJson(std::string json, LoadContext& context, const std::string& label, const GlbLayout* glb,
                        const ByteReader* read) {
    nlohmann::json doc = nlohmann::json::parse(json, nullptr, false);
    if (doc.is_discarded() || !doc.is_object()) {
        if (glb) throw InputError(label + ": the .glb's JSON chunk is not a JSON object");
        return json;
    }
    bool changed = prepareGltfExtensions(doc, label, context.extensions);
    for (int i : context.extensions.fallbackBuffers)  // stand-ins: one byte each, never read
        context.decoded[context.pathOf(doc["buffers"][std::size_t(i)]["uri"].get<std::string>())] = {0};
    if (glb) changed = pointBufferAtBin(doc, *glb, label, context, *read) || changed;
    if (json.find(";base64,") != std::string::npos) changed = decodeDataUris(doc, context, label) || changed;
    return changed ? doc.dump() : json;
}

// tinygltf's file callbacks over a LoadContext: the .glb's BIN chunk and decoded data: URIs from
// memory, other files only from inside the model's folder. FileExists answers "yes" for a path outside
// the folder so that tinygltf goes on to read it and ReadWholeFile can refuse it with a message that
// says why (rather than "file not found").
bool modelFileExists(const std::string& p, void* user) {
    const LoadContext& c = *static_cast<const LoadContext*>(user);
    std::error_code ec;  // a symlink loop or an over-long name is "no such file", never an exception
    return p == c.binPath || c.decoded.count(p) || !insideFolder(p, c.folder) || fs::is_regular_file(fs::path(p), ec);
}

bool readModelFile(std::vector<unsigned char>* out, std::string* err, const std::string& p, void* user) {
    LoadContext& c = *static_cast<LoadContext*>(user);
    if (const auto d = c.decoded.find(p); d != c.decoded.end()) {
        out->swap(d->second);  // asked for once, by the buffer that names it
        return true;
    }
    if (!c.binPath.empty() && p == c.binPath) {
        out->resize(std::size_t(c.binLength));
        (*c.read)(c.binOffset, out->size(), out->data());
        return true;
    }
    if (!insideFolder(p, c.folder) || !insideFolderResolved(p, c.folder)) {
        if (err) *err += "refused URI outside the model's folder: " + p;
        return false;
    }
    std::error_code e;
    const fs::path full(p);
    const std::uintmax_t fileSize = fs::file_size(full, e);
    if (e || fileSize > (std::uintmax_t(1) << 31)) {
        if (err) *err += "cannot read " + p;
        return false;
    }
    std::FILE* f = platform::openFile(full, "rb");
    if (!f) {
        if (err) *err += "cannot open " + p;
        return false;
    }
    const std::size_t size = std::size_t(fileSize);  // at most 2 GiB: fits a 32-bit size_t (the web build)
    out->resize(size);
    const bool ok = std::fread(out->data(), 1, size, f) == size;
    std::fclose(f);
    if (!ok && err) *err += "cannot read " + p;
    return ok;
}

Mesh parseGltf(std::string json, LoadContext& context, const std::string& path, GltfInfo* infoOut) {
    GltfInfo info;
    tinygltf::TinyGLTF loader;
    tinygltf::FsCallbacks fsc{};
    fsc.FileExists = modelFileExists;
    fsc.ExpandFilePath = [](const std::string& p, void*) { return p; };
    fsc.ReadWholeFile = readModelFile;
    fsc.WriteWholeFile = nullptr;
    fsc.user_data = &context;
    loader.SetFsCallbacks(fsc);
    // Images are decoded later, and only those a base colour texture uses (GltfReader::textureSlot):
    // here a URI's bytes are kept as they are. An image in a buffer view is read from the view then,
    // with its range checked (tinygltf hands it over unchecked).
    loader.SetImageLoader(
        [](tinygltf::Image* image, const int, std::string*, std::string*, int, int, const unsigned char* bytes, int size,
           void*) {
            if (image->bufferView < 0 && bytes && size > 0) image->image.assign(bytes, bytes + size);
            return true;
        },
        nullptr);

    tinygltf::Model model;
    std::string err, warn;
    const bool ok = loader.LoadASCIIFromString(&model, &err, &warn, json.data(), static_cast<unsigned int>(json.size()),
                                               context.folder.string());
    // tinygltf copied what it needs: a large file's bytes (a .gltf's data: URIs) need not stay.
    std::string().swap(json);
    if (context.release) std::string().swap(*context.release);
    if (!ok || !err.empty()) {
        std::string msg = err.empty() ? "not a valid glTF file" : err;
        while (!msg.empty() && (msg.back() == '\n' || msg.back() == ' ')) msg.pop_back();
        for (char& c : msg)
            if (c == '\n') c = ';';
        throw InputError(path + ": " + msg);
    }
    decodeCompressedGltf(model, context.extensions, path);
    info.warnings = context.extensions.warnings;
    Mesh mesh = GltfReader(path, model, info).read();
    if (infoOut) *infoOut = std::move(info);
    return mesh;
}

// A .glb through a reader of its bytes (a file or memory).
Mesh parseGlb(std::uint64_t size, const ByteReader& read, const std::string& path, const fs::path& folder,
              GltfInfo* infoOut, std::string* release = nullptr) {
    const GlbLayout layout = splitGlb(size, read, path);
    checkJsonDepth(layout.json, path);
    LoadContext context;
    context.folder = folder;
    std::string json = prepareJson(layout.json, context, path, &layout, &read);
    if (json.size() > std::uint64_t(~0u)) throw InputError(path + ": the JSON chunk is too large");
    context.release = release;
    return parseGltf(std::move(json), context, path, infoOut);
}

}  // namespace

Mesh loadGltf(const std::string& path, GltfInfo* infoOut) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) throw InputError(path + ": cannot read: no such file");
    const fs::path folder = fs::absolute(fs::path(path), ec).parent_path().lexically_normal();
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec) throw InputError(path + ": cannot read: " + ec.message());
    if (size > (std::uintmax_t(1) << 31)) throw InputError(path + ": cannot read: larger than 2048 MiB");
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(platform::openFile(path, "rb"), &std::fclose);
    if (!file) throw InputError(path + ": cannot read: " + std::strerror(errno));
    char magic[4] = {};
    const bool glb = std::fread(magic, 1, 4, file.get()) == 4 && std::memcmp(magic, "glTF", 4) == 0;
    if (!glb) {
        file.reset();
        return loadGltfFromMemory(readTextFile(path, std::uint64_t(1) << 31), path, folder.string(), infoOut);
    }
    // A .glb is read a chunk at a time: the JSON, then buffer 0 straight into tinygltf's buffer.
    const ByteReader read = [&](std::uint64_t offset, std::size_t length, unsigned char* out) {
        if (std::fseek(file.get(), long(offset), SEEK_SET) != 0 || std::fread(out, 1, length, file.get()) != length)
            throw InputError(path + ": cannot read: I/O error");
    };
    return parseGlb(size, read, path, folder, infoOut);
}

Mesh loadGltfFromMemory(std::string bytes, const std::string& label, const std::string& folderName,
                        GltfInfo* infoOut) {
    const fs::path folder(folderName);
    // A .glb starts with the magic "glTF"; anything else is read as JSON.
    if (bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0) {
        const ByteReader read = [&](std::uint64_t offset, std::size_t length, unsigned char* out) {
            std::memcpy(out, bytes.data() + offset, length);  // splitGlb checked every range against the size
        };
        return parseGlb(bytes.size(), read, label, folder, infoOut, &bytes);
    }
    if (bytes.size() > std::uint64_t(~0u)) throw InputError(label + ": larger than 4 GiB");
    checkJsonDepth(bytes, label);
    LoadContext context;
    context.folder = folder;
    std::string json = prepareJson(std::move(bytes), context, label, nullptr, nullptr);
    return parseGltf(std::move(json), context, label, infoOut);
}
std::string describe(const std::string& path, const GltfInfo& i) {
    auto vec = [](const glm::vec3& v) {
        char b[96];
        std::snprintf(b, sizeof b, "[%g, %g, %g]", double(v.x), double(v.y), double(v.z));
        return std::string(b);
    };
    std::string s;
    s += "model: " + path + "\n";
    s += "nodes: " + std::to_string(i.nodes) + " (in the drawn scene)\n";
    s += "meshes: " + std::to_string(i.meshes) + "\n";
    s += "materials: " + std::to_string(i.materials) + "\n";
    if (i.doubleSidedMaterials > 0)
        s += "double-sided materials: " + std::to_string(i.doubleSidedMaterials) + " (both sides drawn, the back lit with its normal flipped)\n";
    s += "textures: " + std::to_string(i.textures) + " base colour image" + (i.textures == 1 ? "" : "s") + " drawn\n";
    s += "primitives: " + std::to_string(i.primitives) + " drawn\n";
    s += "triangles: " + std::to_string(i.fileTriangles) + " in the file's TRIANGLES primitives, " +
         std::to_string(i.triangles) + " drawn\n";
    s += "vertices: " + std::to_string(i.vertices) + "\n";
    s += "bounds: min " + vec(i.boundsMin) + " max " + vec(i.boundsMax) + "\n";
    for (std::size_t c = 0; c < i.cameras.size(); ++c)
        s += "camera " + std::to_string(c) + ": " + i.cameras[c].name +
             (i.cameras[c].perspective ? ", perspective, " + std::to_string(int(std::lround(i.cameras[c].yfovDeg))) + " degrees"
                                       : std::string(", orthographic (not drawn: shadelab's views are perspective)")) +
             " (--camera " + std::to_string(c) + ")\n";
    for (std::size_t l = 0; l < i.lights.size(); ++l) {
        const Light& light = i.lights[l].light;
        char b[160];
        std::snprintf(b, sizeof b, "light %zu: %s, %s, %g %s", l, i.lights[l].name.c_str(), toString(light.type),
                      double(light.intensity), light.type == LightType::Directional ? "lux" : "cd");
        s += std::string(b) + (light.type == LightType::Directional ? " toward " + vec(light.direction) : " at " + vec(light.position)) +
             " (lights the scene when it gives no lights)\n";
    }
    s += "normals: " + (i.generatedNormals ? "generated for " + std::to_string(i.generatedNormals) + " vertices"
                                             : std::string("from the file")) + "\n";
    for (const std::string& w : i.warnings) s += "warning: " + w + "\n";
    return s;
}

}  // namespace shadelab
