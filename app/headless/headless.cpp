#include "headless/headless.hpp"

#include "core/base/error.hpp"
#include "core/scene/memory_budget.hpp"
#include "render/multisample_target.hpp"
#include "render/renderer.hpp"

#include <nlohmann/json.hpp>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <future>
#include <optional>

namespace shadelab {
namespace {

// "scene.json: a 1280x720 frame": what the memory messages call one render.
std::string frameName(const Scene& s) {
    return (s.sourcePath.empty() ? "" : s.sourcePath + ": ") + "a " + std::to_string(s.width) + "x" +
           std::to_string(s.height) + " frame";
}

// The memory budget (core/scene/memory_budget.hpp) for one frame of `s`, with `kept` bytes of frames the
// caller holds; `triangles` once the models are read (before, the procedural meshes' part).
void checkFrameMemory(const Scene& s, int msaaSamples, std::optional<std::uint64_t> triangles, std::uint64_t kept = 0,
                      std::uint64_t textureBytes = 0) {
    MemoryUse use = estimateFrame(s, msaaSamples, triangles, textureBytes);
    use.images = kept;
    checkMemory(use, frameName(s) + (kept ? " with the other frames kept" : ""));
}

// Draws `scene` into `target`: straight, or with msaaSamples > 1 into `msaa`'s multisampled
// framebuffer, then resolved into `target`.
void drawFrame(Renderer& renderer, const Scene& scene, const RenderTarget& target, MultisampleTarget& msaa,
               int msaaSamples) {
    try {
        renderer.render(scene, msaa.begin(target, msaaSamples));
        msaa.resolveInto(target);
    } catch (const GlOutOfMemory& e) {
        throw GlOutOfMemory(frameName(scene) + ": " + e.what());
    }
}

// Headless frames draw flat shading from packed vertices (RendererOptions::packedFlatVertices).
RendererOptions headlessOptions() {
    RendererOptions options;
    options.packedFlatVertices = true;
    return options;
}

// Whether the two scenes draw the same meshes (their geometry can be reused).
bool sameMeshes(const Scene& a, const Scene& b) {
    bool same = a.objects.size() == b.objects.size();
    for (std::size_t o = 0; same && o < a.objects.size(); ++o) same = a.objects[o].mesh == b.objects[o].mesh;
    return same;
}

}  // namespace

Image renderHeadless(const Scene& scene, std::shared_ptr<const SceneGeometry> geometry, const ShaderLibrary& shaders,
                     HeadlessBackend backend, int msaaSamples) {
    checkFrameMemory(scene, msaaSamples, geometry->triangleCount(), 0, geometry->textureBytes());
    const auto context = makeHeadlessContext(backend, scene.width, scene.height);
    Renderer renderer(context->getProcAddress(), shaders, headlessOptions());
    renderer.setGeometry(std::move(geometry));
    const RenderTarget target = context->target();
    MultisampleTarget msaa;
    drawFrame(renderer, scene, target, msaa, msaaSamples);
    return readPixels(target);
}

// One frame of a huge mesh: bound llvmpipe's memory for it (RendererOptions::drawChunkTriangles). 2M-triangle
// sphere: peak 218-255 -> 192-208 MiB, time unchanged (bench/README.md).
constexpr std::size_t kOneFrameDrawChunk = 250000;

HeadlessFrame renderSceneHeadless(Scene scene, const ShaderLibrary& shaders, HeadlessBackend backend, int msaaSamples) {
    checkFrameMemory(scene, msaaSamples, std::nullopt);  // a model's meshes: once read
    // buildSceneGeometry only reads `scene`; nothing here writes it until the thread is joined.
    auto loading = std::async(std::launch::async, [&scene] { return buildSceneGeometry(scene); });
    std::unique_ptr<HeadlessContext> context;
    std::unique_ptr<Renderer> renderer;
    MultisampleTarget msaa;  // after the context: released before it
    try {
        context = makeHeadlessContext(backend, scene.width, scene.height);
        RendererOptions oneFrame = headlessOptions();
        oneFrame.drawChunkTriangles = kOneFrameDrawChunk;
        renderer = std::make_unique<Renderer>(context->getProcAddress(), shaders, oneFrame);
        // Same programs, vertex layout and GL state as the real frame, on one small triangle per object.
        auto placeholder = std::make_shared<SceneGeometry>();
        for (std::size_t o = 0; o < scene.objects.size(); ++o) {
            Mesh m;
            m.positions = {{0.0f, 0.0f, 0.0f}, {1e-3f, 0.0f, 0.0f}, {0.0f, 1e-3f, 0.0f}};
            m.normals.assign(3, glm::vec3(0.0f, 0.0f, 1.0f));
            m.indices = {0, 1, 2};
            placeholder->meshes.push_back(std::move(m));
        }
        renderer->setGeometry(placeholder);
        drawFrame(*renderer, scene, context->target(), msaa, msaaSamples);  // multisampled too: llvmpipe's code differs
        glFinish();
    } catch (...) {
        // A broken input file is the more useful error: report it first if there is one.
        loading.get();
        throw;
    }
    auto geometry = std::make_shared<SceneGeometry>(loading.get());
    checkFrameMemory(scene, msaaSamples, geometry->triangleCount(), 0, geometry->textureBytes());
    frameIfNeeded(scene, *geometry);
    HeadlessFrame frame;
    frame.gltfInfo = geometry->gltfInfo;
    frame.triangles = geometry->triangleCount();
    renderer->setGeometry(std::move(geometry));
    renderer->uploadAndReleaseCpuGeometry(scene);
    drawFrame(*renderer, scene, context->target(), msaa, msaaSamples);
    frame.image = readPixels(context->target());
    frame.scene = std::move(scene);
    return frame;
}

bool SceneGeometryCache::update(const Scene& s, int msaaSamples, std::uint64_t keptBytes) {
    if (built_ && sameMeshes(*built_, s)) return false;
    geometry_.reset();  // the previous meshes go before the next are read
    built_.reset();
    geometry_ = std::make_shared<SceneGeometry>(buildSceneGeometry(s));
    checkFrameMemory(s, msaaSamples, geometry_->triangleCount(), keptBytes, geometry_->textureBytes());
    built_ = std::make_unique<Scene>(s);
    return true;
}

HeadlessSession::HeadlessSession(const ShaderLibrary& shaders, HeadlessBackend backend, int width, int height)
    : context_(makeHeadlessContext(backend, width, height)),
      renderer_(std::make_unique<Renderer>(context_->getProcAddress(), shaders, headlessOptions())),
      msaa_(std::make_unique<MultisampleTarget>()) {}

HeadlessSession::~HeadlessSession() {
    msaa_.reset();  // the GL objects before the context
    renderer_.reset();
}

const char* HeadlessSession::backendName() const { return context_->backendName(); }

Image HeadlessSession::render(Scene& s, int msaaSamples, std::uint64_t keptBytes) {
    if (geometry_.update(s, msaaSamples, keptBytes)) renderer_->setGeometry(geometry_.geometry());
    frameIfNeeded(s, *geometry_.geometry());
    if (context_->target().width != s.width || context_->target().height != s.height)
        context_->resize(s.width, s.height);
    drawFrame(*renderer_, s, context_->target(), *msaa_, msaaSamples);
    return readPixels(context_->target());
}

void renderScenesHeadless(std::vector<Scene>& scenes, const ShaderLibrary& shaders, HeadlessBackend backend,
                          const std::function<void(std::size_t, Image)>& done, int msaaSamples,
                          const KeptBytes& keptBytes, const SceneFailed& failed) {
    if (scenes.empty()) return;
    const auto kept = [&keptBytes](std::size_t i) { return keptBytes ? keptBytes(i) : 0; };
    // With `failed`, a scene's input or shader error is its own (reported, the next scene drawn); without,
    // the first ends the run. An InputError or a ShaderError leaves the context as it was: programs that
    // failed are not kept (ProgramCache builds them again when asked), a model that failed is no geometry.
    const auto each = [&failed](std::size_t i, const std::function<void()>& work) {
        if (!failed) {
            work();
            return true;
        }
        try {
            work();
            return true;
        } catch (const InputError& e) {
            failed(i, e);
        } catch (const ShaderError& e) {
            failed(i, e);
        }
        return false;
    };
    std::vector<bool> refused(scenes.size(), false);
    for (std::size_t i = 0; i < scenes.size(); ++i)  // before any work
        refused[i] = !each(i, [&] { checkFrameMemory(scenes[i], msaaSamples, std::nullopt, kept(i)); });
    HeadlessSession session(shaders, backend, scenes[0].width, scenes[0].height);
    for (std::size_t i = 0; i < scenes.size(); ++i) {
        if (refused[i]) continue;
        Image image;
        const bool drawn = each(i, [&] { image = session.render(scenes[i], msaaSamples, kept(i)); });
        if (drawn) done(i, std::move(image));
    }
}

void renderFramesHeadless(const Scene& base, std::size_t count,
                          const std::function<Scene(const Scene&, std::size_t)>& sceneAt, const ShaderLibrary& shaders,
                          HeadlessBackend backend, const std::function<void(std::size_t, const Image&)>& done,
                          int msaaSamples) {
    checkFrameMemory(base, msaaSamples, std::nullopt);
    Scene framed = base;
    SceneGeometryCache geometry;
    geometry.update(framed, msaaSamples);
    frameIfNeeded(framed, *geometry.geometry());
    const auto context = makeHeadlessContext(backend, base.width, base.height);
    Renderer renderer(context->getProcAddress(), shaders, headlessOptions());
    renderer.setGeometry(geometry.geometry());
    MultisampleTarget msaa;
    Image image;  // every frame read into the same pixels
    for (std::size_t i = 0; i < count; ++i) {
        const Scene s = sceneAt(framed, i);
        if (geometry.update(s, msaaSamples)) renderer.setGeometry(geometry.geometry());
        drawFrame(renderer, s, context->target(), msaa, msaaSamples);
        readPixelsInto(context->target(), image);
        done(i, image);
    }
}

Image renderSweepHeadless(const Scene& base, const std::vector<Sweep>& sweeps, const ShaderLibrary& shaders,
                          HeadlessBackend backend, const std::string& flag, int msaaSamples) {
    const std::size_t columns = sweeps.empty() ? 1 : sweeps[0].values.size();
    const std::size_t rows = sweeps.size() > 1 ? sweeps[1].values.size() : 1;
    // Every tile's scene first: a value that does not fit the scene (tessellation of a cube) is an
    // input error before any context is made.
    std::vector<Scene> scenes;
    std::vector<std::string> labels;
    for (std::size_t r = 0; r < rows; ++r)
        for (std::size_t c = 0; c < columns; ++c) {
            Scene s = base;
            std::string label;
            if (!sweeps.empty()) {
                applySweep(s, sweeps[0], c, flag);
                label = sweepLabel(sweeps[0], c);
            }
            if (sweeps.size() > 1) {
                applySweep(s, sweeps[1], r, flag);
                label += "  " + sweepLabel(sweeps[1], r);
            }
            scenes.push_back(std::move(s));
            labels.push_back(std::move(label));
        }
    std::vector<Image> tiles;
    const auto addTile = [&](std::size_t, Image tile) { tiles.push_back(std::move(tile)); };
    // The tiles are kept, then copied into the sheet: twice their pixels, 4 bytes each.
    const std::uint64_t kept = 2 * 4 * std::uint64_t(base.width) * std::uint64_t(base.height) * scenes.size();
    renderScenesHeadless(scenes, shaders, backend, addTile, msaaSamples, [kept](std::size_t) { return kept; });
    return contactSheet(tiles, labels, int(columns));
}

std::vector<BenchmarkResult> benchmarkHeadless(const Scene& scene, std::shared_ptr<const SceneGeometry> geometry,
                                               const std::vector<ShadingMode>& modes, int frames, int warmup,
                                               const ShaderLibrary& shaders, HeadlessBackend backend,
                                               int progressiveStride, int msaaSamples) {
    checkFrameMemory(scene, msaaSamples, geometry->triangleCount(), 0, geometry->textureBytes());
    const auto context = makeHeadlessContext(backend, scene.width, scene.height);
    RendererOptions manyFrames = headlessOptions();  // of one mesh, as in the viewer
    manyFrames.meshOrder = RendererOptions::MeshOrder::VertexCache;
    Renderer renderer(context->getProcAddress(), shaders, manyFrames);
    const std::size_t triangles = geometry->triangleCount() * scenePaneCount(scene.layout);
    renderer.setGeometry(std::move(geometry));
    const RenderTarget target = context->target();
    MultisampleTarget msaa;
    std::vector<BenchmarkResult> results;
    for (ShadingMode mode : modes) {
        Scene s = scene;
        s.shading = mode;
        std::vector<double> ms;
        for (int f = 0; f < warmup + frames; ++f) {
            const float turn = 0.01f * float(f);
            if (progressiveStride > 0) {
                // The viewer while the view is dragged: the camera orbits, so every frame restarts
                // the sum and draws its first pass; the shadow maps stay valid.
                const glm::vec3 offset = scene.camera.eye - scene.camera.target;
                s.camera.eye = scene.camera.target +
                               glm::vec3(glm::rotate(glm::mat4(1.0f), turn, scene.camera.up) * glm::vec4(offset, 0.0f));
            } else {
                for (SceneObject& o : s.objects)
                    o.transform.rotationDeg.y = scene.objects.front().transform.rotationDeg.y + glm::degrees(turn);
            }
            const auto t0 = std::chrono::steady_clock::now();
            const RenderTarget drawTarget = msaa.begin(target, msaaSamples);
            if (progressiveStride > 0) renderer.renderProgressive(s, drawTarget, progressiveStride, true);
            else renderer.render(s, drawTarget);
            msaa.resolveInto(target);
            glFinish();
            const auto t1 = std::chrono::steady_clock::now();
            if (f >= warmup) ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
        }
        std::sort(ms.begin(), ms.end());
        BenchmarkResult r;
        r.mode = mode;
        r.layout = s.layout;
        r.frames = frames;
        r.triangles = triangles;
        r.width = s.width;
        r.height = s.height;
        r.msaa = std::max(1, msaa.samples());
        const std::size_t n = ms.size();
        r.medianMs = n % 2 ? ms[n / 2] : 0.5 * (ms[n / 2 - 1] + ms[n / 2]);
        r.p95Ms = ms[std::min(n - 1, std::size_t(std::ceil(0.95 * double(n))) - 1)];
        r.minMs = ms.front();
        r.maxMs = ms.back();
        r.glRenderer = renderer.glRenderer();
        r.backend = context->backendName();
        results.push_back(r);
    }
    return results;
}

std::string toJson(const BenchmarkResult& r) {
    // Milliseconds to the microsecond: what a timer on this machine can tell apart.
    auto ms = [](double v) { return std::round(v * 1000.0) / 1000.0; };
    const nlohmann::ordered_json j = {
        {"frames", r.frames},
        {"triangles", r.triangles},
        {"size", {r.width, r.height}},
        {"shading", r.layout == Layout::Compare ? toString(Layout::Compare) : toString(r.mode)},
        {"layout", toString(r.layout)},
        {"msaa", r.msaa},
        {"median_ms", ms(r.medianMs)},
        {"p95_ms", ms(r.p95Ms)},
        {"min_ms", ms(r.minMs)},
        {"max_ms", ms(r.maxMs)},
        {"backend", r.backend},
        {"gl_renderer", r.glRenderer},  // the driver's own text: quotes and backslashes escaped
    };
    // Invalid UTF-8 in a driver's name is replaced rather than thrown over.
    return j.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

}  // namespace shadelab
