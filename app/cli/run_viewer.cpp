// The run modes with a window (run_viewer.hpp): the viewer on one scene or stepping through a playlist.
// Built where the viewer is (SHADELAB_VIEWER).
#include "cli/run_viewer.hpp"

#include "core/geometry/scene_geometry.hpp"
#include "core/probe/probe.hpp"
#include "core/scene/playlist.hpp"
#include "render/shader_library.hpp"
#include "run/session.hpp"
#include "viewer/viewer.hpp"

#include <memory>

namespace shadelab {
namespace {

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
    viewer.formula = options.formula;
    viewer.intersection = options.intersection;
    viewer.resetLayout = options.resetLayout;
    viewer.msaa = options.msaa.value_or(-1);
    viewer.animations = options.animations;
    viewer.verbose = options.verbose;
    return viewer;
}

// --playlist DIR: every preset loaded first (one bad file fails the run before a window opens), then
// the viewer stepping through them.
int runPlaylistViewer(const Options& options) {
    const SceneAdjust adjust = [&options](Scene& s) { applyOverrides(s, options); };
    std::vector<Preset> presets = loadPlaylist(*options.playlist, adjust);
    Scene first = presets.front().scene;
    auto geometry = std::make_shared<SceneGeometry>(buildSceneGeometry(first));
    frameIfNeeded(first, *geometry);
    ViewerOptions viewer = viewerOptions(options, shaderFolder(options.shaderDir));
    viewer.playlist = std::move(presets);
    viewer.adjustPreset = adjust;
    Viewer(std::move(first), std::move(geometry), viewer).run();
    return 0;
}

}  // namespace

int runViewerMode(const Options& options) {
    if (options.mode == RunMode::PlaylistViewer) return runPlaylistViewer(options);
    Scene scene = sceneFromOptions(options);
    if (options.probe) checkProbePixel(scene, options.probe->x, options.probe->y, "--probe");
    auto geometry = loadGeometry(options, scene);
    Viewer(std::move(scene), std::move(geometry), viewerOptions(options, shaderFolder(options.shaderDir))).run();
    return 0;
}

}  // namespace shadelab
