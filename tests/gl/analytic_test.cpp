// Analytic image tests: rendered pixels against the CPU reference of the lecture's formula
// (app/core/shading/lighting.cpp) at the surface point each pixel sees. Golden images can be regenerated;
// these cannot, so a wrong formula cannot hide behind a new baseline.
#include "core/shading/lighting.hpp"
#include "core/geometry/mesh.hpp"
#include "gl/gl_test_support.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace shadelab;
using namespace shadelab::test;

namespace {

int maxChannelDifference(const glm::ivec3& a, const glm::ivec3& b) {
    return std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
}

// Möller-Trumbore: the ray parameter and barycentrics (p = (1-u-v) a + u b + v c), or t < 0 if missed.
struct Hit {
    float t = -1.0f, u = 0.0f, v = 0.0f;
};
Hit intersect(const Ray& r, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::vec3 e1 = b - a, e2 = c - a, p = glm::cross(r.direction, e2);
    const float det = glm::dot(e1, p);
    if (std::fabs(det) < 1e-12f) return {};
    const glm::vec3 s = r.origin - a, q = glm::cross(s, e1);
    Hit h{glm::dot(e2, q) / det, glm::dot(s, p) / det, glm::dot(r.direction, q) / det};
    if (h.u < 0 || h.v < 0 || h.u + h.v > 1) h.t = -1.0f;
    return h;
}

// A UV sphere under threeLightScene()'s lights.
Scene litSphereScene(int slices, int stacks) {
    Scene s = threeLightScene();
    s.objects[0].mesh = MeshSpec{};
    s.objects[0].mesh.slices = slices;
    s.objects[0].mesh.stacks = stacks;
    s.objects[0].material.ke = 32.0f;
    s.width = 128;
    s.height = 128;
    return s;
}

struct PhongCase {
    ReflectionModel model;
    OutputEncoding encoding;
    const char* name;
    // Issue 6: the model extensions and term isolation, each checked against the same reference.
    SpecularNormalization normalization = SpecularNormalization::None;
    FresnelMode fresnel = FresnelMode::None;
    TermView show = {};
    float ke = 32.0f;
    float ks = 0.5f;
    float ior = 1.5f;
};

class PhongVersusRayCast : public ::testing::TestWithParam<PhongCase> {};

}  // namespace

// Phong shading of a finely tessellated sphere (256 x 128, 65k triangles) against a per-pixel ray cast
// of the true unit sphere. Tolerance 2/255 per channel: one step for 8-bit rounding, one for the gap
// between the mesh and the sphere (on this mesh normals differ by < 0.01 degrees and positions by
// < 1e-4; the largest difference measured on llvmpipe is 1). Pixels whose ray passes within 3% of
// the silhouette are left out: there the 256-gon outline and the circle cover different pixels.
TEST_P(PhongVersusRayCast, PixelsMatchTheReferenceOnTheTrueSphere) {
    Scene scene = litSphereScene(256, 128);
    scene.reflection = GetParam().model;
    scene.outputEncoding = GetParam().encoding;
    scene.specularNormalization = GetParam().normalization;
    scene.fresnel = GetParam().fresnel;
    scene.ior = GetParam().ior;
    scene.show = GetParam().show;
    scene.objects[0].material.ke = GetParam().ke;
    scene.objects[0].material.ks = GetParam().ks;
    const Rendered r = renderScene(scene);
    const Pane pane = layoutPanes(scene.layout, scene.shading, scene.width, scene.height)[0];
    const LightingEnvironment env = lightingEnvironment(scene);
    const glm::ivec3 background = quantize(scene.background);
    int checked = 0, worst = 0, backgroundChecked = 0;
    for (int y = 0; y < scene.height; ++y)
        for (int x = 0; x < scene.width; ++x) {
            const Ray ray = pixelRay(scene, pane, float(x) + 0.5f, float(y) + 0.5f);
            const float b = glm::dot(ray.origin, ray.direction);
            const float closest = std::sqrt(std::max(0.0f, glm::dot(ray.origin, ray.origin) - b * b));
            const glm::ivec3 got = quantize(color(r.image, x, y));
            if (closest > 1.03f) {
                EXPECT_EQ(got, background) << "at " << x << "," << y;
                ++backgroundChecked;
                continue;
            }
            if (closest > 0.97f) continue;
            const float t = -b - std::sqrt(b * b - (glm::dot(ray.origin, ray.origin) - 1.0f));
            const glm::vec3 p = ray.origin + t * ray.direction;
            glm::vec3 expected = shade(scene.objects[0].material, env, p, glm::normalize(p));
            if (scene.outputEncoding == OutputEncoding::Srgb)
                expected = {encodeSrgb(expected.x), encodeSrgb(expected.y), encodeSrgb(expected.z)};
            const int d = maxChannelDifference(got, quantize(expected));
            worst = std::max(worst, d);
            EXPECT_LE(d, 2) << "pixel " << x << "," << y;
            ++checked;
        }
    EXPECT_GT(checked, 6000) << "too few sphere pixels checked";
    EXPECT_GT(backgroundChecked, 4000);
    RecordProperty("max_difference", worst);
    if (HasFailure()) saveForInspection(std::string("phong_raycast_") + GetParam().name, r.image);
}

