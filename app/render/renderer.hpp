#pragma once
// The GL renderer: draws a Scene into a framebuffer it is handed. It never creates a context; the
// front end (the GLFW viewer, the OSMesa or any other headless context) makes one current and passes
// its get-proc-address function. All GL state the renderer relies on is set in render().
#include "core/camera.hpp"
#include "core/image.hpp"
#include "core/scene.hpp"
#include "core/scene_geometry.hpp"
#include "render/gl_handles.hpp"
#include "render/shader_library.hpp"
#include "render/shadow_maps.hpp"

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace shadelab {

struct RenderTarget {
    GLuint framebuffer = 0;  // 0: the context's default framebuffer
    int width = 0;
    int height = 0;
};

class Renderer {
public:
    // Loads GL 3.3 core entry points through `getProcAddress` (the context must be current) and
    // checks the version. Programs are compiled on first use. Throws std::runtime_error.
    Renderer(GLADloadfunc getProcAddress, ShaderLibrary shaders = ShaderLibrary());
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
    // Compiles the flat, gouraud and phong programs for `scene`'s specialisation now (render()
    // otherwise compiles each on first use). Throws ShaderError.
    void preparePrograms(const Scene& scene);

    std::string glRenderer() const;
    // Depth views drawn by the last render() for shadows (0: none, or the maps were still valid).
    int shadowViewsRendered() const { return shadowMaps_.viewsRendered(); }
    std::string glVersion() const;

private:
    struct GpuMesh {
        gl::VertexArray vao;
        gl::Buffer vertices;  // interleaved positions, normals and (flat) centroids
        gl::Buffer indices;
        GLsizei indexCount = 0;
    };
    const GpuMesh& gpuMesh(std::size_t object, ShadingMode mode);
    GLuint program(ShadingMode mode, const Scene& scene);

    ShaderLibrary shaders_;
    std::map<std::string, gl::Program> programs_;         // by name + specialisation defines
    std::shared_ptr<const SceneGeometry> geometry_;
    std::vector<std::vector<MeshPart>> objectParts_;      // per object: its parts (one for a plain mesh)
    std::vector<std::array<GpuMesh, 2>> gpuMeshes_;       // per object: [smooth, flat]
    gl::Buffer uniforms_;                                 // pane FrameBlocks, then ObjectBlocks
    GLint uniformAlignment_ = 256;
    std::vector<Aabb> objectBoxes_;                       // per object, object space (for shadow maps)
    ShadowMaps shadowMaps_;
    // Layout diff: copies of the two source panes and the program that subtracts them.
    void drawDifference(const Pane& pane, const Pane& a, const Pane& b, float factor, const RenderTarget& target);
    std::array<gl::Texture, 2> diffSources_;
    int diffWidth_ = 0, diffHeight_ = 0;
    gl::Program diffProgram_;
    gl::VertexArray emptyVao_;                            // core profile draws need a bound VAO
};

// What the shading programs are specialised for (shaders/lighting.glsl): the number of lights, each
// light's kind and attenuation (and an area light's sample counts), the reflection model, the output
// encoding, and with shadows on SL_SHADOWS and the PCF radius, as "NAME VALUE" defines.
// Everything else is a uniform, so editing values never recompiles.
std::vector<std::string> programDefines(const Scene& scene);

// Reads the colour buffer of `target` (bottom-up in GL) into a top-down RGBA image.
Image readPixels(const RenderTarget& target);

}  // namespace shadelab
