#pragma once
// glTF 2.0 (.gltf with external or data: buffers, and .glb) to one world-space Mesh, through Debian's
// tinygltf. The default scene is walked with every node's matrix or TRS applied and baked into the
// vertices; TRIANGLES, TRIANGLE_STRIP and TRIANGLE_FAN primitives become triangles, POINTS and LINES
// are skipped with a warning. Everything is validated before it is used: accessor and buffer-view
// ranges, index values, component types. Failures are InputErrors naming the file and the accessor
// or primitive.
#include "core/geometry/mesh.hpp"

#include <string>
#include <vector>

namespace shadelab {

// A camera of the file, where the drawn scene places it (the first node that uses it).
struct GltfCamera {
    std::string name;
    bool perspective = true;
    glm::vec3 eye{0.0f}, target{0.0f, 0.0f, -1.0f},
        up{0.0f, 1.0f, 0.0f};  // target: on the view axis, level with the model's centre
    float yfovDeg = 45.0f;
    float znear = 0.1f;
    float zfar = 0.0f;  // 0: infinite (the file gave none)
};

// A light of the file (KHR_lights_punctual) where the drawn scene places it: each node that uses it
// gives one. Position and direction are in the model's space; the intensity is the file's, in candela
// (point, spot) or lux (directional) - lecturesLights() (scene_geometry.hpp) converts it to L_l.
struct GltfLight {
    std::string name;
    Light light;  // point: inverse-square with the file's range; spot: cone half-angles in degrees
};

struct GltfInfo {
    int nodes = 0;                               // nodes visited in the drawn scene
    int meshes = 0;                              // meshes in the file
    int materials = 0;                           // materials in the file
    int doubleSidedMaterials = 0;                // of those, how many are doubleSided (drawn from both sides)
    int primitives = 0;                          // primitives drawn (instances counted each time)
    std::size_t fileTriangles = 0;               // TRIANGLES primitives of all meshes, each counted once
    std::size_t triangles = 0;                   // triangles drawn: every instance, strips and fans included
    std::size_t vertices = 0;                    // vertices after baking
    std::size_t generatedNormals = 0;            // vertices whose normal shadelab computed (file had none)
    int textures = 0;                            // base colour images decoded (each image and sampler pair once)
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};  // of the drawn vertices, world space
    std::vector<std::string> warnings;
    std::vector<GltfCamera> cameras;  // in the order the drawn scene reaches them (--camera N)
    std::vector<GltfLight> lights;    // in the order the drawn scene reaches them (at most kMaxLights)
};

Mesh loadGltf(const std::string& path, GltfInfo* info = nullptr);

// The same from bytes already in memory (a .glb if they start with "glTF", else JSON): `label` names
// the input in errors, and external URIs resolve against (and are confined to) `folder`.
Mesh loadGltfFromMemory(std::string bytes, const std::string& label, const std::string& folder,
                        GltfInfo* info = nullptr);

// The lines `shadelab --info` prints for a model.
std::string describe(const std::string& path, const GltfInfo& info);

}  // namespace shadelab
