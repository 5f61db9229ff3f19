#include "render/mesh_cache.hpp"

#include "render/cpu/vertex_order.hpp"
#include "render/gpu_blocks.hpp"
#include "render/program.hpp"

#include <glm/common.hpp>
#include <glm/matrix.hpp>

#include <limits>
#include <stdexcept>

namespace shadelab {

namespace {

Aabb partBounds(const Mesh& mesh, const MeshPart& part) {
    Aabb box{glm::vec3(std::numeric_limits<float>::max()), glm::vec3(-std::numeric_limits<float>::max())};
    const std::size_t end = std::min<std::size_t>(std::size_t(part.firstIndex) + part.indexCount, mesh.indices.size());
    for (std::size_t i = part.firstIndex; i < end; ++i) {
        const glm::vec3& p = mesh.positions[mesh.indices[i]];
        box.lo = glm::min(box.lo, p);
        box.hi = glm::max(box.hi, p);
    }
    return end > part.firstIndex ? box : Aabb{};
}

}  // namespace

MeshCache::MeshCache(const RendererOptions& options) : options_(options) {}

void MeshCache::setGeometry(std::shared_ptr<const SceneGeometry> geometry) {
    geometry_ = std::move(geometry);
    objects_.clear();
    if (!geometry_) return;
    objects_.reserve(geometry_->meshes.size());
    for (std::size_t o = 0; o < geometry_->meshes.size(); ++o)
        objects_.push_back(describe(drawnMesh(o), geometry_->meshes[o]));
}

MeshCache::ObjectMesh MeshCache::describe(const Mesh& mesh, const Mesh& baked) {
    ObjectMesh object;
    for (std::size_t p = 0; p < mesh.parts.size(); ++p)
        for (bool mirrored : {false, true}) {
            InstanceGroup g;
            g.part = p;
            g.first = GLsizei(object.instances.size());
            g.mirrored = mirrored;
            for (const glm::mat4& t : mesh.parts[p].instances)
                if ((glm::determinant(glm::mat3(t)) < 0.0f) == mirrored) object.instances.push_back(t);
            g.count = GLsizei(object.instances.size()) - g.first;
            if (g.count > 0) object.instanceGroups.push_back(g);
        }
    object.variesColor = mesh.variesColor();
    object.emissiveTexture = mesh.hasEmissiveTexture();
    object.images = mesh.textures;
    object.textures.resize(mesh.textures.size());
    object.parts = mesh.parts;
    if (mesh.parts.empty()) {
        MeshPart whole;
        whole.indexCount = std::uint32_t(mesh.indices.size());
        object.parts.push_back(whole);
    }
    for (const MeshPart& part : object.parts)  // only blended parts are sorted by theirs
        object.partBoxes.push_back(part.alphaMode == AlphaMode::Blend ? partBounds(mesh, part) : Aabb{});
    // Bounds and triangle counts of every instance: the baked mesh's.
    Aabb box{glm::vec3(std::numeric_limits<float>::max()), glm::vec3(-std::numeric_limits<float>::max())};
    for (const glm::vec3& p : baked.positions) {
        box.lo = glm::min(box.lo, p);
        box.hi = glm::max(box.hi, p);
    }
    object.box = baked.positions.empty() ? Aabb{} : box;
    object.triangles = baked.triangleCount();
    return object;
}

const Mesh& MeshCache::drawnMesh(std::size_t object) const {
    const Mesh& baked = geometry_->meshes[object];
    return baked.instanced && options_.instancedDraws ? *baked.instanced : baked;
}

void MeshCache::bindInstances(std::size_t object, const InstanceGroup& group) {
    gl::Buffer& buffer = objects_[object].instanceBuffer;
    if (!buffer) {
        buffer = gl::makeBuffer();
        glBindBuffer(GL_ARRAY_BUFFER, buffer.get());
        const std::vector<glm::mat4>& data = objects_[object].instances;
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.size() * sizeof(glm::mat4)), data.data(), GL_STATIC_DRAW);
    }
    // A mat4 attribute takes four locations, a column each, advancing once per instance.
    glBindBuffer(GL_ARRAY_BUFFER, buffer.get());
    for (GLuint c = 0; c < 4; ++c) {
        const std::size_t offset = std::size_t(group.first) * sizeof(glm::mat4) + c * sizeof(glm::vec4);
        glVertexAttribPointer(SL_ATTRIB_INSTANCE + c, 4, GL_FLOAT, GL_FALSE, sizeof(glm::mat4),
                              reinterpret_cast<void*>(offset));
        glVertexAttribDivisor(SL_ATTRIB_INSTANCE + c, 1);
        glEnableVertexAttribArray(SL_ATTRIB_INSTANCE + c);
    }
}

