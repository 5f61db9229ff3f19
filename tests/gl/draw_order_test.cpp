// Two ways the renderer changes the order of its draws for speed or memory, neither of which may
// change a single pixel: meshes reordered for the vertex cache (Renderer::MeshOrder,
// render/cpu/vertex_order.hpp: the same triangles with the same corners in another order) and draws split
// into fenced chunks (RendererOptions::drawChunkTriangles). And a third speed variant that may change
// only rounding: flat shading from packed vertices (shaders/flat_packed.vert, whose face normal's z
// is rebuilt from its unit length) against the readable flat.vert. Checked on the golden scenes with
// several objects, parts (glTF primitives), a mirrored transform, textures, shadow maps and all three
// modes side by side.
#include "core/scene/scene_json.hpp"
#include "gl/gl_test_support.hpp"
#include "render/renderer.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

using namespace shadelab;
using namespace shadelab::test;

namespace {

Image renderWith(const Scene& scene, std::shared_ptr<const SceneGeometry> geometry, Renderer::MeshOrder order,
                 std::size_t chunk = 0, bool packedFlat = false) {
    auto context = makeHeadlessContext(backendUnderTest(), scene.width, scene.height);
    RendererOptions options;
    options.meshOrder = order;
    options.drawChunkTriangles = chunk;
    options.packedFlatVertices = packedFlat;
    Renderer renderer(context->getProcAddress(), ShaderLibrary(), options);
    renderer.setGeometry(std::move(geometry));
    renderer.render(scene, context->target());
    return readPixels(context->target());
}

class DrawOrder : public ::testing::TestWithParam<const char*> {};

}  // namespace

TEST_P(DrawOrder, SamePixelsWhateverTheOrder) {
    const std::string name = GetParam();
    Scene scene = loadSceneFile(std::string(SHADELAB_SOURCE_DIR) + "/tests/scenes/" + name + ".json");
    for (const SceneObject& o : scene.objects)
        if (o.mesh.type == MeshSpec::Type::Gltf && !std::filesystem::exists(o.mesh.resolvedPath))
            GTEST_SKIP() << o.mesh.resolvedPath << " not found: ../shared is absent";
    auto geometry = std::make_shared<SceneGeometry>(buildSceneGeometry(scene));
    frameIfNeeded(scene, *geometry);
    const Image given = renderWith(scene, geometry, Renderer::MeshOrder::AsGiven);
    const Image ordered = renderWith(scene, geometry, Renderer::MeshOrder::VertexCache);
    EXPECT_EQ(compareImages(ordered, given).differingPixels, 0u)
        << name << ": " << saveForInspection("draw_order_" + name + "_given", given) << " vs "
        << saveForInspection("draw_order_" + name + "_ordered", ordered);
    // Chunks of 50 triangles: every draw of these scenes is split, most into many chunks.
    const Image chunked = renderWith(scene, geometry, Renderer::MeshOrder::AsGiven, 50);
    EXPECT_EQ(compareImages(chunked, given).differingPixels, 0u)
        << name << ": " << saveForInspection("draw_order_" + name + "_given", given) << " vs "
        << saveForInspection("draw_order_" + name + "_chunked", chunked);
    // Packed flat vertices: the same picture up to one step of rounding where a face normal's
    // rebuilt z differs in its last bits.
    const Image packed = renderWith(scene, geometry, Renderer::MeshOrder::AsGiven, 0, true);
    const CompareResult r = compareImages(packed, given);
    EXPECT_LE(r.maxDiff, 1) << name << ": " << saveForInspection("draw_order_" + name + "_given", given)
                                  << " vs " << saveForInspection("draw_order_" + name + "_packed_flat", packed);
    EXPECT_LE(r.differingPixels, std::size_t(given.width * given.height / 100)) << name;
    // Not a blank frame on both sides.
    EXPECT_GT(compareImages(given, filled(given.width, given.height)).differingPixels,
              std::size_t(given.width * given.height / 20));
}

INSTANTIATE_TEST_SUITE_P(Scenes, DrawOrder,
                         ::testing::Values("compare_torus", "gem_compare", "objects_lights", "gltf_suzanne_compare",
                                           "gltf_negative_scale", "shadow_objects_compare", "flat_uvsphere",
                                           "textured_globe_compare"),
                         [](const auto& p) { return std::string(p.param); });
