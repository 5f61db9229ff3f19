#pragma once
// Triangle meshes in object space, and the procedural shapes of the scene format.
// All meshes are indexed triangle lists, counter-clockwise seen from outside, with unit vertex normals.
#include "core/scene/scene.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace shadelab {

// glTF's alphaMode: how the base colour's alpha (factor x texel x COLOR_0) covers the surface.
enum class AlphaMode { Opaque, Mask, Blend };

// A run of triangles with a colour of its own (a glTF primitive's base colour factor, and its base
// colour texture when it has one). The scene's material colour overrides both when the scene sets one.
struct MeshPart {
    std::uint32_t firstIndex = 0;
    std::uint32_t indexCount = 0;
    bool hasBaseColor = false;
    glm::vec3 baseColor{1.0f};
    int texture = -1;  // index into Mesh::textures; -1: none
    // Coverage: Opaque ignores alpha; Mask draws where alpha >= alphaCutoff; Blend mixes by alpha.
    float baseAlpha = 1.0f;  // the base colour factor's alpha
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    // E, the light the surface gives off: emissiveFactor x KHR_materials_emissive_strength, times the
    // emissive texture (sRGB, read at Mesh::emissiveTexcoords) where it has one.
    glm::vec3 emissive{0.0f};
    int emissiveTexture = -1;  // index into Mesh::textures; -1: none
    // glTF's material.doubleSided: drawn from both sides, a back face lit with its normal flipped
    // (no back-face culling for this part). False: back faces are culled, as for procedural meshes.
    bool doubleSided = false;
    // Drawn once per transform (a glTF node's EXT_mesh_gpu_instancing instances, in an instanced
    // draw), each applied to the part's vertices in object space; empty: drawn once as it is.
    std::vector<glm::mat4> instances;
};

// An image of the object texture (glTF's baseColorTexture) with its sampler. The texels are sRGB-
// encoded, as glTF stores base colours; they are decoded to linear values when sampled (an sRGB GL
// texture; sampleTexture() on the CPU). Row 0 is the image's top row, at texture coordinate v = 0.
struct TextureImage {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;  // width * height * 4 bytes
    // The sampler, in GL's (and glTF's) enum values.
    int wrapS = 0x2901, wrapT = 0x2901;  // GL_REPEAT (or GL_CLAMP_TO_EDGE 0x812F, GL_MIRRORED_REPEAT 0x8370)
    int magFilter = 0x2601;              // GL_LINEAR (or GL_NEAREST 0x2600)
    int minFilter = 0x2703;              // GL_LINEAR_MIPMAP_LINEAR (or any other GL minification filter)
    std::string name;                    // for messages: the image's URI or "image N"
};

struct Mesh {
    std::vector<glm::vec3> positions;    // object space
    std::vector<glm::vec3> normals;      // object space, unit length, one per position
    std::vector<std::uint32_t> indices;  // three per triangle, counter-clockwise from outside
    std::vector<MeshPart> parts;         // empty: the whole mesh is one part with the scene's colour
    // Where C varies over the surface (a glTF model with a base colour texture or COLOR_0): both are
    // one per position, or both empty. texcoords: the coordinates the part's texture is read with
    // (its TEXCOORD_n, KHR_texture_transform applied; 0 where a part has none); colors: COLOR_0's
    // linear RGBA (1 where a primitive has none). C = base colour x texture(texcoord) x color, and
    // its alpha the same product of alphas.
    std::vector<glm::vec2> texcoords;
    std::vector<glm::vec4> colors;
    // The emissive textures' coordinates (their TEXCOORD_n, transformed), one per position where a
    // part has an emissive texture (the mesh then varies its colour too), else empty.
    std::vector<glm::vec2> emissiveTexcoords;
    // The tangent frame, one per position (object space): xyz the unit tangent T, orthogonal to the
    // normal, w the handedness (the bitangent is B = w N x T). glTF's TANGENT where the file gives it;
    // completeTangents() fills the rest (w = 0 marks a vertex still to fill).
    std::vector<glm::vec4> tangents;
    std::vector<std::shared_ptr<const TextureImage>> textures;  // shared by copies of the mesh
    // The same surface with instanced parts (MeshPart::instances) drawn once each, for the renderer's
    // instanced draws; this mesh holds every instance baked, which everything else reads. Null: none.
    std::shared_ptr<const Mesh> instanced;

    std::size_t triangleCount() const { return indices.size() / 3; }
    bool variesColor() const { return !texcoords.empty(); }
    bool hasEmissiveTexture() const { return !emissiveTexcoords.empty(); }
};