void MeshCache::uploadAndRelease(const std::vector<ShadingMode>& modes, bool textures,
                                 const std::vector<char>& tangents) {
    for (ShadingMode mode : modes)
        for (std::size_t o = 0; o < objects_.size(); ++o) {
            gpuMesh(o, mode);
            if (o < tangents.size() && tangents[o]) gpuMesh(o, mode, true);
        }
    if (textures)
        for (std::size_t o = 0; o < objects_.size(); ++o)
            for (std::size_t t = 0; t < objects_[o].images.size(); ++t) texture(o, int(t));
    geometry_.reset();
    for (ObjectMesh& object : objects_) object.ordered = Mesh{};
}

namespace {

// One interleaved vertex buffer: a vertex's attributes side by side, `layout` saying which (each
// `size` floats at its location, in order).
struct InterleavedVertices {
    struct Attribute {
        GLuint location;
        GLint size;
    };
    std::vector<float> floats;
    std::vector<Attribute> layout;
};

// Where C varies: each vertex's texture coordinates, colour (RGBA) and, with an emissive texture,
// that texture's coordinates.
struct ColorInputs {
    const std::vector<glm::vec2>& texcoords;
    const std::vector<glm::vec4>& colors;
    const std::vector<glm::vec2>& emissiveTexcoords;
    bool varies() const { return !texcoords.empty(); }
    bool emissive() const { return !emissiveTexcoords.empty(); }
    std::size_t floats() const { return varies() ? (emissive() ? 8 : 6) : 0; }
};

// `count` vertices of `floats` each, written by `write(v, i)`, then (where C varies) each vertex's
// ColorInputs.
template <typename Write>
void interleave(InterleavedVertices& out, std::size_t count, std::size_t floats, const ColorInputs& in, Write write) {
    const std::size_t stride = floats + in.floats();
    out.floats.resize(count * stride);
    for (std::size_t i = 0; i < count; ++i) {
        float* v = &out.floats[i * stride];
        write(v, i);
        if (!in.varies()) continue;
        v += floats;
        const glm::vec2& uv = in.texcoords[i];
        const glm::vec4& c = in.colors[i];
        v[0] = uv.x;
        v[1] = uv.y;
        v[2] = c.r;
        v[3] = c.g;
        v[4] = c.b;
        v[5] = c.a;
        if (in.emissive()) {
            v[6] = in.emissiveTexcoords[i].x;
            v[7] = in.emissiveTexcoords[i].y;
        }
    }
    if (in.varies()) {
        out.layout.push_back({SL_ATTRIB_TEXCOORD, 2});
        out.layout.push_back({SL_ATTRIB_COLOR, 4});
    }
    if (in.emissive()) out.layout.push_back({SL_ATTRIB_EMISSIVE_TEXCOORD, 2});
}

// The anisotropic draws' tangent (xyz, w the handedness) after a vertex's other floats; a mesh
// without tangents gets T = +x.
void writeTangent(float* v, const std::vector<glm::vec4>& tangents, std::size_t i) {
    const glm::vec4 t = i < tangents.size() ? tangents[i] : glm::vec4(1.0f, 0.0f, 0.0f, 1.0f);
    v[0] = t.x;
    v[1] = t.y;
    v[2] = t.z;
    v[3] = t.w;
}

// Gouraud and Phong: position xyz, normal xyz (and, with `tangents`, the tangent xyzw).
InterleavedVertices smoothVertices(const Mesh& mesh, bool tangents) {
    InterleavedVertices out;
    out.layout = {{SL_ATTRIB_POSITION, 3}, {SL_ATTRIB_NORMAL, 3}};
    if (tangents) out.layout.push_back({SL_ATTRIB_TANGENT, 4});
    interleave(out, mesh.positions.size(), tangents ? 10 : 6, {mesh.texcoords, mesh.colors, mesh.emissiveTexcoords},
               [&](float* v, std::size_t i) {
                   const glm::vec3 &p = mesh.positions[i], &n = mesh.normals[i];
                   v[0] = p.x;
                   v[1] = p.y;
                   v[2] = p.z;
                   v[3] = n.x;
                   v[4] = n.y;
                   v[5] = n.z;
                   if (tangents) writeTangent(v + 6, mesh.tangents, i);
               });
    return out;
}

// Flat: position xyz, the triangle's centroid xyz and its face normal xyz (shaders/flat.vert), and,
// with `tangents`, its tangent xyzw.
InterleavedVertices flatVertices(const FlatMesh& flat, bool tangents) {
    InterleavedVertices out;
    out.layout = {{SL_ATTRIB_POSITION, 3}, {SL_ATTRIB_CENTROID, 3}, {SL_ATTRIB_NORMAL, 3}};
    if (tangents) out.layout.push_back({SL_ATTRIB_TANGENT, 4});
    interleave(out, flat.positions.size(), tangents ? 13 : 9, {flat.texcoords, flat.colors, flat.emissiveTexcoords},
               [&](float* v, std::size_t i) {
                   const glm::vec3 &p = flat.positions[i], &c = flat.centroids[i], &n = flat.normals[i];
                   v[0] = p.x;
                   v[1] = p.y;
                   v[2] = p.z;
                   v[3] = c.x;
                   v[4] = c.y;
                   v[5] = c.z;
                   v[6] = n.x;
                   v[7] = n.y;
                   v[8] = n.z;
                   if (tangents) writeTangent(v + 9, flat.tangents, i);
               });
    return out;
}

// Flat, packed: the same nine floats in two vec4s (shaders/flat_packed.vert): position xyz and
// centroid x; centroid yz, normal x, and normal y plus SL_FLAT_NORMAL_Z_NEGATIVE when normal z < 0 (the
// shader takes z from the unit length). llvmpipe fetches each attribute of each vertex on its own: two
// fetches instead of three took 7% off a flat frame at 200k triangles (bench/README.md).
InterleavedVertices packedFlatVertices(const FlatMesh& flat) {
    InterleavedVertices out;
    out.layout = {{SL_ATTRIB_POSITION, 4}, {SL_ATTRIB_CENTROID, 4}};
    interleave(out, flat.positions.size(), 8, {flat.texcoords, flat.colors, flat.emissiveTexcoords},
               [&](float* v, std::size_t i) {
                   const glm::vec3 &p = flat.positions[i], &c = flat.centroids[i], &n = flat.normals[i];
                   v[0] = p.x;
                   v[1] = p.y;
                   v[2] = p.z;
                   v[3] = c.x;
                   v[4] = c.y;
                   v[5] = c.z;
                   v[6] = n.x;
                   v[7] = n.z < 0.0f ? n.y + float(SL_FLAT_NORMAL_Z_NEGATIVE) : n.y;
               });
    return out;
}

// A vertex array of `vertices` (freed once uploaded) and `indices`, into `g`.
void uploadVertexArray(MeshCache::GpuMesh& g, InterleavedVertices&& vertices,
                       const std::vector<std::uint32_t>& indices) {
    g.vao = gl::makeVertexArray();
    g.indices = gl::makeBuffer();
    glBindVertexArray(g.vao.get());
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.indices.get());
    g.vertices = gl::makeBuffer();
    glBindBuffer(GL_ARRAY_BUFFER, g.vertices.get());
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.floats.size() * sizeof(float)), vertices.floats.data(),
                 GL_STATIC_DRAW);
    vertices.floats = {};
    GLsizei stride = 0;
    for (const InterleavedVertices::Attribute& a : vertices.layout) stride += GLsizei(a.size * GLint(sizeof(float)));
    std::size_t offset = 0;
    for (const InterleavedVertices::Attribute& a : vertices.layout) {
        glVertexAttribPointer(a.location, a.size, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offset));
        glEnableVertexAttribArray(a.location);
        offset += std::size_t(a.size) * sizeof(float);
    }
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * sizeof(std::uint32_t)), indices.data(),
                 GL_STATIC_DRAW);
    glBindVertexArray(0);
    g.indexCount = GLsizei(indices.size());
}

}  // namespace

