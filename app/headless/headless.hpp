#pragma once
// Headless rendering: one frame to an image, or a timed run of frames, on a headless context (OSMesa or
// EGL, headless/headless_context.hpp).
#include "core/geometry/scene_geometry.hpp"
#include "core/image/image.hpp"
#include "core/scene/scene.hpp"
#include "core/scene/sweep.hpp"
#include "headless/headless_context.hpp"
#include "render/shader_library.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace shadelab {

class Renderer;
class MultisampleTarget;

// `msaaSamples` here and below: with more than 1, each frame is drawn with that many samples per
// pixel (multisample anti-aliasing, render/multisample_target.hpp) and resolved before it is read.
// 1 (the default) draws straight into the context's target: the golden images' pixels.
Image renderHeadless(const Scene& scene, std::shared_ptr<const SceneGeometry> geometry,
                     const ShaderLibrary& shaders = ShaderLibrary(), HeadlessBackend backend = HeadlessBackend::Auto,
                     int msaaSamples = 1);

// One frame of a scene whose geometry is not built yet, as `shadelab --output` needs it. The geometry
// is built (and the camera framed, frameIfNeeded) on a second thread while this one creates the
// context, compiles the programs and draws a placeholder triangle per object, so llvmpipe compiles
// its draw code for the scene's state meanwhile: for a large model that overlap is most of the
// start-up time. The CPU copy of the geometry is released once uploaded.
struct HeadlessFrame {
    Image image;
    Scene scene;                     // as drawn (with the framed camera)
    std::vector<GltfInfo> gltfInfo;  // per object, as buildSceneGeometry() reported it
    std::size_t triangles = 0;
};
HeadlessFrame renderSceneHeadless(Scene scene, const ShaderLibrary& shaders, HeadlessBackend backend,
                                  int msaaSamples = 1);

// The geometry of a run of scenes (HeadlessSession, renderFramesHeadless): built again only when a
// scene's meshes differ from those of the scene it was built for.
class SceneGeometryCache {
public:
    // Makes the geometry `scene`'s: when its meshes differ, the previous geometry is released, the new
    // one built and checked against the memory budget (with `keptBytes` more for the caller's images).
    // Returns whether it was built (the renderer then needs it). Throws InputError; after one the next
    // call builds again.
    bool update(const Scene& scene, int msaaSamples, std::uint64_t keptBytes = 0);
    const std::shared_ptr<SceneGeometry>& geometry() const { return geometry_; }

private:
    std::shared_ptr<SceneGeometry> geometry_;
    std::unique_ptr<Scene> built_;  // whose meshes geometry_ holds
};

// One context and renderer kept for many frames (renderScenesHeadless, --test, the Python module's
// shadelab.Renderer): programs stay compiled, a scene's geometry is built only when its meshes differ from
// the previous scene's, and the context is resized when the size changes. The context is current on
// the thread that made the session: use it from that thread only.
class HeadlessSession {
public:
    HeadlessSession(const ShaderLibrary& shaders, HeadlessBackend backend, int width, int height);
    ~HeadlessSession();
    HeadlessSession(const HeadlessSession&) = delete;
    HeadlessSession& operator=(const HeadlessSession&) = delete;
    // Draws `scene` (framed first when it asks to be: frameIfNeeded) and reads it back. Checks the
    // memory budget with `keptBytes` more for the caller's images once its models are read. Throws
    // InputError, ShaderError; after one the session can draw the next scene.
    Image render(Scene& scene, int msaaSamples = 1, std::uint64_t keptBytes = 0);
    // The CPU geometry of the last scene drawn (for the probe's ray cast); null before the first.
    std::shared_ptr<const SceneGeometry> geometry() const { return geometry_.geometry(); }
    const char* backendName() const;

private:
    std::unique_ptr<HeadlessContext> context_;
    std::unique_ptr<Renderer> renderer_;
    std::unique_ptr<MultisampleTarget> msaa_;
    SceneGeometryCache geometry_;
};

