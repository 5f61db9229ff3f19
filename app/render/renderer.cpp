#include "render/renderer.hpp"

#include "core/base/error.hpp"

#include "core/geometry/camera.hpp"
#include "core/shading/environment.hpp"
#include "core/shading/lighting.hpp"
#include "render/gpu_blocks.hpp"
#include "render/program.hpp"
#include "render/program_cache.hpp"

#include <glm/common.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstring>
#include <map>
#include <optional>
#include <stdexcept>

namespace shadelab {
namespace {

// "llvmpipe (LLVM 15.0.6, 128 bits)": Mesa's software rasteriser on its SSE path (see autoMayInterpolate_).
bool llvmpipeOn128Bits(const std::string& glRenderer) {
    return glRenderer.find("llvmpipe") != std::string::npos && glRenderer.find("128 bits") != std::string::npos;
}

void copyVec(float (&dst)[4], const glm::vec3& v, float w = 0.0f) {
    dst[0] = v.x;
    dst[1] = v.y;
    dst[2] = v.z;
    dst[3] = w;
}

// A program variant as a number, for the per-pane lookup in drawPane.
unsigned variantKey(const ProgramCache::Variant& v) {
    return unsigned(v.accumulate) | unsigned(v.interpolatedInputs) << 1 | unsigned(v.textured) << 2 |
           unsigned(v.instanced) << 3 | unsigned(v.alphaMode) << 4 | unsigned(v.emissive) << 6 |
           unsigned(v.emissiveTexture) << 7 | unsigned(v.doubleSided) << 8 | unsigned(v.anisotropic) << 9 |
           unsigned(v.environment) << 10 | unsigned(v.singleShadowTap) << 13;
}

void bindTexture(int unit, GLuint texture) {
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D, texture);
    glActiveTexture(GL_TEXTURE0);
}

// Whether an object's draws are anisotropic (SL_ANISOTROPY and vertex arrays with tangents): its
// material asks for it and the lobe is Blinn-Phong's (core/shading/lighting.hpp, anisotropicLobe).
bool anisotropicObject(const Scene& s, std::size_t object) {
    return object < s.objects.size() && s.objects[object].material.anisotropic &&
           s.reflection == ReflectionModel::BlinnPhong;
}

// SL_ENVIRONMENT_* for an object's draws: mirror and glass (k_r or k_t) in a scene with an environment
// (core/shading/environment.hpp, mirrorOrGlass); SL_ENVIRONMENT_NONE for every other draw.
int environmentObject(const Scene& s, std::size_t object) {
    return object < s.objects.size() && mirrorOrGlass(s.objects[object].material, s.environment)
               ? environmentDefine(s.environment.kind)
               : SL_ENVIRONMENT_NONE;
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

// `color` is the draw's C: the material's, or a glTF part's base colour; `alpha`, `emissive` and
// `alphaCutoff` what a glTF material adds. The shaders form the formula's products themselves
// (shaders/lecture.glsl reads k_a, k_d, k_s, k_e, C and S as the slide names them).
gpu::ObjectBlock objectBlock(const SceneObject& o, const glm::vec3& color, float alpha, const glm::vec3& emissive,
                             float alphaCutoff) {
    gpu::ObjectBlock b{};
    const glm::mat4 world = worldFromObject(o.transform);
    const glm::mat4 normal = glm::mat4(normalWorldFromObject(world));
    std::memcpy(b.worldFromObject, glm::value_ptr(world), sizeof b.worldFromObject);
    std::memcpy(b.normalWorldFromObject, glm::value_ptr(normal), sizeof b.normalWorldFromObject);
    copyVec(b.color, color, alpha);
    copyVec(b.specularColor, o.material.specularColor);
    copyVec(b.emissive, emissive);
    b.alphaCutoff[0] = alphaCutoff;
    b.coefficients[0] = o.material.ka;
    b.coefficients[1] = o.material.kd;
    b.coefficients[2] = o.material.ks;
    b.coefficients[3] = o.material.ke;
    b.anisotropy[0] = o.material.anisotropy.x;
    b.anisotropy[1] = o.material.anisotropy.y;
    b.mirrorGlass[0] = o.material.mirror;
    b.mirrorGlass[1] = o.material.transmission;
    return b;
}

}  // namespace

Renderer::Renderer(GLADloadfunc getProcAddress, ShaderLibrary shaders, RendererOptions options)
    : options_(options), programs_(std::move(shaders), options.packedFlatVertices), meshes_(options) {
#if SHADELAB_GLES
    (void)getProcAddress;  // WebGL2's functions are linked, not loaded (app/web/gles/glad/gl.h)
#else
    const int version = gladLoadGL(getProcAddress);
    if (version == 0) throw std::runtime_error("could not load OpenGL entry points");
    if (GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) < 33)
        throw std::runtime_error("OpenGL 3.3 core is needed; the context offers " +
                                 std::to_string(GLAD_VERSION_MAJOR(version)) + "." +
                                 std::to_string(GLAD_VERSION_MINOR(version)));
#endif
    uniforms_ = std::make_unique<UniformStager>();
    autoMayInterpolate_ = !llvmpipeOn128Bits(glRenderer());
    checkGl("renderer set-up");
}

