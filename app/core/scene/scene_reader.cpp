// Reading scene files: JSON text to a Scene, every field checked and named by its path in messages
// (scene_json.hpp). The writer is scene_writer.cpp; the checks shared with the command line are scene_checks.cpp.
#include "core/scene/scene_json.hpp"

#include "core/base/embedded.hpp"
#include "core/base/error.hpp"
#include "core/base/file_io.hpp"
#include "core/base/json_depth.hpp"
#include "core/base/message.hpp"
#include "core/scene/panel_sections.hpp"
#include "core/scene/parameters.hpp"
#include "core/scene/scene_names.hpp"

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <initializer_list>

namespace shadelab {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

// Walks a parsed document and turns it into a Scene, naming fields by their path ("lights[0].color").
class SceneReader {
public:
    SceneReader(std::string file, std::string baseDir) : file_(std::move(file)), baseDir_(std::move(baseDir)) {}

    Scene read(const json& root);
    // One light or mesh, on its own (lightFromJson, meshFromJson); `path` names it in messages.
    Light light(const json& j, const std::string& path) const;
    MeshSpec mesh(const json& j, const std::string& path) const;

private:
    [[noreturn]] void fail(const std::string& path, const std::string& what) const {
        throw InputError(file_ + ": " + (path.empty() ? std::string() : path + ": ") + what);
    }
    static std::string join(const std::string& path, const std::string& key) {
        return path.empty() ? key : path + "." + key;
    }
    static const char* typeName(const json& j) {
        if (j.is_boolean()) return "a boolean";
        if (j.is_number()) return "a number";
        if (j.is_string()) return "a string";
        if (j.is_array()) return "an array";
        if (j.is_object()) return "an object";
        return "null";
    }

    void requireObject(const json& j, const std::string& path, std::initializer_list<const char*> allowed) const {
        if (!j.is_object()) fail(path, std::string("expected an object, got ") + typeName(j));
        for (auto it = j.begin(); it != j.end(); ++it) {
            bool known = false;
            for (const char* a : allowed) known = known || it.key() == a;
            if (!known) fail(join(path, quoteInput(it.key())), "unknown field");
        }
    }

