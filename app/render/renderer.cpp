#include "render/renderer.hpp"

#include "core/error.hpp"

#include "core/camera.hpp"
#include "core/lighting.hpp"
#include "core/vertex_order.hpp"
#include "render/gpu_blocks.hpp"
#include "render/multisample_target.hpp"
#include "render/program.hpp"

#include <glm/common.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace shadelab {
namespace {

const char* kProgramNames[3] = {"flat", "gouraud", "phong"};  // by ShadingMode

void copyVec(float (&dst)[4], const glm::vec3& v, float w = 0.0f) {
    dst[0] = v.x, dst[1] = v.y, dst[2] = v.z, dst[3] = w;
}

int attenuationKind(const Light& l) {
    if (l.type == LightType::Directional || l.attenuation != Attenuation::InverseSquare) return SL_ATTENUATION_NONE;
    return l.range > 0.0f ? SL_ATTENUATION_INVERSE_SQUARE_RANGE : SL_ATTENUATION_INVERSE_SQUARE;
}

int lightKind(const Light& l) {
    switch (l.type) {
    case LightType::Point: return SL_LIGHT_POINT;
    case LightType::Directional: return SL_LIGHT_DIRECTIONAL;
    case LightType::Area: return SL_LIGHT_AREA;
    case LightType::Spot: return SL_LIGHT_SPOT;
    }
    return SL_LIGHT_POINT;
}

gpu::FrameBlock frameBlock(const Scene& s, float aspect) {
    gpu::FrameBlock b{};
    const glm::mat4 clipFromWorld = clipFromView(s.camera, aspect) * viewFromWorld(s.camera);
    std::memcpy(b.clipFromWorld, glm::value_ptr(clipFromWorld), sizeof b.clipFromWorld);
    copyVec(b.eyeWorld, s.camera.eye, 1.0f);
    copyVec(b.ambient, s.ambient);
    b.modelSettings[0] = s.ior;
    b.modelSettings[1] = fresnelR0(1.0f, s.ior);
    const int count = int(std::min<std::size_t>(s.lights.size(), SL_MAX_LIGHTS));
    b.settings[0] = count;
    b.settings[1] = s.reflection == ReflectionModel::Phong ? SL_REFLECTION_PHONG : SL_REFLECTION_BLINN_PHONG;
    b.settings[2] = s.outputEncoding == OutputEncoding::Srgb ? SL_ENCODING_SRGB : SL_ENCODING_LINEAR;
    for (int i = 0; i < count; ++i) {
        const Light& l = s.lights[std::size_t(i)];
        gpu::LightGpu& g = b.lights[i];
        copyVec(g.positionOrDirection, l.type == LightType::Directional ? l.direction : l.position);
        copyVec(g.radiance, l.color * l.intensity);
        g.kind[0] = lightKind(l);
        g.kind[1] = attenuationKind(l);
        g.kind[2] = l.type == LightType::Area ? l.samples.x : 1;
        g.kind[3] = l.type == LightType::Area ? l.samples.y : 1;
        g.falloff[0] = l.range > 0.0f ? 1.0f / (l.range * l.range) : 0.0f;
        g.falloff[1] = l.twoSided ? 1.0f : 0.0f;
        if (l.type == LightType::Area) {
            const AreaFrame f = areaFrame(l);
            copyVec(g.areaU, f.u);
            copyVec(g.areaV, f.v);
            copyVec(g.areaNormal, f.n);
        }
        if (l.type == LightType::Spot) {
            const glm::vec2 cone = spotCone(l);
            copyVec(g.spot, glm::normalize(l.direction), cone.x);
            g.falloff[3] = cone.y;
        }
    }
    return b;
}

// `color` is the draw's C: the material's, or a glTF part's base colour.
gpu::ObjectBlock objectBlock(const SceneObject& o, const glm::vec3& color, const Scene& scene) {
    gpu::ObjectBlock b{};
    const glm::mat4 world = worldFromObject(o.transform);
    const glm::mat4 normal = glm::mat4(normalWorldFromObject(world));
    std::memcpy(b.worldFromObject, glm::value_ptr(world), sizeof b.worldFromObject);
    std::memcpy(b.normalWorldFromObject, glm::value_ptr(normal), sizeof b.normalWorldFromObject);
    copyVec(b.color, color);
    copyVec(b.specularColor, o.material.specularColor);
    b.coefficients[0] = o.material.ka;
    b.coefficients[1] = o.material.kd;
    b.coefficients[2] = o.material.ks;
    b.coefficients[3] = o.material.ke;
    copyVec(b.ambientTerm, o.material.ka * scene.ambient * color);
    const std::size_t count = std::min<std::size_t>(scene.lights.size(), SL_MAX_LIGHTS);
    for (std::size_t l = 0; l < count; ++l) {
        const glm::vec3 radiance = scene.lights[l].color * scene.lights[l].intensity;
        copyVec(b.lightDiffuse[l], radiance * o.material.kd * color);
        copyVec(b.lightSpecular[l], radiance * o.material.ks * o.material.specularColor);
    }
    return b;
}

std::size_t alignUp(std::size_t n, std::size_t a) { return (n + a - 1) / a * a; }

// A width x height texture read with texelFetch (nearest, one level).
gl::Texture makeImageTexture(GLint internalFormat, GLenum format, GLenum type, int width, int height) {
    GLuint id = 0;
    glGenTextures(1, &id);
    gl::Texture t(id);
    glBindTexture(GL_TEXTURE_2D, id);
    glTexImage2D(GL_TEXTURE_2D, 0, internalFormat, width, height, 0, format, type, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    return t;
}

gl::Framebuffer makeFramebuffer(GLuint color, GLuint depth, const char* what) {
    GLuint id = 0;
    glGenFramebuffers(1, &id);
    gl::Framebuffer f(id);
    glBindFramebuffer(GL_FRAMEBUFFER, id);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color, 0);
    if (depth) glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth, 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error(std::string(what) + ": the framebuffer is not complete on this GL");
    return f;
}

// The ordered-dither rank of (x, y) in a 2^bits square: bit-reversed interleaving of y and x ^ y.
unsigned bayerRank(unsigned x, unsigned y, int bits) {
    unsigned rank = 0;
    for (int b = 0; b < bits; ++b) {
        rank = (rank << 2) | (((x ^ y) >> b & 1u) << 1) | (y >> b & 1u);
    }
    return rank;
}

void checkGl(const char* where) {
    const GLenum e = glGetError();
    if (e == GL_OUT_OF_MEMORY)  // the request was too big for this GL: an input error, like the budget's
        throw GlOutOfMemory(std::string("the GL ran out of memory in ") + where +
                         " (ask for less: a smaller --size, fewer shadowed lights or smaller shadow maps)");
    if (e != GL_NO_ERROR) {
        char code[16];
        std::snprintf(code, sizeof code, "0x%04x", e);
        throw std::runtime_error(std::string("GL error ") + code + " in " + where);
    }
}

}  // namespace