const Mesh& MeshCache::uploadSource(std::size_t object) {
    const Mesh& drawn = drawnMesh(object);
    if (options_.meshOrder != RendererOptions::MeshOrder::VertexCache) return drawn;
    Mesh& ordered = objects_[object].ordered;
    if (ordered.indices.empty()) ordered = orderedForVertexCache(drawn);
    return ordered;
}

// One interleaved buffer per mesh and mode: llvmpipe fetches interleaved attributes faster (~10% of a
// Phong frame at 200k triangles than one buffer per attribute), and the layout (stride, offsets) does
// not depend on the mesh's size, so draw code llvmpipe compiled for one mesh serves the next (see
// renderSceneHeadless()). Where C varies (Mesh::variesColor), each vertex also carries its texture
// coordinates and colour.
const MeshCache::GpuMesh& MeshCache::gpuMesh(std::size_t object, ShadingMode mode, bool tangents) {
    const bool flat = mode == ShadingMode::Flat;
    std::array<GpuMesh, 4>& gpu = objects_[object].gpu;
    GpuMesh& g = gpu[(flat ? 1 : 0) + (tangents ? 2 : 0)];
    if (g.vao) return g;
    if (!geometry_)
        throw std::logic_error("mesh cache: a shading mode that was not uploaded before the CPU geometry was released");
    const Mesh& mesh = uploadSource(object);
    if (flat) {
        const FlatMesh flatMesh = options_.meshOrder == RendererOptions::MeshOrder::VertexCache
                                      ? makeOrderedFlatMesh(mesh)
                                      : makeFlatMesh(mesh);
        uploadVertexArray(
            g,
            options_.packedFlatVertices && !tangents ? packedFlatVertices(flatMesh) : flatVertices(flatMesh, tangents),
            flatMesh.indices);
    } else {
        uploadVertexArray(g, smoothVertices(mesh, tangents), mesh.indices);
    }
    checkGl("mesh upload");
    if (gpu[0].vao && gpu[1].vao) objects_[object].ordered = Mesh{};  // both uploaded
    return g;
}

