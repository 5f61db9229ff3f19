#pragma once
// The GL renderer: draws a Scene into a framebuffer it is handed. It never creates a context; the
// front end (the GLFW viewer, the OSMesa or any other headless context) makes one current and passes
// its get-proc-address function. All GL state the renderer relies on is set in render().
// A frame's passes are its parts: ShadowMaps, the scene's panes (drawPanes), DifferencePass and, in
// the viewer, ProgressivePass; readPixels() (render/readback.hpp) reads the frame back.
#include "core/geometry/camera.hpp"
#include "core/geometry/scene_geometry.hpp"
#include "core/image/image.hpp"
#include "core/scene/scene.hpp"
#include "render/difference_pass.hpp"
#include "render/environment_pass.hpp"
#include "render/gl_handles.hpp"
#include "render/mesh_cache.hpp"
#include "render/program_cache.hpp"
#include "render/progressive_pass.hpp"
#include "render/readback.hpp"
#include "render/render_target.hpp"
#include "render/renderer_options.hpp"
#include "render/shader_library.hpp"
#include "render/shadow_maps.hpp"
#include "render/uniform_stager.hpp"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace shadelab {

class Renderer {
public:
    using PhongInputs = RendererOptions::PhongInputs;
    using MeshOrder = RendererOptions::MeshOrder;

    // Loads GL 3.3 core entry points through `getProcAddress` (the context must be current) and
    // checks the version. Programs are compiled on first use. Throws std::runtime_error.
    Renderer(GLADloadfunc getProcAddress, ShaderLibrary shaders = ShaderLibrary(), RendererOptions options = {});
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Replaces the meshes; uploads happen lazily, per shading mode, on the next render().
    void setGeometry(std::shared_ptr<const SceneGeometry> geometry);
    // Uploads now what render(scene) will draw (the meshes in each pane's shading mode), then lets go
    // of the CPU copy: a one-frame headless render of a large model need not hold it twice. After
    // this, render() may only use the shading modes of `scene`'s panes.
    void uploadAndReleaseCpuGeometry(const Scene& scene);
    // Draws all panes of the scene's layout. Throws ShaderError or std::runtime_error on a GL error.
    void render(const Scene& scene, const RenderTarget& target);
    // Progressive area-light sampling, for the viewer: an area light's samples cost per fragment in
    // Phong (an 8x8 light with shadows takes ~2 s a frame at 1280x720 on llvmpipe), so they are
    // spread over passes. Each call draws at most one pass, in which Phong panes evaluate every
    // stride-th sample of each area light (both axes) from that pass's first sample, sums the pass
    // into a float buffer, and draws the mean so far - clamped and encoded as render() does - into
    // `target`, depth included. After passCount calls the image is render()'s, within float rounding.
    // `restart` (the scene, camera or size changed) starts a new sum; a complete image is redrawn
    // without drawing the scene. `stride` is clamped per axis to the largest sample count there.
    using ProgressiveStatus = shadelab::ProgressiveStatus;
    ProgressiveStatus renderProgressive(const Scene& scene, const RenderTarget& target, int stride, bool restart);
    // Compiles the flat, gouraud and phong programs for `scene`'s specialisation now, Phong's
    // interpolated-inputs variant included (render() otherwise compiles each on first use). Throws
    // ShaderError.
    void preparePrograms(const Scene& scene);
    // Moving frames (the viewer on a software rasterizer while the view is dragged, a slider held or
    // an animation plays): while on, the shadows of point, spot and directional lights take
    // one shadow-map lookup per light (SL_SHADOW_PCF compiled as 0, its own programs) instead of the
    // scene's (2 pcf + 1)^2, about half of a frame with three shadowed point lights on llvmpipe.
    // The shadow maps are the scene's either way; off (the default) draws the scene as it is.
    void setMovingFrames(bool on) { movingFrames_ = on; }

    static constexpr float kInputsMinPixelsPerTriangle = 16.0f;  // RendererOptions::PhongInputs::Auto
    // Whether `object`'s Phong draws in `pane` take interpolated inputs (always false for flat and
    // Gouraud panes, and past SL_MAX_INTERPOLATED_LIGHTS lights).
    bool interpolatesInputs(std::size_t object, const Pane& pane, const Scene& scene) const;

