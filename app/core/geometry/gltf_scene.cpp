// The drawn glTF scene: the default scene's nodes walked with their matrix or TRS (and
// EXT_mesh_gpu_instancing's instances), a second walk for instanced draws, the cameras and
// KHR_lights_punctual lights the walk reaches, and what was drawn (GltfInfo, describe()).
#include "core/geometry/gltf_import_parts.hpp"

#include "core/scene/scene_names.hpp"
#include "core/shading/lighting.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstdio>
#include <optional>

namespace shadelab {
namespace gltf_import_parts {

namespace {

// Every node drawn is a copy of its meshes in the baked mesh: at most this many, whatever the file's size.
constexpr int kMaxNodeInstances = 1000000;

// Whether every instance transform of the instanced pass is finite and invertible (a zero scale is
// not): otherwise the baked mesh is drawn as it is.
bool instancesInvertible(const Mesh& m) {
    for (const MeshPart& part : m.parts)
        for (const glm::mat4& t : part.instances)
            if (!isFinite(t) || !(std::fabs(glm::determinant(glm::mat3(t))) > 1e-12f)) return false;
    return true;
}

}  // namespace

Mesh GltfReader::read() {
    const std::vector<int> roots = rootNodes();
    for (int r : roots) visit(r, glm::mat4(1.0f), 0);
    if (instanced_) readInstanced(roots);
    summarise();
    if (mesh_.indices.empty()) info_.warnings.push_back("nothing to draw: the default scene has no triangles");
    completeTangents(mesh_);  // TANGENT where given, else from the texture coordinates or the up axis
    return std::move(mesh_);
}

// The default scene's nodes (the first scene's where none is named); with no scene, every node that
// is nobody's child.
std::vector<int> GltfReader::rootNodes() const {
    std::vector<int> roots;
    if (!model_.scenes.empty()) {
        const int si = model_.defaultScene >= 0 ? model_.defaultScene : 0;
        if (std::size_t(si) >= model_.scenes.size()) fail("scene", std::to_string(si) + " does not exist");
        return model_.scenes[std::size_t(si)].nodes;
    }
    std::vector<bool> isChild(model_.nodes.size(), false);
    for (const auto& n : model_.nodes)
        for (int c : n.children)
            if (c >= 0 && std::size_t(c) < isChild.size()) isChild[std::size_t(c)] = true;
    for (std::size_t i = 0; i < model_.nodes.size(); ++i)
        if (!isChild[i]) roots.push_back(int(i));
    return roots;
}

// GPU instancing: the same scene again with each instanced node's primitives once and its instances
// as transforms (MeshPart::instances), for the renderer's instanced draws. The baked mesh of the first
// walk stays what everything else reads (bounds, the probe, overlays).
void GltfReader::readInstanced(const std::vector<int>& roots) {
    const GltfInfo baked = info_;
    auto compact = std::make_shared<Mesh>();
    out_ = compact.get();
    instancedPass_ = true;
    info_.nodes = 0;
    info_.triangles = 0;
    info_.primitives = 0;
    info_.generatedNormals = 0;  // limits count one walk
    for (int r : roots) visit(r, glm::mat4(1.0f), 0);
    out_ = &mesh_;
    instancedPass_ = false;
    info_ = baked;
    compact->textures = mesh_.textures;
    completeTangents(*compact);
    if (instancesInvertible(*compact)) mesh_.instanced = std::move(compact);
}

// What the file holds and what was drawn (info_'s counts and bounds), and each camera's target.
void GltfReader::summarise() {
    info_.meshes = int(model_.meshes.size());
    info_.materials = int(model_.materials.size());
    info_.doubleSidedMaterials = int(std::count_if(model_.materials.begin(), model_.materials.end(),
                                                   [](const tinygltf::Material& m) { return m.doubleSided; }));
    info_.vertices = mesh_.positions.size();
    info_.textures = int(mesh_.textures.size());
    // TRIANGLES primitives of every mesh, each counted once (what the file holds, drawn or not).
    for (const tinygltf::Mesh& m : model_.meshes)
        for (const tinygltf::Primitive& p : m.primitives) {
            if (p.mode >= 0 && p.mode != TINYGLTF_MODE_TRIANGLES) continue;
            const int counted =
                p.indices >= 0 ? p.indices : (p.attributes.count("POSITION") ? p.attributes.at("POSITION") : -1);
            if (counted >= 0 && std::size_t(counted) < model_.accessors.size())
                info_.fileTriangles += model_.accessors[std::size_t(counted)].count / 3;
        }
    if (!mesh_.positions.empty()) {
        info_.boundsMin = info_.boundsMax = mesh_.positions.front();
        for (const glm::vec3& p : mesh_.positions) {
            info_.boundsMin = glm::min(info_.boundsMin, p);
            info_.boundsMax = glm::max(info_.boundsMax, p);
        }
    }
    // Each camera's target: the point of its view axis nearest the model's centre (at least its near plane
    // ahead), so the viewer orbits about the model as the file's camera sees it.
    const glm::vec3 centre = 0.5f * (info_.boundsMin + info_.boundsMax);
    for (GltfCamera& c : info_.cameras) {
        const glm::vec3 forward = c.target - c.eye;
        c.target = c.eye + forward * std::max(glm::dot(centre - c.eye, forward), std::max(c.znear, 1e-3f) * 2.0f);
    }
}

void GltfReader::visit(int ni, const glm::mat4& parent, int depth) {
    if (ni < 0 || std::size_t(ni) >= model_.nodes.size()) fail("node " + std::to_string(ni), "does not exist");
    if (depth > 256) fail("node " + std::to_string(ni), "node hierarchy deeper than 256 (a cycle?)");
    const tinygltf::Node& n = model_.nodes[std::size_t(ni)];
    glm::mat4 local(1.0f);
    if (n.matrix.size() == 16) {
        local = glm::make_mat4(n.matrix.data());
    } else {
        if (n.translation.size() == 3)
            local = glm::translate(
                local, glm::vec3(float(n.translation[0]), float(n.translation[1]), float(n.translation[2])));
        if (n.rotation.size() == 4)  // glTF stores x, y, z, w
            local *= glm::mat4_cast(
                glm::quat(float(n.rotation[3]), float(n.rotation[0]), float(n.rotation[1]), float(n.rotation[2])));
        if (n.scale.size() == 3)
            local = glm::scale(local, glm::vec3(float(n.scale[0]), float(n.scale[1]), float(n.scale[2])));
    }
    const glm::mat4 world = parent * local;
    // A translation of 1e39 is +inf as a float; finite scales can multiply past the float range.
    if (!isFinite(world)) fail("node " + std::to_string(ni), "its transform (with its parents') is not finite");
    // The depth limit does not bound the work: a child listed twice at each of 40 levels is 2^40 visits.
    if (info_.nodes >= kMaxNodeInstances)
        fail("node " + std::to_string(ni), "more than " + std::to_string(kMaxNodeInstances) +
                                               " node instances in the scene (children listed many times?)");
    info_.nodes += 1;
    if (!instancedPass_) {
        if (n.camera >= 0 && std::size_t(n.camera) < model_.cameras.size()) addCamera(n.camera, world);
        addLight(n, ni, world);
    }
    if (n.mesh >= 0) {
        if (std::size_t(n.mesh) >= model_.meshes.size())
            fail("node " + std::to_string(ni), "mesh " + std::to_string(n.mesh) + " does not exist");
        const tinygltf::Mesh& m = model_.meshes[std::size_t(n.mesh)];
        currentNode_ = ni;
        const std::vector<glm::mat4> copies = instances(ni, n);
        instanced_ = instanced_ || copies.size() > 1;
        if (instancedPass_ && copies.size() > 1) {
            // Once, baked with the first instance's transform; the others relative to it.
            const glm::mat4 first = world * copies[0];
            const glm::mat4 firstInverse = glm::inverse(first);
            std::vector<glm::mat4> relative;
            relative.reserve(copies.size());
            for (const glm::mat4& instance : copies) relative.push_back(world * instance * firstInverse);
            relative[0] = glm::mat4(1.0f);
            for (std::size_t k = 0; k < m.primitives.size(); ++k)
                addPrimitive(m.primitives[k], first,
                             "mesh " + std::to_string(n.mesh) + " primitive " + std::to_string(k), relative);
        } else {
            for (const glm::mat4& instance : copies) {
                const glm::mat4 instanceWorld = world * instance;
                if (!isFinite(instanceWorld))
                    fail("node " + std::to_string(ni), "an instance's transform is not finite");
                for (std::size_t k = 0; k < m.primitives.size(); ++k)
                    addPrimitive(m.primitives[k], instanceWorld,
                                 "mesh " + std::to_string(n.mesh) + " primitive " + std::to_string(k));
            }
        }
    }
    for (int child : n.children) visit(child, world, depth + 1);
}

// The node's own transform once, or once per instance of EXT_mesh_gpu_instancing: T * R * S from its
// TRANSLATION, ROTATION and SCALE accessors (each optional; quantized types as the extension allows).
std::vector<glm::mat4> GltfReader::instances(int ni, const tinygltf::Node& n) {
    const auto ext = n.extensions.find("EXT_mesh_gpu_instancing");
    if (ext == n.extensions.end()) return {glm::mat4(1.0f)};
    const std::string where = "node " + std::to_string(ni) + " EXT_mesh_gpu_instancing";
    if (!ext->second.Has("attributes") || !ext->second.Get("attributes").IsObject()) fail(where, "has no attributes");
    const tinygltf::Value& attributes = ext->second.Get("attributes");
    std::optional<View> translation, rotation, scale;
    std::size_t count = 0;
    bool counted = false;
    const auto read = [&](const char* name, int type, const std::vector<int>& componentTypes,
                          std::optional<View>& out) {
        if (!attributes.Has(name)) return;
        out = view(attributes.Get(name).GetNumberAsInt(), where + " " + name, {type}, componentTypes);
        if (counted && out->count != count) fail(where, std::string(name) + " counts differ from the other attributes");
        count = out->count;
        counted = true;
    };
    read("TRANSLATION", TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT}, translation);
    read("ROTATION", TINYGLTF_TYPE_VEC4,
         {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT}, rotation);
    read("SCALE", TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT}, scale);
    if (!counted) fail(where, "has none of TRANSLATION, ROTATION and SCALE");
    if (count == 0) fail(where, "has no instances");
    if (std::size_t(info_.nodes) + count > std::size_t(kMaxNodeInstances))
        fail(where, "more than " + std::to_string(kMaxNodeInstances) + " instances in the scene");
    info_.nodes += int(count) - 1;  // the node itself is already counted
    std::vector<glm::mat4> out(count, glm::mat4(1.0f));
    for (std::size_t i = 0; i < count; ++i) {
        glm::mat4& m = out[i];
        if (translation)
            m = glm::translate(
                m, glm::vec3(scalarAt(*translation, i, 0), scalarAt(*translation, i, 1), scalarAt(*translation, i, 2)));
        if (rotation)  // x, y, z, w as in a node's rotation
            m *= glm::mat4_cast(glm::normalize(glm::quat(scalarAt(*rotation, i, 3), scalarAt(*rotation, i, 0),
                                                         scalarAt(*rotation, i, 1), scalarAt(*rotation, i, 2))));
        if (scale) m = glm::scale(m, glm::vec3(scalarAt(*scale, i, 0), scalarAt(*scale, i, 1), scalarAt(*scale, i, 2)));
    }
    return out;
}