GLuint MeshCache::texture(std::size_t object, int slot) {
    ObjectMesh& o = objects_[object];
    if (slot < 0 || std::size_t(slot) >= o.textures.size()) {
        if (!whiteTexture_) {
            const unsigned char white[4] = {255, 255, 255, 255};
            whiteTexture_ = gl::makeTexture();
            glBindTexture(GL_TEXTURE_2D, whiteTexture_.get());
            glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, white);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        }
        return whiteTexture_.get();
    }
    gl::Texture& t = o.textures[std::size_t(slot)];
    if (t) return t.get();
    const std::shared_ptr<const TextureImage> image = std::move(o.images[std::size_t(slot)]);
    if (!image) throw std::logic_error("mesh cache: a texture that was released before it was uploaded");
    t = gl::makeTexture();
    glBindTexture(GL_TEXTURE_2D, t.get());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    // glTF's base colours are sRGB-encoded: an sRGB texture decodes them to linear values when sampled.
    glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, image->width, image->height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 image->rgba.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, image->wrapS);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, image->wrapT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, image->magFilter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, image->minFilter);
    if (image->minFilter != GL_NEAREST && image->minFilter != GL_LINEAR) gl::generateMipmaps();
    checkGl(("texture upload (" + image->name + ")").c_str());
    return t.get();
}

}  // namespace shadelab