// Renders each scene in turn on one context (resized when a scene's size differs from the previous
// one's; programs are kept, geometry is rebuilt only when the meshes differ from the previous scene's)
// and hands each image to `done` with its index as soon as it is read back, so a long playlist never
// holds more than one image. A glTF scene without a camera is framed as for --output. Every scene is
// checked against the memory budget (core/scene/memory_budget.hpp) with `keptBytes(i)` more for the images
// the caller keeps while scene i is drawn, before anything is drawn and again once its models are read.
// Without `failed`, the first InputError or ShaderError ends the whole call; with it (`--test`), a scene
// that fails (a model that cannot be read, over the budget, a shader that does not compile) is handed
// to `failed` instead of `done` and the next scene is drawn on the same context and programs.
using SceneFailed = std::function<void(std::size_t, const std::exception&)>;
using KeptBytes = std::function<std::uint64_t(std::size_t)>;  // none: 0
void renderScenesHeadless(std::vector<Scene>& scenes, const ShaderLibrary& shaders, HeadlessBackend backend,
                          const std::function<void(std::size_t, Image)>& done, int msaaSamples = 1,
                          const KeptBytes& keptBytes = nullptr, const SceneFailed& failed = nullptr);

// The frames of a scene that changes with time (an animation: core/scene/animation.hpp), on one context
// with one renderer. `base` is framed once as for --output (a glTF model without a camera, its lights);
// frame i is then `sceneAt(framed, i)`, drawn and handed to `done` as soon as it is read back, so memory
// does not grow with `count`. Geometry is rebuilt only when a frame's meshes differ from the previous
// frame's (a tessellation ramp). Every frame has `base`'s size.
void renderFramesHeadless(const Scene& base, std::size_t count,
                          const std::function<Scene(const Scene& framed, std::size_t index)>& sceneAt,
                          const ShaderLibrary& shaders, HeadlessBackend backend,
                          const std::function<void(std::size_t, const Image&)>& done, int msaaSamples = 1);

// A sweep sheet (core/scene/sweep.hpp): one tile of the scene's size per value of sweeps[0] (columns) and,
// with two sweeps, per value of sweeps[1] (rows), each labelled, rendered on one context. Geometry is
// rebuilt only when a tile's meshes differ from the previous tile's (a tessellation sweep).
Image renderSweepHeadless(const Scene& scene, const std::vector<Sweep>& sweeps, const ShaderLibrary& shaders,
                          HeadlessBackend backend, const std::string& flag = "--sweep", int msaaSamples = 1);

struct BenchmarkResult {
    ShadingMode mode = ShadingMode::Phong;
    Layout layout = Layout::Single;
    int frames = 0;
    std::size_t triangles = 0;  // per frame, all panes
    int width = 0, height = 0;
    int msaa = 1;  // samples per pixel the driver gave (1: no MSAA)
    double medianMs = 0, p95Ms = 0, minMs = 0, maxMs = 0;
    std::string glRenderer;
    std::string backend;
};
// Renders `warmup + frames` frames of each mode (glFinish after each, as ../shared/bench/probe.cpp
// does) and reports per-frame times of the last `frames`. The objects turn by 0.01 rad about y per
// frame, like the probe's sphere, so no frame repeats the previous one. With `progressiveStride` > 0
// a frame is the viewer's first progressive pass (Renderer::renderProgressive) and the camera orbits
// instead, as when the view is dragged.
std::vector<BenchmarkResult> benchmarkHeadless(const Scene& scene, std::shared_ptr<const SceneGeometry> geometry,
                                               const std::vector<ShadingMode>& modes, int frames, int warmup,
                                               const ShaderLibrary& shaders = ShaderLibrary(),
                                               HeadlessBackend backend = HeadlessBackend::Auto,
                                               int progressiveStride = 0, int msaaSamples = 1);
std::string toJson(const BenchmarkResult& r);

}  // namespace shadelab
