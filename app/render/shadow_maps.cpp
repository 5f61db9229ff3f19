#include "render/shadow_maps.hpp"

#include "core/base/error.hpp"
#include "core/shading/lighting.hpp"
#include "render/program.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <cstring>

namespace shadelab {
namespace {

void put(std::vector<float>& s, const glm::vec3& v) { s.insert(s.end(), {v.x, v.y, v.z}); }

// Everything a light's maps depend on, flattened: if it is unchanged, so are the maps.
std::vector<float> signatureOf(const Scene& scene, const std::vector<ShadowMaps::DepthDraw>& draws) {
    std::vector<float> s;
    const ShadowSettings& st = scene.shadows;
    s.insert(s.end(), {float(st.mapSize), float(st.areaMapSize), float(st.pcf), st.depthBias});
    for (const Light& l : scene.lights) {
        s.insert(s.end(), {float(int(l.type)), float(l.samples.x), float(l.samples.y), l.size.x, l.size.y,
                           l.twoSided ? 1.0f : 0.0f});
        put(s, l.position);
        put(s, l.direction);
        put(s, l.normal);
    }
    for (const ShadowMaps::DepthDraw& d : draws) {
        s.insert(s.end(), {float(d.vao), float(d.first), float(d.count), float(d.maskTexture), d.alpha, d.alphaCutoff});
        s.insert(s.end(), glm::value_ptr(d.worldFromObject), glm::value_ptr(d.worldFromObject) + 16);
    }
    return s;
}

void copy4(float (&dst)[4], const glm::vec4& v) { std::memcpy(dst, glm::value_ptr(v), sizeof dst); }

// The GL state of the depth views: depth only, no culling, slope-scaled offset `bias`.
void beginDepthPass(float bias) {
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);  // open meshes (a plane) cast from both sides
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    // Slope-scaled offset: surfaces at a grazing angle to the light get pushed further.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(bias, bias);
    glClearDepth(1.0);
}

}  // namespace

// The depth program and framebuffer (once), the layers each light takes, and texture arrays that hold them.
void ShadowMaps::prepareTargets(const Scene& scene, std::size_t count, const ShaderLibrary& shaders) {
    if (!solid_.program) {
        solid_ = depthProgram(shaders, {});
        framebuffer_ = gl::makeFramebuffer();
    }
    layout_ = shadowLayout(scene.lights, count);
    GLint maxLayers = 256;
    glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &maxLayers);
    if (std::max(layout_.layers, layout_.areaLayers) > maxLayers)
        throw GlOutOfMemory("shadows: the lights need " + std::to_string(std::max(layout_.layers, layout_.areaLayers)) +
                            " shadow-map layers in one texture array; this GL has at most " +
                            std::to_string(maxLayers) + " (fewer area-light samples or shadowed lights)");
    maps_.allocate(scene.shadows.mapSize, layout_.layers);
    areaMaps_.allocate(scene.shadows.areaMapSize, layout_.areaLayers);
    projections_.resize(count);
}

void ShadowMaps::render(const Scene& scene, const std::vector<DepthDraw>& draws, const std::vector<Aabb>& boxes,
                        const ShaderLibrary& shaders) {
    viewsRendered_ = 0;
    const std::size_t count = std::min<std::size_t>(scene.lights.size(), SL_MAX_LIGHTS);
    std::vector<float> signature = signatureOf(scene, draws);
    if (signature == signature_ && projections_.size() == count) return;

    prepareTargets(scene, count, shaders);
    signature_ = std::move(signature);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    bool cutOuts = false;
    for (const DepthDraw& d : draws) cutOuts = cutOuts || d.maskTexture != 0;
    if (cutOuts && !cutOut_.program) cutOut_ = depthProgram(shaders, {"SL_ALPHA_MODE SL_ALPHA_MASK"});
    beginDepthPass(scene.shadows.depthBias);
    GLuint current = 0;

    for (std::size_t l = 0; l < count; ++l) {
        projections_[l] = shadowProjection(scene.lights[l], boxes, scene.shadows);
        const ShadowProjection& projection = projections_[l];
        const LayerArray& maps = scene.lights[l].type == LightType::Area ? areaMaps_ : maps_;
        glViewport(0, 0, maps.size, maps.size);
        for (std::size_t layer = 0; layer < projection.clipFromWorld.size(); ++layer) {
            glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, maps.texture.get(), 0,
                                      layout_.firstLayer[l] + int(layer));
            glClear(GL_DEPTH_BUFFER_BIT);
            for (const DepthDraw& d : draws) drawDepth(d, projection.clipFromWorld[layer], current);
            ++viewsRendered_;
        }
    }
    glBindVertexArray(0);
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, 0, 0, 0);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