std::vector<std::string> programDefines(const Scene& s) {
    const std::size_t count = std::min<std::size_t>(s.lights.size(), SL_MAX_LIGHTS);
    static const char* const kKinds[] = {"SL_LIGHT_POINT", "SL_LIGHT_DIRECTIONAL", "SL_LIGHT_AREA", "SL_LIGHT_SPOT"};
    static const char* const kAttenuations[] = {"SL_ATTENUATION_NONE", "SL_ATTENUATION_INVERSE_SQUARE",
                                                "SL_ATTENUATION_INVERSE_SQUARE_RANGE"};
    // Per light, as comma-separated lists that shaders/lighting.glsl reads into constant arrays.
    std::string kinds, attenuations, samplesX, samplesY;
    bool area = false;
    for (std::size_t l = 0; l < count; ++l) {
        const Light& light = s.lights[l];
        const char* comma = l > 0 ? ", " : "";
        kinds += comma + std::string(kKinds[lightKind(light)]);
        attenuations += comma + std::string(kAttenuations[attenuationKind(light)]);
        samplesX += comma + std::to_string(light.type == LightType::Area ? light.samples.x : 1);
        samplesY += comma + std::to_string(light.type == LightType::Area ? light.samples.y : 1);
        area = area || light.type == LightType::Area;
    }
    std::vector<std::string> d;
    d.push_back("SL_LIGHT_COUNT " + std::to_string(count));
    if (count > 0) {
        d.push_back("SL_LIGHT_KINDS " + kinds);
        d.push_back("SL_LIGHT_ATTENUATIONS " + attenuations);
        d.push_back("SL_AREA_SAMPLES_X " + samplesX);
        d.push_back("SL_AREA_SAMPLES_Y " + samplesY);
    }
    if (area) d.push_back("SL_AREA_LIGHTS 1");
    d.push_back(std::string("SL_REFLECTION ") +
                (s.reflection == ReflectionModel::Phong ? "SL_REFLECTION_PHONG" : "SL_REFLECTION_BLINN_PHONG"));
    d.push_back(std::string("SL_ENCODING ") +
                (s.outputEncoding == OutputEncoding::Srgb ? "SL_ENCODING_SRGB" : "SL_ENCODING_LINEAR"));
    // The model extensions and term isolation: only scenes that use them get these defines, so every
    // other scene compiles to the programs it always did.
    if (s.specularNormalization == SpecularNormalization::Energy)
        d.push_back("SL_SPECULAR_NORMALIZATION SL_NORMALIZATION_ENERGY");
    if (s.fresnel != FresnelMode::None)
        d.push_back(std::string("SL_FRESNEL ") +
                    (s.fresnel == FresnelMode::Schlick ? "SL_FRESNEL_SCHLICK" : "SL_FRESNEL_EXACT"));
    switch (s.show.term) {
    case ShowTerm::All: break;
    case ShowTerm::Ambient: d.push_back("SL_SHOW SL_SHOW_AMBIENT"); break;
    case ShowTerm::Diffuse: d.push_back("SL_SHOW SL_SHOW_DIFFUSE"); break;
    case ShowTerm::Specular: d.push_back("SL_SHOW SL_SHOW_SPECULAR"); break;
    case ShowTerm::Unlit: d.push_back("SL_SHOW SL_SHOW_UNLIT"); break;
    case ShowTerm::Light:
        d.push_back("SL_SHOW SL_SHOW_LIGHT");
        d.push_back("SL_SHOW_LIGHT_INDEX " + std::to_string(s.show.light));
        break;
    }
    // Only scenes with shadows get these: without them the programs are the ones they always were.
    if (s.shadows.enabled && count > 0) {
        d.push_back("SL_SHADOWS 1");
        d.push_back("SL_SHADOW_PCF " + std::to_string(s.shadows.pcf));
        std::string layers;
        for (int first : shadowLayout(s.lights, count).firstLayer) layers += (layers.empty() ? "" : ", ") + std::to_string(first);
        d.push_back("SL_SHADOW_LAYERS " + layers);
    }
    return d;
}

