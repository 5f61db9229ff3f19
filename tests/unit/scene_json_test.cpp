// The scene-file format: defaults, every field, every error (which must name the file and the field),
// and the round trip through sceneToJson that the viewer's "save scene" relies on.
#include "core/base/error.hpp"
#include "core/scene/scene_json.hpp"
#include "options/shorthand.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace shadelab;
namespace fs = std::filesystem;

namespace {

Scene parse(const std::string& json) { return parseScene(json, "test.json", "/scenes"); }

// A path as the scene reader resolves it: with the platform's separators ('\\' on Windows).
std::string nativePath(const std::string& generic) { return fs::path(generic).make_preferred().string(); }

// Expects an InputError whose message starts with "test.json: " and contains every fragment.
void expectError(const std::string& json, std::initializer_list<const char*> fragments) {
    try {
        parse(json);
        ADD_FAILURE() << "no error for " << json;
    } catch (const InputError& e) {
        const std::string msg = e.what();
        EXPECT_EQ(msg.rfind("test.json: ", 0), 0u) << msg;
        EXPECT_EQ(msg.find('\n'), std::string::npos) << "error must be one line: " << msg;
        for (const char* f : fragments) EXPECT_NE(msg.find(f), std::string::npos) << "'" << f << "' not in: " << msg;
    }
}

}  // namespace

TEST(SceneJson, EmptyObjectGivesDocumentedDefaults) {
    const Scene s = parse("{}");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(s.objects[0].mesh.type, MeshSpec::Type::UvSphere);
    EXPECT_EQ(s.objects[0].mesh.slices, 64);
    EXPECT_EQ(s.objects[0].mesh.stacks, 32);
    EXPECT_EQ(s.shading, ShadingMode::Phong);
    EXPECT_EQ(s.layout, Layout::Single);
    EXPECT_EQ(s.reflection, ReflectionModel::BlinnPhong);
    EXPECT_FLOAT_EQ(s.objects[0].material.ka, 0.1f);
    EXPECT_FLOAT_EQ(s.objects[0].material.kd, 0.7f);
    EXPECT_FLOAT_EQ(s.objects[0].material.ks, 0.5f);
    EXPECT_FLOAT_EQ(s.objects[0].material.ke, 32.0f);
    EXPECT_EQ(s.objects[0].material.specularColor, glm::vec3(1.0f));
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].type, LightType::Point);
    EXPECT_FLOAT_EQ(s.camera.fovYDeg, 45.0f);
    EXPECT_FALSE(s.cameraGiven);
    EXPECT_EQ(s.outputEncoding, OutputEncoding::Linear);
}

TEST(SceneJson, EveryFieldIsRead) {
    const Scene s = parse(R"({
      "objects": [
        {"mesh": {"type": "icosphere", "subdivisions": 2, "radius": 0.5},
         "material": {"color": [0.1, 0.2, 0.3], "specular_color": [0.9, 0.8, 0.7], "ka": 0.2, "kd": 0.3, "ks": 0.4, "ke": 64},
         "transform": {"translation": [1, 2, 3], "rotation_deg": [10, 20, 30], "scale": [1, -1, 2]}},
        {"mesh": {"type": "torus", "major_radius": 2, "minor_radius": 0.5, "major_segments": 10, "minor_segments": 6}},
        {"mesh": {"type": "cube", "size": 3}},
        {"mesh": {"type": "plane", "size": 5, "subdivisions": 4}},
        {"mesh": {"type": "uvsphere", "slices": 8, "stacks": 4, "radius": 2}},
        {"mesh": {"type": "gltf", "path": "models/box.glb"}}
      ],
      "shading": "gouraud", "layout": "compare", "reflection": "phong",
      "ambient": [0.5, 0.5, 0.5],
      "lights": [{"type": "point", "position": [1, 2, 3], "color": [1, 0, 0], "intensity": 2, "attenuation": "inverse-square"},
                 {"type": "directional", "direction": [0, -1, 0], "color": [0, 1, 0], "intensity": 0.5}],
      "camera": {"eye": [0, 0, 9], "target": [0, 1, 0], "up": [0, 1, 0], "fov_y_deg": 30, "near": 0.5, "far": 50},
      "background": [0.2, 0.3, 0.4],
      "size": [320, 200],
      "output_encoding": "srgb"
    })");
    ASSERT_EQ(s.objects.size(), 6u);
    EXPECT_EQ(s.objects[0].mesh.subdivisions, 2);
    EXPECT_EQ(s.objects[0].material.color, glm::vec3(0.1f, 0.2f, 0.3f));
    EXPECT_FLOAT_EQ(s.objects[0].material.ke, 64.0f);
    EXPECT_EQ(s.objects[0].transform.scale, glm::vec3(1, -1, 2));
    EXPECT_EQ(s.objects[1].mesh.majorSegments, 10);
    EXPECT_FLOAT_EQ(s.objects[2].mesh.size, 3.0f);
    EXPECT_EQ(s.objects[3].mesh.planeSubdivisions, 4);
    EXPECT_EQ(s.objects[4].mesh.slices, 8);
    EXPECT_EQ(s.objects[5].mesh.resolvedPath, nativePath("/scenes/models/box.glb"));  // relative to the scene file
    EXPECT_EQ(s.shading, ShadingMode::Gouraud);
    EXPECT_EQ(s.layout, Layout::Compare);
    EXPECT_EQ(s.reflection, ReflectionModel::Phong);
    ASSERT_EQ(s.lights.size(), 2u);
    EXPECT_EQ(s.lights[0].attenuation, Attenuation::InverseSquare);
    EXPECT_EQ(s.lights[1].type, LightType::Directional);
    EXPECT_TRUE(s.cameraGiven);
    EXPECT_FLOAT_EQ(s.camera.farPlane, 50.0f);
    EXPECT_EQ(s.width, 320);
    EXPECT_EQ(s.height, 200);
    EXPECT_EQ(s.outputEncoding, OutputEncoding::Srgb);
}