ShadowMaps::DepthProgram ShadowMaps::depthProgram(const ShaderLibrary& shaders,
                                                  const std::vector<std::string>& defines) {
    ShadowMaps::DepthProgram p;
    p.program = buildProgram("shadow_depth", shaders, defines);
    p.clipFromObject = glGetUniformLocation(p.program.get(), "u_shadowClipFromObject");
    p.alpha = glGetUniformLocation(p.program.get(), "u_alpha");
    p.alphaCutoff = glGetUniformLocation(p.program.get(), "u_alphaCutoffValue");
    return p;
}

void ShadowMaps::drawDepth(const DepthDraw& d, const glm::mat4& clipFromWorld, GLuint& current) {
    if (d.count == 0) return;
    const DepthProgram& p = d.maskTexture ? cutOut_ : solid_;
    if (p.program.get() != current) glUseProgram(current = p.program.get());
    const glm::mat4 clipFromObject = clipFromWorld * d.worldFromObject;
    glUniformMatrix4fv(p.clipFromObject, 1, GL_FALSE, glm::value_ptr(clipFromObject));
    if (d.maskTexture) {
        glUniform1f(p.alpha, d.alpha);
        glUniform1f(p.alphaCutoff, d.alphaCutoff);
        glActiveTexture(GL_TEXTURE0 + SL_TEXTURE_BASE_COLOR);
        glBindTexture(GL_TEXTURE_2D, d.maskTexture);
        glActiveTexture(GL_TEXTURE0);
    }
    glBindVertexArray(d.vao);
    glDrawElements(GL_TRIANGLES, d.count, GL_UNSIGNED_INT,
                   reinterpret_cast<void*>(std::size_t(d.first) * sizeof(std::uint32_t)));
}

void ShadowMaps::LayerArray::allocate(int newSize, int newLayers) {
    if (newLayers == 0) newSize = newLayers = 1;  // an unused array still needs a texture to bind
    if (texture && size == newSize && layers == newLayers) return;
    texture = gl::makeTexture();
    size = newSize;
    layers = newLayers;
    glBindTexture(GL_TEXTURE_2D_ARRAY, texture.get());
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_DEPTH_COMPONENT24, size, size, layers, 0, GL_DEPTH_COMPONENT,
                 GL_UNSIGNED_INT, nullptr);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, 0);
#if SHADELAB_GLES
    // WebGL2 has no border colour: outside a map repeats its edge (docs/web.md). The maps are fitted
    // to what casts and receives shadows, so a lookup outside is rare.
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
#else
    // Outside a map is lit: depth 1 at the border compares as "nothing in front".
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    const float border[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    glTexParameterfv(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_BORDER_COLOR, border);
#endif
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
}

void ShadowMaps::fillBlock(const Scene& scene, gpu::FrameBlock& b) const {
    b.shadowSettings[0] = scene.shadows.normalBias;
    for (std::size_t l = 0; l < projections_.size() && l < std::size_t(SL_MAX_LIGHTS); ++l) {
        const ShadowProjection& p = projections_[l];
        gpu::LightGpu& g = b.lights[l];
        g.falloff[2] = p.size > 0 ? 1.0f / float(p.size) : 0.0f;
        const glm::mat4& clip = p.clipFromWorld.empty()                   ? glm::mat4(1.0f)
                                : scene.lights[l].type == LightType::Area ? p.centreClipFromWorld
                                                                          : p.clipFromWorld.front();
        std::memcpy(g.shadowClipFromWorld, glm::value_ptr(clip), sizeof g.shadowClipFromWorld);
        copy4(g.shadowU, p.uClip);
        copy4(g.shadowV, p.vClip);
        copy4(g.shadow, glm::vec4(p.texelWorld, p.depthA, p.depthB, p.tanHalf));
    }
}

void ShadowMaps::bindTextures() const {
    glActiveTexture(GL_TEXTURE0 + SL_TEXTURE_SHADOW_MAPS);
    glBindTexture(GL_TEXTURE_2D_ARRAY, maps_.texture.get());
    glActiveTexture(GL_TEXTURE0 + SL_TEXTURE_AREA_SHADOW_MAPS);
    glBindTexture(GL_TEXTURE_2D_ARRAY, areaMaps_.texture.get());
    glActiveTexture(GL_TEXTURE0);
}

}  // namespace shadelab
