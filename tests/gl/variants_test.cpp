// glTF as the tools write it: every file in tests/gltf-variants/ (quantized, meshopt- and
// Draco-compressed, instanced; made by gltfpack and glTF Transform) renders like the original it was
// made from, in all three modes, with the same number of triangles (every instance drawn; less the few a quantizer makes degenerate). The renders
// are written to build/tests/output/variants/ for a person to look at.
#include "core/scene_json.hpp"
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
        const CompareTolerance tolerance;
        const CompareResult r = compareImages(actual, expected, tolerance.pixelThreshold);
        EXPECT_TRUE(r.matches(tolerance)) << describe(r, tolerance);
        ++compared;
    }
    EXPECT_GE(compared, 14);  // the project's own models' variants need nothing from ../shared
    if (skipped) std::cout << "[ SKIPPED  ] " << skipped << " variants of models in ../shared (absent)\n";
}