TEST(SceneJson, ErrorsNameTheFileAndTheField) {
    expectError("{\"mesh\": {\"type\": \"uvsphere\"", {"malformed JSON", "line 1"});
    expectError("[]", {"expected an object"});
    expectError(R"({"colour": [1, 0, 0]})", {"colour", "unknown field"});
    expectError(R"({"material": {"kd": 0.5, "shininess": 3}})", {"material.shininess", "unknown field"});
    expectError(R"({"material": {"ka": -0.1}})", {"material.ka", ">= 0"});
    expectError(R"({"material": {"ka": "0.1"}})", {"material.ka", "expected a number"});
    expectError(R"({"material": {"ke": 0}})", {"material.ke", ">= 1"});
    expectError(R"({"material": {"ke": 1000000}})", {"material.ke", "<= 10000"});
    expectError(R"({"material": {"color": [1, 0]}})", {"material.color", "3 numbers"});
    expectError(R"({"material": {"color": [1, 0, 2]}})", {"material.color[2]", "<= 1"});
    expectError(R"({"shading": "toon"})", {"shading", "\"toon\"", "flat"});
    expectError(R"({"layout": 3})", {"layout", "got a number"});
    expectError(R"({"size": [0, 100]})", {"size", "between 1 and"});
    expectError(R"({"size": [-5, 100]})", {"size"});
    expectError(R"({"size": [100000, 100000]})", {"size", "16384"});
    expectError(R"({"size": [1.5, 100]})", {"size", "integers"});
    expectError(R"({"mesh": {"type": "uvsphere", "slices": 2}})", {"mesh.slices", ">= 3"});
    expectError(R"({"mesh": {"type": "uvsphere", "slices": 10000000}})", {"mesh.slices", "<= 4096"});
    expectError(R"({"mesh": {"type": "uvsphere", "subdivisions": 2}})", {"mesh.subdivisions", "unknown field"});
    expectError(R"({"mesh": {"type": "teapot"}})", {"mesh.type", "teapot"});
    expectError(R"({"mesh": {"type": "gltf"}})", {"mesh.path"});
    expectError(R"({"lights": [{"type": "point", "intensity": -1}]})", {"lights[0].intensity", ">= 0"});
    expectError(R"({"lights": [{}, {"type": "directional", "direction": [0, 0, 0]}]})", {"lights[1].direction", "zero-length"});
    expectError(R"({"lights": [{"type": "directional", "attenuation": "none"}]})", {"lights[0].attenuation", "unknown field"});
    expectError(R"({"camera": {"eye": [1, 2, 3], "target": [1, 2, 3]}})", {"camera.target", "differ from eye"});
    expectError(R"({"camera": {"fov_y_deg": 0}})", {"camera.fov_y_deg"});
    expectError(R"({"camera": {"fov_y_deg": 180}})", {"camera.fov_y_deg"});
    expectError(R"({"camera": {"near": 5, "far": 5}})", {"camera.far", "greater than near"});
    expectError(R"({"camera": {"up": [0, 0, 0]}})", {"camera.up", "zero-length"});
    expectError(R"({"camera": {"eye": [0, 5, 0], "up": [0, 1, 0]}})", {"camera.up", "parallel"});
    expectError(R"({"objects": [{"transform": {"scale": [1, 0, 1]}}]})", {"objects[0].transform.scale"});
    expectError(R"({"objects": [], "mesh": {"type": "cube"}})", {"objects", "not both"});
    expectError(R"({"layout": "sidebyside"})", {"layout", "\"diff\""});
    expectError(R"({"diff": {"a": "toon"}})", {"diff.a", "toon"});
    expectError(R"({"diff": {"factor": 0.5}})", {"diff.factor", ">= 1"});
    expectError(R"({"diff": {"c": 1}})", {"diff.c", "unknown field"});
    expectError(R"({"specular_normalization": "physical"})", {"specular_normalization", "\"energy\""});
    expectError(R"({"fresnel": true})", {"fresnel", "got a boolean"});
    expectError(R"({"ior": 0.1})", {"ior", ">= 0.2"});
    expectError(R"({"ior": 11})", {"ior", "<= 10"});
    expectError(R"({"show": "glossy"})", {"show", "unknown value \"glossy\""});
    expectError(R"({"show": "light:x"})", {"show", "not a light index"});
    expectError(R"({"show": "light:1"})", {"show", "light 1 does not exist"});
    expectError(R"({"show": "light:99"})", {"show", "out of range"});
    expectError(R"({"show": 3})", {"show", "expected a string"});
    expectError(R"({"title": 3})", {"title", "expected a string"});
    expectError(R"({"caption": "two\nlines"})", {"caption", "one line"});
    std::string many = R"({"lights": [)";
    for (int i = 0; i < 17; ++i) many += std::string(i ? "," : "") + "{}";
    expectError(many + "]}", {"lights", "at most 16"});
}

