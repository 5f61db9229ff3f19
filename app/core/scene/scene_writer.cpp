// Writing scene files: a Scene to JSON with every field, so that reading it back gives the same image
// (scene_json.hpp). The reader is scene_reader.cpp.
#include "core/scene/scene_json.hpp"

#include "core/scene/parameters.hpp"
#include "core/scene/scene_names.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>

namespace shadelab {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

json vecJson(const glm::vec3& v) { return json::array({v.x, v.y, v.z}); }

// A file the scene names, written relative to the directory the scene is saved in (as given where that fails).
std::string relativeTo(const std::string& resolvedPath, const std::string& saveDir) {
    std::error_code ec;
    fs::path abs = fs::absolute(resolvedPath, ec);
    fs::path rel = ec ? fs::path() : abs.lexically_relative(fs::absolute(saveDir.empty() ? "." : saveDir, ec));
    return (ec || rel.empty()) ? resolvedPath : rel.generic_string();
}

nlohmann::ordered_json meshJson(const MeshSpec& m, const std::string& saveDir) {
    nlohmann::ordered_json j;
    j["type"] = toString(m.type);
    switch (m.type) {
    case MeshSpec::Type::UvSphere:
        j["slices"] = m.slices;
        j["stacks"] = m.stacks;
        j["radius"] = m.radius;
        break;
    case MeshSpec::Type::IcoSphere:
        j["subdivisions"] = m.subdivisions;
        j["radius"] = m.radius;
        break;
    case MeshSpec::Type::Torus:
        j["major_radius"] = m.majorRadius;
        j["minor_radius"] = m.minorRadius;
        j["major_segments"] = m.majorSegments;
        j["minor_segments"] = m.minorSegments;
        break;
    case MeshSpec::Type::Cube: j["size"] = m.size; break;
    case MeshSpec::Type::Plane:
        j["size"] = m.size;
        j["subdivisions"] = m.planeSubdivisions;
        break;
    case MeshSpec::Type::Gltf: j["path"] = relativeTo(m.resolvedPath, saveDir); break;
    }
    return j;
}

// `reflection`: anisotropy is written under blinn-phong only, where it applies (the reader refuses it under phong).
nlohmann::ordered_json materialJson(const Material& m, const MeshSpec& mesh, ReflectionModel reflection) {
    nlohmann::ordered_json j;
    // A glTF model's own colours stay unless a colour was chosen: write it only then.
    if (m.colorSet || mesh.type != MeshSpec::Type::Gltf) j["color"] = vecJson(m.color);
    j["specular_color"] = vecJson(m.specularColor);
    for (Param p : {Param::Ka, Param::Kd, Param::Ks, Param::Ke}) j[parameter(p).name] = materialValue(parameter(p), m);
    if (m.anisotropic && reflection == ReflectionModel::BlinnPhong) j["anisotropy"] = {m.anisotropy.x, m.anisotropy.y};
    if (m.mirror > 0.0f) j["mirror"] = m.mirror;
    if (m.transmission > 0.0f) j["transmission"] = m.transmission;
    return j;
}

bool isIdentity(const Transform& t) {
    return t.translation == glm::vec3(0.0f) && t.rotationDeg == glm::vec3(0.0f) && t.scale == glm::vec3(1.0f);
}

// A light's fields, those of its type only.
nlohmann::ordered_json lightJson(const Light& l) {
    nlohmann::ordered_json lj;
    lj["type"] = toString(l.type);
    if (l.type == LightType::Directional) {
        lj["direction"] = vecJson(l.direction);
    } else {
        lj["position"] = vecJson(l.position);
    }
    if (l.type == LightType::Spot) {
        lj["direction"] = vecJson(l.direction);
        lj["inner_cone_deg"] = l.innerConeDeg;
        lj["outer_cone_deg"] = l.outerConeDeg;
    }
    if (l.type == LightType::Area) {
        lj["normal"] = vecJson(l.normal);
        lj["size"] = {l.size.x, l.size.y};
        lj["samples"] = {l.samples.x, l.samples.y};
        lj["two_sided"] = l.twoSided;
    }
    lj["color"] = vecJson(l.color);
    lj["intensity"] = l.intensity;
    if (l.type != LightType::Directional) {
        lj["attenuation"] = toString(l.attenuation);
        if (l.attenuation == Attenuation::InverseSquare && l.range > 0.0f) lj["range"] = l.range;
    }
    return lj;
}

// "test": the thresholds and masks that were set.
json testJson(const TestSettings& test) {
    json t = json::object();
    if (test.maxDiff) t["max_diff"] = *test.maxDiff;
    if (test.meanDiff) t["mean_diff"] = *test.meanDiff;
    if (test.maxDiffPixels) t["max_diff_pixels"] = *test.maxDiffPixels;
    if (!test.masks.empty()) {
        t["masks"] = json::array();
        for (const glm::ivec4& r : test.masks) t["masks"].push_back({r.x, r.y, r.z, r.w});
    }
    return t;
}

}  // namespace

