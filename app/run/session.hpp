#pragma once
// What a run of frames shares, in the program's headless modes and in the Python module: the small
// interface they call around a HeadlessSession (headless/headless.hpp). GL-free to include; the
// functions marked "headless" are defined where a headless context is built (run_headless.cpp,
// SHADELAB_OSMESA or SHADELAB_EGL), the others everywhere (session.cpp).
#include "core/geometry/gltf_import.hpp"
#include "core/geometry/scene_geometry.hpp"
#include "core/image/image.hpp"
#include "core/probe/probe.hpp"
#include "options/options.hpp"

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace shadelab {

enum class HeadlessBackend;  // headless/headless_context.hpp

// --output, --sweep, --probe, --benchmark, --playlist with --output, videos and --test: frames from a
// headless context (headless).
int runHeadlessMode(const Options& options);

// --msaa's value for a headless frame (off unless asked for, so the golden images stay pixel-exact),
// --backend's context, and a rendered frame finished as --output writes it (--formula's overlay, with a
// probed pixel's terms when there is one, then --captions' strip) (headless).
int headlessMsaa(const Options& options);
HeadlessBackend headlessBackend(const Options& options);
Image finishedFrame(const Options& options, Image image, const Scene& scene, const std::string& title,
                    const ProbeResult* probe = nullptr);

// --verbose's account of what was loaded, and every glTF warning.
void report(const Options& options, const Scene& drawn, const std::vector<GltfInfo>& gltfInfo, std::size_t triangles);

// The scene's meshes built (glTF files read), the camera framed if the scene asks for it, and reported.
std::shared_ptr<SceneGeometry> loadGeometry(const Options& options, Scene& scene);

}  // namespace shadelab
