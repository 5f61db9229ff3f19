#include "viewer/placed_geometry.hpp"

#include "core/geometry/camera.hpp"

namespace shadelab {
namespace {

bool sameTransform(const Transform& a, const Transform& b) {
    return a.translation == b.translation && a.rotationDeg == b.rotationDeg && a.scale == b.scale;
}

}  // namespace

bool PlacedGeometry::same(const Scene& scene, const std::shared_ptr<const SceneGeometry>& geometry) const {
    bool same = remembered_ && geometry_.lock() == geometry && transforms_.size() == scene.objects.size();
    for (std::size_t o = 0; same && o < scene.objects.size(); ++o)
        same = sameTransform(transforms_[o], scene.objects[o].transform);
    return same;
}

void PlacedGeometry::remember(const Scene& scene, const std::shared_ptr<const SceneGeometry>& geometry) {
    remembered_ = true;
    geometry_ = geometry;
    transforms_.clear();
    for (const SceneObject& o : scene.objects) transforms_.push_back(o.transform);
}

const std::vector<BoundingSphere>& ModelSpheres::of(const Scene& scene,
                                                    const std::shared_ptr<const SceneGeometry>& geometry) {
    if (from_.same(scene, geometry)) return spheres_;
    spheres_.clear();
    for (std::size_t o = 0; geometry && o < scene.objects.size() && o < geometry->meshes.size(); ++o) {
        if (scene.objects[o].mesh.type == MeshSpec::Type::Plane) continue;
        spheres_.push_back(worldBounds({&geometry->meshes[o]}, {worldFromObject(scene.objects[o].transform)}));
    }
    from_.remember(scene, geometry);
    return spheres_;
}

}  // namespace shadelab