Renderer::~Renderer() = default;

void Renderer::setGeometry(std::shared_ptr<const SceneGeometry> geometry) {
    meshes_.setGeometry(std::move(geometry));
    shadowMaps_.invalidate();
}

void Renderer::uploadAndReleaseCpuGeometry(const Scene& scene) {
    std::vector<ShadingMode> modes;
    for (const Pane& pane : layoutPanes(scene.layout, scene.shading, 1, 1, scene.diff)) modes.push_back(pane.mode);
    std::vector<char> tangents(meshes_.objects(), 0);
    for (std::size_t o = 0; o < tangents.size() && o < scene.objects.size(); ++o)
        tangents[o] = anisotropicObject(scene, o);
    meshes_.uploadAndRelease(modes, scene.textures, tangents);
}

std::string Renderer::glRenderer() const { return reinterpret_cast<const char*>(glGetString(GL_RENDERER)); }
std::string Renderer::glVersion() const { return reinterpret_cast<const char*>(glGetString(GL_VERSION)); }

void Renderer::preparePrograms(const Scene& scene) {
    bool textured = false, doubleSided = false;
    for (std::size_t o = 0; o < meshes_.objects(); ++o) {
        textured = textured || (meshes_.variesColor(o) && scene.textures);
        for (const MeshPart& part : meshes_.parts(o)) doubleSided = doubleSided || part.doubleSided;
    }
    for (bool t : {false, true})
        for (bool d : {false, true}) {
            if ((t && !textured) || (d && !doubleSided)) continue;
            for (ShadingMode mode : {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong})
                programs_.get(mode, scene, {false, false, t, false, d});
            // Zooming can switch a Phong draw to the other variant (interpolatesInputs): build it too.
            if (scene.lights.size() <= SL_MAX_INTERPOLATED_LIGHTS && mayInterpolate())
                programs_.get(ShadingMode::Phong, scene, {false, true, t, false, d});
        }
    // The variants of anisotropic and of mirror-and-glass objects (each object's combination).
    for (std::size_t o = 0; o < meshes_.objects(); ++o) {
        ProgramCache::Variant v;
        v.anisotropic = anisotropicObject(scene, o);
        v.environment = environmentObject(scene, o);
        if (!v.anisotropic && v.environment == SL_ENVIRONMENT_NONE) continue;
        for (ShadingMode mode : {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong})
            programs_.get(mode, scene, v);
    }
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
            while (glClientWaitSync(previous, GL_SYNC_FLUSH_COMMANDS_BIT, 1000000000u) == GL_TIMEOUT_EXPIRED) {}
            glDeleteSync(previous);
        } else {
            glFlush();  // start the first chunk while the second is submitted
        }
        previous = submitted;
    }
    glDeleteSync(previous);
}

