// glTF's doubleSided (issue 27): a double-sided material is drawn from both sides, and its back is lit
// as a surface facing the other way, with the normal flipped, in flat, Gouraud and Phong shading.
// The model is an open bowl - the lower half of the unit sphere, normals pointing out - written here
// as glTF, seen from above so the outside of its near wall (front faces) and the inside of the rest
// (back faces) are both in view.
//
// Tolerances (per channel, out of 255) are those of analytic_test.cpp and probe_test.cpp: Phong on a
// fine mesh against the true sphere 2 (8-bit rounding, and the mesh's facets against the sphere);
// against the probe flat and Phong 1, Gouraud 2 (llvmpipe's fixed-point interpolation).
#include "core/geometry/ray_cast.hpp"
#include "core/probe/probe.hpp"
#include "core/shading/lighting.hpp"
#include "gl/gl_test_support.hpp"
#include "render/renderer.hpp"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

using namespace shadelab;
using namespace shadelab::test;
namespace fs = std::filesystem;

namespace {

struct BowlOptions {
    int slices = 24, stacks = 6;  // around the y axis; from the bottom to the rim
    bool doubleSided = true;
    bool vertexColors = false;    // COLOR_0, so C varies over the surface (the SL_TEXTURED programs)
};

template <typename T>
void appendBytes(std::vector<unsigned char>& b, const std::vector<T>& values) {
    const auto* p = reinterpret_cast<const unsigned char*>(values.data());
    b.insert(b.end(), p, p + values.size() * sizeof(T));
}

// The bowl as NAME.gltf and NAME.bin under the test output folder; returns the .gltf's path. Each
// triangle is wound counter-clockwise seen from outside (its face normal points away from the centre).
std::string writeBowl(const std::string& name, const BowlOptions& o) {
    std::vector<float> positions, normals, colors;
    for (int j = 0; j <= o.stacks; ++j)
        for (int i = 0; i <= o.slices; ++i) {
            const float alpha = glm::radians(90.0f) * float(j) / float(o.stacks);  // from -y toward the rim
            const float phi = glm::radians(360.0f) * float(i) / float(o.slices);
            const glm::vec3 p(std::sin(alpha) * std::cos(phi), -std::cos(alpha), std::sin(alpha) * std::sin(phi));
            positions.insert(positions.end(), {p.x, p.y, p.z});
            normals.insert(normals.end(), {p.x, p.y, p.z});
            colors.insert(colors.end(), {0.6f + 0.4f * p.x, 0.8f, 0.6f - 0.4f * p.z});
        }
    std::vector<std::uint32_t> indices;
    auto vertex = [&](int i, int j) { return std::uint32_t(j * (o.slices + 1) + i); };
    auto at = [&](std::uint32_t v) { return glm::vec3(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]); };
    auto triangle = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        const glm::vec3 n = glm::cross(at(b) - at(a), at(c) - at(a));
        if (glm::dot(n, at(a) + at(b) + at(c)) < 0.0f) std::swap(b, c);  // outward: counter-clockwise from outside
        indices.insert(indices.end(), {a, b, c});
    };
    for (int j = 0; j < o.stacks; ++j)
        for (int i = 0; i < o.slices; ++i) {
            triangle(vertex(i, j + 1), vertex(i + 1, j + 1), vertex(i, j));
            if (j > 0) triangle(vertex(i + 1, j), vertex(i, j), vertex(i + 1, j + 1));  // the bottom row meets at the pole
        }
    std::vector<unsigned char> bin;
    appendBytes(bin, positions);
    appendBytes(bin, normals);
    appendBytes(bin, colors);
    appendBytes(bin, indices);
    const std::size_t vertexBytes = positions.size() * sizeof(float), count = positions.size() / 3;
    nlohmann::json attributes = {{"POSITION", 0}, {"NORMAL", 1}};
    if (o.vertexColors) attributes["COLOR_0"] = 2;
    const nlohmann::json doc = {
        {"asset", {{"version", "2.0"}}},
        {"scene", 0},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes", {{{"mesh", 0}}}},
        {"materials", {{{"pbrMetallicRoughness", {{"baseColorFactor", {0.9, 0.55, 0.3, 1.0}}}}, {"doubleSided", o.doubleSided}}}},
        {"meshes", {{{"primitives", {{{"attributes", attributes}, {"indices", 3}, {"material", 0}}}}}}},
        {"buffers", {{{"uri", name + ".bin"}, {"byteLength", bin.size()}}}},
        {"bufferViews",
         {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", vertexBytes}},
          {{"buffer", 0}, {"byteOffset", vertexBytes}, {"byteLength", vertexBytes}},
          {{"buffer", 0}, {"byteOffset", 2 * vertexBytes}, {"byteLength", vertexBytes}},
          {{"buffer", 0}, {"byteOffset", 3 * vertexBytes}, {"byteLength", indices.size() * 4}}}},
        {"accessors",
         {{{"bufferView", 0}, {"componentType", 5126}, {"count", count}, {"type", "VEC3"}, {"min", {-1, -1, -1}}, {"max", {1, 0, 1}}},
          {{"bufferView", 1}, {"componentType", 5126}, {"count", count}, {"type", "VEC3"}},
          {{"bufferView", 2}, {"componentType", 5126}, {"count", count}, {"type", "VEC3"}},
          {{"bufferView", 3}, {"componentType", 5125}, {"count", indices.size()}, {"type", "SCALAR"}}}}};
    const fs::path folder = fs::path(SHADELAB_TEST_OUTPUT_DIR) / "double_sided";
    fs::create_directories(folder);
    std::ofstream(folder / (name + ".bin"), std::ios::binary)
        .write(reinterpret_cast<const char*>(bin.data()), std::streamsize(bin.size()));
    std::ofstream(folder / (name + ".gltf")) << doc.dump();
    return (folder / (name + ".gltf")).string();
}