INSTANTIATE_TEST_SUITE_P(Models, PhongVersusRayCast,
                         ::testing::Values(PhongCase{ReflectionModel::BlinnPhong, OutputEncoding::Linear, "blinn"},
                                           PhongCase{ReflectionModel::Phong, OutputEncoding::Linear, "phong"},
                                           PhongCase{ReflectionModel::BlinnPhong, OutputEncoding::Srgb, "srgb"},
                                           PhongCase{ReflectionModel::BlinnPhong, OutputEncoding::Linear, "energy_schlick",
                                                     SpecularNormalization::Energy, FresnelMode::Schlick, {}, 128.0f,
                                                     4.0f, 1.5f},
                                           PhongCase{ReflectionModel::Phong, OutputEncoding::Linear, "energy_exact",
                                                     SpecularNormalization::Energy, FresnelMode::Exact, {}, 8.0f,
                                                     3.0f, 1.33f},
                                           PhongCase{ReflectionModel::BlinnPhong, OutputEncoding::Linear, "show_specular",
                                                     SpecularNormalization::None, FresnelMode::None,
                                                     TermView{ShowTerm::Specular, 0}},
                                           PhongCase{ReflectionModel::Phong, OutputEncoding::Linear, "show_diffuse",
                                                     SpecularNormalization::None, FresnelMode::None,
                                                     TermView{ShowTerm::Diffuse, 0}},
                                           PhongCase{ReflectionModel::BlinnPhong, OutputEncoding::Srgb, "show_light1",
                                                     SpecularNormalization::None, FresnelMode::None,
                                                     TermView{ShowTerm::Light, 1}},
                                           PhongCase{ReflectionModel::BlinnPhong, OutputEncoding::Linear, "show_ambient",
                                                     SpecularNormalization::None, FresnelMode::None,
                                                     TermView{ShowTerm::Ambient, 0}},
                                           PhongCase{ReflectionModel::BlinnPhong, OutputEncoding::Linear, "show_unlit",
                                                     SpecularNormalization::None, FresnelMode::None,
                                                     TermView{ShowTerm::Unlit, 0}}),
                         [](const auto& p) { return std::string(p.param.name); });

