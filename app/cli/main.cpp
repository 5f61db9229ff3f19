// shadelab's entry point: parse the command line, build the scene, hand it to the headless renderer
// or the viewer, report errors as one line. Exit status: 0 ok, 2 bad input, 1 anything else.
#include "cli/options.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/gltf_import.hpp"
#include "core/image.hpp"
#include "core/memory_budget.hpp"
#include "core/message.hpp"
#include "core/plot_image.hpp"
#include "core/probe.hpp"
#include "core/ray_cast.hpp"
#include "core/playlist.hpp"
#include "core/scene_geometry.hpp"
#include "headless/headless.hpp"
#include "platform/platform.hpp"
#include "render/program.hpp"
#include "viewer/viewer.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#ifndef SHADELAB_VERSION
#define SHADELAB_VERSION "0"
#endif

namespace shadelab {
namespace {

struct Stopwatch {
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    double ms() const { return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count(); }
};

// --msaa for --output and --benchmark: off unless asked for, so the golden images stay pixel-exact.
int headlessMsaa(const Options& options) { return options.msaa.value_or(1); }

ViewerOptions viewerOptions(const Options& options, const std::string& shaderDir) {
    ViewerOptions viewer;
    viewer.shaderDir = shaderDir;
    viewer.frames = options.frames;
    viewer.screenshotPath = options.screenshot.value_or("");
    viewer.viewScreenshotPath = options.screenshotView.value_or("");
    viewer.saveScenePath = options.saveScene.value_or("");
    viewer.hidePanel = options.hidePanel;
    viewer.progressiveStride = options.progressiveStride;
    for (Overlay o : options.overlays) viewer.overlays.shown(o) = true;
    viewer.plots = plotSettings(options);
    viewer.panelSections = options.panelSections;
    if (options.probe) viewer.probe = *options.probe;
    viewer.selectedLight = options.selectLight.value_or(-1);
    viewer.uiScale = options.uiScale.value_or(0.0f);
    viewer.fullscreen = options.fullscreen;
    viewer.noLabels = options.noLabels;
    viewer.resetLayout = options.resetLayout;
    viewer.msaa = options.msaa.value_or(-1);
    viewer.verbose = options.verbose;
    return viewer;
}

// --playlist DIR: every preset loaded first (one bad file fails the run before anything is written),
// then either one PNG per preset into the --output folder, or the viewer stepping through them.
int runPlaylist(const Options& options, const std::string& shaderDir, const ShaderLibrary& shaders,
                HeadlessBackend backend) {
    const bool images = options.mode == RunMode::PlaylistImages;  // else the viewer
    if (images) checkOutputFolder(*options.output, "--output");
    const SceneAdjust adjust = [&options](Scene& s) { applyOverrides(s, options); };
    std::vector<Preset> presets = loadPlaylist(*options.playlist, adjust);
    if (images) {
        std::vector<Scene> scenes;
        for (const Preset& p : presets) scenes.push_back(p.scene);
        // Every preset rendered before any file is written: a model that fails to load in the last
        // preset leaves the folder as it was (the frames wait in memory, within the budget).
        std::vector<Image> frames(presets.size());
        std::uint64_t kept = 0;  // every frame's pixels (a caption strip adds a little)
        for (const Scene& s : scenes) kept += 4 * std::uint64_t(s.width) * std::uint64_t(s.height);
        renderScenesHeadless(scenes, shaders, backend, [&](std::size_t i, Image image) {
            const Preset& p = presets[i];
            frames[i] = options.captions ? withCaptionStrip(image, presetTitle(p), p.scene.caption) : std::move(image);
        }, headlessMsaa(options), kept);
        createOutputFolder(*options.output, "--output");
        for (std::size_t i = 0; i < presets.size(); ++i) {
            const std::string path = (std::filesystem::path(*options.output) / (presets[i].name + ".png")).string();
            writePng(path, frames[i]);
            if (options.verbose) std::cerr << "shadelab: wrote " << path << "\n";
        }
        return 0;
    }
    Scene first = presets.front().scene;
    auto geometry = std::make_shared<SceneGeometry>(buildSceneGeometry(first));
    frameIfNeeded(first, *geometry);
    ViewerOptions viewer = viewerOptions(options, shaderDir);
    viewer.playlist = std::move(presets);
    viewer.adjustPreset = adjust;
    Viewer(std::move(first), std::move(geometry), viewer).run();
    return 0;
}

// What a run needs beside the options: where the GLSL comes from and which headless context.
struct RunContext {
    const Options& options;
    std::string shaderDir;
    ShaderLibrary shaders;
    HeadlessBackend backend;
};

// --plot: drawn on the CPU from core/lighting's formulas: no GL, no context, no shaders.
int runPlot(const Options& options, const Scene& scene) {
    const Material material = scene.objects.empty() ? Material{} : scene.objects.front().material;
    const Image image = renderPlotImage(scenePlot(*options.plot, scene, material, plotSettings(options)),
                                        options.width.value_or(kPlotDefaultWidth),
                                        options.height.value_or(kPlotDefaultHeight));
    writePng(*options.output, image);
    if (options.verbose) std::cerr << "shadelab: wrote " << *options.output << " (" << toString(*options.plot) << " plot)\n";
    return 0;
}

// --verbose's account of what was loaded, and every glTF warning.
void report(const Options& options, const Scene& drawn, const std::vector<GltfInfo>& gltfInfo, std::size_t triangles) {
    for (std::size_t i = 0; i < gltfInfo.size(); ++i) {
        const GltfInfo& info = gltfInfo[i];
        const std::string& path = drawn.objects[i].mesh.resolvedPath;
        for (const std::string& w : info.warnings) std::cerr << oneLine("shadelab: warning: " + path + ": " + w) << "\n";
        if (options.verbose && drawn.objects[i].mesh.type == MeshSpec::Type::Gltf) {
            std::cerr << "shadelab: " << path << ": " << info.triangles << " triangles, " << info.generatedNormals
                      << " generated normals";
            if (info.textures) std::cerr << ", " << info.textures << " base colour texture(s)";
            std::cerr << "\n";
        }
    }
    if (options.verbose)
        std::cerr << "shadelab: " << (options.input.empty() ? "built-in default scene" : options.input) << ": "
                  << drawn.objects.size() << " object(s), " << triangles << " triangles\n";
}

int runSweepSheet(const RunContext& run, const Scene& scene) {
    const Options& options = run.options;
    const Stopwatch clock;
    const Image sheet = renderSweepHeadless(scene, options.sweeps, run.shaders, run.backend, "--sweep", headlessMsaa(options));
    writePng(*options.output, sheet);
    if (options.verbose)
        std::cerr << "shadelab: wrote " << *options.output << " (" << sheet.width << "x" << sheet.height << ", "
                  << clock.ms() << " ms)\n";
    return 0;
}

// The probe needs the CPU geometry after the render, so this path builds it itself rather than
// through renderSceneHeadless (which lets go of it once uploaded).
int runProbeImage(const RunContext& run, Scene scene) {
    const Options& options = run.options;
    auto geometry = std::make_shared<SceneGeometry>(buildSceneGeometry(scene));
    frameIfNeeded(scene, *geometry);
    report(options, scene, geometry->gltfInfo, geometry->triangleCount());
    const ProbeResult probe = probePixel(scene, *geometry, SceneRayCaster(scene, *geometry), options.probe->x,
                                         options.probe->y);
    writePng(*options.output, renderHeadless(scene, geometry, run.shaders, run.backend, headlessMsaa(options)));
    std::cout << probeToJson(scene, probe) << std::endl;
    return 0;
}

int runImage(const RunContext& run, Scene scene) {
    const Options& options = run.options;
    const Stopwatch clock;
    const HeadlessFrame frame = renderSceneHeadless(std::move(scene), run.shaders, run.backend, headlessMsaa(options));
    report(options, frame.scene, frame.gltfInfo, frame.triangles);
    const double renderedMs = clock.ms();
    writePng(*options.output, options.captions ? withCaptionStrip(frame.image, frame.scene.title, frame.scene.caption)
                                               : frame.image);
    if (options.verbose)
        std::cerr << "shadelab: wrote " << *options.output << " (geometry, context and render " << renderedMs
                  << " ms, PNG " << clock.ms() - renderedMs << " ms)\n";
    return 0;
}

int runInfo(const Scene& scene, const SceneGeometry& geometry) {
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const MeshSpec& spec = scene.objects[i].mesh;
        if (spec.type == MeshSpec::Type::Gltf) {
            std::cout << describe(spec.resolvedPath, geometry.gltfInfo[i]);
        } else {
            std::cout << "object " << i << ": " << toString(spec.type) << ", " << geometry.meshes[i].triangleCount()
                      << " triangles, " << geometry.meshes[i].positions.size() << " vertices\n";
        }
    }
    return 0;
}

int runBenchmark(const RunContext& run, const Scene& scene, const std::shared_ptr<SceneGeometry>& geometry) {
    const Options& options = run.options;
    std::vector<ShadingMode> modes;
    if (scene.layout == Layout::Compare) modes = {scene.shading};
    else if (options.shading) modes = {*options.shading};
    else modes = {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong};
    for (const BenchmarkResult& r : benchmarkHeadless(scene, geometry, modes, options.benchmarkFrames, 3, run.shaders,
                                                      run.backend, options.progressiveStride, headlessMsaa(options)))
        std::cout << toJson(r) << std::endl;
    return 0;
}

// One scene (not a playlist): the mode parseOptions decided.
int runScene(const RunContext& run) {
    const Options& options = run.options;
    Scene scene = sceneFromOptions(options);
    if (options.mode == RunMode::Plot) return runPlot(options, scene);
    if (options.probe) checkProbePixel(scene, options.probe->x, options.probe->y, "--probe");
    switch (options.mode) {
    case RunMode::SweepSheet: return runSweepSheet(run, scene);
    case RunMode::ProbeImage: return runProbeImage(run, std::move(scene));
    case RunMode::Image: return runImage(run, std::move(scene));
    default: break;
    }
    auto geometry = std::make_shared<SceneGeometry>(buildSceneGeometry(scene));
    frameIfNeeded(scene, *geometry);
    if (options.mode == RunMode::Info) return runInfo(scene, *geometry);
    report(options, scene, geometry->gltfInfo, geometry->triangleCount());
    if (options.mode == RunMode::Benchmark) return runBenchmark(run, scene, geometry);
    Viewer(std::move(scene), std::move(geometry), viewerOptions(options, run.shaderDir)).run();
    return 0;
}

int run(const std::vector<std::string>& args) {
    const Options options = parseOptions(args);
    setMemoryBudget(options.maxMemory);
    if (options.mode == RunMode::Help) {
        std::cout << usage();
        return 0;
    }
    if (options.mode == RunMode::Version) {
        std::cout << "shadelab " << SHADELAB_VERSION << "\n";
        return 0;
    }
    if (options.output && !options.playlist) checkOutputPath(*options.output, "--output");
    if (options.screenshot) checkOutputPath(*options.screenshot, "--screenshot");
    if (options.screenshotView) checkOutputPath(*options.screenshotView, "--screenshot-view");
    if (options.saveScene) checkOutputPath(*options.saveScene, "--save-scene");
    // GLSL from --shader-dir, else from the folder beside the program (defaultShaderFolder), else built in.
    const std::string shaderDir = options.shaderDir.empty() ? defaultShaderFolder() : options.shaderDir;
    const RunContext context{options, shaderDir, ShaderLibrary(shaderDir),
                             options.backend == "egl"      ? HeadlessBackend::Egl
                             : options.backend == "osmesa" ? HeadlessBackend::OsMesa
                                                           : HeadlessBackend::Auto};
    if (options.mode == RunMode::PlaylistImages || options.mode == RunMode::PlaylistViewer)
        return runPlaylist(options, shaderDir, context.shaders, context.backend);
    return runScene(context);
}

}  // namespace

}  // namespace shadelab

int main(int argc, char** argv) {
    shadelab::platform::restartWithHugePagesIfAsked(argv);
    try {
        return shadelab::run(std::vector<std::string>(argv + 1, argv + argc));
    } catch (const shadelab::InputError& e) {
        std::cerr << "shadelab: " << shadelab::oneLine(e.what()) << "\n";
        return 2;
    } catch (const shadelab::ShaderError& e) {
        // The compiler's log is lines of its own: joined with "; " (the viewer shows them as lines).
        std::string log = e.what();
        while (!log.empty() && log.back() == '\n') log.pop_back();
        for (std::size_t at = 0; (at = log.find('\n', at)) != std::string::npos;)
            log.replace(at, 1, at > 0 && log[at - 1] == ':' ? " " : "; ");
        std::cerr << "shadelab: " << shadelab::oneLine(log) << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "shadelab: " << shadelab::oneLine(e.what()) << "\n";
        return 1;
    }
}