Renderer::Renderer(GLADloadfunc getProcAddress, ShaderLibrary shaders, RendererOptions options)
    : shaders_(std::move(shaders)), options_(options) {
    const int version = gladLoadGL(getProcAddress);
    if (version == 0) throw std::runtime_error("could not load OpenGL entry points");
    if (GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) < 33)
        throw std::runtime_error("OpenGL 3.3 core is needed; the context offers " +
                                 std::to_string(GLAD_VERSION_MAJOR(version)) + "." +
                                 std::to_string(GLAD_VERSION_MINOR(version)));
    glGetIntegerv(GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT, &uniformAlignment_);
    if (uniformAlignment_ <= 0) uniformAlignment_ = 256;
    uniforms_ = gl::makeBuffer();
    checkGl("renderer set-up");
}

Renderer::~Renderer() = default;

std::string Renderer::glRenderer() const { return reinterpret_cast<const char*>(glGetString(GL_RENDERER)); }
std::string Renderer::glVersion() const { return reinterpret_cast<const char*>(glGetString(GL_VERSION)); }

void Renderer::setGeometry(std::shared_ptr<const SceneGeometry> geometry) {
    geometry_ = std::move(geometry);
    gpuMeshes_.clear();
    gpuMeshes_.resize(geometry_ ? geometry_->meshes.size() : 0);
    orderedMeshes_.clear();
    orderedMeshes_.resize(gpuMeshes_.size());
    objectParts_.clear();
    objectBoxes_.clear();
    objectTriangles_.clear();
    objectVariesColor_.clear();
    objectImages_.clear();
    objectTextures_.clear();
    shadowMaps_.invalidate();
    if (!geometry_) return;
    objectInstanceGroups_.clear();
    objectInstances_.clear();
    objectInstanceBuffers_.clear();
    for (std::size_t o = 0; o < geometry_->meshes.size(); ++o) {
        const Mesh& mesh = drawnMesh(o);
        objectInstanceGroups_.emplace_back();
        objectInstances_.emplace_back();
        objectInstanceBuffers_.emplace_back();
        for (std::size_t p = 0; p < mesh.parts.size(); ++p)
            for (bool mirrored : {false, true}) {
                InstanceGroup g;
                g.part = p;
                g.first = GLsizei(objectInstances_.back().size());
                g.mirrored = mirrored;
                for (const glm::mat4& t : mesh.parts[p].instances)
                    if ((glm::determinant(glm::mat3(t)) < 0.0f) == mirrored) objectInstances_.back().push_back(t);
                g.count = GLsizei(objectInstances_.back().size()) - g.first;
                if (g.count > 0) objectInstanceGroups_.back().push_back(g);
            }
        objectVariesColor_.push_back(mesh.variesColor());
        objectImages_.push_back(mesh.textures);
        objectTextures_.emplace_back(mesh.textures.size());
        objectParts_.push_back(mesh.parts);
        if (mesh.parts.empty()) {
            MeshPart whole;
            whole.indexCount = std::uint32_t(mesh.indices.size());
            objectParts_.back().push_back(whole);
        }
        // Bounds and triangle counts of every instance: the baked mesh's.
        const Mesh& baked = geometry_->meshes[o];
        Aabb box{glm::vec3(std::numeric_limits<float>::max()), glm::vec3(-std::numeric_limits<float>::max())};
        for (const glm::vec3& p : baked.positions) box.lo = glm::min(box.lo, p), box.hi = glm::max(box.hi, p);
        if (baked.positions.empty()) box = Aabb{};
        objectBoxes_.push_back(box);
        objectTriangles_.push_back(baked.triangleCount());
    }
}

const Mesh& Renderer::drawnMesh(std::size_t object) const {
    const Mesh& baked = geometry_->meshes[object];
    return baked.instanced && options_.instancedDraws ? *baked.instanced : baked;
}

void Renderer::bindInstances(std::size_t object, const InstanceGroup& group) {
    gl::Buffer& buffer = objectInstanceBuffers_[object];
    if (!buffer) {
        buffer = gl::makeBuffer();
        glBindBuffer(GL_ARRAY_BUFFER, buffer.get());
        const std::vector<glm::mat4>& data = objectInstances_[object];
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.size() * sizeof(glm::mat4)), data.data(), GL_STATIC_DRAW);
    }
    // A mat4 attribute takes four locations, a column each, advancing once per instance.
    glBindBuffer(GL_ARRAY_BUFFER, buffer.get());
    for (GLuint c = 0; c < 4; ++c) {
        const std::size_t offset = std::size_t(group.first) * sizeof(glm::mat4) + c * sizeof(glm::vec4);
        glVertexAttribPointer(SL_ATTRIB_INSTANCE + c, 4, GL_FLOAT, GL_FALSE, sizeof(glm::mat4), reinterpret_cast<void*>(offset));
        glVertexAttribDivisor(SL_ATTRIB_INSTANCE + c, 1);
        glEnableVertexAttribArray(SL_ATTRIB_INSTANCE + c);
    }
}

void Renderer::uploadAndReleaseCpuGeometry(const Scene& scene) {
    for (const Pane& pane : layoutPanes(scene.layout, scene.shading, 1, 1, scene.diff))
        for (std::size_t o = 0; o < gpuMeshes_.size(); ++o) gpuMesh(o, pane.mode);
    if (scene.textures)
        for (std::size_t o = 0; o < objectImages_.size(); ++o)
            for (std::size_t t = 0; t < objectImages_[o].size(); ++t) objectTexture(o, int(t));
    geometry_.reset();
    orderedMeshes_.clear();
}

