// The run modes that render without a window (session.hpp): one frame, a sweep sheet, a probed frame,
// a benchmark, a playlist's images, a video. Built where a headless context is (SHADELAB_OSMESA or SHADELAB_EGL).
#include "core/base/file_io.hpp"
#include "core/figures/formula_image.hpp"
#include "core/figures/intersection_image.hpp"
#include "core/geometry/camera.hpp"
#include "core/geometry/ray_cast.hpp"
#include "core/geometry/scene_geometry.hpp"
#include "core/image/image.hpp"
#include "core/probe/probe.hpp"
#include "core/scene/playlist.hpp"
#include "headless/headless.hpp"
#include "headless/headless_context.hpp"
#include "render/shader_library.hpp"
#include "run/reference.hpp"
#include "run/session.hpp"
#include "run/test_suite.hpp"
#if SHADELAB_HAVE_VIDEO
#include "core/scene/animation.hpp"
#include "video/video_encoder.hpp"
#endif

#include <glm/geometric.hpp>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

namespace shadelab {

int headlessMsaa(const Options& options) { return options.msaa.value_or(1); }

HeadlessBackend headlessBackend(const Options& options) {
    if (options.backend == "egl") return HeadlessBackend::Egl;
    if (options.backend == "osmesa") return HeadlessBackend::OsMesa;
    return HeadlessBackend::Auto;
}

Image finishedFrame(const Options& options, Image image, const Scene& scene, const std::string& title,
                    const ProbeResult* probe) {
    if (options.formula) {
        const bool hit = probe && !probe->miss;
        const Material material = hit                     ? probe->material
                                  : scene.objects.empty() ? Material{}
                                                          : scene.objects[0].material;
        FormulaInput in = formulaInput(scene, material);
        if (hit) {
            in.probed = probedTerms(*probe);
            in.probedAt = probedPlace(*probe);
        }
        std::vector<FormulaPane> panes;
        for (const Pane& p : layoutPanes(scene.layout, scene.shading, scene.width, scene.height, scene.diff))
            panes.push_back({float(p.x), float(p.y), float(p.width), float(p.height), p.mode, p.difference});
        drawFormulaOverlay(image, in, panes);
    }
    return options.captions ? withCaptionStrip(image, title, scene.caption) : image;
}

namespace {

struct Stopwatch {
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    double ms() const {
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    }
};

// What a run needs beside the options: where the GLSL comes from and which headless context.
struct RunContext {
    const Options& options;
    ShaderLibrary shaders;
    HeadlessBackend backend;
};

// --playlist DIR --output OUT/: every preset loaded and rendered before any file is written (one bad
// file, or a model that fails to load in the last preset, leaves the folder as it was; the frames wait
// in memory, within the budget), then one PNG per preset.
int runPlaylistImages(const RunContext& run) {
    const Options& options = run.options;
    checkOutputFolder(*options.output, "--output");
    std::vector<Preset> presets = loadPlaylist(*options.playlist, [&options](Scene& s) { applyOverrides(s, options); });
    std::vector<Scene> scenes;
    scenes.reserve(presets.size());
    for (const Preset& p : presets) scenes.push_back(p.scene);
    std::vector<Image> frames(presets.size());
    std::uint64_t kept = 0;  // every frame's pixels (a caption strip adds a little)
    for (const Scene& s : scenes) kept += 4 * std::uint64_t(s.width) * std::uint64_t(s.height);
    renderScenesHeadless(
        scenes, run.shaders, run.backend,
        [&](std::size_t i, Image image) {
            const Preset& p = presets[i];
            frames[i] = finishedFrame(options, std::move(image), scenes[i], presetTitle(p));
        },
        headlessMsaa(options), [kept](std::size_t) { return kept; });
    createOutputFolder(*options.output, "--output");
    for (std::size_t i = 0; i < presets.size(); ++i) {
        const std::string path = (std::filesystem::path(*options.output) / (presets[i].name + ".png")).string();
        writePng(path, frames[i]);
        if (options.verbose) std::cerr << "shadelab: wrote " << path << "\n";
    }
    return 0;
}

int runSweepSheet(const RunContext& run, const Scene& scene) {
    const Options& options = run.options;
    const Stopwatch clock;
    const Image sheet =
        renderSweepHeadless(scene, options.sweeps, run.shaders, run.backend, "--sweep", headlessMsaa(options));
    writePng(*options.output, sheet);
    if (options.verbose)
        std::cerr << "shadelab: wrote " << *options.output << " (" << sheet.width << "x" << sheet.height << ", "
                  << clock.ms() << " ms)\n";
    return 0;
}

// --intersection: where the diagram stands, the probed point with the normal its mode has there
// (phong: the interpolated normal; flat: the face's; gouraud: the corners' weighted like the colours).
std::optional<IntersectionPoint> intersectionPoint(const Scene& scene, const ProbeResult& probe) {
    if (probe.miss || probe.modes.empty() || probe.modes[0].evaluations.empty()) return std::nullopt;
    const std::vector<ProbeEvaluation>& e = probe.modes[0].evaluations;
    glm::vec3 n = e[0].nrmWorld;
    if (e.size() == 3)
        n = glm::normalize(probe.anchor.barycentric.x * e[0].nrmWorld + probe.anchor.barycentric.y * e[1].nrmWorld +
                           probe.anchor.barycentric.z * e[2].nrmWorld);
    const Pane& pane = probe.paneRect;
    IntersectionPoint at;
    at.posWorld = probe.posWorld;
    at.nrmWorld = n;
    at.clipFromWorld =
        clipFromView(scene.camera, float(pane.width) / float(std::max(pane.height, 1))) * viewFromWorld(scene.camera);
    at.paneX = float(pane.x);
    at.paneY = float(pane.y);
    at.paneWidth = float(pane.width);
    at.paneHeight = float(pane.height);
    return at;
}

// The probe needs the CPU geometry after the render, so this path builds it itself rather than
// through renderSceneHeadless (which lets go of it once uploaded).
int runProbeImage(const RunContext& run, Scene scene) {
    const Options& options = run.options;
    const auto geometry = loadGeometry(options, scene);
    const ProbeResult probe =
        probePixel(scene, *geometry, SceneRayCaster(scene, *geometry), options.probe->x, options.probe->y);
    Image frame = renderHeadless(scene, geometry, run.shaders, run.backend, headlessMsaa(options));
    if (options.intersection) {
        if (const std::optional<IntersectionPoint> at = intersectionPoint(scene, probe))
            drawIntersectionDiagram(frame, scene, *at);
        else
            std::cerr << "shadelab: --intersection: pixel " << probe.x << "," << probe.y
                      << " shows no surface; no diagram\n";
    }
    writePng(*options.output, finishedFrame(options, std::move(frame), scene, scene.title, &probe));
    std::cout << probeToJson(scene, probe) << std::endl;
    return 0;
}

// --output, with --reference: compared with it (run/reference.hpp), which is read before the render.
int runImage(const RunContext& run, Scene scene) {
    const Options& options = run.options;
    const std::optional<Image> reference = readReference(options);
    const Stopwatch clock;
    const HeadlessFrame frame = renderSceneHeadless(std::move(scene), run.shaders, run.backend, headlessMsaa(options));
    report(options, frame.scene, frame.gltfInfo, frame.triangles);
    const double renderedMs = clock.ms();
    const int status =
        writeOutputAndCompare(options, finishedFrame(options, frame.image, frame.scene, frame.scene.title), reference,
                              frame.scene.diff.factor);
    if (options.verbose)
        std::cerr << "shadelab: wrote " << *options.output << " (geometry, context and render " << renderedMs
                  << " ms, PNG and comparison " << clock.ms() - renderedMs << " ms)\n";
    return status;
}

int runBenchmark(const RunContext& run, Scene scene) {
    const Options& options = run.options;
    const auto geometry = loadGeometry(options, scene);
    std::vector<ShadingMode> modes;
    if (scene.layout == Layout::Compare) modes = {scene.shading};
    else if (options.shading) modes = {*options.shading};
    else modes = {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong};
    for (const BenchmarkResult& r : benchmarkHeadless(scene, geometry, modes, options.benchmarkFrames, 3, run.shaders,
                                                      run.backend, options.progressiveStride, headlessMsaa(options)))
        std::cout << toJson(r) << std::endl;
    return 0;
}

#if SHADELAB_HAVE_VIDEO
// --animate SPEC --output FILE.gif|.mp4|.webm: the animation rendered frame by frame on one context and
// streamed into the encoder (video/video_encoder.hpp), one frame held at a time. Needs SHADELAB_VIDEO.
int runVideo(const RunContext& run, const Scene& scene) {
    const Options& options = run.options;
    const Stopwatch clock;
    const int fps = options.fps.value_or(kDefaultVideoFps);
    const double seconds = options.duration.value_or(animationsDuration(options.animations));
    const int frames = animationFrameCount(options.animations, seconds, fps);
    const auto sceneAt = [&](const Scene& framed, std::size_t i) {
        return sceneAtTime(framed, options.animations, double(i) / fps, "--animate");
    };
    // An animation that does not fit the scene (light-orbit without a light) is refused before any work.
    sceneAt(scene, 0);
    sceneAt(scene, std::size_t(frames - 1));
    VideoSettings settings;
    settings.fps = fps;
    settings.dither = options.dither;
    writeVideo(*options.output, scene.width, scene.height, settings, [&](VideoEncoder& encoder) {
        renderFramesHeadless(
            scene, std::size_t(frames), sceneAt, run.shaders, run.backend,
            [&encoder](std::size_t, const Image& frame) { encoder.addFrame(frame); }, options.msaa.value_or(1));
    });
    if (options.verbose)
        std::cerr << "shadelab: wrote " << *options.output << " (" << frames << " frames of " << scene.width << "x"
                  << scene.height << " at " << fps << " fps, " << clock.ms() / 1000.0 << " s)\n";
    return 0;
}
#endif

}  // namespace

int runHeadlessMode(const Options& options) {
    const RunContext run{options, ShaderLibrary(shaderFolder(options.shaderDir)), headlessBackend(options)};
    if (options.mode == RunMode::PlaylistImages) return runPlaylistImages(run);
    if (options.mode == RunMode::TestSuite)
        return runTestSuite(options, run.shaders, run.backend, headlessMsaa(options));
    Scene scene = sceneFromOptions(options);
    if (options.probe) checkProbePixel(scene, options.probe->x, options.probe->y, "--probe");
    switch (options.mode) {
    case RunMode::SweepSheet: return runSweepSheet(run, scene);
    case RunMode::ProbeImage: return runProbeImage(run, std::move(scene));
    case RunMode::Benchmark: return runBenchmark(run, std::move(scene));
#if SHADELAB_HAVE_VIDEO
    case RunMode::Video: return runVideo(run, scene);
#endif
    default: return runImage(run, std::move(scene));
    }
}

}  // namespace shadelab