std::string sceneToJson(const Scene& s, const std::string& saveDir) {
    nlohmann::ordered_json j;
    const bool shorthand = !s.usesObjectList && s.objects.size() == 1 && isIdentity(s.objects[0].transform);
    if (shorthand) {
        j["mesh"] = meshJson(s.objects[0].mesh, saveDir);
        j["material"] = materialJson(s.objects[0].material, s.objects[0].mesh, s.reflection);
    } else {
        j["objects"] = nlohmann::ordered_json::array();
        for (const SceneObject& o : s.objects) {
            nlohmann::ordered_json oj;
            oj["mesh"] = meshJson(o.mesh, saveDir);
            oj["material"] = materialJson(o.material, o.mesh, s.reflection);
            oj["transform"] = {{"translation", vecJson(o.transform.translation)},
                               {"rotation_deg", vecJson(o.transform.rotationDeg)},
                               {"scale", vecJson(o.transform.scale)}};
            j["objects"].push_back(oj);
        }
    }
    j["shading"] = toString(s.shading);
    j["layout"] = toString(s.layout);
    j["reflection"] = toString(s.reflection);
    j["ambient"] = vecJson(s.ambient);
    j["lights"] = nlohmann::ordered_json::array();
    for (const Light& l : s.lights) j["lights"].push_back(lightJson(l));
    j["shadows"] = s.shadows.enabled;
    if (!s.textures) j["textures"] = false;
    j["shadow_settings"] = {{"normal_bias", s.shadows.normalBias},
                            {"depth_bias", s.shadows.depthBias},
                            {"pcf", s.shadows.pcf},
                            {"map_size", s.shadows.mapSize},
                            {"area_map_size", s.shadows.areaMapSize}};
    j["camera"] = {{"eye", vecJson(s.camera.eye)},  {"target", vecJson(s.camera.target)}, {"up", vecJson(s.camera.up)},
                   {"fov_y_deg", s.camera.fovYDeg}, {"near", s.camera.nearPlane},         {"far", s.camera.farPlane}};
    j["background"] = vecJson(s.background);
    j["size"] = {s.width, s.height};
    j["output_encoding"] = toString(s.outputEncoding);
    j["specular_normalization"] = toString(s.specularNormalization);
    j["fresnel"] = toString(s.fresnel);
    j["ior"] = s.ior;
    if (s.environment.kind == EnvironmentKind::Image)
        j["environment"] = relativeTo(s.environment.resolvedPath, saveDir);
    else if (s.environment.kind != EnvironmentKind::None) j["environment"] = toString(s.environment.kind);
    j["show"] = toString(s.show);
    j["diff"] = {{"a", toString(s.diff.a)}, {"b", toString(s.diff.b)}, {"factor", s.diff.factor}};
    if (!s.title.empty()) j["title"] = s.title;
    if (!s.caption.empty()) j["caption"] = s.caption;
    if (!s.test.empty()) j["test"] = testJson(s.test);
    if (!s.viewer.empty()) {
        json v = json::object();
        if (s.viewer.probe) {  // in pixels of the size written (the viewer saves at its view's)
            const glm::ivec2 p = s.viewer.probeIn(s.width, s.height);
            v["probe"] = {p.x, p.y};
        }
        if (s.viewer.intersection) v["intersection"] = true;
        if (s.viewer.panelSections) v["panel_sections"] = *s.viewer.panelSections;
        if (!s.viewer.plot.empty()) v["plot"] = s.viewer.plot;
        j["viewer"] = v;
    }
    return j.dump(2) + "\n";
}

}  // namespace shadelab