void Renderer::preparePrograms(const Scene& scene) {
    bool textured = false;
    for (char v : objectVariesColor_) textured = textured || (v && scene.textures);
    for (bool t : {false, true}) {
        if (t && !textured) break;
        for (ShadingMode mode : {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong}) program(mode, scene, false, false, t);
        // Zooming can switch a Phong draw to the other variant (interpolatesInputs): build it too.
        if (scene.lights.size() <= SL_MAX_INTERPOLATED_LIGHTS && options_.phongInputs != PhongInputs::Uniform)
            program(ShadingMode::Phong, scene, false, true, t);
    }
}

GLuint Renderer::program(ShadingMode mode, const Scene& scene, bool accumulate, bool interpolatedInputs, bool textured,
                         bool instanced) {
    std::vector<std::string> defines = programDefines(scene);
    if (accumulate) defines.push_back("SL_ACCUMULATE 1");
    if (interpolatedInputs && mode == ShadingMode::Phong) defines.push_back("SL_INTERPOLATED_INPUTS 1");
    if (textured) defines.push_back("SL_TEXTURED 1");
    if (instanced) defines.push_back("SL_INSTANCED 1");
    const std::string name = kProgramNames[std::size_t(mode)];
    const std::string vertex = mode == ShadingMode::Flat && options_.packedFlatVertices ? "flat_packed" : name;
    std::string key = vertex;
    for (const std::string& d : defines) key += ";" + d;
    gl::Program& p = programs_[key];
    if (!p) p = buildProgram(name, shaders_, defines, vertex);
    return p.get();
}

const Renderer::GpuMesh& Renderer::gpuMesh(std::size_t object, ShadingMode mode) {
    const bool flat = mode == ShadingMode::Flat;
    GpuMesh& g = gpuMeshes_[object][flat ? 1 : 0];
    if (g.vao) return g;
    if (!geometry_) throw std::logic_error("renderer: a shading mode that was not uploaded before the CPU geometry was released");
    const Mesh* source = &drawnMesh(object);
    if (options_.meshOrder == MeshOrder::VertexCache) {
        Mesh& ordered = orderedMeshes_[object];
        if (ordered.indices.empty()) ordered = orderedForVertexCache(*source);
        source = &ordered;
    }
    const Mesh& mesh = *source;
    g.vao = gl::makeVertexArray();
    g.indices = gl::makeBuffer();
    glBindVertexArray(g.vao.get());
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.indices.get());
    // One interleaved buffer: a vertex's attributes side by side. llvmpipe fetches interleaved
    // attributes faster (~10% of a Phong frame at 200k triangles than one buffer per attribute), and
    // the layout (stride, offsets) does not depend on the mesh's size, so draw code llvmpipe compiled
    // for one mesh serves the next (see renderSceneHeadless()).
    FlatMesh flatMesh;
    if (flat) flatMesh = options_.meshOrder == MeshOrder::VertexCache ? makeOrderedFlatMesh(mesh) : makeFlatMesh(mesh);
    const std::vector<std::uint32_t>& indices = flat ? flatMesh.indices : mesh.indices;
    struct Attribute {
        GLuint location;
        GLint size;
    };
    std::vector<float> interleaved;
    std::vector<Attribute> layout;
    // Where C varies (Mesh::variesColor), each vertex also carries its texture coordinates and colour.
    const bool varies = mesh.variesColor();
    const std::vector<glm::vec2>& texcoords = flat ? flatMesh.texcoords : mesh.texcoords;
    const std::vector<glm::vec3>& colors = flat ? flatMesh.colors : mesh.colors;
    // `floats` per vertex written by `write(v, i)`, then the texture coordinates and colour if C varies.
    const auto interleave = [&](std::size_t count, std::size_t floats, auto write) {
        const std::size_t stride = floats + (varies ? 5 : 0);
        interleaved.resize(count * stride);
        for (std::size_t i = 0; i < count; ++i) {
            float* v = &interleaved[i * stride];
            write(v, i);
            if (!varies) continue;
            v += floats;
            v[0] = texcoords[i].x, v[1] = texcoords[i].y, v[2] = colors[i].r, v[3] = colors[i].g, v[4] = colors[i].b;
        }
    };
    if (!flat) {
        // position xyz, normal xyz
        layout.push_back({SL_ATTRIB_POSITION, 3});
        layout.push_back({SL_ATTRIB_NORMAL, 3});
        interleave(mesh.positions.size(), 6, [&](float* v, std::size_t i) {
            const glm::vec3 &p = mesh.positions[i], &n = mesh.normals[i];
            v[0] = p.x, v[1] = p.y, v[2] = p.z, v[3] = n.x, v[4] = n.y, v[5] = n.z;
        });
    } else if (!options_.packedFlatVertices) {
        // position xyz, the triangle's centroid xyz and its face normal xyz (shaders/flat.vert)
        layout.push_back({SL_ATTRIB_POSITION, 3});
        layout.push_back({SL_ATTRIB_CENTROID, 3});
        layout.push_back({SL_ATTRIB_NORMAL, 3});
        interleave(flatMesh.positions.size(), 9, [&](float* v, std::size_t i) {
            const glm::vec3 &p = flatMesh.positions[i], &c = flatMesh.centroids[i], &n = flatMesh.normals[i];
            v[0] = p.x, v[1] = p.y, v[2] = p.z, v[3] = c.x, v[4] = c.y, v[5] = c.z, v[6] = n.x, v[7] = n.y, v[8] = n.z;
        });
    } else {
        // The same nine floats in two vec4s (shaders/flat_packed.vert): position xyz and centroid x;
        // centroid yz, normal x, and normal y plus SL_FLAT_NORMAL_Z_NEGATIVE when normal z < 0 (the
        // shader takes z from the unit length). llvmpipe fetches each attribute of each vertex on its
        // own: two fetches instead of three took 7% off a flat frame at 200k triangles (bench/README.md).
        layout.push_back({SL_ATTRIB_POSITION, 4});
        layout.push_back({SL_ATTRIB_CENTROID, 4});
        interleave(flatMesh.positions.size(), 8, [&](float* v, std::size_t i) {
            const glm::vec3 &p = flatMesh.positions[i], &c = flatMesh.centroids[i], &n = flatMesh.normals[i];
            v[0] = p.x, v[1] = p.y, v[2] = p.z, v[3] = c.x;
            v[4] = c.y, v[5] = c.z, v[6] = n.x, v[7] = n.z < 0.0f ? n.y + float(SL_FLAT_NORMAL_Z_NEGATIVE) : n.y;
        });
    }
    if (varies) {
        layout.push_back({SL_ATTRIB_TEXCOORD, 2});
        layout.push_back({SL_ATTRIB_COLOR, 3});
    }
    g.vertices = gl::makeBuffer();
    glBindBuffer(GL_ARRAY_BUFFER, g.vertices.get());
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(interleaved.size() * sizeof(float)), interleaved.data(), GL_STATIC_DRAW);
    interleaved = {};
    GLsizei stride = 0;
    for (const Attribute& a : layout) stride += GLsizei(a.size * GLint(sizeof(float)));
    std::size_t offset = 0;
    for (const Attribute& a : layout) {
        glVertexAttribPointer(a.location, a.size, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offset));
        glEnableVertexAttribArray(a.location);
        offset += std::size_t(a.size) * sizeof(float);
    }
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * sizeof(std::uint32_t)), indices.data(),
                 GL_STATIC_DRAW);
    glBindVertexArray(0);
    g.indexCount = GLsizei(indices.size());
    checkGl("mesh upload");
    if (gpuMeshes_[object][0].vao && gpuMeshes_[object][1].vao) orderedMeshes_[object] = Mesh{};  // both uploaded
    return g;
}

