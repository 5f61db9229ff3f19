// glTF as the tools write it: every file in tests/gltf-variants/ (quantized, meshopt- and
// Draco-compressed, instanced; made by gltfpack and glTF Transform) renders like the original it was
// made from, in all three modes, with the same number of triangles (every instance drawn; less the few a quantizer makes degenerate). The renders
// are written to build/tests/output/variants/ for a person to look at.
#include "core/scene/scene_json.hpp"
#include "gl/gl_test_support.hpp"
#include "render/renderer.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace shadelab;
namespace fs = std::filesystem;

TEST(GltfVariants, RenderLikeTheirOriginals) {
    const fs::path folder = fs::path(SHADELAB_SOURCE_DIR) / "tests" / "gltf-variants";
    const fs::path shared = fs::path(SHADELAB_SOURCE_DIR) / ".." / "shared" / "assets" / "gltf" / "sample-assets";
    const fs::path out = fs::path(SHADELAB_TEST_OUTPUT_DIR) / "variants";
    fs::create_directories(out);
    std::ifstream list(folder / "variants.txt");
    ASSERT_TRUE(list) << "variants.txt";
    const auto context = makeHeadlessContext(test::backendUnderTest(), 480, 160);
    Renderer renderer(context->getProcAddress());
    const RenderTarget target = context->target();
    const auto render = [&](const fs::path& model, std::size_t* triangles) {
        Scene scene = sceneForModel(model.string());
        scene.layout = Layout::Compare;
        scene.width = 480, scene.height = 160;
        auto geometry = std::make_shared<SceneGeometry>(buildSceneGeometry(scene));
        frameIfNeeded(scene, *geometry);
        *triangles = geometry->triangleCount();
        renderer.setGeometry(geometry);
        renderer.render(scene, target);
        return readPixels(target);
    };
    int compared = 0, skipped = 0;
    for (std::string line; std::getline(list, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream words(line);
        std::string variant, original;
        words >> variant >> original;
        SCOPED_TRACE(variant);
        const fs::path source = original.rfind("shared/", 0) == 0 ? shared / original.substr(7)
                                                                   : fs::path(SHADELAB_SOURCE_DIR) / original;
        if (!fs::exists(source)) {
            ++skipped;
            continue;
        }
        std::size_t originalTriangles = 0, variantTriangles = 0;
        const Image expected = render(source, &originalTriangles);
        const Image actual = render(folder / variant, &variantTriangles);
        writePng((out / (variant + ".png")).string(), actual);
        // Every triangle, every instance: gltfpack drops only the few that quantization makes
        // degenerate (196 of MetalRoughSpheres' 1,040,409).
        EXPECT_LE(variantTriangles, originalTriangles);
        EXPECT_GE(double(variantTriangles), 0.999 * double(originalTriangles));
        const ImageTolerance tolerance = toleranceWithShare(expected.width, expected.height);
        const CompareResult r = tolerance.compare(actual, expected);
        EXPECT_TRUE(tolerance.matches(r)) << describe(r, tolerance);
        ++compared;
    }
    EXPECT_GE(compared, 14);  // the project's own models' variants need nothing from ../shared
    if (skipped) std::cout << "[ SKIPPED  ] " << skipped << " variants of models in ../shared (absent)\n";
}

// EXT_mesh_gpu_instancing as instanced draws (RendererOptions::instancedDraws): the instanced parts
// are uploaded once and drawn once per instance, mirrored instances in a draw of their own; the
// picture is the one every instance baked gives, shadows included (the depth pass draws each
// instance).
TEST(GltfVariants, InstancesAreDrawnInstanced) {
    const fs::path model = fs::path(SHADELAB_SOURCE_DIR) / "tests" / "gltf-variants" / "NegativeScaleTest.gltfpack-mi-c.glb";
    Scene scene = sceneForModel(model.string());
    scene.layout = Layout::Compare;
    scene.width = 480, scene.height = 160;
    scene.shadows.enabled = true;
    auto geometry = std::make_shared<SceneGeometry>(buildSceneGeometry(scene));
    frameIfNeeded(scene, *geometry);
    const Mesh& baked = geometry->meshes[0];
    ASSERT_TRUE(baked.instanced);
    std::size_t instancedParts = 0, mirrored = 0;
    for (const MeshPart& part : baked.instanced->parts) {
        instancedParts += !part.instances.empty();
        for (const glm::mat4& t : part.instances) mirrored += glm::determinant(glm::mat3(t)) < 0.0f;
    }
    EXPECT_GT(instancedParts, 0u);
    EXPECT_GT(mirrored, 0u);  // the test model's point: instances with a negative scale
    EXPECT_LT(baked.instanced->triangleCount(), baked.triangleCount());
    const auto render = [&](bool instanced) {
        const auto context = makeHeadlessContext(test::backendUnderTest(), scene.width, scene.height);
        RendererOptions options;
        options.instancedDraws = instanced;
        Renderer renderer(context->getProcAddress(), ShaderLibrary(), options);
        renderer.setGeometry(geometry);
        renderer.render(scene, context->target());
        return readPixels(context->target());
    };
    const Image instanced = render(true), bakedImage = render(false);
    const ImageTolerance tolerance = toleranceWithShare(bakedImage.width, bakedImage.height);
    const CompareResult r = tolerance.compare(instanced, bakedImage);
    EXPECT_TRUE(tolerance.matches(r)) << describe(r, tolerance);
    EXPECT_LE(r.maxDiff, 2) << "the same transforms, composed in another order: float rounding only";
    if (HasFailure()) test::saveForInspection("instanced_draws", instanced);
}
