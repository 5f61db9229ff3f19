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

// How a renderer is tuned for the way it is used (a one-off frame, the viewer, a benchmark, a test
// that compares two paths). Given at construction; the pictures are the same whatever the choice.
struct RendererOptions {
    // Where Phong draws read the per-object products and the vectors to the eye and the lights
    // (shaders/phong_interface.glsl): Auto picks interpolated inputs for a draw whose triangles
    // cover at least kInputsMinPixelsPerTriangle pixels each (bounding box on screen / front-facing
    // triangles), the uniform blocks otherwise. The other two force one path (tests compare them).
    enum class PhongInputs { Auto, Interpolated, Uniform };
    PhongInputs phongInputs = PhongInputs::Auto;

    // The order meshes are uploaded in. VertexCache reorders each mesh's triangles and vertices for
    // the driver's vertex cache (core/vertex_order.hpp): the same picture with up to ~40% fewer
    // vertex-shader runs a frame, for a one-off cost at upload (~0.15 s per million triangles). Worth
    // it for a mesh drawn many times (the viewer, --benchmark), not for one --output frame.
    enum class MeshOrder { AsGiven, VertexCache };
    MeshOrder meshOrder = MeshOrder::AsGiven;

    // Draws of more than this many triangles go in chunks of that many, and after submitting a chunk
    // the renderer waits for the one before it (a fence), so the driver never holds more than two.
    // llvmpipe bins every triangle of what it was given before its threads rasterise, a few scenes of
    // ~36 MiB at a time: a frame of the 2M-triangle sphere raised resident memory by ~100 MiB, in
    // chunks of 250k by ~30 MiB. The waits cost steady frames ~9% (binning and rasterising overlap
    // less), so it is for a one-off frame (headless --output), not the viewer. 0 (the default): off.
    std::size_t drawChunkTriangles = 0;

    // A glTF model's GPU instances (EXT_mesh_gpu_instancing, Mesh::instanced) as instanced draws: one
    // copy of the instanced parts uploaded, drawn once per instance. Off: every instance baked into
    // the vertex buffer, as the CPU side holds them (a test compares the two).
    bool instancedDraws = true;

    // Flat shading's nine floats per vertex (position, centroid, face normal) in two vec4s, drawn by
    // shaders/flat_packed.vert, instead of three vec3s (flat.vert): ~7% off a flat frame at 200k
    // triangles on llvmpipe (bench/README.md). For headless frames; the viewer draws with flat.vert,
    // the file a lecturer reads and edits (F5 reloads it). A test compares the two pixel for pixel.
    bool packedFlatVertices = false;
};

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
    struct ProgressiveStatus {
        int passesDone = 0;
        int passCount = 1;
        bool complete() const { return passesDone >= passCount; }
    };
    ProgressiveStatus renderProgressive(const Scene& scene, const RenderTarget& target, int stride, bool restart);
    // Compiles the flat, gouraud and phong programs for `scene`'s specialisation now, Phong's
    // interpolated-inputs variant included (render() otherwise compiles each on first use). Throws
    // ShaderError.
    void preparePrograms(const Scene& scene);

    static constexpr float kInputsMinPixelsPerTriangle = 16.0f;  // RendererOptions::PhongInputs::Auto
    // Whether `object`'s Phong draws in `pane` take interpolated inputs (always false for flat and
    // Gouraud panes, and past SL_MAX_INTERPOLATED_LIGHTS lights).
    bool interpolatesInputs(std::size_t object, const Pane& pane, const Scene& scene) const;

    std::string glRenderer() const;
    // Depth views drawn by the last render() for shadows (0: none, or the maps were still valid).
    int shadowViewsRendered() const { return shadowMaps_.viewsRendered(); }
    std::string glVersion() const;