GLuint Renderer::objectTexture(std::size_t object, int slot) {
    if (slot < 0 || std::size_t(slot) >= objectTextures_[object].size()) {
        if (!whiteTexture_) {
            const unsigned char white[4] = {255, 255, 255, 255};
            GLuint id = 0;
            glGenTextures(1, &id);
            whiteTexture_ = gl::Texture(id);
            glBindTexture(GL_TEXTURE_2D, id);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, white);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        }
        return whiteTexture_.get();
    }
    gl::Texture& t = objectTextures_[object][std::size_t(slot)];
    if (t) return t.get();
    const std::shared_ptr<const TextureImage> image = std::move(objectImages_[object][std::size_t(slot)]);
    if (!image) throw std::logic_error("renderer: a texture that was released before it was uploaded");
    GLuint id = 0;
    glGenTextures(1, &id);
    t = gl::Texture(id);
    glBindTexture(GL_TEXTURE_2D, id);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    // glTF's base colours are sRGB-encoded: an sRGB texture decodes them to linear values when sampled.
    glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, image->width, image->height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 image->rgba.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, image->wrapS);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, image->wrapT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, image->magFilter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, image->minFilter);
    if (image->minFilter != GL_NEAREST && image->minFilter != GL_LINEAR) glGenerateMipmap(GL_TEXTURE_2D);
    checkGl(("texture upload (" + image->name + ")").c_str());
    return t.get();
}

void Renderer::drawTriangles(GLsizei firstIndex, GLsizei indexCount) {
    const auto offset = [](std::size_t index) { return reinterpret_cast<void*>(index * sizeof(std::uint32_t)); };
    const std::size_t chunk = 3 * options_.drawChunkTriangles;
    if (chunk == 0 || std::size_t(indexCount) <= chunk) {
        glDrawElements(GL_TRIANGLES, indexCount, GL_UNSIGNED_INT, offset(std::size_t(firstIndex)));
        return;
    }
    // Submit chunk i, then wait for chunk i - 1: the driver holds at most two chunks' work.
    GLsync previous = nullptr;
    for (std::size_t done = 0; done < std::size_t(indexCount); done += chunk) {
        glDrawElements(GL_TRIANGLES, GLsizei(std::min(chunk, std::size_t(indexCount) - done)), GL_UNSIGNED_INT,
                       offset(std::size_t(firstIndex) + done));
        GLsync submitted = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
        if (previous) {
            while (glClientWaitSync(previous, GL_SYNC_FLUSH_COMMANDS_BIT, 1000000000u) == GL_TIMEOUT_EXPIRED) {
            }
            glDeleteSync(previous);
        } else {
            glFlush();  // start the first chunk while the second is submitted
        }
        previous = submitted;
    }
    glDeleteSync(previous);
}

bool Renderer::interpolatesInputs(std::size_t object, const Pane& pane, const Scene& scene) const {
    if (pane.mode != ShadingMode::Phong || scene.lights.size() > SL_MAX_INTERPOLATED_LIGHTS ||
        options_.phongInputs == PhongInputs::Uniform)
        return false;
    if (options_.phongInputs == PhongInputs::Interpolated) return true;
    // Each input costs llvmpipe set-up work per triangle, each uniform read work per fragment: the
    // inputs pay off where the triangles are large on screen (measured break-even ~6 pixels per
    // front-facing triangle on the benchmark sphere; 16 leaves a margin for the box's overestimate).
    const Aabb box = transformAabb(objectBoxes_[object], worldFromObject(scene.objects[object].transform));
    const float frontTriangles = std::max(1.0f, 0.5f * float(objectTriangles_[object]));
    return projectedBoxPixels(scene.camera, pane, box.lo, box.hi) >= kInputsMinPixelsPerTriangle * frontTriangles;
}

