#pragma once
// Shadow maps for Renderer, rendered before the shaded passes when the scene asks for shadows: two
// depth texture arrays, one for the point, spot and directional lights and one for the area lights
// (their maps have their own size), each light's layers from its first layer (ShadowLayout). What
// each layer sees is decided GL-free in render/cpu/shadow_projection.hpp; this class owns the textures, the
// depth-only program and the pass.
// The maps are re-rendered only when something they depend on changed (lights, settings, object
// transforms, geometry), so a still scene in the viewer pays for them once.
#include "core/scene/scene.hpp"
#include "render/cpu/shadow_projection.hpp"
#include "render/gl_handles.hpp"
#include "render/gpu_blocks.hpp"
#include "render/shader_library.hpp"

#include <glm/mat4x4.hpp>

#include <vector>

namespace shadelab {

class ShadowMaps {
public:
    // One object part to draw into the maps: a VAO with positions at SL_ATTRIB_POSITION.
    struct DepthDraw {
        GLuint vao = 0;
        GLsizei first = 0, count = 0;  // indices (uint32)
        glm::mat4 worldFromObject{1.0f};
        // glTF's MASK: a cut-out casts a cut-out shadow. The base colour texture (its alpha), the
        // factor's alpha and the cutoff; the vertex array carries the texture coordinates and COLOR_0.
        GLuint maskTexture = 0;  // 0: the draw is solid
        float alpha = 1.0f, alphaCutoff = 0.5f;
    };

    ShadowMaps() = default;
    ShadowMaps(const ShadowMaps&) = delete;
    ShadowMaps& operator=(const ShadowMaps&) = delete;

    // Renders every light's maps (if anything changed). `objectBoxes` are world-space boxes of all
    // objects. Leaves the framebuffer binding and viewport for the caller to set.
    void render(const Scene& scene, const std::vector<DepthDraw>& draws, const std::vector<Aabb>& objectBoxes,
                const ShaderLibrary& shaders);
    // Writes the per-light shadow data and the settings into a FrameBlock.
    void fillBlock(const Scene& scene, gpu::FrameBlock& block) const;
    // Binds the two arrays to texture units SL_TEXTURE_SHADOW_MAPS and SL_TEXTURE_AREA_SHADOW_MAPS.
    void bindTextures() const;
    // Forget the cached maps (new geometry may reuse the old VAO names).
    void invalidate() { signature_.clear(); }
    // How many depth views the last render() drew (0 when the cache was used): for tests and the HUD.
    int viewsRendered() const { return viewsRendered_; }

private:
    void prepareTargets(const Scene& scene, std::size_t count, const ShaderLibrary& shaders);  // render()'s first step
    struct LayerArray {
        gl::Texture texture;
        int size = 0, layers = 0;
        void allocate(int size, int layers);  // (re)creates the texture when either changed
    };
    // The depth program, and its variant for cut-outs (SL_ALPHA_MASK).
    struct DepthProgram {
        gl::Program program;
        GLint clipFromObject = -1, alpha = -1, alphaCutoff = -1;
    };
    DepthProgram solid_, cutOut_;
    static DepthProgram depthProgram(const ShaderLibrary& shaders, const std::vector<std::string>& defines);
    void drawDepth(const DepthDraw& d, const glm::mat4& clipFromWorld, GLuint& current);
    gl::Framebuffer framebuffer_;
    LayerArray maps_, areaMaps_;
    std::vector<ShadowProjection> projections_;  // per light
    ShadowLayout layout_;
    std::vector<float> signature_;  // everything the maps depend on, as of the last render
    int viewsRendered_ = 0;
};

}  // namespace shadelab