    double number(const json& j, const std::string& path, double lo, double hi) const {
        if (!j.is_number()) fail(path, std::string("expected a number, got ") + typeName(j));
        double v = j.get<double>();
        if (!std::isfinite(v)) fail(path, "must be a finite number");
        if (v < lo) fail(path, "must be >= " + formatNumber(lo) + " (got " + formatNumber(v) + ")");
        if (v > hi) fail(path, "must be <= " + formatNumber(hi) + " (got " + formatNumber(v) + ")");
        return v;
    }
    void number(const json& o, const char* key, const std::string& path, float& out, double lo, double hi) const {
        if (o.contains(key)) out = static_cast<float>(number(o[key], join(path, key), lo, hi));
    }
    void integer(const json& o, const char* key, const std::string& path, int& out, int lo, int hi) const {
        if (o.contains(key)) out = integer(o[key], join(path, key), lo, hi);
    }
    int integer(const json& j, const std::string& p, int lo, int hi) const {
        if (!j.is_number_integer()) fail(p, std::string("expected an integer, got ") + typeName(j));
        // nlohmann stores non-negative integers as unsigned: compare in the type it holds.
        const bool tooBig = j.is_number_unsigned() ? j.get<unsigned long long>() > static_cast<unsigned long long>(hi)
                                                   : j.get<long long>() > hi;
        const bool tooSmall = j.is_number_unsigned() ? j.get<unsigned long long>() < static_cast<unsigned long long>(lo)
                                                     : j.get<long long>() < lo;
        if (tooBig) fail(p, "must be <= " + std::to_string(hi) + " (got " + j.dump() + ")");
        if (tooSmall) fail(p, "must be >= " + std::to_string(lo) + " (got " + j.dump() + ")");
        return j.get<int>();
    }
    glm::vec3 vec3(const json& j, const std::string& path, double lo, double hi) const {
        if (!j.is_array() || j.size() != 3) fail(path, "expected an array of 3 numbers");
        glm::vec3 v;
        for (int i = 0; i < 3; ++i)
            v[i] = static_cast<float>(number(j[static_cast<size_t>(i)], path + "[" + std::to_string(i) + "]", lo, hi));
        return v;
    }
    void vec3(const json& o, const char* key, const std::string& path, glm::vec3& out, double lo, double hi) const {
        if (o.contains(key)) out = vec3(o[key], join(path, key), lo, hi);
    }
    void boolean(const json& o, const char* key, const std::string& path, bool& out) const {
        if (!o.contains(key)) return;
        if (!o[key].is_boolean()) fail(join(path, key), std::string("expected true or false, got ") + typeName(o[key]));
        out = o[key].get<bool>();
    }
    // [x, y] of numbers in [lo, hi]
    void vec2(const json& o, const char* key, const std::string& path, glm::vec2& out, double lo, double hi) const {
        if (!o.contains(key)) return;
        const json& j = o[key];
        const std::string p = join(path, key);
        if (!j.is_array() || j.size() != 2) fail(p, "expected an array of 2 numbers");
        for (int i = 0; i < 2; ++i)
            out[i] = static_cast<float>(number(j[static_cast<size_t>(i)], p + "[" + std::to_string(i) + "]", lo, hi));
    }
    // A parameter of the table (core/scene/parameters.hpp), by its name and in its range.
    void value(const json& o, const std::string& path, Param id, float& out) const {
        const Parameter& p = parameter(id);
        number(o, p.name, path, out, p.range.lo, p.range.hi);
    }
    void value(const json& o, const std::string& path, Param id, int& out) const {
        const Parameter& p = parameter(id);
        integer(o, p.name, path, out, int(p.range.lo), int(p.range.hi));
    }
    void value(const json& o, const std::string& path, Param id, glm::vec2& out) const {
        const Parameter& p = parameter(id);
        vec2(o, p.name, path, out, p.range.lo, p.range.hi);
    }
    void value(const json& o, const std::string& path, Param id, glm::vec3& out) const {
        const Parameter& p = parameter(id);
        vec3(o, p.name, path, out, p.range.lo, p.range.hi);
    }
    // [x, y] of integers in [lo, hi]
    void ivec2(const json& o, const char* key, const std::string& path, glm::ivec2& out, int lo, int hi) const {
        if (!o.contains(key)) return;
        const json& j = o[key];
        const std::string p = join(path, key);
        if (!j.is_array() || j.size() != 2) fail(p, "expected an array of 2 integers");
        for (int i = 0; i < 2; ++i)
            out[i] = integer(j[static_cast<size_t>(i)], p + "[" + std::to_string(i) + "]", lo, hi);
    }
    // A short single-line text (titles, captions): at most 500 characters, no control characters.
    void text(const json& o, const char* key, std::string& out) const {
        if (!o.contains(key)) return;
        if (!o[key].is_string()) fail(key, std::string("expected a string, got ") + typeName(o[key]));
        const std::string t = o[key].get<std::string>();
        if (t.size() > 500) fail(key, "at most 500 characters (got " + std::to_string(t.size()) + ")");
        for (char c : t)
            if (static_cast<unsigned char>(c) < 0x20) fail(key, "must be one line without control characters");
        out = t;
    }
    void nonZero(const glm::vec3& v, const std::string& path) const {
        if (glm::length(v) < 1e-6f) fail(path, "must not be a zero-length vector");
    }
    template <typename E, size_t N>
    void choice(const json& o, const char* key, const std::string& path, E& out,
                const std::pair<const char*, E> (&options)[N]) const {
        if (!o.contains(key)) return;
        const json& j = o[key];
        const std::string p = join(path, key);
        std::string allowed;
        for (const auto& opt : options) allowed += std::string(allowed.empty() ? "" : ", ") + "\"" + opt.first + "\"";
        if (!j.is_string()) fail(p, "expected one of " + allowed + ", got " + typeName(j));
        for (const auto& opt : options)
            if (j.get<std::string>() == opt.first) {
                out = opt.second;
                return;
            }
        fail(p, "unknown value \"" + quoteInput(j.get<std::string>()) + "\" (expected one of " + allowed + ")");
    }