TEST(SceneJson, FileErrorsNameTheFile) {
    const fs::path dir = fs::temp_directory_path() / "shadelab-scene-json-test";
    fs::create_directories(dir);
    try {
        loadSceneFile((dir / "missing.json").string());
        ADD_FAILURE();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("missing.json: cannot read"), std::string::npos) << e.what();
    }
    try {
        loadSceneFile(dir.string());
        ADD_FAILURE();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("is a directory"), std::string::npos) << e.what();
    }
    std::ofstream(dir / "bad.json") << "{\"ka\": }";
    try {
        loadSceneFile((dir / "bad.json").string());
        ADD_FAILURE();
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind((dir / "bad.json").string() + ": malformed JSON", 0), 0u) << e.what();
    }
    fs::remove_all(dir);
}

TEST(SceneJson, SavedSceneLoadsBackTheSame) {
    Scene s = parse(R"({
      "objects": [{"mesh": {"type": "torus", "major_segments": 10}, "material": {"ke": 77, "color": [0.1, 0.5, 0.9]},
                   "transform": {"translation": [1, 0, 0], "rotation_deg": [0, 45, 0], "scale": [2, 2, 2]}},
                  {"mesh": {"type": "gltf", "path": "m/box.gltf"}}],
      "shading": "flat", "layout": "compare", "reflection": "phong", "ambient": [0.3, 0.2, 0.1],
      "lights": [{"type": "directional", "direction": [1, -1, 0], "intensity": 0.7}],
      "camera": {"eye": [3, 3, 3], "fov_y_deg": 60}, "size": [64, 48], "output_encoding": "srgb"})");
    const std::string saved = sceneToJson(s, "/scenes");
    const Scene r = parseScene(saved, "saved.json", "/scenes");
    ASSERT_EQ(r.objects.size(), 2u);
    EXPECT_EQ(r.objects[0].mesh, s.objects[0].mesh);
    EXPECT_EQ(r.objects[1].mesh.resolvedPath, nativePath("/scenes/m/box.gltf"));
    EXPECT_EQ(r.objects[0].material.color, s.objects[0].material.color);
    EXPECT_FLOAT_EQ(r.objects[0].material.ke, 77.0f);
    EXPECT_EQ(r.objects[0].transform.rotationDeg, s.objects[0].transform.rotationDeg);
    EXPECT_EQ(r.shading, s.shading);
    EXPECT_EQ(r.layout, s.layout);
    EXPECT_EQ(r.reflection, s.reflection);
    EXPECT_EQ(r.ambient, s.ambient);
    ASSERT_EQ(r.lights.size(), 1u);
    EXPECT_EQ(r.lights[0].direction, s.lights[0].direction);
    EXPECT_EQ(r.camera.eye, s.camera.eye);
    EXPECT_FLOAT_EQ(r.camera.fovYDeg, 60.0f);
    EXPECT_EQ(r.width, 64);
    EXPECT_EQ(r.outputEncoding, OutputEncoding::Srgb);
    // Saved from another folder, the model path is rewritten so it still points at the same file.
    const Scene moved = parseScene(sceneToJson(s, "/elsewhere/deeper"), "moved.json", "/elsewhere/deeper");
    EXPECT_EQ(moved.objects[1].mesh.resolvedPath, nativePath("/scenes/m/box.gltf"));
    // Saving is stable: a second round trip gives identical text.
    EXPECT_EQ(sceneToJson(r, "/scenes"), saved);
}