private:
    struct GpuMesh {
        gl::VertexArray vao;
        gl::Buffer vertices;  // interleaved positions, normals and (flat) centroids, texture coordinates and colours
        gl::Buffer indices;
        GLsizei indexCount = 0;
    };
    const GpuMesh& gpuMesh(std::size_t object, ShadingMode mode);
    void drawTriangles(GLsizei firstIndex, GLsizei indexCount);  // from the bound vertex array, see drawChunkTriangles
    GLuint program(ShadingMode mode, const Scene& scene, bool accumulate = false, bool interpolatedInputs = false,
                   bool textured = false, bool instanced = false);
    // The mesh an object's draws upload: its instanced form (Mesh::instanced) when it has one.
    const Mesh& drawnMesh(std::size_t object) const;
    // An instanced part's transforms, split by handedness (a mirroring one turns the winding): one
    // instanced draw each, reading them from the object's instance buffer from `first` on.
    struct InstanceGroup {
        std::size_t part = 0;
        GLsizei first = 0, count = 0;
        bool mirrored = false;
    };
    void bindInstances(std::size_t object, const InstanceGroup& group);
    // The GL texture of an object's Mesh::textures[slot] (uploaded on first use: sRGB, mipmapped as its
    // sampler asks), or a white texel for a part without one.
    GLuint objectTexture(std::size_t object, int slot);
    // The samples one progressive pass evaluates: i = first.x + k stride.x, j = first.y + m stride.y.
    struct AreaSamplePass {
        glm::ivec2 first{0};
        glm::ivec2 stride{1};
    };
    // Shadow maps, then every pane but the difference into `target`; with `pass`, the accumulating
    // programs (linear output, alpha 0 where nothing was drawn) evaluate that pass's samples, and
    // with `add` they are added to what the target holds, where its depth equals theirs.
    void drawPanes(const Scene& scene, const std::vector<Pane>& panes, const RenderTarget& target,
                   const AreaSamplePass* pass, bool add);

    ShaderLibrary shaders_;
    std::map<std::string, gl::Program> programs_;         // by name + specialisation defines
    std::shared_ptr<const SceneGeometry> geometry_;
    std::vector<std::vector<MeshPart>> objectParts_;      // per object: its parts (one for a plain mesh)
    std::vector<std::array<GpuMesh, 2>> gpuMeshes_;       // per object: [smooth, flat]
    gl::Buffer uniforms_;                                 // pane FrameBlocks, then ObjectBlocks
    GLint uniformAlignment_ = 256;
    std::vector<Aabb> objectBoxes_;                       // per object, object space (shadow maps, Phong inputs)
    std::vector<std::size_t> objectTriangles_;            // per object, all parts
    std::vector<char> objectVariesColor_;                 // per object: has texture coordinates and colours
    std::vector<std::vector<InstanceGroup>> objectInstanceGroups_;  // per object
    std::vector<std::vector<glm::mat4>> objectInstances_;           // per object, until uploaded
    std::vector<gl::Buffer> objectInstanceBuffers_;                 // per object (mat4 each)
    // Per object: its base colour images until uploaded, and the textures made of them.
    std::vector<std::vector<std::shared_ptr<const TextureImage>>> objectImages_;
    std::vector<std::vector<gl::Texture>> objectTextures_;
    gl::Texture whiteTexture_;
    const RendererOptions options_;
    std::vector<Mesh> orderedMeshes_;                     // per object, with VertexCache: until both its uploads are done
    ShadowMaps shadowMaps_;
    // Layout diff: copies of the two source panes (blitted through their framebuffers) and the
    // program that subtracts them.
    void drawDifference(const Pane& pane, const Pane& a, const Pane& b, float factor, const RenderTarget& target);
    std::array<gl::Texture, 2> diffSources_;
    std::array<gl::Framebuffer, 2> diffSourceFbos_;
    int diffWidth_ = 0, diffHeight_ = 0;
    gl::Program diffProgram_;
    gl::VertexArray emptyVao_;                            // core profile draws need a bound VAO
    // Progressive sampling: the passes are summed in sumColor (alpha counts them), over the depth
    // the first pass wrote.
    struct Progressive {
        gl::Framebuffer sumFbo;
        gl::Texture sumColor, depth;                     // RGBA32F, DEPTH24
        int width = 0, height = 0;
        glm::ivec2 stride{0};
        std::vector<glm::ivec2> order;                   // each pass's first sample
        int done = 0;
        std::array<gl::Program, 2> resolve;              // by output encoding (linear, sRGB)
    } progressive_;
    // One triangle over the viewport with `program` (shaders/fullscreen.vert): the image passes.
    void drawFullscreen(GLuint program);
};

// The order of progressive sampling's passes for `stride` (x, y): every first sample in
// [0, stride.x) x [0, stride.y) once, in ordered-dither (Bayer) order, so the passes drawn so far are
// spread over the light instead of filling it row by row.
std::vector<glm::ivec2> progressivePassOrder(const glm::ivec2& stride);

// What the shading programs are specialised for (shaders/lighting.glsl): the number of lights, each
// light's kind and attenuation (and an area light's sample counts), the reflection model, the output
// encoding, and with shadows on SL_SHADOWS and the PCF radius, as "NAME VALUE" defines.
// Everything else is a uniform, so editing values never recompiles.
std::vector<std::string> programDefines(const Scene& scene);

// Reads the colour buffer of `target` (bottom-up in GL) into a top-down RGBA image; a multisampled
// target (render/multisample_target.hpp) is resolved into a temporary copy first.
Image readPixels(const RenderTarget& target);

}  // namespace shadelab
