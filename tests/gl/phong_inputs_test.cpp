// Phong's two programs: phong.vert/.frag read the formula's values from the uniform blocks
// (shaders/values_from_blocks.glsl), the speed variant phong_interpolated.vert/.frag gets them as
// inputs from the vertex stage. The renderer picks one per draw by
// triangle density; both must draw the same picture, whatever the lights, shadows, reflection model
// or term shown, and the choice must follow the density.
//
// Tolerance: the to-eye and to-light vectors are interpolated instead of computed from the
// interpolated position; the two differ by float rounding, 1 of 255 at a rounding boundary at most.
#include "core/scene/scene_json.hpp"
#include "gl/gl_test_support.hpp"
#include "render/gpu_blocks.hpp"
#include "render/renderer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <string>

using namespace shadelab;
using namespace shadelab::test;

namespace {

Image renderWith(const Scene& scene, Renderer::PhongInputs inputs) {
    auto context = makeHeadlessContext(backendUnderTest(), scene.width, scene.height);
    RendererOptions options;
    options.phongInputs = inputs;
    Renderer renderer(context->getProcAddress(), ShaderLibrary(), options);
    renderer.setGeometry(std::make_shared<SceneGeometry>(buildSceneGeometry(scene)));
    renderer.render(scene, context->target());
    return readPixels(context->target());
}

void expectSamePicture(const Scene& scene, const std::string& name) {
    const Image blocks = renderWith(scene, Renderer::PhongInputs::Uniform);
    const Image inputs = renderWith(scene, Renderer::PhongInputs::Interpolated);
    ASSERT_EQ(blocks.rgba.size(), inputs.rgba.size());
    // Pixels of the object: away from the background colour (the top-left pixel) by more than 8 levels.
    int maxDelta = 0, drawn = 0;
    for (std::size_t i = 0; i < blocks.rgba.size(); ++i) {
        if (i % 4 == 3) continue;
        maxDelta = std::max(maxDelta, std::abs(int(blocks.rgba[i]) - int(inputs.rgba[i])));
        if (i % 4 == 0)
            for (int c = 0; c < 3; ++c)
                if (std::abs(int(blocks.rgba[i + c]) - int(blocks.rgba[c])) > 8) {
                    ++drawn;
                    break;
                }
    }
    if (std::getenv("SHADELAB_TEST_SAVE")) saveForInspection("phong_inputs_" + name, blocks);
    EXPECT_LE(maxDelta, 1) << name << ": " << saveForInspection("phong_inputs_" + name + "_blocks", blocks) << " vs "
                           << saveForInspection("phong_inputs_" + name + "_inputs", inputs);
    EXPECT_GT(drawn, int(blocks.rgba.size() / 4 / 20)) << name << ": hardly anything drawn, the comparison proves nothing";
}

Scene small(Scene s) {
    s.width = 160, s.height = 120;
    s.shading = ShadingMode::Phong;
    s.layout = Layout::Single;
    return s;
}

}  // namespace

TEST(PhongInputs, BothPathsDrawTheSamePicture) {
    Scene three = small(threeLightScene());  // point, inverse-square point and directional lights
    expectSamePicture(three, "three_lights");
    three.reflection = ReflectionModel::Phong;
    three.specularNormalization = SpecularNormalization::Energy;
    three.fresnel = FresnelMode::Schlick;
    expectSamePicture(three, "phong_energy_schlick");
    three.show.term = ShowTerm::Specular;
    expectSamePicture(three, "specular_only");
    three.show.term = ShowTerm::Light;
    three.show.light = 1;
    expectSamePicture(three, "light_1_only");
    Scene none = small(threeLightScene());
    none.lights.clear();  // ambient only: no per-light inputs at all
    expectSamePicture(none, "no_lights");
}

TEST(PhongInputs, ShadowsAndAreaLightsDrawTheSamePicture) {
    for (const char* file : {"shadow_point.json", "shadow_directional.json", "shadow_area_4x4.json"}) {
        Scene s = small(loadSceneFile(std::string(SHADELAB_SOURCE_DIR) + "/assets/scenes/" + file));
        expectSamePicture(s, file);
    }
}

TEST(PhongInputs, ChosenWhereTrianglesAreLargeOnScreen) {
    auto context = makeHeadlessContext(backendUnderTest(), 320, 240);
    Renderer renderer(context->getProcAddress());
    Scene s = small(threeLightScene());
    s.width = 320, s.height = 240;
    const Pane pane = layoutPanes(s.layout, s.shading, s.width, s.height).front();
    auto chosen = [&](int slices, int stacks) {
        s.objects[0].mesh.slices = slices, s.objects[0].mesh.stacks = stacks;
        renderer.setGeometry(std::make_shared<SceneGeometry>(buildSceneGeometry(s)));
        return renderer.interpolatesInputs(0, pane, s);
    };
    EXPECT_TRUE(chosen(32, 16));     // ~1k triangles on ~40k pixels
    EXPECT_FALSE(chosen(256, 128));  // ~65k triangles on the same pixels
    s.camera.eye *= 40.0f;           // far away: a few pixels
    EXPECT_FALSE(chosen(32, 16));
    Pane flatPane = pane;
    flatPane.mode = ShadingMode::Flat;
    s.camera.eye /= 40.0f;
    EXPECT_FALSE(renderer.interpolatesInputs(0, flatPane, s));  // only Phong programs have them
    RendererOptions forced;
    forced.phongInputs = RendererOptions::PhongInputs::Interpolated;
    Renderer interpolating(context->getProcAddress(), ShaderLibrary(), forced);
    interpolating.setGeometry(std::make_shared<SceneGeometry>(buildSceneGeometry(s)));
    s.lights.resize(SL_MAX_INTERPOLATED_LIGHTS + 1, s.lights[0]);
    EXPECT_FALSE(interpolating.interpolatesInputs(0, pane, s));  // past the varying budget: the blocks
}