TEST(SceneJson, LectureFieldsAreReadAndSaved) {
    const Scene defaults = parse("{}");
    EXPECT_EQ(defaults.specularNormalization, SpecularNormalization::None);
    EXPECT_EQ(defaults.fresnel, FresnelMode::None);
    EXPECT_FLOAT_EQ(defaults.ior, 1.5f);
    EXPECT_EQ(defaults.show.term, ShowTerm::All);
    EXPECT_EQ(defaults.diff.a, ShadingMode::Gouraud);
    EXPECT_EQ(defaults.diff.b, ShadingMode::Phong);
    EXPECT_FLOAT_EQ(defaults.diff.factor, 4.0f);
    EXPECT_TRUE(defaults.title.empty());
    const Scene s = parse(R"({"layout": "diff", "diff": {"a": "flat", "b": "gouraud", "factor": 16},
      "specular_normalization": "energy", "fresnel": "exact", "ior": 1.33, "show": "light:1",
      "lights": [{}, {"type": "directional"}], "title": "Fresnel", "caption": "Glass reflects more at grazing angles."})");
    EXPECT_EQ(s.layout, Layout::Diff);
    EXPECT_EQ(s.diff.a, ShadingMode::Flat);
    EXPECT_EQ(s.diff.b, ShadingMode::Gouraud);
    EXPECT_FLOAT_EQ(s.diff.factor, 16.0f);
    EXPECT_EQ(s.specularNormalization, SpecularNormalization::Energy);
    EXPECT_EQ(s.fresnel, FresnelMode::Exact);
    EXPECT_FLOAT_EQ(s.ior, 1.33f);
    EXPECT_EQ(s.show, (TermView{ShowTerm::Light, 1}));
    EXPECT_EQ(s.title, "Fresnel");
    const Scene r = parse(sceneToJson(s, "/scenes"));
    EXPECT_EQ(r.layout, s.layout);
    EXPECT_EQ(r.diff.a, s.diff.a);
    EXPECT_FLOAT_EQ(r.diff.factor, s.diff.factor);
    EXPECT_EQ(r.specularNormalization, s.specularNormalization);
    EXPECT_EQ(r.fresnel, s.fresnel);
    EXPECT_FLOAT_EQ(r.ior, s.ior);
    EXPECT_EQ(r.show, s.show);
    EXPECT_EQ(r.title, s.title);
    EXPECT_EQ(r.caption, s.caption);
    for (const char* term : {"all", "ambient", "diffuse", "specular", "unlit"})
        EXPECT_EQ(toString(parse(std::string(R"({"show": ")") + term + "\"}").show), term);
}