void Renderer::render(const Scene& scene, const RenderTarget& target) {
    const std::vector<Pane> panes = layoutPanes(scene.layout, scene.shading, target.width, target.height, scene.diff);
    drawPanes(scene, panes, target, nullptr, false);
    if (panes.size() == 3 && panes[2].difference) drawDifference(panes[2], panes[0], panes[1], scene.diff.factor, target);
    checkGl("render");
}

void Renderer::drawPanes(const Scene& scene, const std::vector<Pane>& panes, const RenderTarget& target,
                         const AreaSamplePass* pass, bool add) {
    const std::size_t objects = std::min(objectParts_.size(), scene.objects.size());

    // One draw per object part (a glTF primitive's base colour and texture, or the whole mesh). A
    // scene's material colour replaces C, texture and vertex colours included.
    struct Draw {
        std::size_t object;
        GLsizei first, count;
        glm::vec3 color;
        bool textured;  // SL_TEXTURED: C varies (the part's texture, or white, times the vertex colours)
        int texture;    // the part's slot in Mesh::textures, or -1
        int instances;  // SL_INSTANCED: index into objectInstanceGroups_[object]; -1: drawn once
    };
    std::vector<Draw> draws;
    for (std::size_t o = 0; o < objects; ++o) {
        const Material& m = scene.objects[o].material;
        const bool textured = objectVariesColor_[o] && scene.textures && !m.colorSet;
        const std::vector<InstanceGroup>& groups = objectInstanceGroups_[o];
        std::size_t g = 0;  // the groups are in part order
        for (std::size_t p = 0; p < objectParts_[o].size(); ++p) {
            const MeshPart& part = objectParts_[o][p];
            Draw d{o, GLsizei(part.firstIndex), GLsizei(part.indexCount),
                   (m.colorSet || !part.hasBaseColor) ? m.color : part.baseColor, textured, textured ? part.texture : -1, -1};
            if (part.instances.empty()) draws.push_back(d);
            for (; g < groups.size() && groups[g].part == p; ++g) {
                d.instances = int(g);
                draws.push_back(d);
            }
        }
    }

    // Shadow maps first: they bind their own framebuffer, program and viewport.
    const bool shadows = scene.shadows.enabled && !scene.lights.empty();
    if (shadows) {
        std::vector<ShadowMaps::DepthDraw> depthDraws;
        std::vector<Aabb> boxes;
        for (std::size_t o = 0; o < objects; ++o)
            boxes.push_back(transformAabb(objectBoxes_[o], worldFromObject(scene.objects[o].transform)));
        for (const Draw& d : draws) {
            const GLuint vao = gpuMesh(d.object, ShadingMode::Phong).vao.get();
            const glm::mat4 world = worldFromObject(scene.objects[d.object].transform);
            if (d.instances < 0) {
                depthDraws.push_back({vao, d.first, d.count, world});
                continue;
            }
            // The depth pass draws each instance on its own (it has no instanced variant).
            const InstanceGroup& g = objectInstanceGroups_[d.object][std::size_t(d.instances)];
            for (GLsizei i = 0; i < g.count; ++i)
                depthDraws.push_back({vao, d.first, d.count, world * objectInstances_[d.object][std::size_t(g.first + i)]});
        }
        shadowMaps_.render(scene, depthDraws, boxes, shaders_);
    }

    // All uniforms of the frame in one upload: a FrameBlock per pane, then an ObjectBlock per draw,
    // each at an offset glBindBufferRange accepts.
    const auto align = std::size_t(uniformAlignment_);
    const std::size_t frameStride = alignUp(sizeof(gpu::FrameBlock), align);
    const std::size_t objectStride = alignUp(sizeof(gpu::ObjectBlock), align);
    const std::size_t objectsOffset = frameStride * panes.size();
    std::vector<unsigned char> staging(objectsOffset + objectStride * draws.size());
    for (std::size_t p = 0; p < panes.size(); ++p) {
        gpu::FrameBlock b = frameBlock(scene, float(panes[p].width) / float(std::max(panes[p].height, 1)));
        if (shadows) shadowMaps_.fillBlock(scene, b);
        // Only Phong panes split the samples: flat and Gouraud clamp per face or vertex before the
        // rasteriser, so their passes evaluate every sample (they are cheap) and their mean is exact.
        const bool split = pass && panes[p].mode == ShadingMode::Phong;
        const glm::ivec2 first = split ? pass->first : glm::ivec2(0), stride = split ? pass->stride : glm::ivec2(1);
        b.areaPass[0] = first.x, b.areaPass[1] = first.y, b.areaPass[2] = stride.x, b.areaPass[3] = stride.y;
        std::memcpy(staging.data() + p * frameStride, &b, sizeof b);
    }
    for (std::size_t d = 0; d < draws.size(); ++d) {
        const gpu::ObjectBlock b = objectBlock(scene.objects[draws[d].object], draws[d].color, scene);
        std::memcpy(staging.data() + objectsOffset + d * objectStride, &b, sizeof b);
    }
    glBindBuffer(GL_UNIFORM_BUFFER, uniforms_.get());
    glBufferData(GL_UNIFORM_BUFFER, GLsizeiptr(staging.size()), staging.data(), GL_STREAM_DRAW);

    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glViewport(0, 0, target.width, target.height);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glEnable(GL_DEPTH_TEST);
    if (add) {
        glDepthMask(GL_FALSE);
        glDepthFunc(GL_EQUAL);
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        glBlendFunc(GL_ONE, GL_ONE);
    } else {
        glDepthMask(GL_TRUE);
        // A progressive pass marks uncovered pixels with alpha 0 (shaders/resolve.frag).
        if (pass) glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
        else glClearColor(scene.background.r, scene.background.g, scene.background.b, 1.0f);
        glClearDepth(1.0);
        // Only the target's rectangle: in the viewer's window the rest is the panel and the bands.
        glEnable(GL_SCISSOR_TEST);
        glScissor(0, 0, target.width, target.height);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glDisable(GL_SCISSOR_TEST);
        glDepthFunc(GL_LESS);
    }
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glProvokingVertex(GL_LAST_VERTEX_CONVENTION);  // FlatMesh puts each triangle's own vertex last
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glDisable(GL_POLYGON_OFFSET_FILL);
    if (shadows) shadowMaps_.bindTextures();

    for (std::size_t p = 0; p < panes.size(); ++p) {
        const Pane& pane = panes[p];
        if (pane.difference) continue;  // drawn below, from the other two panes
        glViewport(pane.x, target.height - pane.y - pane.height, pane.width, pane.height);
        glBindBufferRange(GL_UNIFORM_BUFFER, SL_BINDING_FRAME, uniforms_.get(), GLintptr(p * frameStride),
                          sizeof(gpu::FrameBlock));
        // Per object: does this pane's Phong program take interpolated inputs (see interpolatesInputs)?
        // Only the variants some draw uses are built (each is an LLVM compile on first use).
        std::vector<char> inputs(objects, 0);
        for (std::size_t o = 0; o < objects; ++o) inputs[o] = interpolatesInputs(o, pane, scene);
        GLuint programs[2][2][2] = {}, current = 0;  // [interpolated inputs][textured][instanced]
        for (std::size_t d = 0; d < draws.size(); ++d) {
            const Draw& draw = draws[d];
            if (draw.count == 0) continue;
            const bool instanced = draw.instances >= 0;
            GLuint& variant = programs[inputs[draw.object] ? 1 : 0][draw.textured ? 1 : 0][instanced ? 1 : 0];
            if (!variant)
                variant = program(pane.mode, scene, pass != nullptr, inputs[draw.object] != 0, draw.textured, instanced);
            if (variant != current) glUseProgram(current = variant);
            if (draw.textured) {
                const GLuint texture = objectTexture(draw.object, draw.texture);
                glActiveTexture(GL_TEXTURE0 + SL_TEXTURE_BASE_COLOR);
                glBindTexture(GL_TEXTURE_2D, texture);
                glActiveTexture(GL_TEXTURE0);
            }
            const GpuMesh& mesh = gpuMesh(draw.object, pane.mode);
            glBindBufferRange(GL_UNIFORM_BUFFER, SL_BINDING_OBJECT, uniforms_.get(),
                              GLintptr(objectsOffset + d * objectStride), sizeof(gpu::ObjectBlock));
            // A mirroring transform turns the mesh's counter-clockwise triangles clockwise on screen.
            const glm::mat4 world = worldFromObject(scene.objects[draw.object].transform);
            bool mirrored = glm::determinant(glm::mat3(world)) < 0.0f;
            glBindVertexArray(mesh.vao.get());
            if (!instanced) {
                glFrontFace(mirrored ? GL_CW : GL_CCW);
                drawTriangles(draw.first, draw.count);
                continue;
            }
            const InstanceGroup& group = objectInstanceGroups_[draw.object][std::size_t(draw.instances)];
            mirrored = mirrored != group.mirrored;
            glFrontFace(mirrored ? GL_CW : GL_CCW);
            bindInstances(draw.object, group);
            glDrawElementsInstanced(GL_TRIANGLES, draw.count, GL_UNSIGNED_INT,
                                    reinterpret_cast<void*>(std::size_t(draw.first) * sizeof(std::uint32_t)), group.count);
        }
    }
    glBindVertexArray(0);
    glFrontFace(GL_CCW);
    if (add) {
        glDisable(GL_BLEND);
        glDepthMask(GL_TRUE);
        glDepthFunc(GL_LESS);
    }
}

