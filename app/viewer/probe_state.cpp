#include "viewer/probe_state.hpp"

namespace shadelab {

ProbeState::Outcome ProbeState::set(const Scene& scene, const std::shared_ptr<const SceneGeometry>& geometry, int x,
                                    int y) {
    const std::string pixel = std::to_string(x) + "," + std::to_string(y);
    if (!geometry || x < 0 || y < 0 || x >= scene.width || y >= scene.height)
        return {false, true,
                "probe: pixel " + pixel + " is outside the " + std::to_string(scene.width) + "x" +
                    std::to_string(scene.height) + " view"};
    const ProbeResult r = probePixel(scene, *geometry, rayCaster(scene, geometry), x, y);
    if (r.miss) return {false, false, "probe: no surface at pixel " + pixel + " (background)"};
    anchor_ = r.anchor;
    anchorGeometry_ = geometry;
    return {true, false, "probe at pixel " + pixel + " (Esc clears it)"};
}

void ProbeState::evaluate(const Scene& scene, const std::shared_ptr<const SceneGeometry>& geometry) {
    result_.reset();
    if (anchor_ && geometry != anchorGeometry_.lock()) anchor_.reset();  // its triangle was in the old meshes
    if (!anchor_ || !geometry || !validAnchor(scene, *geometry, *anchor_)) return;
    // The ray caster is only needed for occlusion: without shadows, dragging a transform must not
    // rebuild it every frame.
    result_ =
        probeAnchor(scene, *geometry, scene.shadows.enabled ? rayCaster(scene, geometry) : noTriangles_, *anchor_);
}

const SceneRayCaster& ProbeState::rayCaster(const Scene& scene, const std::shared_ptr<const SceneGeometry>& geometry) {
    if (!caster_ || !casterFrom_.same(scene, geometry)) {
        caster_ = geometry ? std::make_unique<SceneRayCaster>(scene, *geometry) : std::make_unique<SceneRayCaster>();
        casterFrom_.remember(scene, geometry);
    }
    return *caster_;
}

}  // namespace shadelab
