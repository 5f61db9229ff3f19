// Every real model in ../shared/assets/gltf renders headless in all three modes, auto-framed, with no
// GL error and a picture that is not empty. The renders are written to build/tests/output/models/
// for a person to look at.
#include "core/scene/scene_json.hpp"
#include "gl/gl_test_support.hpp"
#include "render/renderer.hpp"

#include <gtest/gtest.h>

#include <filesystem>

using namespace shadelab;
namespace fs = std::filesystem;


TEST(SharedModels, RenderInEveryMode) {
    const fs::path root = fs::path(SHADELAB_SOURCE_DIR) / ".." / "shared" / "assets" / "gltf";
    if (!fs::exists(root)) GTEST_SKIP() << root << " not found: ../shared is absent";
    std::vector<fs::path> files;
    for (const auto& e : fs::recursive_directory_iterator(root))
        if (e.is_regular_file() && (e.path().extension() == ".gltf" || e.path().extension() == ".glb") &&
            e.path().string().find("/Negative/") == std::string::npos)
            files.push_back(e.path());
    std::sort(files.begin(), files.end());
    ASSERT_GE(files.size(), 44u);
    const auto context = makeHeadlessContext(test::backendUnderTest(), 96, 96);
    Renderer renderer(context->getProcAddress());
    const RenderTarget target = context->target();
    int drawn = 0;
    for (const fs::path& file : files) {
        SCOPED_TRACE(file.string());
        Scene scene = sceneForModel(file.string());
        scene.width = scene.height = 96;
        auto geometry = std::make_shared<SceneGeometry>(buildSceneGeometry(scene));
        frameIfNeeded(scene, *geometry);
        renderer.setGeometry(geometry);
        for (ShadingMode mode : {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong}) {
            scene.shading = mode;
            ASSERT_NO_THROW(renderer.render(scene, target));
            const Image image = readPixels(target);
            const std::size_t covered = compareImages(image, test::filled(96, 96, test::quantize(scene.background))).differingPixels;
            if (geometry->triangleCount() > 0) {
                EXPECT_GT(covered, 30u) << toString(mode) << ": the model is not visible";
            } else {
                EXPECT_EQ(covered, 0u) << "nothing to draw, yet something was drawn";
            }
            const std::string name = fs::relative(file, root).string();
            std::string flat;
            for (char c : name) flat += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
            test::saveForInspection("models/" + flat + "." + toString(mode), image);
        }
        drawn += geometry->triangleCount() > 0;
    }
    EXPECT_GE(drawn, 30);
}