// A glTF camera looks down its node's -Z with +Y up (glTF 2.0, 3.10.1); only the first node using it counts.
void GltfReader::addCamera(int ci, const glm::mat4& world) {
    if (std::find(cameraIndices_.begin(), cameraIndices_.end(), ci) != cameraIndices_.end()) return;
    const tinygltf::Camera& c = model_.cameras[std::size_t(ci)];
    GltfCamera cam;
    cam.name = c.name.empty() ? "camera " + std::to_string(ci) : c.name;
    cam.perspective = c.type != "orthographic";
    cam.eye = glm::vec3(world[3]);
    const glm::vec3 forward =
        safeNormalize(glm::mat3(world) * glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 0.0f, -1.0f));
    cam.target = cam.eye + forward;  // moved onto the model once its bounds are known (read())
    cam.up = safeNormalize(glm::mat3(world) * glm::vec3(0.0f, 1.0f, 0.0f));
    if (cam.perspective) {
        cam.yfovDeg = float(glm::degrees(c.perspective.yfov));
        cam.znear = float(c.perspective.znear);
        cam.zfar = float(c.perspective.zfar);
    }
    cameraIndices_.push_back(ci);
    info_.cameras.push_back(cam);
}

// A node's KHR_lights_punctual light: at the node's origin, pointing down its -Z (glTF 2.0's
// convention for lights and cameras). Values the extension forbids are refused; a light past
// kMaxLights is left out with a warning.
void GltfReader::addLight(const tinygltf::Node& n, int ni, const glm::mat4& world) {
    const auto ext = n.extensions.find("KHR_lights_punctual");
    if (ext == n.extensions.end() || !ext->second.Has("light")) return;
    const std::string where = "node " + std::to_string(ni) + " KHR_lights_punctual";
    const tinygltf::Value& index = ext->second.Get("light");
    if (!index.IsInt() || index.GetNumberAsInt() < 0 || std::size_t(index.GetNumberAsInt()) >= model_.lights.size())
        fail(where, "light " + std::to_string(index.IsNumber() ? index.GetNumberAsInt() : -1) + " does not exist");
    const tinygltf::Light& src = model_.lights[std::size_t(index.GetNumberAsInt())];
    const std::string name = "light " + std::to_string(index.GetNumberAsInt());
    if (info_.lights.size() >= std::size_t(kMaxLights)) {
        if (lightsLeftOut_++ == 0)
            info_.warnings.push_back("more than " + std::to_string(kMaxLights) + " lights: only the first " +
                                     std::to_string(kMaxLights) + " the scene reaches are drawn");
        return;
    }
    GltfLight out;
    out.name = src.name.empty() ? name : src.name;
    Light& l = out.light;
    const std::optional<LightType> type = valueNamed(kPunctualLightTypeNames, src.type);
    if (!type) fail(name, "type \"" + src.type + "\" is not " + namesList(kPunctualLightTypeNames, ", ", " or "));
    l.type = *type;
    if (!std::isfinite(src.intensity) || src.intensity < 0.0) fail(name, "intensity must be a finite number >= 0");
    l.intensity = float(src.intensity);
    if (src.color.size() >= 3) {
        const glm::vec3 c(float(src.color[0]), float(src.color[1]), float(src.color[2]));
        if (!isFinite(c)) fail(name, "color is not finite");
        l.color = glm::clamp(c, 0.0f, 1.0f);
    } else {
        l.color = glm::vec3(1.0f);
    }
    l.position = glm::vec3(world[3]);
    l.direction = safeNormalize(glm::mat3(world) * glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 0.0f, -1.0f));
    if (l.type != LightType::Directional) {
        // Physical point lights fall off with 1/r^2, windowed to zero at the range when there is one
        // (the extension's recommendation, shadelab's "range").
        l.attenuation = Attenuation::InverseSquare;
        l.range = std::isfinite(src.range) && src.range > 0.0 ? float(src.range) : 0.0f;
    }
    if (l.type == LightType::Spot) {
        const double inner = src.spot.innerConeAngle, outer = src.spot.outerConeAngle;
        if (!std::isfinite(inner) || !std::isfinite(outer) || inner < 0.0 || outer <= inner ||
            outer > 1.5707963268 + 1e-6)
            fail(name, "spot cone angles must satisfy 0 <= innerConeAngle < outerConeAngle <= pi/2");
        l.outerConeDeg = std::clamp(float(glm::degrees(outer)), float(kSpotOuterConeDegRange.lo), kSpotConeDegRange.hi);
        l.innerConeDeg = std::clamp(float(glm::degrees(inner)), 0.0f, std::max(l.outerConeDeg - 0.01f, 0.0f));
    }
    info_.lights.push_back(std::move(out));
}

}  // namespace gltf_import_parts