// threeLightScene()'s lights (the key light above reaches the bowl's inside, the others its outside
// too) on the bowl, seen from above and in front: the near wall's outside below the rim, the inside
// of the far wall and the bottom through the opening. The scene's colour is the material's.
Scene bowlScene(const std::string& path) {
    Scene s = threeLightScene();
    s.objects[0].mesh = MeshSpec{};
    s.objects[0].mesh.type = MeshSpec::Type::Gltf;
    s.objects[0].mesh.path = s.objects[0].mesh.resolvedPath = path;
    s.objects[0].material.ke = 24.0f;
    s.objects[0].material.ks = 0.6f;
    s.camera.eye = {0.35f, 1.25f, 2.3f};
    s.camera.target = {0.0f, -0.35f, 0.0f};
    s.width = s.height = 128;
    return s;
}

int maxChannelDifference(const glm::ivec3& a, const glm::ivec3& b) {
    return std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
}

// What the pixel's ray meets on the true bowl (the unit sphere's half below y = 0).
struct BowlHit {
    enum Kind { Background, Outside, Inside, Unsure } kind = Unsure;
    glm::vec3 point{0.0f};
};
BowlHit rayOnTrueBowl(const Ray& ray) {
    // Away from the silhouette and the rim (where the mesh's polygons and the sphere's circles cover
    // different pixels) by 3% of the radius.
    constexpr float margin = 0.03f;
    const float b = glm::dot(ray.origin, ray.direction), c = glm::dot(ray.origin, ray.origin) - 1.0f;
    const float closest = std::sqrt(std::max(0.0f, c + 1.0f - b * b));
    if (closest > 1.0f + margin) return {BowlHit::Background};
    if (closest > 1.0f - margin) return {};
    const float root = std::sqrt(b * b - c);
    const glm::vec3 nearHit = ray.origin + (-b - root) * ray.direction, farHit = ray.origin + (-b + root) * ray.direction;
    if (nearHit.y < -margin) return {BowlHit::Outside, nearHit};   // the near wall's outside: a front face
    if (nearHit.y < margin) return {};
    if (farHit.y < -margin) return {BowlHit::Inside, farHit};      // through the opening: the inside, a back face
    return farHit.y > margin ? BowlHit{BowlHit::Background} : BowlHit{};
}

}  // namespace