std::vector<glm::ivec2> progressivePassOrder(const glm::ivec2& stride) {
    std::vector<glm::ivec2> order;
    for (int y = 0; y < stride.y; ++y)
        for (int x = 0; x < stride.x; ++x) order.emplace_back(x, y);
    int bits = 0;
    while ((1 << bits) < std::max(stride.x, stride.y)) ++bits;
    std::stable_sort(order.begin(), order.end(), [bits](const glm::ivec2& a, const glm::ivec2& b) {
        return bayerRank(unsigned(a.x), unsigned(a.y), bits) < bayerRank(unsigned(b.x), unsigned(b.y), bits);
    });
    return order;
}

Renderer::ProgressiveStatus Renderer::renderProgressive(const Scene& scene, const RenderTarget& target, int stride,
                                                        bool restart) {
    Progressive& pr = progressive_;
    const int w = target.width, h = target.height;
    // Along each axis no stride beyond the largest sample count: such passes would have no samples.
    glm::ivec2 maxSamples(1);
    for (const Light& l : scene.lights)
        if (l.type == LightType::Area) maxSamples = glm::max(maxSamples, l.samples);
    const glm::ivec2 s = glm::clamp(glm::ivec2(stride), glm::ivec2(1), maxSamples);
    if (pr.width != w || pr.height != h) {
        pr.sumColor = makeImageTexture(GL_RGBA32F, GL_RGBA, GL_FLOAT, w, h);
        pr.depth = makeImageTexture(GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, w, h);
        pr.sumFbo = makeFramebuffer(pr.sumColor.get(), pr.depth.get(), "progressive sampling (float sum)");
        pr.width = w, pr.height = h;
        restart = true;
    }
    if (restart || s != pr.stride) {
        pr.stride = s;
        pr.order = progressivePassOrder(s);
        pr.done = 0;
    }
    const std::vector<Pane> panes = layoutPanes(scene.layout, scene.shading, w, h, scene.diff);
    if (pr.done < int(pr.order.size())) {
        // The first pass draws the sum's surfaces and depth as a frame does. The others add into it:
        // the same programs draw the same surfaces at the same depths, so with GL_EQUAL exactly the
        // visible fragment of each pixel is shaded and added (and hidden ones cost nothing).
        const AreaSamplePass pass{pr.order[std::size_t(pr.done)], s};
        drawPanes(scene, panes, RenderTarget{pr.sumFbo.get(), w, h}, &pass, pr.done > 0);
        ++pr.done;
    }

    // The image so far, with the surfaces' depth for the overlays.
    const std::size_t encoding = scene.outputEncoding == OutputEncoding::Srgb ? 1 : 0;
    gl::Program& resolve = pr.resolve[encoding];
    if (!resolve) {
        resolve = buildProgram("resolve", shaders_, {encoding ? "SL_ENCODING SL_ENCODING_SRGB" : "SL_ENCODING SL_ENCODING_LINEAR"},
                               kFullscreenVertex);
        glUseProgram(resolve.get());
        glUniform1i(glGetUniformLocation(resolve.get(), "u_sum"), 0);
        glUniform1i(glGetUniformLocation(resolve.get(), "u_depth"), 1);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
    glViewport(0, 0, w, h);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, pr.sumColor.get());
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, pr.depth.get());
    glActiveTexture(GL_TEXTURE0);
    glUseProgram(resolve.get());
    glUniform3f(glGetUniformLocation(resolve.get(), "u_background"), scene.background.r, scene.background.g,
                scene.background.b);
    drawFullscreen(resolve.get());
    glDepthFunc(GL_LESS);
    if (panes.size() == 3 && panes[2].difference) drawDifference(panes[2], panes[0], panes[1], scene.diff.factor, target);
    checkGl("progressive render");
    return {pr.done, int(pr.order.size())};
}