// "viewer": what a preset's slide opens with in the viewer (a probe, the diagram, panel sections); the
// probe is a pixel of the scene's own size, so it is checked against "size" wherever that is written.
TEST(SceneJson, ViewerStartIsReadCheckedAndSaved) {
    EXPECT_TRUE(parse("{}").viewer.empty());
    const Scene s = parse(R"({"viewer": {"probe": [639, 10], "intersection": true, "panel_sections": ["plots", "lights"]},
      "size": [640, 360]})");
    ASSERT_TRUE(s.viewer.probe.has_value());
    EXPECT_EQ(*s.viewer.probe, glm::ivec2(639, 10));
    EXPECT_EQ(s.viewer.probeOf, glm::ivec2(640, 360));
    EXPECT_TRUE(s.viewer.intersection);
    EXPECT_EQ(s.viewer.panelSections, (std::vector<std::string>{"plots", "lights"}));
    const Scene r = parse(sceneToJson(s, "/scenes"));
    EXPECT_EQ(r.viewer.probe, s.viewer.probe);
    EXPECT_EQ(r.viewer.intersection, s.viewer.intersection);
    EXPECT_EQ(r.viewer.panelSections, s.viewer.panelSections);
    // The viewer saves at its view's size: the probe follows the picture (scaled with the height about the
    // centre) and stays inside.
    Scene resized = s;
    resized.width = 320, resized.height = 180;
    const Scene saved = parse(sceneToJson(resized, "/scenes"));
    EXPECT_EQ(*saved.viewer.probe, glm::ivec2(319, 5));
    EXPECT_EQ(saved.viewer.probeOf, glm::ivec2(320, 180));
    expectError(R"({"viewer": {"probe": [640, 10]}, "size": [640, 360]})", {"viewer.probe[0]"});
    expectError(R"({"viewer": {"probe": [1, 2, 3]}})", {"viewer.probe", "[x, y]"});
    expectError(R"({"viewer": {"intersection": true}})", {"viewer.intersection", "probe"});
    expectError(R"({"viewer": {"panel_sections": ["plot"]}})", {"viewer.panel_sections[0]", "\"plot\"", "plots"});
    expectError(R"({"viewer": {"zoom": 2}})", {"viewer.zoom", "unknown field"});
    EXPECT_EQ(parse(R"({"viewer": {"plot": "lobe3d"}})").viewer.plot, "lobe3d");
    EXPECT_EQ(parse(sceneToJson(parse(R"({"viewer": {"plot": "brdf-slice"}})"), "/")).viewer.plot, "brdf-slice");
    expectError(R"({"viewer": {"plot": "lobe-3d"}})", {"viewer.plot", "\"lobe-3d\"", "lobe3d"});
}

TEST(SceneJson, DefaultSceneIsBuiltInAndValid) {
    const Scene s = defaultScene();
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(s.objects[0].mesh.type, MeshSpec::Type::UvSphere);
    EXPECT_EQ(s.reflection, ReflectionModel::BlinnPhong);
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].type, LightType::Point);
}

TEST(SceneJson, MeshShorthand) {
    const MeshSpec uv = parseMeshShorthand("uvsphere:16:8", "--mesh");
    EXPECT_EQ(uv.type, MeshSpec::Type::UvSphere);
    EXPECT_EQ(uv.slices, 16);
    EXPECT_EQ(uv.stacks, 8);
    EXPECT_EQ(parseMeshShorthand("icosphere:2", "--mesh").subdivisions, 2);
    EXPECT_EQ(parseMeshShorthand("cube", "--mesh").type, MeshSpec::Type::Cube);
    EXPECT_EQ(parseMeshShorthand("a/b.GLB", "--mesh").type, MeshSpec::Type::Gltf);
    EXPECT_THROW(parseMeshShorthand("uvsphere:x", "--mesh"), InputError);
    EXPECT_THROW(parseMeshShorthand("uvsphere:16:8:4", "--mesh"), InputError);
    EXPECT_THROW(parseMeshShorthand("icosphere:99", "--mesh"), InputError);
    EXPECT_THROW(parseMeshShorthand("teapot", "--mesh"), InputError);
}