bool Renderer::interpolatesInputs(std::size_t object, const Pane& pane, const Scene& scene) const {
    if (pane.mode != ShadingMode::Phong || scene.lights.size() > SL_MAX_INTERPOLATED_LIGHTS || !mayInterpolate())
        return false;
    if (options_.phongInputs == PhongInputs::Interpolated) return true;
    // Each input costs llvmpipe set-up work per triangle, each uniform read work per fragment: the
    // inputs pay off where the triangles are large on screen (measured break-even ~6 pixels per
    // front-facing triangle on the benchmark sphere; 16 leaves a margin for the box's overestimate).
    const Aabb box = transformAabb(meshes_.box(object), worldFromObject(scene.objects[object].transform));
    const float frontTriangles = std::max(1.0f, 0.5f * float(meshes_.triangles(object)));
    return projectedBoxPixels(scene.camera, pane, box.lo, box.hi) >= kInputsMinPixelsPerTriangle * frontTriangles;
}

void Renderer::render(const Scene& scene, const RenderTarget& target) {
    const std::vector<Pane> panes = layoutPanes(scene.layout, scene.shading, target.width, target.height, scene.diff);
    drawPanes(scene, panes, target, nullptr, false);
    difference_.draw(panes, scene.diff.factor, target, programs_.shaders());
    checkGl("render");
}

// A part as drawn: its C, texture, alpha and E. A scene's material colour replaces the glTF
// material (C, texture and vertex colours, alpha and E); --no-textures keeps its factors alone.
Renderer::Draw Renderer::partDraw(const Scene& scene, std::size_t o, std::size_t p) const {
    const Material& m = scene.objects[o].material;
    const MeshPart& part = meshes_.parts(o)[p];
    const bool textured = meshes_.variesColor(o) && scene.textures && !m.colorSet;
    Draw d{o,
           GLsizei(part.firstIndex),
           GLsizei(part.indexCount),
           (m.colorSet || !part.hasBaseColor) ? m.color : part.baseColor,
           textured,
           textured ? part.texture : -1,
           -1};
    d.doubleSided = part.doubleSided;  // the surface's, whatever colour it is drawn in
    if (m.colorSet) return d;
    d.alpha = part.baseAlpha;
    d.alphaMode = part.alphaMode;
    d.alphaCutoff = part.alphaCutoff;
    // Without a texture or vertex colours the alpha is the factor's, the same over the whole part: a
    // MASK part is all there or all cut out.
    if (!textured && d.alphaMode == AlphaMode::Mask) {
        d.alphaMode = AlphaMode::Opaque;
        if (d.alpha < d.alphaCutoff) d.count = 0;
    }
    d.emissive = part.emissive;
    if (textured && part.emissive != glm::vec3(0.0f) && meshes_.hasEmissiveTexture(o))
        d.emissiveTexture = part.emissiveTexture;
    return d;
}