    Material material(const json& j, const std::string& path) const;
    Transform transform(const json& j, const std::string& path) const;
    ShadowSettings shadowSettings(const json& j, const std::string& path) const;
    Camera camera(const json& j, const std::string& path) const;
    void readObjects(const json& root, Scene& scene) const;
    DiffSettings diff(const json& j, const std::string& path) const;
    std::vector<Light> lights(const json& j, const std::string& path) const;
    TermView show(const json& j, const std::string& path, std::size_t lightCount) const;
    glm::ivec2 imageSize(const json& j, const std::string& path) const;
    TestSettings testSettings(const json& j, const std::string& path) const;
    ViewerStart viewerStart(const json& j, const std::string& path, glm::ivec2 size) const;
    std::string oneOf(const std::string& name, const std::vector<std::string>& names, const std::string& path,
                      const char* what) const;

    std::string file_;
    std::string baseDir_;
};

MeshSpec SceneReader::mesh(const json& j, const std::string& path) const {
    MeshSpec m;
    if (!j.is_object()) fail(path, std::string("expected an object, got ") + typeName(j));
    choice(j, "type", path, m.type, kMeshTypeNames);
    switch (m.type) {
    case MeshSpec::Type::UvSphere:
        requireObject(j, path, {"type", "slices", "stacks", "radius"});
        value(j, path, Param::UvSphereSlices, m.slices);
        value(j, path, Param::UvSphereStacks, m.stacks);
        number(j, "radius", path, m.radius, kSizeRange.lo, kSizeRange.hi);
        break;
    case MeshSpec::Type::IcoSphere:
        requireObject(j, path, {"type", "subdivisions", "radius"});
        value(j, path, Param::IcoSphereSubdivisions, m.subdivisions);
        number(j, "radius", path, m.radius, kSizeRange.lo, kSizeRange.hi);
        break;
    case MeshSpec::Type::Torus:
        requireObject(j, path, {"type", "major_radius", "minor_radius", "major_segments", "minor_segments"});
        number(j, "major_radius", path, m.majorRadius, kSizeRange.lo, kSizeRange.hi);
        number(j, "minor_radius", path, m.minorRadius, kSizeRange.lo, kSizeRange.hi);
        value(j, path, Param::TorusMajorSegments, m.majorSegments);
        value(j, path, Param::TorusMinorSegments, m.minorSegments);
        break;
    case MeshSpec::Type::Cube:
        requireObject(j, path, {"type", "size"});
        number(j, "size", path, m.size, kSizeRange.lo, kSizeRange.hi);
        break;
    case MeshSpec::Type::Plane:
        requireObject(j, path, {"type", "size", "subdivisions"});
        number(j, "size", path, m.size, kSizeRange.lo, kSizeRange.hi);
        value(j, path, Param::PlaneSubdivisions, m.planeSubdivisions);
        break;
    case MeshSpec::Type::Gltf: {
        requireObject(j, path, {"type", "path"});
        if (!j.contains("path")) fail(join(path, "path"), "a gltf mesh needs a path");
        if (!j["path"].is_string() || j["path"].get<std::string>().empty())
            fail(join(path, "path"), "expected a non-empty string");
        m.path = j["path"].get<std::string>();
        fs::path p(m.path);
        m.resolvedPath = (p.is_absolute() ? p : fs::path(baseDir_) / p).lexically_normal().string();
        break;
    }
    }
    return m;
}

Material SceneReader::material(const json& j, const std::string& path) const {
    Material m;
    requireObject(j, path, {"color", "specular_color", "ka", "kd", "ks", "ke", "anisotropy", "mirror", "transmission"});
    value(j, path, Param::Color, m.color);
    m.colorSet = j.contains(parameter(Param::Color).name);
    value(j, path, Param::SpecularColor, m.specularColor);
    value(j, path, Param::Ka, m.ka);
    value(j, path, Param::Kd, m.kd);
    value(j, path, Param::Ks, m.ks);
    value(j, path, Param::Ke, m.ke);
    m.anisotropic = j.contains(parameter(Param::Anisotropy).name);
    value(j, path, Param::Anisotropy, m.anisotropy);
    value(j, path, Param::Mirror, m.mirror);
    value(j, path, Param::Transmission, m.transmission);
    return m;
}

Transform SceneReader::transform(const json& j, const std::string& path) const {
    Transform t;
    requireObject(j, path, {"translation", "rotation_deg", "scale"});
    vec3(j, "translation", path, t.translation, kCoordinateRange.lo, kCoordinateRange.hi);
    vec3(j, "rotation_deg", path, t.rotationDeg, kCoordinateRange.lo, kCoordinateRange.hi);
    vec3(j, "scale", path, t.scale, kCoordinateRange.lo, kCoordinateRange.hi);
    for (int i = 0; i < 3; ++i)
        if (std::fabs(t.scale[i]) < 1e-6f) fail(join(path, "scale"), "components must not be 0");
    return t;
}

Light SceneReader::light(const json& j, const std::string& path) const {
    Light l;
    if (!j.is_object()) fail(path, std::string("expected an object, got ") + typeName(j));
    choice(j, "type", path, l.type, kLightTypeNames);
    switch (l.type) {
    case LightType::Point:
        requireObject(j, path, {"type", "position", "color", "intensity", "attenuation", "range"});
        vec3(j, "position", path, l.position, kCoordinateRange.lo, kCoordinateRange.hi);
        break;
    case LightType::Directional:
        requireObject(j, path, {"type", "direction", "color", "intensity"});
        vec3(j, "direction", path, l.direction, kCoordinateRange.lo, kCoordinateRange.hi);
        nonZero(l.direction, join(path, "direction"));
        break;
    case LightType::Area:
        requireObject(j, path,
                      {"type", "position", "normal", "size", "samples", "color", "intensity", "two_sided",
                       "attenuation", "range"});
        vec3(j, "position", path, l.position, kCoordinateRange.lo, kCoordinateRange.hi);
        vec3(j, "normal", path, l.normal, kCoordinateRange.lo, kCoordinateRange.hi);
        nonZero(l.normal, join(path, "normal"));
        vec2(j, "size", path, l.size, kSizeRange.lo, kSizeRange.hi);
        ivec2(j, "samples", path, l.samples, 1, kAreaSamplesPerSideRange.hi);
        boolean(j, "two_sided", path, l.twoSided);
        break;
    case LightType::Spot:
        requireObject(j, path,
                      {"type", "position", "direction", "inner_cone_deg", "outer_cone_deg", "color", "intensity",
                       "attenuation", "range"});
        vec3(j, "position", path, l.position, kCoordinateRange.lo, kCoordinateRange.hi);
        vec3(j, "direction", path, l.direction, kCoordinateRange.lo, kCoordinateRange.hi);
        nonZero(l.direction, join(path, "direction"));
        value(j, path, Param::OuterCone, l.outerConeDeg);
        value(j, path, Param::InnerCone, l.innerConeDeg);
        if (!j.contains("inner_cone_deg")) l.innerConeDeg = 0.5f * l.outerConeDeg;
        if (l.innerConeDeg >= l.outerConeDeg)
            fail(join(path, "inner_cone_deg"),
                 "must be less than outer_cone_deg (" + std::to_string(l.outerConeDeg) + ")");
        break;
    }
    if (l.type != LightType::Directional) {
        choice(j, "attenuation", path, l.attenuation, kAttenuationNames);
        number(j, "range", path, l.range, kLightRangeRange.lo, kLightRangeRange.hi);
        if (j.contains("range") && l.attenuation != Attenuation::InverseSquare)
            fail(join(path, "range"), "a range needs \"attenuation\": \"inverse-square\"");
    }
    vec3(j, "color", path, l.color, 0.0, 1.0);
    value(j, path, Param::Intensity, l.intensity);
    return l;
}

ShadowSettings SceneReader::shadowSettings(const json& j, const std::string& path) const {
    ShadowSettings s;
    requireObject(j, path, {"normal_bias", "depth_bias", "pcf", "map_size", "area_map_size"});
    value(j, path, Param::NormalBias, s.normalBias);
    value(j, path, Param::DepthBias, s.depthBias);
    value(j, path, Param::Pcf, s.pcf);
    integer(j, "map_size", path, s.mapSize, kShadowMapSizeRange.lo, kShadowMapSizeRange.hi);
    integer(j, "area_map_size", path, s.areaMapSize, kShadowMapSizeRange.lo, kShadowMapSizeRange.hi);
    return s;
}

Camera SceneReader::camera(const json& j, const std::string& path) const {
    Camera c;
    requireObject(j, path, {"eye", "target", "up", "fov_y_deg", "near", "far"});
    vec3(j, "eye", path, c.eye, kCoordinateRange.lo, kCoordinateRange.hi);
    vec3(j, "target", path, c.target, kCoordinateRange.lo, kCoordinateRange.hi);
    vec3(j, "up", path, c.up, kCoordinateRange.lo, kCoordinateRange.hi);
    value(j, path, Param::FovY, c.fovYDeg);
    number(j, "near", path, c.nearPlane, 1e-6, 1e6);
    number(j, "far", path, c.farPlane, 1e-6, 1e7);
    if (c.farPlane <= c.nearPlane) fail(join(path, "far"), "must be greater than near");
    const glm::vec3 forward = c.target - c.eye;
    if (glm::length(forward) < 1e-6f) fail(join(path, "target"), "must differ from eye");
    nonZero(c.up, join(path, "up"));
    if (glm::length(glm::cross(glm::normalize(forward), glm::normalize(c.up))) < 1e-4f)
        fail(join(path, "up"), "must not be parallel to the viewing direction (target - eye)");
    return c;
}

// The fields in the order their checks depend on: "show" names a light, so it comes after "lights".
Scene SceneReader::read(const json& root) {
    Scene s;
    requireObject(root, "",
                  {"mesh",
                   "material",
                   "objects",
                   "shading",
                   "layout",
                   "reflection",
                   "ambient",
                   "lights",
                   "shadows",
                   "shadow_settings",
                   "camera",
                   "background",
                   "size",
                   "output_encoding",
                   "specular_normalization",
                   "fresnel",
                   "ior",
                   "show",
                   "diff",
                   "title",
                   "caption",
                   "textures",
                   "test",
                   "environment",
                   "viewer"});
    readObjects(root, s);
    choice(root, "shading", "", s.shading, kShadingModeNames);
    choice(root, "layout", "", s.layout, kLayoutNames);
    if (root.contains("diff")) s.diff = diff(root["diff"], "diff");
    choice(root, "specular_normalization", "", s.specularNormalization, kSpecularNormalizationNames);
    choice(root, "fresnel", "", s.fresnel, kFresnelModeNames);
    value(root, "", Param::Ior, s.ior);
    if (root.contains("environment")) {
        if (!root["environment"].is_string())
            fail("environment", std::string("expected a string, got ") + typeName(root["environment"]));
        s.environment = parseEnvironment(root["environment"].get<std::string>(), baseDir_, file_ + ": environment");
    }
    text(root, "title", s.title);
    text(root, "caption", s.caption);
    choice(root, "reflection", "", s.reflection, kReflectionModelNames);
    for (const SceneObject& o : s.objects)
        if (o.material.anisotropic && s.reflection == ReflectionModel::Phong)
            fail("reflection",
                 "phong cannot go with a material's \"anisotropy\": Ashikhmin and Shirley's lobe is "
                 "Blinn-Phong's (about H)");
    choice(root, "output_encoding", "", s.outputEncoding, kOutputEncodingNames);
    s.outputEncodingGiven = root.contains("output_encoding");
    value(root, "", Param::Ambient, s.ambient);
    value(root, "", Param::Background, s.background);
    if (root.contains("lights")) {
        s.lights = lights(root["lights"], "lights");
        s.lightsGiven = true;
    }
    if (root.contains("show")) s.show = show(root["show"], "show", s.lights.size());
    if (root.contains("shadow_settings")) s.shadows = shadowSettings(root["shadow_settings"], "shadow_settings");
    boolean(root, "shadows", "", s.shadows.enabled);
    boolean(root, "textures", "", s.textures);
    if (root.contains("camera")) {
        s.camera = camera(root["camera"], "camera");
        s.cameraGiven = true;
    }
    if (root.contains("size")) {
        const glm::ivec2 size = imageSize(root["size"], "size");
        s.width = size.x;
        s.height = size.y;
    }
    if (root.contains("test")) s.test = testSettings(root["test"], "test");
    if (root.contains("viewer")) s.viewer = viewerStart(root["viewer"], "viewer", glm::ivec2(s.width, s.height));
    return s;
}

// `name` if it is one of `names`, else an error naming the field and every choice.
std::string SceneReader::oneOf(const std::string& name, const std::vector<std::string>& names, const std::string& path,
                               const char* what) const {
    std::string allowed;
    for (const std::string& n : names) allowed += (allowed.empty() ? "" : ", ") + n;
    if (std::find(names.begin(), names.end(), name) == names.end())
        fail(path, "unknown " + std::string(what) + " \"" + name + "\" (one of " + allowed + ")");
    return name;
}

ViewerStart SceneReader::viewerStart(const json& j, const std::string& path, glm::ivec2 size) const {
    ViewerStart v;
    requireObject(j, path, {"probe", "intersection", "panel_sections", "plot"});
    if (j.contains("probe")) {
        const json& p = j["probe"];
        const std::string at = join(path, "probe");
        if (!p.is_array() || p.size() != 2) fail(at, "expected [x, y], a pixel of the scene's size");
        v.probe = glm::ivec2(integer(p[0], at + "[0]", 0, size.x - 1), integer(p[1], at + "[1]", 0, size.y - 1));
        v.probeOf = size;
    }
    boolean(j, "intersection", path, v.intersection);
    if (v.intersection && !v.probe)
        fail(join(path, "intersection"), "draws the diagram at a probed point: give \"probe\"");
    if (j.contains("panel_sections")) {
        const json& list = j["panel_sections"];
        const std::string at = join(path, "panel_sections");
        if (!list.is_array()) fail(at, std::string("expected an array of section names, got ") + typeName(list));
        v.panelSections.emplace();
        std::vector<std::string> sectionNames;
        for (const auto& [n, section] : kPanelSections) sectionNames.push_back(n);
        for (std::size_t i = 0; i < list.size(); ++i) {
            const std::string item = at + "[" + std::to_string(i) + "]";
            if (!list[i].is_string()) fail(item, std::string("expected a section name, got ") + typeName(list[i]));
            const std::string name = list[i].get<std::string>();
            v.panelSections->push_back(oneOf(name, sectionNames, item, "section"));
        }
    }
    if (j.contains("plot")) {
        const std::string at = join(path, "plot");
        if (!j["plot"].is_string()) fail(at, std::string("expected a plot's name, got ") + typeName(j["plot"]));
        v.plot = oneOf(j["plot"].get<std::string>(), {std::begin(kPanelPlots), std::end(kPanelPlots)}, at, "plot");
    }
    return v;
}

TestSettings SceneReader::testSettings(const json& j, const std::string& path) const {
    TestSettings t;
    requireObject(j, path, {"max_diff", "mean_diff", "max_diff_pixels", "masks"});
    if (j.contains("max_diff"))
        t.maxDiff = integer(j["max_diff"], join(path, "max_diff"), kMaxDiffRange.lo, kMaxDiffRange.hi);
    if (j.contains("mean_diff"))
        t.meanDiff = float(number(j["mean_diff"], join(path, "mean_diff"), kMeanDiffRange.lo, kMeanDiffRange.hi));
    if (j.contains("max_diff_pixels"))
        t.maxDiffPixels = std::uint64_t(integer(j["max_diff_pixels"], join(path, "max_diff_pixels"),
                                                kMaxDiffPixelsRange.lo, kMaxDiffPixelsRange.hi));
    if (!j.contains("masks")) return t;
    const json& masks = j["masks"];
    const std::string p = join(path, "masks");
    if (!masks.is_array()) fail(p, std::string("expected an array of [x, y, w, h] rectangles, got ") + typeName(masks));
    if (masks.size() > std::size_t(kMaxTestMasks))
        fail(p, "at most " + std::to_string(kMaxTestMasks) + " rectangles (got " + std::to_string(masks.size()) + ")");
    for (std::size_t i = 0; i < masks.size(); ++i) {
        const std::string m = p + "[" + std::to_string(i) + "]";
        if (!masks[i].is_array() || masks[i].size() != 4) fail(m, "expected [x, y, w, h] in pixels (4 integers)");
        glm::ivec4 r;
        for (int k = 0; k < 4; ++k)
            r[k] =
                integer(masks[i][std::size_t(k)], m + "[" + std::to_string(k) + "]", k < 2 ? 0 : 1, kImageSideRange.hi);
        t.masks.push_back(r);
    }
    return t;
}

// "objects", or the one-object shorthand "mesh" and "material" (not both).
void SceneReader::readObjects(const json& root, Scene& s) const {
    if (!root.contains("objects")) {
        if (root.contains("mesh")) s.objects[0].mesh = mesh(root["mesh"], "mesh");
        if (root.contains("material")) s.objects[0].material = material(root["material"], "material");
        return;
    }
    if (root.contains("mesh") || root.contains("material"))
        fail("objects", "give either \"objects\" or the one-object shorthand \"mesh\"/\"material\", not both");
    const json& list = root["objects"];
    if (!list.is_array()) fail("objects", std::string("expected an array, got ") + typeName(list));
    if (list.size() > 256) fail("objects", "at most 256 objects (got " + std::to_string(list.size()) + ")");
    s.objects.clear();
    s.usesObjectList = true;
    for (size_t i = 0; i < list.size(); ++i) {
        const std::string p = "objects[" + std::to_string(i) + "]";
        requireObject(list[i], p, {"mesh", "material", "transform"});
        SceneObject o;
        if (list[i].contains("mesh")) o.mesh = mesh(list[i]["mesh"], p + ".mesh");
        if (list[i].contains("material")) o.material = material(list[i]["material"], p + ".material");
        if (list[i].contains("transform")) o.transform = transform(list[i]["transform"], p + ".transform");
        s.objects.push_back(o);
    }
}

DiffSettings SceneReader::diff(const json& j, const std::string& path) const {
    DiffSettings d;
    requireObject(j, path, {"a", "b", "factor"});
    choice(j, "a", path, d.a, kShadingModeNames);
    choice(j, "b", path, d.b, kShadingModeNames);
    value(j, path, Param::DiffFactor, d.factor);
    return d;
}

std::vector<Light> SceneReader::lights(const json& j, const std::string& path) const {
    if (!j.is_array()) fail(path, std::string("expected an array, got ") + typeName(j));
    if (j.size() > static_cast<size_t>(kMaxLights))
        fail(path, "at most " + std::to_string(kMaxLights) + " lights (got " + std::to_string(j.size()) + ")");
    std::vector<Light> list;
    for (size_t i = 0; i < j.size(); ++i) list.push_back(light(j[i], path + "[" + std::to_string(i) + "]"));
    return list;
}

// "show": a term of the formula, or "light:N" for one of the scene's `lightCount` lights.
TermView SceneReader::show(const json& j, const std::string& path, std::size_t lightCount) const {
    if (!j.is_string()) fail(path, std::string("expected a string, got ") + typeName(j));
    TermView t;
    try {
        t = parseTermView(j.get<std::string>(), "");
    } catch (const InputError& e) {
        fail(path, e.what());
    }
    if (t.term == ShowTerm::Light && t.light >= int(lightCount))
        fail(path, "light " + std::to_string(t.light) + " does not exist (the scene has " + std::to_string(lightCount) +
                       " light(s))");
    return t;
}

// [width, height] in pixels, each in kImageSideRange.
glm::ivec2 SceneReader::imageSize(const json& j, const std::string& path) const {
    if (!j.is_array() || j.size() != 2 || !j[0].is_number_integer() || !j[1].is_number_integer())
        fail(path, "expected [width, height] as two integers");
    const long long w = j[0].get<long long>(), h = j[1].get<long long>();
    if (w < 1 || h < 1 || w > kImageSideRange.hi || h > kImageSideRange.hi)
        fail(path, "width and height must be between 1 and " + std::to_string(kImageSideRange.hi) + " (got " +
                       std::to_string(w) + "x" + std::to_string(h) + ")");
    return {static_cast<int>(w), static_cast<int>(h)};
}

// The text as JSON, within the nesting limit; a malformed text is an InputError "LABEL: malformed JSON: ...".
json parseJson(const std::string& text, const std::string& label) {
    checkJsonDepth(text, label);
    try {
        return json::parse(text);
    } catch (const json::exception& e) {
        // parse_error ("[json.exception.parse_error.101] parse error at line 3, column 5: ...") and
        // out_of_range for numbers too large for a double ("... number overflow parsing '1e999'").
        std::string what = e.what();
        const size_t bracket = what.find("] ");
        if (what.rfind("[json.exception", 0) == 0 && bracket != std::string::npos) what = what.substr(bracket + 2);
        for (char& c : what)
            if (c == '\n') c = ' ';
        throw InputError(label + ": malformed JSON: " + what);
    }
}

}  // namespace