// Flat shading: every pixel inside a triangle (at least one pixel from its edges) has one colour, equal
// to the formula evaluated once at the triangle's centroid with the face normal
// normalize((c-b) x (a-b)). The object is rotated and scaled non-uniformly so the normal transform is
// exercised. Tolerance 1/255: float rounding on either side of the 8-bit quantisation.
TEST(FlatShading, EachTriangleIsItsCentroidEvaluation) {
    Scene scene = litSphereScene(12, 6);
    scene.shading = ShadingMode::Flat;
    scene.objects[0].transform.rotationDeg = {20.0f, 35.0f, 0.0f};
    scene.objects[0].transform.scale = {1.15f, 0.9f, 1.0f};
    scene.width = scene.height = 200;
    const Rendered r = renderScene(scene);
    const Pane pane = layoutPanes(scene.layout, scene.shading, scene.width, scene.height)[0];
    const LightingEnvironment env = lightingEnvironment(scene);
    const glm::mat4 world = worldFromObject(scene.objects[0].transform);
    const Mesh& mesh = r.geometry->meshes[0];
    int trianglesChecked = 0, pixelsChecked = 0;
    for (size_t t = 0; t < mesh.indices.size(); t += 3) {
        glm::vec3 w[3];
        glm::vec2 s[3];
        for (int k = 0; k < 3; ++k) {
            w[k] = glm::vec3(world * glm::vec4(mesh.positions[mesh.indices[t + size_t(k)]], 1.0f));
            s[k] = projectToImage(scene, pane, w[k]);
        }
        const glm::vec3 centroid = (w[0] + w[1] + w[2]) / 3.0f;
        const glm::vec3 n = faceNormal(w[0], w[1], w[2]);
        if (glm::dot(n, scene.camera.eye - centroid) <= 0.0f) continue;  // back face: culled
        const glm::ivec3 expected = quantize(shade(scene.objects[0].material, env, centroid, n));
        int inside = 0;
        const int x0 = std::max(0, int(std::min({s[0].x, s[1].x, s[2].x})));
        const int x1 = std::min(scene.width - 1, int(std::max({s[0].x, s[1].x, s[2].x})));
        const int y0 = std::max(0, int(std::min({s[0].y, s[1].y, s[2].y})));
        const int y1 = std::min(scene.height - 1, int(std::max({s[0].y, s[1].y, s[2].y})));
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const glm::vec2 p(float(x) + 0.5f, float(y) + 0.5f);
                bool deepInside = true;
                for (int k = 0; k < 3 && deepInside; ++k) {
                    const glm::vec2 a = s[k], b = s[(k + 1) % 3], c = s[(k + 2) % 3];
                    const glm::vec2 e = b - a;
                    const float len = glm::length(e);
                    // signed distance of p from edge ab, positive on the side of the third corner
                    const float side = (e.x * (c.y - a.y) - e.y * (c.x - a.x)) > 0 ? 1.0f : -1.0f;
                    const float dist = side * (e.x * (p.y - a.y) - e.y * (p.x - a.x)) / len;
                    deepInside = dist >= 1.0f;
                }
                if (!deepInside) continue;
                const int d = maxChannelDifference(quantize(color(r.image, x, y)), expected);
                EXPECT_LE(d, 1) << "triangle " << t / 3 << " pixel " << x << "," << y;
                ++inside;
            }
        if (inside > 0) ++trianglesChecked;
        pixelsChecked += inside;
    }
    EXPECT_GT(trianglesChecked, 40);  // of ~60 front-facing triangles; the rest are slivers at the silhouette
    EXPECT_GT(pixelsChecked, 8000);
    if (HasFailure()) saveForInspection("flat_centroid", r.image);
}

namespace {

// A coarse icosphere with the eye and a directional light both straight above the centre of face 0:
// there the true surface normal, the light and the eye line up, so Phong shading puts the peak of the
// highlight (spec = 1) in the middle of the face, between its vertices. At the vertices the normals
// are ~20 degrees away, where cos^100 is ~0.002: Gouraud interpolates three dull vertex colours and the
// highlight is lost.
struct HighlightSetup {
    Scene scene;
    glm::vec3 axis;           // unit, through the centre of face 0
    glm::vec3 corners[3];     // face 0, world = object space
    glm::vec2 centrePixel;
};

HighlightSetup highlightBetweenVertices(ShadingMode mode) {
    HighlightSetup h;
    Scene& s = h.scene;
    s.objects[0].mesh = MeshSpec{};
    s.objects[0].mesh.type = MeshSpec::Type::IcoSphere;
    s.objects[0].mesh.subdivisions = 1;
    s.objects[0].material.ke = 100.0f;
    s.objects[0].material.ks = 0.6f;
    const Mesh mesh = makeIcoSphere(1, 1.0f);
    for (int k = 0; k < 3; ++k) h.corners[k] = mesh.positions[mesh.indices[size_t(k)]];
    h.axis = glm::normalize(h.corners[0] + h.corners[1] + h.corners[2]);
    Light light;
    light.type = LightType::Directional;
    light.direction = -h.axis;
    s.lights = {light};
    s.camera.eye = 6.0f * h.axis;
    s.camera.target = glm::vec3(0.0f);
    s.camera.up = std::fabs(h.axis.y) > 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    s.cameraGiven = true;
    s.shading = mode;
    s.width = s.height = 256;  // face 0 is ~30 pixels across: room for a 9 x 9 patch inside it
    const Pane pane = layoutPanes(s.layout, s.shading, s.width, s.height)[0];
    h.centrePixel = projectToImage(s, pane, (h.corners[0] + h.corners[1] + h.corners[2]) / 3.0f);
    return h;
}

}  // namespace