std::string describe(const std::string& path, const GltfInfo& i) {
    auto vec = [](const glm::vec3& v) {
        char b[96];
        std::snprintf(b, sizeof b, "[%g, %g, %g]", double(v.x), double(v.y), double(v.z));
        return std::string(b);
    };
    std::string s;
    s += "model: " + path + "\n";
    s += "nodes: " + std::to_string(i.nodes) + " (in the drawn scene)\n";
    s += "meshes: " + std::to_string(i.meshes) + "\n";
    s += "materials: " + std::to_string(i.materials) + "\n";
    if (i.doubleSidedMaterials > 0)
        s += "double-sided materials: " + std::to_string(i.doubleSidedMaterials) +
             " (both sides drawn, the back lit with its normal flipped)\n";
    s += "textures: " + std::to_string(i.textures) + " base colour image" + (i.textures == 1 ? "" : "s") + " drawn\n";
    s += "primitives: " + std::to_string(i.primitives) + " drawn\n";
    s += "triangles: " + std::to_string(i.fileTriangles) + " in the file's TRIANGLES primitives, " +
         std::to_string(i.triangles) + " drawn\n";
    s += "vertices: " + std::to_string(i.vertices) + "\n";
    s += "bounds: min " + vec(i.boundsMin) + " max " + vec(i.boundsMax) + "\n";
    for (std::size_t c = 0; c < i.cameras.size(); ++c)
        s += "camera " + std::to_string(c) + ": " + i.cameras[c].name +
             (i.cameras[c].perspective
                  ? ", perspective, " + std::to_string(int(std::lround(i.cameras[c].yfovDeg))) + " degrees"
                  : std::string(", orthographic (not drawn: shadelab's views are perspective)")) +
             " (--camera " + std::to_string(c) + ")\n";
    for (std::size_t l = 0; l < i.lights.size(); ++l) {
        const Light& light = i.lights[l].light;
        char b[160];
        std::snprintf(b, sizeof b, "light %zu: %s, %s, %g %s", l, i.lights[l].name.c_str(), toString(light.type),
                      double(light.intensity), light.type == LightType::Directional ? "lux" : "cd");
        s += std::string(b) +
             (light.type == LightType::Directional ? " toward " + vec(light.direction) : " at " + vec(light.position)) +
             " (lights the scene when it gives no lights)\n";
    }
    s += "normals: " +
         (i.generatedNormals ? "generated for " + std::to_string(i.generatedNormals) + " vertices"
                             : std::string("from the file")) +
         "\n";
    for (const std::string& w : i.warnings) s += "warning: " + w + "\n";
    return s;
}

}  // namespace shadelab