// Issue 5: area lights, attenuation ranges, shadows and their settings.
TEST(SceneJson, LightsOfEveryKindAndShadowSettings) {
    const Scene s = parse(R"({
      "lights": [{"type": "point", "position": [1, 2, 3], "attenuation": "inverse-square", "range": 7.5},
                 {"type": "area", "position": [0, 3, 0], "normal": [0, -1, 0.2], "size": [2, 0.5],
                  "samples": [8, 3], "color": [1, 0.9, 0.8], "intensity": 12, "two_sided": true,
                  "attenuation": "inverse-square"},
                 {"type": "area"}],
      "shadows": true,
      "shadow_settings": {"normal_bias": 2.5, "depth_bias": 3, "pcf": 2, "map_size": 512, "area_map_size": 128}
    })");
    ASSERT_EQ(s.lights.size(), 3u);
    EXPECT_FLOAT_EQ(s.lights[0].range, 7.5f);
    const Light& a = s.lights[1];
    EXPECT_EQ(a.type, LightType::Area);
    EXPECT_EQ(a.normal, glm::vec3(0, -1, 0.2f));
    EXPECT_EQ(a.size, glm::vec2(2, 0.5f));
    EXPECT_EQ(a.samples, glm::ivec2(8, 3));
    EXPECT_TRUE(a.twoSided);
    EXPECT_EQ(a.attenuation, Attenuation::InverseSquare);
    EXPECT_FLOAT_EQ(a.intensity, 12.0f);
    // Documented defaults of an area light: 1 x 1 m facing down, 4 x 4 samples, one-sided, no falloff.
    const Light& d = s.lights[2];
    EXPECT_EQ(d.normal, glm::vec3(0, -1, 0));
    EXPECT_EQ(d.size, glm::vec2(1, 1));
    EXPECT_EQ(d.samples, glm::ivec2(4, 4));
    EXPECT_FALSE(d.twoSided);
    EXPECT_EQ(d.attenuation, Attenuation::None);
    EXPECT_TRUE(s.shadows.enabled);
    EXPECT_FLOAT_EQ(s.shadows.normalBias, 2.5f);
    EXPECT_FLOAT_EQ(s.shadows.depthBias, 3.0f);
    EXPECT_EQ(s.shadows.pcf, 2);
    EXPECT_EQ(s.shadows.mapSize, 512);
    EXPECT_EQ(s.shadows.areaMapSize, 128);
    // Off unless asked for; the defaults of the settings are the documented ones.
    const Scene plain = parse("{}");
    EXPECT_FALSE(plain.shadows.enabled);
    EXPECT_EQ(plain.shadows, ShadowSettings{});

    // The round trip keeps all of it.
    const Scene r = parse(sceneToJson(s, "/scenes"));
    ASSERT_EQ(r.lights.size(), 3u);
    EXPECT_FLOAT_EQ(r.lights[0].range, 7.5f);
    EXPECT_EQ(r.lights[1].samples, a.samples);
    EXPECT_EQ(r.lights[1].size, a.size);
    EXPECT_EQ(r.lights[1].normal, a.normal);
    EXPECT_TRUE(r.lights[1].twoSided);
    EXPECT_EQ(r.shadows, s.shadows);
    EXPECT_EQ(sceneToJson(r, "/scenes"), sceneToJson(s, "/scenes"));
}

// Spot lights: position, axis and cone half-angles; the inner angle defaults to half the outer one.
TEST(SceneJson, SpotLightsAreReadAndSaved) {
    const Scene s = parse(R"({"lights": [
      {"type": "spot", "position": [0, 4, 1], "direction": [0, -1, 0], "outer_cone_deg": 40, "inner_cone_deg": 25,
       "attenuation": "inverse-square", "range": 9, "intensity": 3},
      {"type": "spot", "outer_cone_deg": 16},
      {"type": "spot"}]})");
    ASSERT_EQ(s.lights.size(), 3u);
    const Light& a = s.lights[0];
    EXPECT_EQ(a.type, LightType::Spot);
    EXPECT_EQ(a.position, glm::vec3(0, 4, 1));
    EXPECT_EQ(a.direction, glm::vec3(0, -1, 0));
    EXPECT_FLOAT_EQ(a.outerConeDeg, 40.0f);
    EXPECT_FLOAT_EQ(a.innerConeDeg, 25.0f);
    EXPECT_FLOAT_EQ(a.range, 9.0f);
    EXPECT_FLOAT_EQ(s.lights[1].innerConeDeg, 8.0f);
    EXPECT_FLOAT_EQ(s.lights[2].outerConeDeg, 30.0f);
    EXPECT_FLOAT_EQ(s.lights[2].innerConeDeg, 15.0f);
    const Scene r = parse(sceneToJson(s, "/scenes"));
    EXPECT_EQ(sceneToJson(r, "/scenes"), sceneToJson(s, "/scenes"));
    EXPECT_FLOAT_EQ(r.lights[0].innerConeDeg, 25.0f);
    EXPECT_EQ(r.lights[0].direction, a.direction);

    const Light l = parseLightShorthand("spot:0,3,2:direction=0,-3,-2:outer=25:inner=15:intensity=2", "--light");
    EXPECT_EQ(l.type, LightType::Spot);
    EXPECT_EQ(l.direction, glm::vec3(0, -3, -2));
    EXPECT_FLOAT_EQ(l.outerConeDeg, 25.0f);
    EXPECT_FLOAT_EQ(l.innerConeDeg, 15.0f);
    EXPECT_FLOAT_EQ(parseLightShorthand("spot:0,3,2:outer=12", "--light").innerConeDeg, 6.0f);
    for (const char* bad : {"spot:0,3,2:inner=30:outer=20", "spot:0,3,2:outer=91", "spot:0,3,2:normal=0,1,0",
                            "spot:0,3,2:direction=0,0,0", "point:0,3,2:outer=20"})
        EXPECT_THROW(parseLightShorthand(bad, "--light"), InputError) << bad;
}

