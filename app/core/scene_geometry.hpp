#pragma once
// The meshes a scene draws, built from its mesh specs (procedural shapes, or glTF files read from
// disk). Kept apart from Scene so that editing a material never rebuilds geometry.
#include "core/gltf_import.hpp"
#include "core/mesh.hpp"
#include "core/scene.hpp"

#include <vector>

namespace shadelab {

struct SceneGeometry {
    std::vector<Mesh> meshes;        // one per scene object, in object space
    std::vector<MeshSpec> specs;     // what each mesh was built from
    std::vector<GltfInfo> gltfInfo;  // per object; empty for procedural meshes
    std::size_t triangleCount() const;
    std::uint64_t textureBytes() const;  // decoded base colour images, every mesh's
};

// Builds every object's mesh. glTF failures are InputErrors naming the file.
SceneGeometry buildSceneGeometry(const Scene& scene);

// A scene that gives no camera and draws a glTF model gets a camera (and, with no lights given, a
// light) placed to fit the model's bounding sphere.
void frameIfNeeded(Scene& scene, const SceneGeometry& geometry);

}  // namespace shadelab
