#pragma once
// The meshes a scene draws, built from its mesh specs (procedural shapes, or glTF files read from
// disk). Kept apart from Scene so that editing a material never rebuilds geometry.
#include "core/geometry/gltf_import.hpp"
#include "core/geometry/mesh.hpp"
#include "core/scene/scene.hpp"

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
// light) placed to fit the model's bounding sphere. A scene that gives no lights and draws a glTF
// model with lights of its own (KHR_lights_punctual) is lit by those (lecturesLights), the first such
// model's. A scene that does not choose its output encoding and draws a model with a base colour
// texture is written sRGB-encoded.
void frameIfNeeded(Scene& scene, const SceneGeometry& geometry);

// A model's lights as the lecture's L_l. The file gives physical units: candela for point and spot
// lights, whose illuminance at distance r is I / r^2 (shadelab's inverse-square attenuation, windowed
// by the file's range), and lux for directional lights. All of them are scaled by one factor, so that
// their ratios stay the file's and the brightest delivers L = 1 (its colour's largest channel) at the
// centre of `bounds` (spot lights with their cone; one nearer than a tenth of the radius counted at
// that distance). Positions and directions go through `worldFromObject`.
std::vector<Light> lecturesLights(const std::vector<GltfLight>& lights, const glm::mat4& worldFromObject,
                                  const BoundingSphere& bounds);

}  // namespace shadelab
