#include "core/scene_geometry.hpp"

#include "core/camera.hpp"

namespace shadelab {

std::size_t SceneGeometry::triangleCount() const {
    std::size_t n = 0;
    for (const Mesh& m : meshes) n += m.triangleCount();
    return n;
}

SceneGeometry buildSceneGeometry(const Scene& scene) {
    SceneGeometry g;
    for (const SceneObject& o : scene.objects) {
        GltfInfo info;
        if (o.mesh.type == MeshSpec::Type::Gltf) {
            g.meshes.push_back(loadGltf(o.mesh.resolvedPath, &info));
        } else {
            g.meshes.push_back(makeProceduralMesh(o.mesh));
        }
        g.specs.push_back(o.mesh);
        g.gltfInfo.push_back(std::move(info));
    }
    return g;
}

void frameIfNeeded(Scene& scene, const SceneGeometry& g) {
    if (scene.cameraGiven) return;
    bool hasModel = false;
    for (const SceneObject& o : scene.objects) hasModel = hasModel || o.mesh.type == MeshSpec::Type::Gltf;
    if (!hasModel) return;
    std::vector<const Mesh*> meshes;
    std::vector<glm::mat4> transforms;
    for (size_t i = 0; i < g.meshes.size() && i < scene.objects.size(); ++i) {
        meshes.push_back(&g.meshes[i]);
        transforms.push_back(worldFromObject(scene.objects[i].transform));
    }
    const auto panes = layoutPanes(scene.layout, scene.shading, scene.width, scene.height, scene.diff);
    const Pane& p = panes.front();
    frameBounds(scene, worldBounds(meshes, transforms), float(p.width) / float(p.height));
}

}  // namespace shadelab