// A texture's linear RGB at texture coordinates `uv`: bilinear (or nearest, by the sampler's
// magnification filter) on the full-size image, with its wrap modes; the texels are sRGB-decoded
// first, as GL does for an sRGB texture. The GPU reads smaller mip levels where the texture is
// minified; this is what it reads where the texture is magnified.
glm::vec3 sampleTexture(const TextureImage& texture, const glm::vec2& uv);
// The same sample with its alpha (alpha is stored linear: not decoded).
glm::vec4 sampleTextureRgba(const TextureImage& texture, const glm::vec2& uv);

// `v` scaled to unit length, or `fallback` when that is not possible (zero, not finite, or so small
// that its direction is lost to rounding). Rescales by the largest component first, so huge and
// tiny (denormal) vectors normalise accurately. Input files can hold any such normal.
glm::vec3 safeNormalize(const glm::vec3& v, const glm::vec3& fallback = glm::vec3(0.0f, 1.0f, 0.0f));

// The lecture's face normal of a counter-clockwise triangle a, b, c: normalize((c - b) x (a - b)).
glm::vec3 faceNormal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);

// UV sphere laid out exactly like ../shared/bench (seam column duplicated, one triangle per pole quad):
// (stacks + 1) * (slices + 1) vertices, 2 * slices * (stacks - 1) triangles.
Mesh makeUvSphere(int slices, int stacks, float radius);
Mesh makeIcoSphere(int subdivisions, float radius);  // 20 * 4^n triangles
Mesh makeTorus(float majorRadius, float minorRadius, int majorSegments, int minorSegments);
Mesh makeCube(float size);                     // 24 vertices, one normal per face
Mesh makePlane(float size, int subdivisions);  // x-z square at y = 0, facing +y

// Where a vertex's tangent frame comes from (anisotropic reflection), in this order of preference.
enum class TangentSource { Given, Texcoords, UpAxis };
// (tangentAroundUp and orthogonalTangent: core/shading/lighting.hpp.)
// Fills Mesh::tangents where the file gave none (w = 0, or the whole array when empty): from the
// texture coordinates where the mesh has them (each triangle's dP/du and dP/dv accumulated per vertex,
// then Gram-Schmidt against N, w the sign of B against N x T), else around the up axis. A vertex
// whose triangles' coordinates are degenerate gets the up-axis frame. Returns the source used for the
// filled vertices (Given when the file gave every tangent).
TangentSource completeTangents(Mesh& mesh);
const char* toString(TangentSource source);

// Builds a procedural mesh (not glTF: see gltf_import.hpp).
Mesh makeProceduralMesh(const MeshSpec& spec);

// Vertex data for flat shading. GL takes a `flat` varying from the provoking (last) vertex of each
// triangle, so every triangle needs a vertex of its own in that slot, carrying its face normal and
// centroid. Each triangle is rotated (which keeps its winding) so that a corner no other triangle has
// claimed comes last; only triangles whose three corners are all taken get a new vertex. On a closed
// mesh (T = 2V) that is about T vertices instead of the V + T of one new vertex per triangle, and a
// third fewer vertex-shader runs. The colour is still evaluated once per triangle, at its centroid.
struct FlatMesh {
    std::vector<glm::vec3> positions;    // object space
    std::vector<glm::vec3> normals;      // face normal at each provoking vertex (vertex normal elsewhere)
    std::vector<glm::vec3> centroids;    // triangle centroid at each provoking vertex (position elsewhere)
    std::vector<std::uint32_t> indices;  // per triangle, its corners rotated so the provoking one is last
    std::vector<glm::vec2> texcoords;    // as the Mesh's (empty when it has none), copied to added vertices
    std::vector<glm::vec4> colors;
    std::vector<glm::vec2> emissiveTexcoords;
    // Anisotropic draws: at each provoking vertex the triangle's tangent (its corners' tangents averaged,
    // then Gram-Schmidt against the face normal), its w the provoking corner's; elsewhere the vertex's.
    // Empty when the mesh has no tangents.
    std::vector<glm::vec4> tangents;
};
// The tangent flat shading evaluates a triangle with: its corners' tangents averaged (handedness of
// the last corner), made orthogonal to the face normal `faceNrm`.
glm::vec4 faceTangent(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c, const glm::vec3& faceNrm);
FlatMesh makeFlatMesh(const Mesh& mesh);

struct BoundingSphere {
    glm::vec3 center{0.0f};
    float radius = 0.0f;
};
// Bounding sphere of all meshes after their object-to-world transforms (centre of the box, radius
// to the farthest vertex). Empty input gives radius 0.
BoundingSphere worldBounds(const std::vector<const Mesh*>& meshes, const std::vector<glm::mat4>& worldFromObject);

}  // namespace shadelab
