// The --light and --mesh shorthands written back (options/shorthand.hpp): what the parser reads from a
// light's or a mesh's shorthand is that light or mesh again, for every light and mesh of the project's
// scenes and lecture presets and for lights with every key set; untouched values are left out.
#include "core/base/error.hpp"
#include "core/scene/playlist.hpp"
#include "core/scene/scene_json.hpp"
#include "options/shorthand.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

using namespace shadelab;

namespace {

void expectSameLight(const Light& a, const Light& b, const std::string& shorthand) {
    EXPECT_EQ(a.type, b.type) << shorthand;
    if (a.type == LightType::Directional) {
        EXPECT_EQ(a.direction, b.direction) << shorthand;
    } else {
        EXPECT_EQ(a.position, b.position) << shorthand;
    }
    EXPECT_EQ(a.color, b.color) << shorthand;
    EXPECT_EQ(a.intensity, b.intensity) << shorthand;
    if (a.type == LightType::Directional) return;
    EXPECT_EQ(a.attenuation, b.attenuation) << shorthand;
    if (a.attenuation == Attenuation::InverseSquare) {
        EXPECT_EQ(a.range, b.range) << shorthand;
    }
    if (a.type == LightType::Area) {
        EXPECT_EQ(a.normal, b.normal) << shorthand;
        EXPECT_EQ(a.size, b.size) << shorthand;
        EXPECT_EQ(a.samples, b.samples) << shorthand;
        EXPECT_EQ(a.twoSided, b.twoSided) << shorthand;
    }
    if (a.type == LightType::Spot) {
        EXPECT_EQ(a.direction, b.direction) << shorthand;
        EXPECT_EQ(a.outerConeDeg, b.outerConeDeg) << shorthand;
        EXPECT_EQ(a.innerConeDeg, b.innerConeDeg) << shorthand;
    }
}

void expectRoundTrip(const Light& l) {
    const std::string text = lightShorthand(l);
    expectSameLight(l, parseLightShorthand(text, "--light"), text);
}

}  // namespace

TEST(Shorthand, MeshesAreReadAndWritten) {
    const MeshSpec uv = parseMeshShorthand("uvsphere:16:8", "--mesh");
    EXPECT_EQ(uv.slices, 16);
    EXPECT_EQ(uv.stacks, 8);
    EXPECT_EQ(meshShorthand(uv), "uvsphere:16:8");
    EXPECT_EQ(meshShorthand(parseMeshShorthand("icosphere", "--mesh")), "icosphere:3");
    EXPECT_EQ(meshShorthand(parseMeshShorthand("torus:40", "--mesh")), "torus:40:24");
    EXPECT_EQ(meshShorthand(parseMeshShorthand("plane:6", "--mesh")), "plane:6");
    EXPECT_EQ(meshShorthand(parseMeshShorthand("cube", "--mesh")), "cube");
    EXPECT_EQ(meshShorthand(parseMeshShorthand("models/a b.glb", "--mesh")), "models/a b.glb");
    EXPECT_THROW(parseMeshShorthand("icosphere:99", "--mesh"), InputError);
}

TEST(Shorthand, AnUntouchedLightIsItsPlace) {
    Light l;
    l.position = {1.5f, -2.0f, 0.1f};
    EXPECT_EQ(lightShorthand(l), "point:1.5,-2,0.1");
    l.type = LightType::Directional;
    l.direction = {0.0f, -1.0f, 0.25f};
    EXPECT_EQ(lightShorthand(l), "directional:0,-1,0.25");
    Light spot;
    spot.type = LightType::Spot;
    spot.outerConeDeg = 40.0f;
    spot.innerConeDeg = 20.0f;  // half the outer: what the shorthand gives when inner is left out
    EXPECT_EQ(lightShorthand(spot), "spot:3,4,5:outer=40");
}

TEST(Shorthand, EveryKeyReadsBack) {
    Light area;
    area.type = LightType::Area;
    area.position = {0.0f, 3.0f, 0.0f};
    area.color = {0.9f, 0.8f, 1.0f / 3.0f};
    area.intensity = 9.125f;
    area.attenuation = Attenuation::InverseSquare;
    area.range = 12.5f;
    area.normal = {0.1f, -1.0f, 0.0f};
    area.size = {1.6f, 0.7f};
    area.samples = {8, 3};
    area.twoSided = true;
    expectRoundTrip(area);
    EXPECT_EQ(lightShorthand(area),
              "area:0,3,0:color=0.9,0.8,0.33333334:intensity=9.125:attenuation=inverse-square:range=12.5:"
              "normal=0.1,-1,0:size=1.6,0.7:samples=8x3:two-sided");
    Light spot;
    spot.type = LightType::Spot;
    spot.direction = {0.0f, -2.0f, -1.0f};
    spot.outerConeDeg = 25.0f;
    spot.innerConeDeg = 15.0f;
    expectRoundTrip(spot);
    EXPECT_EQ(lightShorthand(spot), "spot:3,4,5:direction=0,-2,-1:outer=25:inner=15");
}

TEST(Shorthand, EveryLightOfTheProjectsScenesReadsBack) {
    namespace fs = std::filesystem;
    const fs::path scenes = fs::path(SHADELAB_SOURCE_DIR) / "assets" / "scenes";
    int lights = 0;
    for (const fs::path& folder : {scenes, scenes / "lecture"}) {
        for (const auto& entry : fs::directory_iterator(folder)) {
            if (entry.path().extension() != ".json") continue;
            const Scene scene = loadSceneFile(entry.path().string());
            for (const Light& l : scene.lights) {
                expectRoundTrip(l);
                ++lights;
            }
            for (const SceneObject& o : scene.objects) {
                if (o.mesh.type == MeshSpec::Type::Gltf) continue;
                const MeshSpec back = parseMeshShorthand(meshShorthand(o.mesh), "--mesh");
                EXPECT_EQ(meshShorthand(back), meshShorthand(o.mesh)) << entry.path();
            }
        }
    }
    EXPECT_GT(lights, 30);
}

TEST(Shorthand, ShortestNumbersReadBackExactly) {
    for (float v : {0.0f, 1.0f, 0.1f, 1.0f / 3.0f, 1e-4f, 123456.789f, -2.5f, 1e9f, 3.14159265f}) {
        const std::string text = shortestNumber(v);
        EXPECT_EQ(std::strtof(text.c_str(), nullptr), v) << text;
    }
    EXPECT_EQ(shortestNumber(0.1f), "0.1");
    EXPECT_EQ(shortestNumber(32.0f), "32");
    EXPECT_EQ(shortestNumber(40.0f), "40");
    EXPECT_EQ(shortestNumber(-1e6f), "-1000000");
}

TEST(Shorthand, ALightGivenAsSceneJsonIsItsOption) {
    const Light l = lightFromJson(R"({"type": "spot", "position": [0, 4, 2], "direction": [0, -2, -1], "outer_cone_deg": 25})",
                                  "light");
    EXPECT_EQ(lightShorthand(l), "spot:0,4,2:direction=0,-2,-1:outer=25");
    EXPECT_EQ(meshShorthand(meshFromJson(R"({"type": "torus", "major_segments": 12})", "mesh")), "torus:12:24");
    try {
        lightFromJson(R"({"type": "point", "intensity": -1})", "light");
        FAIL() << "a negative intensity is refused";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "light: intensity: must be >= 0 (got -1)");
    }
    EXPECT_THROW(lightFromJson("{", "light"), InputError);
}