TEST(GouraudShading, LosesTheHighlightThatPhongShows) {
    const HighlightSetup phongSetup = highlightBetweenVertices(ShadingMode::Phong);
    const HighlightSetup gouraudSetup = highlightBetweenVertices(ShadingMode::Gouraud);
    const Scene& scene = phongSetup.scene;
    const Rendered phong = renderScene(scene);
    const Rendered gouraud = renderScene(gouraudSetup.scene);
    const Pane pane = layoutPanes(scene.layout, scene.shading, scene.width, scene.height)[0];
    const LightingEnvironment env = lightingEnvironment(scene);
    const Material& m = scene.objects[0].material;
    const glm::vec3* c = phongSetup.corners;

    // Check a patch of pixels around the face centre against the references computed from the
    // barycentrics of the point each pixel sees (perspective-correct, as GL interpolates).
    const glm::vec3 vertexColor[3] = {shade(m, env, c[0], glm::normalize(c[0])), shade(m, env, c[1], glm::normalize(c[1])),
                                      shade(m, env, c[2], glm::normalize(c[2]))};
    int checked = 0;
    const int cx = int(phongSetup.centrePixel.x), cy = int(phongSetup.centrePixel.y);
    for (int y = cy - 4; y <= cy + 4; ++y)
        for (int x = cx - 4; x <= cx + 4; ++x) {
            const Ray ray = pixelRay(scene, pane, float(x) + 0.5f, float(y) + 0.5f);
            const Hit hit = intersect(ray, c[0], c[1], c[2]);
            ASSERT_GT(hit.t, 0.0f) << "pixel " << x << "," << y << " is not on face 0";
            const float w0 = 1.0f - hit.u - hit.v;
            const glm::vec3 p = ray.origin + hit.t * ray.direction;
            const glm::vec3 n = glm::normalize(w0 * glm::normalize(c[0]) + hit.u * glm::normalize(c[1]) +
                                               hit.v * glm::normalize(c[2]));
            // Phong: the formula at the interpolated, renormalised normal. Tolerance 1/255 (rounding).
            EXPECT_LE(maxChannelDifference(quantize(color(phong.image, x, y)), quantize(shade(m, env, p, n))), 1)
                << "phong pixel " << x << "," << y;
            // Gouraud: the vertex colours interpolated. Tolerance 2/255: GL interpolates in fixed point.
            const glm::vec3 interpolated = w0 * vertexColor[0] + hit.u * vertexColor[1] + hit.v * vertexColor[2];
            EXPECT_LE(maxChannelDifference(quantize(color(gouraud.image, x, y)), quantize(interpolated)), 2)
                << "gouraud pixel " << x << "," << y;
            ++checked;
        }
    EXPECT_EQ(checked, 81);

    // And the lecture's point, in numbers: at the face centre Phong shows the highlight (the specular
    // term adds k_s = 0.6 to every channel), Gouraud does not (its vertices see almost none of it).
    const glm::vec3 phongCentre = color(phong.image, cx, cy), gouraudCentre = color(gouraud.image, cx, cy);
    EXPECT_GT(phongCentre.g, 0.75f);
    EXPECT_LT(gouraudCentre.g, 0.35f);
    EXPECT_GT(phongCentre.g - gouraudCentre.g, 0.4f);
    if (HasFailure()) {
        saveForInspection("highlight_phong", phong.image);
        saveForInspection("highlight_gouraud", gouraud.image);
    }
}

// Each pane of the compare layout is the single-mode render of that pane's size: one camera,
// the same projection per pane.
TEST(CompareLayout, PanesEqualSingleRendersOfTheirMode) {
    Scene scene = litSphereScene(16, 8);
    scene.layout = Layout::Compare;
    scene.width = 3 * 64;
    scene.height = 80;
    const Rendered compare = renderScene(scene);
    const ShadingMode modes[3] = {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong};
    for (int i = 0; i < 3; ++i) {
        Scene single = scene;
        single.layout = Layout::Single;
        single.shading = modes[i];
        single.width = 64;
        const Rendered one = renderScene(single);
        Image pane(64, 80);
        for (int y = 0; y < 80; ++y)
            for (int x = 0; x < 64; ++x) std::copy_n(compare.image.pixel(64 * i + x, y), 4, pane.pixel(x, y));
        // 1/255: the pane's viewport offset changes float rounding in llvmpipe's setup by an ulp.
        const CompareResult d = compareImages(pane, one.image, 0);
        EXPECT_LE(d.maxDiff, 1) << toString(modes[i]);
        EXPECT_GT(compareImages(one.image, filled(64, 80)).differingPixels, 1000u) << "blank render";
    }
}

