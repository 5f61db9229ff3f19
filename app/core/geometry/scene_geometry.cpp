#include "core/geometry/scene_geometry.hpp"

#include "core/base/error.hpp"
#include "core/geometry/camera.hpp"
#include "core/shading/lighting.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>

namespace shadelab {

std::uint64_t SceneGeometry::textureBytes() const {
    std::uint64_t n = 0;
    for (const Mesh& m : meshes)
        for (const auto& t : m.textures) n += t->rgba.size();
    return n;
}

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

namespace {

// --camera N: the model's camera N (gltf_import.hpp: GltfCamera), through the object's own transform.
void useModelCamera(Scene& scene, const SceneGeometry& g) {
    std::size_t object = 0;
    while (object < scene.objects.size() && scene.objects[object].mesh.type != MeshSpec::Type::Gltf) ++object;
    if (object >= scene.objects.size() || object >= g.gltfInfo.size())
        throw InputError("--camera: the scene has no glTF model");
    const std::string& path = scene.objects[object].mesh.resolvedPath;
    const std::vector<GltfCamera>& cameras = g.gltfInfo[object].cameras;
    const auto n = std::size_t(scene.modelCamera);
    if (n >= cameras.size())
        throw InputError("--camera: " + path + " has " + std::to_string(cameras.size()) + " camera" +
                         (cameras.size() == 1 ? "" : "s") + " in its drawn scene" +
                         (cameras.empty() ? "" : " (0.." + std::to_string(cameras.size() - 1) + ")"));
    const GltfCamera& c = cameras[n];
    if (!c.perspective)
        throw InputError("--camera: camera " + std::to_string(n) + " of " + path +
                         " is orthographic: shadelab's views are perspective");
    const glm::mat4 world = worldFromObject(scene.objects[object].transform);
    Camera& cam = scene.camera;
    cam.eye = glm::vec3(world * glm::vec4(c.eye, 1.0f));
    cam.target = glm::vec3(world * glm::vec4(c.target, 1.0f));
    cam.up = safeNormalize(glm::mat3(world) * c.up);
    cam.fovYDeg = glm::clamp(c.yfovDeg, 1.0f, 179.0f);
    // Far: the file's, or (infinite in the file) just past the model seen from the eye.
    const glm::vec3 lo = glm::vec3(world * glm::vec4(g.gltfInfo[object].boundsMin, 1.0f));
    const glm::vec3 hi = glm::vec3(world * glm::vec4(g.gltfInfo[object].boundsMax, 1.0f));
    const float reach = glm::distance(cam.eye, 0.5f * (lo + hi)) + glm::distance(lo, hi);
    cam.nearPlane = c.znear > 0.0f ? c.znear : std::max(reach * 1e-4f, 1e-4f);
    cam.farPlane = c.zfar > cam.nearPlane ? c.zfar : std::max(reach * 1.5f, cam.nearPlane * 10.0f);
    scene.cameraGiven = true;
}

// A scene without lights of its own is lit by the first model's lights, when it has some.
void useModelLights(Scene& scene, const SceneGeometry& g) {
    if (scene.lightsGiven) return;
    for (std::size_t o = 0; o < scene.objects.size() && o < g.gltfInfo.size(); ++o) {
        if (g.gltfInfo[o].lights.empty()) continue;
        const glm::mat4 world = worldFromObject(scene.objects[o].transform);
        scene.lights = lecturesLights(g.gltfInfo[o].lights, world, worldBounds({&g.meshes[o]}, {world}));
        scene.lightsGiven = true;
        return;
    }
}

}  // namespace

std::vector<Light> lecturesLights(const std::vector<GltfLight>& lights, const glm::mat4& world,
                                  const BoundingSphere& b) {
    std::vector<Light> out;
    const float scale = std::cbrt(std::fabs(glm::determinant(glm::mat3(world))));
    const float radius = b.radius > 0.0f ? b.radius : 1.0f;
    float brightest = 0.0f, brightestIgnoringCones = 0.0f;
    for (const GltfLight& gl : lights) {
        Light l = gl.light;
        l.position = glm::vec3(world * glm::vec4(l.position, 1.0f));
        l.direction = safeNormalize(glm::mat3(world) * l.direction, glm::vec3(0.0f, 0.0f, -1.0f));
        l.range *= scale;
        float e = l.intensity * std::max({l.color.r, l.color.g, l.color.b});
        if (l.type != LightType::Directional) {
            const glm::vec3 d = l.position - b.center;
            const float r = std::max(glm::length(d), 0.1f * radius);
            e *= attenuationFactor(l, r * r);
            brightestIgnoringCones = std::max(brightestIgnoringCones, e);
            if (glm::length(d) > 0.0f) e *= spotFalloff(l, glm::normalize(d));
        } else {
            brightestIgnoringCones = std::max(brightestIgnoringCones, e);
        }
        brightest = std::max(brightest, e);
        out.push_back(l);
    }
    // Spot lights that all point away from the centre: scaled as if they did not.
    const float reference = brightest > 0.0f ? brightest : brightestIgnoringCones;
    if (reference > 0.0f && std::isfinite(reference))
        for (Light& l : out) l.intensity = std::min(l.intensity / reference, 1e9f);
    return out;
}

void frameIfNeeded(Scene& scene, const SceneGeometry& g) {
    useModelLights(scene, g);
    // glTF's colours (factors, COLOR_0, decoded base colour texels) are linear values meant for an
    // sRGB display: a scene that draws a model is written sRGB-encoded unless it says otherwise,
    // whatever stores the colour and whether a texture loaded.
    if (!scene.outputEncodingGiven)
        for (const SceneObject& o : scene.objects)
            if (o.mesh.type == MeshSpec::Type::Gltf) {
                scene.outputEncoding = OutputEncoding::Srgb;
                scene.outputEncodingGiven = true;
            }
    scene.emissiveModel = false;
    for (std::size_t o = 0; o < scene.objects.size() && o < g.meshes.size(); ++o)
        for (const MeshPart& part : g.meshes[o].parts)
            if (part.emissive != glm::vec3(0.0f) && !scene.objects[o].material.colorSet) scene.emissiveModel = true;
    if (scene.modelCamera >= 0) return useModelCamera(scene, g);
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
