#pragma once
// What the glTF importer's parts share: GltfReader, which turns a parsed tinygltf::Model into one
// Mesh, its limits and isFinite(). Internal to core/geometry; gltf_import.hpp is the public interface.
// GltfReader's members are defined where their job is:
//   gltf_container.cpp  reading .gltf and .glb, URIs (data:, external, refused); the parsed model to GltfReader
//   gltf_accessors.cpp  accessors (ranges, sparse, normalisation) and the vertex attributes read from them
//   gltf_primitives.cpp a primitive into the mesh: triangulated, baked with its node's transform, appended
//   gltf_materials.cpp  base colour, emission, textures, samplers and the materials' KHR extensions
//   gltf_scene.cpp      the node walk: transforms, instancing, cameras, lights, the summary and describe()
#include "core/base/error.hpp"
#include "core/geometry/gltf_import.hpp"

#include <tiny_gltf.h>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace shadelab::gltf_import_parts {

constexpr std::size_t kMaxTriangles = 50'000'000;  // ~1.8 GB of vertex data after baking: refuse beyond

inline bool isFinite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
inline bool isFinite(const glm::mat4& m) {
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
    void materialiseSparse(const tinygltf::Accessor& a, std::size_t elementSize, const std::string& name,
                           View& v) const;
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
    void bakeVertices(std::vector<glm::vec3>&& positions, std::vector<glm::vec3>&& normals,
                      const glm::mat4& worldFromObject, int positionAccessor, const std::string& where);
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
        int slot = -1;              // index into mesh_.textures
        int texCoord = 0;           // which TEXCOORD_n
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
    std::vector<glm::vec4> vertexColors(const tinygltf::Primitive& p, std::size_t count,
                                        const std::string& where) const;
    // TANGENT (xyz, w the handedness), or empty; appended to *out_ baked with `world` (w = 0 where a
    // primitive has none: completeTangents fills those).
    std::vector<glm::vec4> readTangents(const tinygltf::Primitive& p, std::size_t count,
                                        const std::string& where) const;
    void appendTangents(std::uint32_t base, std::size_t count, const std::vector<glm::vec4>& tangents,
                        const glm::mat4& world);
    std::map<std::pair<int, int>, int> textureSlots_;  // (image, sampler) -> slot, or -1

    const std::string& path_;
    const tinygltf::Model& model_;
    GltfInfo& info_;
    Mesh mesh_;
    Mesh* out_ = &mesh_;          // where addPrimitive appends: mesh_, or the instanced pass's mesh
    bool instancedPass_ = false;  // read()'s second walk (a file with EXT_mesh_gpu_instancing)
    bool instanced_ = false;      // a node drew more than one instance
    int currentNode_ = -1;        // the node whose meshes addPrimitive is baking
};

}  // namespace shadelab::gltf_import_parts