// Phong on a fine bowl (256 x 64 quads) against the formula on the true sphere at each pixel: outside
// with N = p, inside with the flipped normal N = -p. Without double-sided drawing the inside is culled
// (the background shows); without the flip it is lit from behind (ambient alone where the key light
// shines in).
TEST(DoubleSided, PhongMatchesTheFormulaWithTheNormalFlippedOnTheBack) {
    BowlOptions fine;
    fine.slices = 256;
    fine.stacks = 64;
    const Scene scene = bowlScene(writeBowl("fine", fine));
    const Rendered r = renderScene(scene);
    const Pane pane = layoutPanes(scene.layout, scene.shading, scene.width, scene.height)[0];
    const LightingEnvironment env = lightingEnvironment(scene);
    Material m = scene.objects[0].material;
    m.color = {0.9f, 0.55f, 0.3f};  // the file's base colour
    int inside = 0, outside = 0, background = 0, worst = 0;
    for (int y = 0; y < scene.height; ++y)
        for (int x = 0; x < scene.width; ++x) {
            const BowlHit hit = rayOnTrueBowl(pixelRay(scene, pane, float(x) + 0.5f, float(y) + 0.5f));
            const glm::ivec3 got = quantize(color(r.image, x, y));
            if (hit.kind == BowlHit::Background) {
                EXPECT_EQ(got, quantize(scene.background)) << "at " << x << "," << y;
                ++background;
            }
            if (hit.kind != BowlHit::Inside && hit.kind != BowlHit::Outside) continue;
            const glm::vec3 n = hit.kind == BowlHit::Inside ? -hit.point : hit.point;
            const int d = maxChannelDifference(got, quantize(shade(m, env, hit.point, n)));
            worst = std::max(worst, d);
            EXPECT_LE(d, 2) << (hit.kind == BowlHit::Inside ? "inside" : "outside") << " pixel " << x << "," << y;
            (hit.kind == BowlHit::Inside ? inside : outside) += 1;
        }
    EXPECT_GT(inside, 3000);
    EXPECT_GT(outside, 1000);
    EXPECT_GT(background, 4000);
    RecordProperty("max_difference", worst);
    saveForInspection("double_sided_phong_bowl", r.image);
}

// The same bowl single-sided: where the true bowl shows its inside, the rasteriser culls those back
// faces and nothing is behind them, so the background shows; the outside is drawn as before.
TEST(DoubleSided, SingleSidedBackFacesAreStillCulled) {
    BowlOptions single;
    single.doubleSided = false;
    single.slices = 96;
    single.stacks = 24;
    const Scene scene = bowlScene(writeBowl("single", single));
    const Rendered r = renderScene(scene);
    const Pane pane = layoutPanes(scene.layout, scene.shading, scene.width, scene.height)[0];
    const SceneRayCaster caster(r.scene, *r.geometry);
    int inside = 0, outside = 0;
    for (int y = 0; y < scene.height; ++y)
        for (int x = 0; x < scene.width; ++x) {
            const BowlHit hit = rayOnTrueBowl(pixelRay(scene, pane, float(x) + 0.5f, float(y) + 0.5f));
            const glm::ivec3 got = quantize(color(r.image, x, y));
            if (hit.kind == BowlHit::Inside) {
                EXPECT_EQ(got, quantize(scene.background)) << "at " << x << "," << y;
                EXPECT_TRUE(probePixel(r.scene, *r.geometry, caster, x, y).miss) << "probe at " << x << "," << y;
                ++inside;
            } else if (hit.kind == BowlHit::Outside) {
                EXPECT_NE(got, quantize(scene.background)) << "at " << x << "," << y;
                ++outside;
            }
        }
    EXPECT_GT(inside, 3000);
    EXPECT_GT(outside, 1000);
    saveForInspection("double_sided_single_sided_bowl", r.image);
}

namespace {

struct ProbeSweep {
    int checked[3] = {0, 0, 0}, back[3] = {0, 0, 0}, worst[3] = {0, 0, 0};  // by ShadingMode
};

// Every third pixel of every pane against the probe (its evaluation is the CPU reference's with the
// normals flipped on the back), where the pixels two to each side see the same triangle (see
// probe_test.cpp: at an edge the rasteriser and the ray cast may pick different triangles).
ProbeSweep compareWithProbe(const Rendered& r) {
    const SceneRayCaster caster(r.scene, *r.geometry);
    ProbeSweep sweep;
    for (int y = 2; y < r.scene.height - 2; y += 3)
        for (int x = 2; x < r.scene.width - 2; x += 3) {
            const ProbeResult p = probePixel(r.scene, *r.geometry, caster, x, y);
            const glm::ivec3 got = quantize(color(r.image, x, y));
            if (p.miss) {
                EXPECT_EQ(got, p.output8) << "background at " << x << "," << y;
                continue;
            }
            bool interior = true;
            for (const auto& [dx, dy] : {std::pair{-2, 0}, std::pair{2, 0}, std::pair{0, -2}, std::pair{0, 2}}) {
                const ProbeResult n = probePixel(r.scene, *r.geometry, caster, x + dx, y + dy);
                interior = interior && !n.miss && n.pane == p.pane && n.anchor.triangle == p.anchor.triangle;
            }
            if (!interior) continue;
            const ShadingMode mode = p.modes[0].mode;
            const int d = maxChannelDifference(got, p.output8);
            EXPECT_LE(d, mode == ShadingMode::Gouraud ? 2 : 1)
                << toString(mode) << (p.backFace ? " back" : " front") << " pixel " << x << "," << y;
            const auto k = std::size_t(mode);
            sweep.worst[k] = std::max(sweep.worst[k], d);
            ++sweep.checked[k];
            sweep.back[k] += p.backFace;
        }
    return sweep;
}

class DoubleSidedModes : public ::testing::TestWithParam<bool> {};  // COLOR_0 or not

}  // namespace