void Renderer::drawFullscreen(GLuint program) {
    if (!emptyVao_) emptyVao_ = gl::makeVertexArray();
    glDisable(GL_CULL_FACE);
    glUseProgram(program);
    glBindVertexArray(emptyVao_.get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glEnable(GL_CULL_FACE);
}

void Renderer::drawDifference(const Pane& pane, const Pane& a, const Pane& b, float factor, const RenderTarget& target) {
    if (pane.width <= 0 || pane.height <= 0) return;
    if (!diffProgram_) {
        diffProgram_ = buildProgram("difference", shaders_, {}, kFullscreenVertex);
        glUseProgram(diffProgram_.get());
        glUniform1i(glGetUniformLocation(diffProgram_.get(), "u_sourceA"), 0);
        glUniform1i(glGetUniformLocation(diffProgram_.get(), "u_sourceB"), 1);
    }
    if (!diffSources_[0] || diffWidth_ != pane.width || diffHeight_ != pane.height) {
        for (std::size_t k = 0; k < 2; ++k) {
            diffSources_[k] = makeImageTexture(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, pane.width, pane.height);
            diffSourceFbos_[k] = makeFramebuffer(diffSources_[k].get(), 0, "layout diff");
        }
        diffWidth_ = pane.width, diffHeight_ = pane.height;
    }
    // Copy both source panes out of the target (GL's rows run bottom-up: y flips). A blit, not
    // glCopyTexSubImage2D: it also reads a multisampled target (MSAA), resolving the panes.
    const Pane* sources[2] = {&a, &b};
    for (std::size_t k = 0; k < 2; ++k) {
        blitColor(target.framebuffer, sources[k]->x, target.height - sources[k]->y - sources[k]->height,
                  diffSourceFbos_[k].get(), 0, 0, pane.width, pane.height);
        glActiveTexture(GLenum(GL_TEXTURE0 + k));
        glBindTexture(GL_TEXTURE_2D, diffSources_[k].get());
    }
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
    const int originY = target.height - pane.y - pane.height;
    glViewport(pane.x, originY, pane.width, pane.height);
    glDisable(GL_DEPTH_TEST);
    glUseProgram(diffProgram_.get());
    glUniform2i(glGetUniformLocation(diffProgram_.get(), "u_paneOrigin"), pane.x, originY);
    glUniform1f(glGetUniformLocation(diffProgram_.get(), "u_factor"), factor);
    drawFullscreen(diffProgram_.get());
    glActiveTexture(GL_TEXTURE0);
    glEnable(GL_DEPTH_TEST);
}

Image readPixels(const RenderTarget& target) {
    Image img(target.width, target.height);
    // glReadPixels cannot read a multisampled framebuffer (MSAA): resolve it into a plain one first.
    gl::Framebuffer resolved;
    gl::Texture resolvedColor;
    if (isMultisampled(target.framebuffer)) {
        resolvedColor = makeImageTexture(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, target.width, target.height);
        resolved = makeFramebuffer(resolvedColor.get(), 0, "readPixels (MSAA resolve)");
        blitColor(target.framebuffer, 0, 0, resolved.get(), 0, 0, target.width, target.height);
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, resolved ? resolved.get() : target.framebuffer);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    std::vector<std::uint8_t> bottomUp(img.rgba.size());
    glReadPixels(0, 0, target.width, target.height, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
    const std::size_t row = std::size_t(target.width) * 4;
    for (int y = 0; y < target.height; ++y)
        std::memcpy(img.pixel(0, y), bottomUp.data() + std::size_t(target.height - 1 - y) * row, row);
    checkGl("readPixels");
    return img;
}

}  // namespace shadelab
