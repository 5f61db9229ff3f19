// shadelab's entry point: parse the command line, run the mode it asks for, report errors as one line.
// Exit status: 0 ok, 2 bad input, 1 anything else (and, with --reference, an image that differs from it:
// run/reference.hpp; its line on stdout tells the two apart). What needs no GL runs here; rendering and the
// viewer are in run/run_headless.cpp and run_viewer.cpp, built where their parts are (run/session.hpp).
#include "cli/run_viewer.hpp"
#include "core/base/error.hpp"
#include "core/base/file_io.hpp"
#include "core/base/message.hpp"
#include "core/geometry/scene_geometry.hpp"
#include "core/image/image.hpp"
#include "core/scene/memory_budget.hpp"
#include "options/options.hpp"
#include "platform/platform.hpp"
#include "run/reference.hpp"
#include "run/session.hpp"

#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

#ifndef SHADELAB_VERSION
#define SHADELAB_VERSION "0"
#endif

namespace shadelab {

namespace {

// --plot: drawn on the CPU from core/shading/lighting's formulas: no GL, no context, no shaders.
int runPlot(const Options& options, const Scene& scene) {
    const std::optional<Image> reference = readReference(options);
    const Image image = plotImage(options, scene);
    const int status = writeOutputAndCompare(options, image, reference, scene.diff.factor);
    if (options.verbose)
        std::cerr << "shadelab: wrote " << *options.output << " (" << toString(*options.plot) << " plot)\n";
    return status;
}

int runInfo(const Options& options) {
    Scene scene = sceneFromOptions(options);
    const SceneGeometry geometry = buildSceneGeometry(scene);
    frameIfNeeded(scene, geometry);
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

// Rendering and the viewer, or one line that says this build has not got them.
#if SHADELAB_HAVE_HEADLESS
int runHeadless(const Options& options) { return runHeadlessMode(options); }
#else
int runHeadless(const Options& options) {
    const char* flag = options.mode == RunMode::TestSuite    ? "--test"
                       : options.mode == RunMode::SweepSheet ? "--sweep"
                       : options.mode == RunMode::ProbeImage ? "--probe"
                       : options.mode == RunMode::Benchmark  ? "--benchmark"
                                                             : "--output";
    throw InputError(std::string(flag) +
                     ": this shadelab was built without a headless GL context (CMake options "
                     "SHADELAB_OSMESA, SHADELAB_EGL)");
}
#endif

#if SHADELAB_HAVE_VIEWER
int runViewer(const Options& options) { return runViewerMode(options); }
#else
int runViewer(const Options&) {
    throw InputError(
        "this shadelab was built without the viewer (CMake option SHADELAB_VIEWER): give "
        "--output FILE.png for a picture");
}
#endif

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
#if SHADELAB_HAVE_HEADLESS && !SHADELAB_HAVE_VIDEO  // (without a context, runHeadless says that is missing)
    if (options.mode == RunMode::Video)
        throw InputError("--output: " + *options.output +
                         ": this shadelab was built without video encoding (CMake "
                         "option SHADELAB_VIDEO: FFmpeg's libavcodec, libavformat, libswscale)");
#endif
    if (options.output && !options.playlist) checkOutputPath(*options.output, "--output");
    if (options.screenshot) checkOutputPath(*options.screenshot, "--screenshot");
    if (options.screenshotView) checkOutputPath(*options.screenshotView, "--screenshot-view");
    if (options.saveScene) checkOutputPath(*options.saveScene, "--save-scene");
    if (options.junit) checkOutputPath(*options.junit, "--junit");
    if (options.report) checkOutputPath(*options.report, "--report");
    switch (options.mode) {
    case RunMode::Plot: return runPlot(options, sceneFromOptions(options));
    case RunMode::Info: return runInfo(options);
    case RunMode::Viewer:
    case RunMode::PlaylistViewer: return runViewer(options);
    default: return runHeadless(options);
    }
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
        // The compiler's log is lines of its own: joined (the viewer shows them as lines).
        std::cerr << "shadelab: " << shadelab::oneLine(shadelab::joinedLines(e.what())) << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "shadelab: " << shadelab::oneLine(e.what()) << "\n";
        return 1;
    }
}