TEST(SceneJson, LightAndShadowErrorsNameTheField) {
    expectError(R"({"lights": [{"type": "torch"}]})",
                {"lights[0].type", "unknown value \"torch\"", "\"point\", \"directional\", \"area\", \"spot\""});
    expectError(R"({"lights": [{"type": "spot", "outer_cone_deg": 95}]})", {"lights[0].outer_cone_deg", "<= 90"});
    expectError(R"({"lights": [{"type": "spot", "outer_cone_deg": 20, "inner_cone_deg": 25}]})",
                {"lights[0].inner_cone_deg", "less than outer_cone_deg"});
    expectError(R"({"lights": [{"type": "spot", "direction": [0, 0, 0]}]})", {"lights[0].direction", "zero-length"});
    expectError(R"({"lights": [{"type": "spot", "normal": [0, -1, 0]}]})", {"lights[0].normal", "unknown field"});
    expectError(R"({"lights": [{"type": "area", "samples": [0, 4]}]})", {"lights[0].samples[0]", ">= 1"});
    expectError(R"({"lights": [{"type": "area", "samples": [4, 17]}]})", {"lights[0].samples[1]", "<= 16"});
    expectError(R"({"lights": [{"type": "area", "samples": [4]}]})", {"lights[0].samples", "2 integers"});
    expectError(R"({"lights": [{"type": "area", "samples": [2.5, 4]}]})", {"lights[0].samples[0]", "integer"});
    expectError(R"({"lights": [{"type": "area", "size": [1, 0]}]})", {"lights[0].size[1]", ">= 0.0001"});
    expectError(R"({"lights": [{"type": "area", "normal": [0, 0, 0]}]})", {"lights[0].normal", "zero-length"});
    expectError(R"({"lights": [{"type": "area", "two_sided": 1}]})", {"lights[0].two_sided", "true or false"});
    expectError(R"({"lights": [{"type": "area", "direction": [0, -1, 0]}]})", {"lights[0].direction", "unknown field"});
    expectError(R"({"lights": [{"type": "point", "range": 5}]})", {"lights[0].range", "inverse-square"});
    expectError(R"({"lights": [{"type": "point", "attenuation": "inverse-square", "range": 0}]})",
                {"lights[0].range", ">= 0.0001"});
    expectError(R"({"lights": [{"type": "directional", "range": 5}]})", {"lights[0].range", "unknown field"});
    expectError(R"({"shadows": "yes"})", {"shadows", "true or false"});
    expectError(R"({"shadow_settings": {"pcf": 3}})", {"shadow_settings.pcf", "<= 2"});
    expectError(R"({"shadow_settings": {"map_size": 32}})", {"shadow_settings.map_size", ">= 64"});
    expectError(R"({"shadow_settings": {"area_map_size": 8192}})", {"shadow_settings.area_map_size", "<= 4096"});
    expectError(R"({"shadow_settings": {"normal_bias": -1}})", {"shadow_settings.normal_bias", ">= 0"});
    expectError(R"({"shadow_settings": {"bias": 1}})", {"shadow_settings.bias", "unknown field"});
}

// Every shipped scene parses (the shadow scenes among them).
TEST(SceneJson, ShippedScenesLoad) {
    // Sub-folders included: assets/scenes/lecture holds the lecture's presets.
    for (const auto& entry : fs::recursive_directory_iterator(std::string(SHADELAB_SOURCE_DIR) + "/assets/scenes")) {
        if (!entry.is_regular_file()) continue;
        SCOPED_TRACE(entry.path().string());
        EXPECT_NO_THROW(loadSceneFile(entry.path().string()));
    }
}