// One draw per object part (a glTF primitive's base colour and texture, or the whole mesh), and per
// group of its instances. Opaque and cut-out (MASK) draws first, in the model's order; then the
// blended ones (BLEND), farthest first by the distance of their bounds' centre from the eye, so each
// is blended over what is behind it.
std::vector<Renderer::Draw> Renderer::drawList(const Scene& scene) const {
    const std::size_t objects = std::min(meshes_.objects(), scene.objects.size());
    std::vector<Draw> draws;
    std::vector<std::pair<float, Draw>> blended;
    for (std::size_t o = 0; o < objects; ++o) {
        const std::vector<MeshCache::InstanceGroup>& groups = meshes_.instanceGroups(o);
        const glm::mat4 world = worldFromObject(scene.objects[o].transform);
        std::size_t g = 0;  // the groups are in part order
        for (std::size_t p = 0; p < meshes_.parts(o).size(); ++p) {
            Draw d = partDraw(scene, o, p);
            const MeshPart& part = meshes_.parts(o)[p];
            const auto add = [&](const Draw& draw, const glm::mat4& instance) {
                if (draw.alphaMode != AlphaMode::Blend) return draws.push_back(draw);
                const Aabb& box = meshes_.partBox(o, p);
                const glm::vec3 centre = glm::vec3(world * instance * glm::vec4(0.5f * (box.lo + box.hi), 1.0f));
                blended.emplace_back(glm::distance(centre, scene.camera.eye), draw);
            };
            if (part.instances.empty()) add(d, glm::mat4(1.0f));
            for (; g < groups.size() && groups[g].part == p; ++g) {
                d.instances = int(g);
                add(d, meshes_.instance(o, std::size_t(groups[g].first)));
            }
        }
    }
    std::stable_sort(blended.begin(), blended.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    for (const auto& b : blended) draws.push_back(b.second);
    return draws;
}

// The shadow pass: every draw's triangles into the lights' depth maps (ShadowMaps, which binds its own
// framebuffer, program and viewport).
void Renderer::renderShadowMaps(const Scene& scene, const std::vector<Draw>& draws) {
    std::vector<ShadowMaps::DepthDraw> depthDraws;
    std::vector<Aabb> boxes;
    for (std::size_t o = 0; o < std::min(meshes_.objects(), scene.objects.size()); ++o)
        boxes.push_back(transformAabb(meshes_.box(o), worldFromObject(scene.objects[o].transform)));
    for (const Draw& d : draws) {
        ShadowMaps::DepthDraw depth{meshes_.gpuMesh(d.object, ShadingMode::Phong).vao.get(), d.first, d.count,
                                    worldFromObject(scene.objects[d.object].transform)};
        // A cut-out casts a cut-out shadow; a blended part casts one as if it were opaque.
        if (d.alphaMode == AlphaMode::Mask) {
            depth.maskTexture = meshes_.texture(d.object, d.texture);
            depth.alpha = d.alpha;
            depth.alphaCutoff = d.alphaCutoff;
        }
        if (d.instances < 0) {
            depthDraws.push_back(depth);
            continue;
        }
        // The depth pass draws each instance on its own (it has no instanced variant).
        const MeshCache::InstanceGroup& g = meshes_.instanceGroups(d.object)[std::size_t(d.instances)];
        const glm::mat4 world = depth.worldFromObject;
        for (GLsizei i = 0; i < g.count; ++i) {
            depth.worldFromObject = world * meshes_.instance(d.object, std::size_t(g.first + i));
            depthDraws.push_back(depth);
        }
    }
    shadowMaps_.render(scene, depthDraws, boxes, programs_.shaders());
}

// All uniforms of the frame in one upload: a FrameBlock per pane, then an ObjectBlock per draw.
void Renderer::stageUniforms(const Scene& scene, const std::vector<Pane>& panes, const std::vector<Draw>& draws,
                             const AreaSamplePass* pass, bool shadows) {
    uniforms_->begin(panes.size(), draws.size());
    for (std::size_t p = 0; p < panes.size(); ++p) {
        gpu::FrameBlock b = frameBlock(scene, float(panes[p].width) / float(std::max(panes[p].height, 1)));
        if (shadows) shadowMaps_.fillBlock(scene, b);
        // Only Phong panes split the samples: flat and Gouraud clamp per face or vertex before the
        // rasteriser, so their passes evaluate every sample (they are cheap) and their mean is exact.
        const bool split = pass && panes[p].mode == ShadingMode::Phong;
        const glm::ivec2 first = split ? pass->first : glm::ivec2(0), stride = split ? pass->stride : glm::ivec2(1);
        b.areaPass[0] = first.x;
        b.areaPass[1] = first.y;
        b.areaPass[2] = stride.x;
        b.areaPass[3] = stride.y;
        uniforms_->setFrame(p, b);
    }
    for (std::size_t d = 0; d < draws.size(); ++d)
        uniforms_->setObject(d, objectBlock(scene.objects[draws[d].object], draws[d].color, draws[d].alpha,
                                            draws[d].emissive, draws[d].alphaCutoff));
    uniforms_->upload();
}

// The GL state the scene's draws rely on, and the target cleared (or, with `add`, blending onto it
// where the depth equals).
void Renderer::beginPanes(const Scene& scene, const RenderTarget& target, bool accumulate, bool add) {
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
        if (accumulate) glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
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
}

// Per object: does this pane's Phong program take interpolated inputs (see interpolatesInputs)?
// Anisotropic objects take the tangent from their own vertex arrays, which the speed variant does not read.
// So do mirror-and-glass objects (their programs have the variant's inputs only for the lecture's sum).
std::vector<char> Renderer::paneInputs(const Scene& scene, const Pane& pane) const {
    const std::size_t objects = std::min(meshes_.objects(), scene.objects.size());
    std::vector<char> inputs(objects, 0);
    for (std::size_t o = 0; o < objects; ++o)
        inputs[o] = interpolatesInputs(o, pane, scene) && !anisotropicObject(scene, o) &&
                    environmentObject(scene, o) == SL_ENVIRONMENT_NONE;
    return inputs;
}

// The program variant one draw needs.
ProgramCache::Variant Renderer::drawVariant(const Scene& scene, const Draw& draw, bool accumulate,
                                            bool interpolatedInputs) const {
    ProgramCache::Variant v{accumulate, interpolatedInputs, draw.textured, draw.instances >= 0, draw.doubleSided};
    // A progressive pass sums its samples: blended parts are drawn in it as if opaque.
    v.alphaMode = draw.alphaMode == AlphaMode::Mask                   ? SL_ALPHA_MASK
                  : draw.alphaMode == AlphaMode::Blend && !accumulate ? SL_ALPHA_BLEND
                                                                      : SL_ALPHA_OPAQUE;
    v.emissive = draw.emissive != glm::vec3(0.0f);
    v.emissiveTexture = draw.emissiveTexture >= 0;
    v.anisotropic = anisotropicObject(scene, draw.object);
    v.environment = environmentObject(scene, draw.object);
    v.singleShadowTap = movingFrames_;
    return v;
}

// Draw d's textures, object block and triangles (once, or its group of instances), with the program bound.
void Renderer::drawMesh(const Scene& scene, const Draw& draw, std::size_t d, ShadingMode mode,
                        const ProgramCache::Variant& v) {
    if (draw.textured) bindTexture(SL_TEXTURE_BASE_COLOR, meshes_.texture(draw.object, draw.texture));
    if (v.emissiveTexture) bindTexture(SL_TEXTURE_EMISSIVE, meshes_.texture(draw.object, draw.emissiveTexture));
    const MeshCache::GpuMesh& mesh = meshes_.gpuMesh(draw.object, mode, v.anisotropic);
    uniforms_->bindObject(d);
    // A mirroring transform turns the mesh's counter-clockwise triangles clockwise on screen.
    const glm::mat4 world = worldFromObject(scene.objects[draw.object].transform);
    bool mirrored = glm::determinant(glm::mat3(world)) < 0.0f;
    glBindVertexArray(mesh.vao.get());
    if (!v.instanced) {
        glFrontFace(mirrored ? GL_CW : GL_CCW);
        drawTriangles(draw.first, draw.count);
        return;
    }
    const MeshCache::InstanceGroup& group = meshes_.instanceGroups(draw.object)[std::size_t(draw.instances)];
    mirrored = mirrored != group.mirrored;
    glFrontFace(mirrored ? GL_CW : GL_CCW);
    meshes_.bindInstances(draw.object, group);
    glDrawElementsInstanced(GL_TRIANGLES, draw.count, GL_UNSIGNED_INT,
                            reinterpret_cast<void*>(std::size_t(draw.first) * sizeof(std::uint32_t)), group.count);
}

// Pane p's draws with its shading mode's programs.
void Renderer::drawPane(const Scene& scene, const Pane& pane, std::size_t p, const RenderTarget& target,
                        const std::vector<Draw>& draws, bool accumulate) {
    uniforms_->bindFrame(p);
    // The environment behind the surfaces (a progressive pass sums surfaces only: renderProgressive
    // draws it after the resolve, where no surface is).
    if (!accumulate) environment_.drawBackground(scene, pane, target, programs_.shaders(), false);
    glViewport(pane.x, target.height - pane.y - pane.height, pane.width, pane.height);
    // Only the variants some draw uses are built (each is an LLVM compile on first use).
    const std::vector<char> inputs = paneInputs(scene, pane);
    std::map<unsigned, GLuint> programs;  // by variantKey()
    GLuint current = 0;
    bool blending = false;
    bool culling = true;  // beginPanes enabled it
    for (std::size_t d = 0; d < draws.size(); ++d) {
        const Draw& draw = draws[d];
        if (draw.count == 0) continue;
        const ProgramCache::Variant v = drawVariant(scene, draw, accumulate, inputs[draw.object] != 0);
        GLuint& variant = programs[variantKey(v)];
        if (!variant) variant = programs_.get(pane.mode, scene, v);
        if (variant != current) glUseProgram(current = variant);
        if (culling == draw.doubleSided) {  // glTF's doubleSided: both faces drawn (the shaders light the back)
            culling = !draw.doubleSided;
            if (culling) glEnable(GL_CULL_FACE);
            else glDisable(GL_CULL_FACE);
        }
        if (v.alphaMode == SL_ALPHA_BLEND && !blending) {
            // The blended draws come last (drawList): over what is behind them, tested against its
            // depth but leaving it as it is, so the ones behind still show through.
            blending = true;
            glEnable(GL_BLEND);
            glBlendEquation(GL_FUNC_ADD);
            glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
            glDepthMask(GL_FALSE);
        }
        drawMesh(scene, draw, d, pane.mode, v);
    }
    if (blending) {
        glDisable(GL_BLEND);
        glDepthMask(GL_TRUE);
    }
    if (!culling) glEnable(GL_CULL_FACE);
}

void Renderer::drawPanes(const Scene& scene, const std::vector<Pane>& panes, const RenderTarget& target,
                         const AreaSamplePass* pass, bool add) {
    const std::vector<Draw> draws = drawList(scene);
    const bool shadows = scene.shadows.enabled && !scene.lights.empty();
    if (shadows) renderShadowMaps(scene, draws);  // first: it binds its own framebuffer
    stageUniforms(scene, panes, draws, pass, shadows);
    beginPanes(scene, target, pass != nullptr, add);
    if (shadows) shadowMaps_.bindTextures();
    environment_.bindTexture(scene);
    for (std::size_t p = 0; p < panes.size(); ++p)
        if (!panes[p].difference) drawPane(scene, panes[p], p, target, draws, pass != nullptr);  // difference: below
    glBindVertexArray(0);
    glFrontFace(GL_CCW);
    if (add) {
        glDisable(GL_BLEND);
        glDepthMask(GL_TRUE);
        glDepthFunc(GL_LESS);
    }
}

Renderer::ProgressiveStatus Renderer::renderProgressive(const Scene& scene, const RenderTarget& target, int stride,
                                                        bool restart) {
    progressive_.prepare(scene, target.width, target.height, stride, restart);
    const std::vector<Pane> panes = layoutPanes(scene.layout, scene.shading, target.width, target.height, scene.diff);
    if (const std::optional<AreaSamplePass> pass = progressive_.nextPass()) {
        // The first pass draws the sum's surfaces and depth as a frame does. The others add into it:
        // the same programs draw the same surfaces at the same depths, so with GL_EQUAL exactly the
        // visible fragment of each pixel is shaded and added (and hidden ones cost nothing).
        drawPanes(scene, panes, progressive_.sumTarget(), &*pass, !progressive_.firstPass());
        progressive_.passDrawn();
    }
    progressive_.resolveInto(scene, target, programs_.shaders());  // the image so far, depth included
    if (scene.environment.kind != EnvironmentKind::None) {
        environment_.bindTexture(scene);
        for (const Pane& pane : panes)
            if (!pane.difference) environment_.drawBackground(scene, pane, target, programs_.shaders(), true);
    }
    difference_.draw(panes, scene.diff.factor, target, programs_.shaders());
    checkGl("progressive render");
    return progressive_.status();
}

}  // namespace shadelab