Scene parseScene(const std::string& text, const std::string& fileLabel, const std::string& baseDir) {
    const json root = parseJson(text, fileLabel);
    Scene s = SceneReader(fileLabel, baseDir).read(root);
    s.sourcePath = fileLabel;
    return s;
}

Light lightFromJson(const std::string& text, const std::string& label) {
    return SceneReader(label, "").light(parseJson(text, label), "");
}

MeshSpec meshFromJson(const std::string& text, const std::string& label) {
    return SceneReader(label, "").mesh(parseJson(text, label), "");
}

Scene loadSceneFile(const std::string& path) {
    const std::string text = readTextFile(path, 64u << 20);
    const fs::path parent = fs::path(path).parent_path();
    return parseScene(text, path, parent.empty() ? "." : parent.string());
}

Scene defaultScene() {
    const char* text = findEmbedded(kEmbeddedScenes, "default.json");
    Scene s = parseScene(text ? text : "{}", "(built-in default scene)", ".");
    s.sourcePath.clear();
    return s;
}

Scene sceneForModel(const std::string& modelPath) {
    Scene s;
    s.objects[0].mesh.type = MeshSpec::Type::Gltf;
    s.objects[0].mesh.path = modelPath;
    s.objects[0].mesh.resolvedPath = fs::path(modelPath).lexically_normal().string();
    return s;
}

}  // namespace shadelab
