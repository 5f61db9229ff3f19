#pragma once
// The pixel probe in the viewer: set at a pixel of the 3D view (a click, --probe), it stays at the same
// surface point (ProbeAnchor) and is evaluated again every frame with the scene as it is then, so its
// numbers follow a slider; new meshes drop it (its triangle was in the old ones). GL-free.
#include "core/geometry/ray_cast.hpp"
#include "core/geometry/scene_geometry.hpp"
#include "core/probe/probe.hpp"
#include "core/scene/scene.hpp"
#include "viewer/placed_geometry.hpp"

#include <glm/vec2.hpp>

#include <memory>
#include <optional>
#include <string>
#include <utility>

namespace shadelab {

class ProbeState {
public:
    // --probe X,Y: set on the first frame, once the view has its size.
    explicit ProbeState(std::optional<glm::ivec2> pending = std::nullopt) : pending_(pending) {}
    std::optional<glm::ivec2> takePending() { return std::exchange(pending_, std::nullopt); }

    // Sets the probe at 3D-view pixel (x, y): `set` when there was a surface there; `message` says what
    // happened, for the status line (an error outside the view).
    struct Outcome {
        bool set = false;
        bool isError = false;
        std::string message;
    };
    Outcome set(const Scene& scene, const std::shared_ptr<const SceneGeometry>& geometry, int x, int y);
    void clear() {
        anchor_.reset();
        result_.reset();
    }
    bool anchored() const { return anchor_.has_value(); }

    // This frame's evaluation at the anchor (none without one, or where its triangle is gone).
    void evaluate(const Scene& scene, const std::shared_ptr<const SceneGeometry>& geometry);
    const ProbeResult* result() const { return result_ ? &*result_ : nullptr; }

private:
    // Rebuilt when the geometry or an object's transform changes.
    const SceneRayCaster& rayCaster(const Scene& scene, const std::shared_ptr<const SceneGeometry>& geometry);

    std::optional<glm::ivec2> pending_;
    std::optional<ProbeAnchor> anchor_;
    // The meshes anchor_'s triangle is in (weak, as PlacedGeometry's).
    std::weak_ptr<const SceneGeometry> anchorGeometry_;
    std::optional<ProbeResult> result_;
    std::unique_ptr<SceneRayCaster> caster_;
    PlacedGeometry casterFrom_;
    const SceneRayCaster noTriangles_;  // what probeAnchor() gets when shadows are off (it is not used)
};

}  // namespace shadelab
