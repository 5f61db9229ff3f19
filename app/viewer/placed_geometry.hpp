#pragma once
// What the viewer's world-space caches are built from: the scene's geometry and each object's
// transform. The probe's ray caster and the models' bounding spheres (which the light labels keep off)
// are rebuilt when either changes, and only then: dragging a light or the camera keeps them. GL-free.
#include "core/geometry/mesh.hpp"
#include "core/geometry/scene_geometry.hpp"
#include "core/scene/scene.hpp"

#include <memory>
#include <vector>

namespace shadelab {

class PlacedGeometry {
public:
    // Whether `scene`'s transforms and `geometry` are those remembered (never before the first remember()).
    bool same(const Scene& scene, const std::shared_ptr<const SceneGeometry>& geometry) const;
    void remember(const Scene& scene, const std::shared_ptr<const SceneGeometry>& geometry);

private:
    bool remembered_ = false;
    // Weak: a rebuilt geometry may reuse a freed one's address, an expired pointer cannot be mistaken for it.
    std::weak_ptr<const SceneGeometry> geometry_;
    std::vector<Transform> transforms_;
};

// Each object's world-space bounding sphere (a plane, a floor, left out), for the light labels.
class ModelSpheres {
public:
    const std::vector<BoundingSphere>& of(const Scene& scene, const std::shared_ptr<const SceneGeometry>& geometry);

private:
    PlacedGeometry from_;
    std::vector<BoundingSphere> spheres_;
};

}  // namespace shadelab