// Layout diff: panes A | B | |A - B| * factor, all 64 wide (the 2 leftover columns stay background).
// The difference pane is exactly |pane A - pane B| * factor of the displayed 8-bit values (<= 1 for the
// rounding of (a - b) / 255 * factor back to 8 bits), and the source panes are the single renders of
// their mode (<= 1, as in the compare layout), so the difference pane is within factor + 1 of
// |single A - single B| * factor.
TEST(DiffLayout, DifferencePaneIsTheAmplifiedDifferenceOfTheSingleRenders) {
    Scene scene = litSphereScene(16, 8);
    scene.layout = Layout::Diff;
    scene.diff = DiffSettings{ShadingMode::Gouraud, ShadingMode::Phong, 4.0f};
    scene.width = 3 * 64 + 2;
    scene.height = 80;
    const Rendered diff = renderScene(scene);
    Image singles[2] = {Image(64, 80), Image(64, 80)};
    for (int k = 0; k < 2; ++k) {
        Scene single = scene;
        single.layout = Layout::Single;
        single.shading = k == 0 ? scene.diff.a : scene.diff.b;
        single.width = 64;
        singles[k] = renderScene(single).image;
    }
    int nonZero = 0, worstVsPanes = 0, worstVsSingles = 0;
    const glm::ivec3 background = quantize(scene.background);
    for (int y = 0; y < 80; ++y) {
        for (int x = 0; x < 64; ++x) {
            const glm::ivec3 a = quantize(color(diff.image, x, y)), b = quantize(color(diff.image, 64 + x, y));
            const glm::ivec3 d = quantize(color(diff.image, 128 + x, y));
            const glm::ivec3 sa = quantize(color(singles[0], x, y)), sb = quantize(color(singles[1], x, y));
            EXPECT_LE(maxChannelDifference(a, sa), 1);
            EXPECT_LE(maxChannelDifference(b, sb), 1);
            const glm::ivec3 fromPanes = glm::min(glm::abs(a - b) * 4, glm::ivec3(255));
            const glm::ivec3 fromSingles = glm::min(glm::abs(sa - sb) * 4, glm::ivec3(255));
            worstVsPanes = std::max(worstVsPanes, maxChannelDifference(d, fromPanes));
            worstVsSingles = std::max(worstVsSingles, maxChannelDifference(d, fromSingles));
            nonZero += d != glm::ivec3(0);
        }
        for (int x = 192; x < 194; ++x) EXPECT_EQ(quantize(color(diff.image, x, y)), background);
    }
    EXPECT_LE(worstVsPanes, 1);
    EXPECT_LE(worstVsSingles, 5);
    EXPECT_GT(nonZero, 300) << "gouraud and phong should differ on a 16 x 8 sphere";
    if (HasFailure()) saveForInspection("diff_layout", diff.image);
}

// A mirroring transform must not turn the object inside out: back-face culling follows the winding
// flip, so a sphere mirrored in x looks like the sphere (it is symmetric), lit from the outside.
TEST(Transforms, MirroredObjectIsDrawnFromTheOutside) {
    Scene scene = litSphereScene(64, 32);
    const Rendered plain = renderScene(scene);
    scene.objects[0].transform.scale = {-1.0f, 1.0f, 1.0f};
    const Rendered mirrored = renderScene(scene);
    // At most 0.2% of the pixels over 8/255, a mean of each pixel's largest difference under 0.3/255.
    const ImageTolerance tolerance = toleranceWithShare(plain.image.width, plain.image.height, 8, 0.002, 0.3 / 4);
    const CompareResult d = tolerance.compare(mirrored.image, plain.image);
    EXPECT_TRUE(tolerance.matches(d)) << describe(d, tolerance);
}