    std::string glRenderer() const;
    // Depth views drawn by the last render() for shadows (0: none, or the maps were still valid).
    int shadowViewsRendered() const { return shadowMaps_.viewsRendered(); }
    std::string glVersion() const;

private:
    void drawTriangles(GLsizei firstIndex, GLsizei indexCount);  // from the bound vertex array, see drawChunkTriangles
    // Shadow maps, then every pane but the difference into `target`; with `pass`, the accumulating
    // programs (linear output, alpha 0 where nothing was drawn) evaluate that pass's samples, and
    // with `add` they are added to what the target holds, where its depth equals theirs. In steps:
    void drawPanes(const Scene& scene, const std::vector<Pane>& panes, const RenderTarget& target,
                   const AreaSamplePass* pass, bool add);
    struct Draw {  // one object part, or one group of its instances
        std::size_t object;
        GLsizei first, count;      // indices
        glm::vec3 color;           // C
        bool textured;             // SL_TEXTURED: C varies (the part's texture, or white, times the vertex colours)
        int texture;               // the part's slot in Mesh::textures, or -1
        int instances;             // SL_INSTANCED: index into meshes_.instanceGroups(object); -1: drawn once
        bool doubleSided = false;  // SL_DOUBLE_SIDED: the part's glTF material is double-sided, drawn without culling
        // What a glTF material adds (shaders/object_color.glsl; none where the scene sets the colour).
        float alpha = 1.0f;  // the base colour factor's alpha
        AlphaMode alphaMode = AlphaMode::Opaque;
        float alphaCutoff = 0.5f;
        glm::vec3 emissive{0.0f};  // E's factor; 0: no SL_EMISSIVE
        int emissiveTexture = -1;  // its slot in Mesh::textures (textured draws), or -1
    };
    // The Draw for part `p` of object `o` (without its instances).
    Draw partDraw(const Scene& scene, std::size_t o, std::size_t p) const;
    std::vector<Draw> drawList(const Scene& scene) const;
    void renderShadowMaps(const Scene& scene, const std::vector<Draw>& draws);
    void stageUniforms(const Scene& scene, const std::vector<Pane>& panes, const std::vector<Draw>& draws,
                       const AreaSamplePass* pass, bool shadows);
    void beginPanes(const Scene& scene, const RenderTarget& target, bool accumulate, bool add);
    void drawPane(const Scene& scene, const Pane& pane, std::size_t p, const RenderTarget& target,
                  const std::vector<Draw>& draws, bool accumulate);
    // drawPane's steps: which objects take interpolated inputs in the pane, each draw's program variant,
    // and one draw's textures, object block and triangles.
    std::vector<char> paneInputs(const Scene& scene, const Pane& pane) const;
    ProgramCache::Variant drawVariant(const Scene& scene, const Draw& draw, bool accumulate,
                                      bool interpolatedInputs) const;
    void drawMesh(const Scene& scene, const Draw& draw, std::size_t d, ShadingMode mode,
                  const ProgramCache::Variant& v);

    const RendererOptions options_;
    // PhongInputs::Auto may pick the interpolated-inputs variant: not on llvmpipe's 128-bit path
    // (LP_NATIVE_VECTOR_WIDTH=128, a CPU without AVX), where Mesa 22.3 corrupts its own heap drawing
    // that program (glibc aborts in the first large Phong draw; the uniform variant, the same picture,
    // is fine). Decided once from GL_RENDERER.
    bool autoMayInterpolate_ = true;
    bool mayInterpolate() const {
        return options_.phongInputs == PhongInputs::Interpolated ||
               (options_.phongInputs == PhongInputs::Auto && autoMayInterpolate_);
    }
    ProgramCache programs_;
    MeshCache meshes_;
    ShadowMaps shadowMaps_;
    std::unique_ptr<UniformStager> uniforms_;  // made once the GL is loaded
    DifferencePass difference_;                // layout diff's third pane, after the others
    EnvironmentPass environment_;              // the environment's texture and background
    ProgressivePass progressive_;              // renderProgressive()'s sum and its resolve
    bool movingFrames_ = false;                // setMovingFrames()
};

}  // namespace shadelab
