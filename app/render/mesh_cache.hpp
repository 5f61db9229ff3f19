#pragma once
// The renderer's copy of a scene's meshes on the GPU: per object, its parts (a glTF primitive each,
// or the whole mesh), a vertex array per shading mode (smooth: positions and normals; flat: a
// provoking vertex per triangle with its centroid and face normal, FlatMesh), uploaded on first use
// in the order RendererOptions::meshOrder asks; its GPU instances (EXT_mesh_gpu_instancing) split by
// handedness; and its base colour textures. GL-free work (ordering, flat meshes) is in core.
#include "core/geometry/scene_geometry.hpp"
#include "core/scene/scene.hpp"
#include "render/cpu/shadow_projection.hpp"
#include "render/gl_handles.hpp"
#include "render/renderer_options.hpp"

#include <glm/mat4x4.hpp>

#include <array>
#include <memory>
#include <vector>

namespace shadelab {

class MeshCache {
public:
    explicit MeshCache(const RendererOptions& options);

    // Replaces the meshes; nothing is uploaded until it is drawn.
    void setGeometry(std::shared_ptr<const SceneGeometry> geometry);
    // Uploads what `modes` draw (and the textures), then lets go of the CPU copy: a one-frame
    // headless render of a large model need not hold it twice. After this only `modes` can be drawn.
    // `tangents`: per object, whether its anisotropic vertex arrays are drawn too (empty: none are).
    void uploadAndRelease(const std::vector<ShadingMode>& modes, bool textures, const std::vector<char>& tangents = {});

    std::size_t objects() const { return objects_.size(); }
    const std::vector<MeshPart>& parts(std::size_t object) const { return objects_[object].parts; }
    const Aabb& box(std::size_t object) const { return objects_[object].box; }  // object space, every instance
    std::size_t triangles(std::size_t object) const { return objects_[object].triangles; }
    bool variesColor(std::size_t object) const {
        return objects_[object].variesColor;
    }  // texture coordinates and colours
    bool hasEmissiveTexture(std::size_t object) const {
        return objects_[object].emissiveTexture;
    }  // and emissive coordinates
    // A blended part's bounds in object space (of the vertices it draws once; an instanced part's before
    // its instances), for the back-to-front order; empty for other parts.
    const Aabb& partBox(std::size_t object, std::size_t part) const { return objects_[object].partBoxes[part]; }

    struct GpuMesh {
        gl::VertexArray vao;
        gl::Buffer vertices;  // interleaved positions, normals and (flat) centroids, texture coordinates and colours
        gl::Buffer indices;
        GLsizei indexCount = 0;
    };
    // The object's vertex array for `mode` (uploaded now if it was not). `tangents`: the anisotropic
    // draws' own arrays, the same vertices with each one's tangent (Mesh::tangents; flat:
    // FlatMesh::tangents) at SL_ATTRIB_TANGENT, flat's never packed. Other draws keep the arrays they had.
    const GpuMesh& gpuMesh(std::size_t object, ShadingMode mode, bool tangents = false);

    // An instanced part's transforms, split by handedness (a mirroring one turns the winding): one
    // instanced draw each, reading them from the object's instance buffer from `first` on.
    struct InstanceGroup {
        std::size_t part = 0;
        GLsizei first = 0, count = 0;
        bool mirrored = false;
    };
    const std::vector<InstanceGroup>& instanceGroups(std::size_t object) const {
        return objects_[object].instanceGroups;
    }
    const glm::mat4& instance(std::size_t object, std::size_t i) const { return objects_[object].instances[i]; }
    // Points the bound vertex array's SL_ATTRIB_INSTANCE attributes at the group's transforms.
    void bindInstances(std::size_t object, const InstanceGroup& group);

    // The GL texture of an object's Mesh::textures[slot] (uploaded on first use: sRGB, mipmapped as its
    // sampler asks), or a white texel for a part without one.
    GLuint texture(std::size_t object, int slot);

private:
    // The mesh an object's draws upload: its instanced form (Mesh::instanced) when it has one.
    const Mesh& drawnMesh(std::size_t object) const;
    // What gpuMesh() uploads: drawnMesh(), in vertex-cache order when RendererOptions::meshOrder asks
    // (kept in ObjectMesh::ordered until both of the object's uploads are done).
    const Mesh& uploadSource(std::size_t object);

    // Everything the cache keeps of one object.
    struct ObjectMesh {
        std::vector<MeshPart> parts;  // its parts (one for a plain mesh)
        std::array<GpuMesh, 4> gpu;   // [smooth, flat, smooth + tangents, flat + tangents]
        Mesh ordered;                 // with VertexCache: until both its uploads are done
        Aabb box;                     // object space, every instance (the baked mesh's)
        std::size_t triangles = 0;    // the baked mesh's
        bool variesColor = false, emissiveTexture = false;
        std::vector<Aabb> partBoxes;  // per part: a blended one's bounds, else empty
        std::vector<InstanceGroup> instanceGroups;
        std::vector<glm::mat4> instances;  // (the shadow pass draws them one by one)
        gl::Buffer instanceBuffer;         // mat4 each, made on the first instanced draw
        // Its base colour images until uploaded, and the textures made of them.
        std::vector<std::shared_ptr<const TextureImage>> images;
        std::vector<gl::Texture> textures;
    };
    // One object's entry, made from the mesh its draws upload (`drawn`) and the baked one (`baked`).
    static ObjectMesh describe(const Mesh& drawn, const Mesh& baked);

    const RendererOptions options_;
    std::shared_ptr<const SceneGeometry> geometry_;
    std::vector<ObjectMesh> objects_;
    gl::Texture whiteTexture_;
};

}  // namespace shadelab