// Flat, Gouraud and Phong (compare layout) on a coarse bowl, with and without vertex colours (the
// textured programs, which combine the per-face or per-vertex terms with C per fragment), against
// the probe: the back faces are lit with -N per triangle (flat), per vertex (Gouraud's second
// evaluation) and per fragment (Phong).
TEST_P(DoubleSidedModes, EveryModeMatchesTheProbeOnBothSides) {
    BowlOptions coarse;
    coarse.vertexColors = GetParam();
    Scene scene = bowlScene(writeBowl(GetParam() ? "coarse_colors" : "coarse", coarse));
    scene.layout = Layout::Compare;
    scene.width = 3 * 160;
    scene.height = 160;
    const Rendered r = renderScene(scene);
    const ProbeSweep sweep = compareWithProbe(r);
    for (int mode = 0; mode < 3; ++mode) {
        EXPECT_GT(sweep.back[mode], 150) << toString(ShadingMode(mode)) << ": back faces checked";
        EXPECT_GT(sweep.checked[mode] - sweep.back[mode], 50) << toString(ShadingMode(mode)) << ": front faces checked";
        RecordProperty(std::string("worst_") + toString(ShadingMode(mode)), sweep.worst[mode]);
    }
    saveForInspection(std::string("double_sided_compare") + (GetParam() ? "_colors" : ""), r.image);
}

INSTANTIATE_TEST_SUITE_P(Colors, DoubleSidedModes, ::testing::Bool(),
                         [](const auto& p) { return std::string(p.param ? "VertexColors" : "Plain"); });

// Progressive area-light sampling (the SL_ACCUMULATE programs) draws the double-sided bowl as a frame
// does: once every pass is summed, the image is the one-pass render's (1/255: the float sum's rounding,
// as in progressive_test.cpp).
TEST(DoubleSided, ProgressivePassesSumToTheOnePassImage) {
    Scene scene = bowlScene(writeBowl("progressive", BowlOptions{}));
    Light area;
    area.type = LightType::Area;
    area.position = {0.3f, 2.2f, 0.6f};
    area.size = {1.2f, 1.2f};
    area.samples = {4, 4};
    area.intensity = 1.5f;
    scene.lights = {area};
    scene.layout = Layout::Compare;
    scene.width = 3 * 96;
    scene.height = 96;
    auto context = makeHeadlessContext(backendUnderTest(), scene.width, scene.height);
    Renderer renderer(context->getProcAddress());
    renderer.setGeometry(std::make_shared<SceneGeometry>(buildSceneGeometry(scene)));
    const RenderTarget target = context->target();
    renderer.render(scene, target);
    const Image onePass = readPixels(target);
    Renderer::ProgressiveStatus status = renderer.renderProgressive(scene, target, 2, true);
    while (!status.complete()) status = renderer.renderProgressive(scene, target, 2, false);
    const Image progressive = readPixels(target);
    EXPECT_EQ(status.passCount, 4);
    EXPECT_LE(compareImages(progressive, onePass).maxDiff, 1);
    // And the inside is drawn, in every pane.
    int inside = 0;
    for (const Pane& pane : layoutPanes(scene.layout, scene.shading, scene.width, scene.height))
        for (int y = pane.y; y < pane.y + pane.height; ++y)
            for (int x = pane.x; x < pane.x + pane.width; ++x) {
                if (rayOnTrueBowl(pixelRay(scene, pane, float(x) + 0.5f, float(y) + 0.5f)).kind != BowlHit::Inside) continue;
                EXPECT_NE(quantize(color(progressive, x, y)), quantize(scene.background)) << "at " << x << "," << y;
                ++inside;
            }
    EXPECT_GT(inside, 3000);
    saveForInspection("double_sided_progressive", progressive);
}
