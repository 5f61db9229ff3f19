#pragma once
// The shadelab program's run modes, by the part of the build each needs. main.cpp parses the command
// line and runs what needs no GL (--help, --version, --plot, --info) itself; the rest is here, compiled
// only where its part is (CMake options SHADELAB_OSMESA / SHADELAB_EGL, SHADELAB_VIEWER).
#include "cli/options.hpp"
#include "core/geometry/gltf_import.hpp"
#include "core/geometry/scene_geometry.hpp"
#include "core/image/image.hpp"
#include "core/probe/probe.hpp"

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace shadelab {

enum class HeadlessBackend;  // headless/headless_context.hpp

// --output, --sweep, --probe, --benchmark and --playlist with --output: frames from a headless context
// (run_headless.cpp; needs SHADELAB_OSMESA or SHADELAB_EGL).
int runHeadlessMode(const Options& options);

// What the headless modes share with the Python module (app/python), which renders as --output does:
// --msaa's value for a headless frame (off unless asked for, so the golden images stay pixel-exact),
// --backend's context, and a rendered frame finished as --output writes it (--formula's overlay, with a
// probed pixel's terms when there is one, then --captions' strip).
int headlessMsaa(const Options& options);
HeadlessBackend headlessBackend(const Options& options);
Image finishedFrame(const Options& options, Image image, const Scene& scene, const std::string& title,
                    const ProbeResult* probe = nullptr);

// The interactive viewer, for one scene or a playlist (run_viewer.cpp; needs SHADELAB_VIEWER).
int runViewerMode(const Options& options);

// --verbose's account of what was loaded, and every glTF warning (main.cpp).
void report(const Options& options, const Scene& drawn, const std::vector<GltfInfo>& gltfInfo, std::size_t triangles);

// The scene's meshes built (glTF files read), the camera framed if the scene asks for it, and reported.
std::shared_ptr<SceneGeometry> loadGeometry(const Options& options, Scene& scene);

}  // namespace shadelab
