// Shadows against geometry: a sphere of radius 0.7 at the origin over the plane y = -1, lit from
// above, rendered with Phong shading and compared pixel by pixel with the CPU reference at the plane
// point each pixel sees, where a ray cast against the true sphere decides what is occluded.
//
// Margin for the shadow map: a shadow edge may be off by the map's texels (1024 per 90 degrees for a
// point light, 256 per area-light sample map), the normal bias (1.5 texels), PCF (1 texel) and the
// bilinear compare - about 5 texels, 0.01 rad seen from the light, ~0.03 world units at the sphere.
// Pixels are checked only where every light point is occluded (or visible) with the segment passing
// at least kMargin = 0.06 inside (outside) the sphere, twice that.
#include "core/shading/lighting.hpp"
#include "gl/gl_test_support.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace shadelab;
using namespace shadelab::test;

namespace {

constexpr float kRadius = 0.7f;
constexpr float kMargin = 0.06f;
constexpr float kPlaneY = -1.0f;

int maxChannelDifference(const glm::ivec3& a, const glm::ivec3& b) {
    return std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
}

// Distance from the sphere's centre (the origin) to the segment a-b.
float segmentDistance(const glm::vec3& a, const glm::vec3& b) {
    const glm::vec3 ab = b - a;
    const float t = std::clamp(-glm::dot(a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
    return glm::length(a + t * ab);
}

Scene sphereOverPlane(const Light& light) {
    Scene s;
    s.objects.resize(2);
    s.objects[0].mesh.type = MeshSpec::Type::Plane;
    s.objects[0].mesh.size = 8.0f;
    s.objects[0].material.color = {0.75f, 0.75f, 0.72f};
    s.objects[0].material.ka = 0.15f;
    s.objects[0].material.ks = 0.1f;
    s.objects[0].material.ke = 16.0f;
    s.objects[0].transform.translation = {0.0f, kPlaneY, 0.0f};
    s.objects[1].mesh.type = MeshSpec::Type::UvSphere;
    s.objects[1].mesh.radius = kRadius;
    s.objects[1].mesh.slices = 128;
    s.objects[1].mesh.stacks = 64;
    s.usesObjectList = true;
    s.ambient = {0.5f, 0.55f, 0.65f};
    s.lights = {light};
    s.shadows.enabled = true;
    s.camera.eye = {0.0f, 4.0f, 3.5f};
    s.camera.target = {0.0f, -1.0f, -0.3f};
    s.cameraGiven = true;
    s.width = 200;
    s.height = 150;
    return s;
}

// The plane point a pixel sees, if it sees the plane (not the sphere, not the sky, not past the edge).
bool planePoint(const Scene& s, const Pane& pane, int x, int y, glm::vec3& p) {
    const Ray r = pixelRay(s, pane, float(x) + 0.5f, float(y) + 0.5f);
    const float b = glm::dot(r.origin, r.direction);
    const float c = glm::dot(r.origin, r.origin) - (kRadius + 0.02f) * (kRadius + 0.02f);
    if (b * b - c > 0.0f) return false;  // the ray hits (or grazes) the sphere
    if (r.direction.y >= 0.0f) return false;
    p = r.origin + (kPlaneY - r.origin.y) / r.direction.y * r.direction;
    return std::fabs(p.x) < 3.9f && std::fabs(p.z) < 3.9f;
}

enum class Region { Lit, Umbra, Between };

// Where p is for a light made of the given points: occluded from all of them with margin (umbra),
// visible to all with margin (lit), or anything else.
Region classify(const glm::vec3& p, const std::vector<glm::vec3>& lightPoints) {
    bool allHidden = true, allVisible = true;
    for (const glm::vec3& l : lightPoints) {
        const float d = segmentDistance(p, l);
        allHidden = allHidden && d < kRadius - kMargin;
        allVisible = allVisible && d > kRadius + kMargin;
    }
    return allHidden ? Region::Umbra : allVisible ? Region::Lit : Region::Between;
}

// The light's extent as a dense grid of points (the true rectangle, not just its samples).
std::vector<glm::vec3> densePoints(const Light& l) {
    if (l.type != LightType::Area) return {l.position};
    const AreaFrame f = areaFrame(l);
    std::vector<glm::vec3> pts;
    for (int j = 0; j <= 12; ++j)
        for (int i = 0; i <= 12; ++i) pts.push_back(l.position + (float(i) / 12.0f - 0.5f) * f.u + (float(j) / 12.0f - 0.5f) * f.v);
    return pts;
}

struct RegionCounts {
    int umbra = 0, lit = 0, between = 0;
};

// Checks every plane pixel: umbra pixels carry the ambient term alone (1/255: rounding), lit pixels
// the unshadowed reference (2/255, as the other analytic tests). Returns how many of each it saw.
RegionCounts checkAgainstGeometry(const Scene& scene, const char* name) {
    const Rendered r = renderScene(scene);
    const Pane pane = layoutPanes(scene.layout, scene.shading, scene.width, scene.height)[0];
    const LightingEnvironment env = lightingEnvironment(scene);
    const Material& plane = scene.objects[0].material;
    const std::vector<glm::vec3> lightPoints = densePoints(scene.lights[0]);
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    RegionCounts n;
    for (int y = 0; y < scene.height; ++y)
        for (int x = 0; x < scene.width; ++x) {
            glm::vec3 p;
            if (!planePoint(scene, pane, x, y, p)) continue;
            const glm::ivec3 got = quantize(color(r.image, x, y));
            const ShadingTerms lit = shadeTerms(plane, env, p, up);
            switch (classify(p, lightPoints)) {
            case Region::Umbra:
                EXPECT_LE(maxChannelDifference(got, quantize(lit.ambient)), 1) << name << " umbra pixel " << x << "," << y;
                ++n.umbra;
                break;
            case Region::Lit:
                EXPECT_LE(maxChannelDifference(got, quantize(lit.total)), 2) << name << " lit pixel " << x << "," << y;
                ++n.lit;
                break;
            case Region::Between: {
                // Penumbra (or the uncertain band of a hard edge): between the two, never outside.
                const glm::ivec3 a = quantize(lit.ambient), b = quantize(lit.total);
                EXPECT_GE(got.x, std::min(a.x, b.x) - 2) << name << " " << x << "," << y;
                EXPECT_LE(got.x, std::max(a.x, b.x) + 2) << name << " " << x << "," << y;
                ++n.between;
                break;
            }
            }
        }
    if (::testing::Test::HasFailure()) saveForInspection(std::string("shadow_") + name, r.image);
    return n;
}

}  // namespace

// A point light: the plane points the sphere hides get the ambient term only, the others the full
// unshadowed value; the hard edge between them is narrow.
TEST(Shadows, PointLightHidesExactlyWhatTheSphereHides) {
    Light light;
    light.position = {0.5f, 2.2f, -1.2f};
    light.intensity = 9.0f;
    light.attenuation = Attenuation::InverseSquare;
    const Scene scene = sphereOverPlane(light);
    const RegionCounts n = checkAgainstGeometry(scene, "point");
    EXPECT_GT(n.umbra, 800);
    EXPECT_GT(n.lit, 10000);
    EXPECT_LT(n.between, n.umbra) << "a point light's shadow edge is a band of about the margin";

    // And the two points of the issue, by name: the centre of the shadow (straight behind the sphere
    // from the light) and a point as far on the other side.
    const Pane pane = layoutPanes(scene.layout, scene.shading, scene.width, scene.height)[0];
    const glm::vec3 l = light.position;
    const glm::vec3 hidden = l + (kPlaneY - l.y) / (0.0f - l.y) * (glm::vec3(0.0f) - l);
    const glm::vec3 open = glm::vec3(2.0f * l.x - hidden.x, kPlaneY, 2.0f * l.z - hidden.z);
    ASSERT_EQ(classify(hidden, {l}), Region::Umbra);
    ASSERT_EQ(classify(open, {l}), Region::Lit);
    glm::vec3 seen;
    for (const glm::vec3& p : {hidden, open}) {
        const glm::vec2 px = projectToImage(scene, pane, p);
        ASSERT_TRUE(planePoint(scene, pane, int(px.x), int(px.y), seen)) << "the camera must see the plane there";
    }
    const Rendered r = renderScene(scene);
    const LightingEnvironment env = lightingEnvironment(scene);
    for (const glm::vec3& p : {hidden, open}) {
        const glm::vec2 px = projectToImage(scene, pane, p);
        const ShadingTerms t = shadeTerms(scene.objects[0].material, env, p, {0, 1, 0});
        const glm::vec3 expected = p == hidden ? t.ambient : t.total;
        EXPECT_LE(maxChannelDifference(quantize(color(r.image, int(px.x), int(px.y))), quantize(expected)), 2);
    }
}

// A directional light: the same, with an orthographic map.
TEST(Shadows, DirectionalLightHidesExactlyWhatTheSphereHides) {
    Light light;
    light.type = LightType::Directional;
    light.direction = {-0.4f, -1.0f, -0.3f};
    light.intensity = 0.9f;
    // The light "points" are far up the light's direction: the segment test becomes a ray test.
    Scene scene = sphereOverPlane(light);
    Light far = light;
    far.type = LightType::Point;
    far.position = -1000.0f * glm::normalize(light.direction);
    const Rendered r = renderScene(scene);
    const Pane pane = layoutPanes(scene.layout, scene.shading, scene.width, scene.height)[0];
    const LightingEnvironment env = lightingEnvironment(scene);
    int umbra = 0, lit = 0;
    for (int y = 0; y < scene.height; ++y)
        for (int x = 0; x < scene.width; ++x) {
            glm::vec3 p;
            if (!planePoint(scene, pane, x, y, p)) continue;
            const ShadingTerms t = shadeTerms(scene.objects[0].material, env, p, {0, 1, 0});
            const glm::ivec3 got = quantize(color(r.image, x, y));
            const Region region = classify(p, {far.position});
            if (region == Region::Umbra) {
                EXPECT_LE(maxChannelDifference(got, quantize(t.ambient)), 1) << x << "," << y;
            } else if (region == Region::Lit) {
                EXPECT_LE(maxChannelDifference(got, quantize(t.total)), 2) << x << "," << y;
            }
            umbra += region == Region::Umbra, lit += region == Region::Lit;
        }
    EXPECT_GT(umbra, 200);
    EXPECT_GT(lit, 10000);
    if (HasFailure()) saveForInspection("shadow_directional", r.image);
}

// Area lights of two sizes, 8 x 8 samples: inside the umbra computed on the CPU (every point of the
// rectangle hidden) only ambient; outside the penumbra (every point visible) the unshadowed value;
// in between, partial values. The bigger light has the smaller umbra and the wider penumbra, on the
// CPU and in the image.
TEST(Shadows, AreaLightPenumbraGrowsWithTheLightAndLiesWhereGeometrySays) {
    RegionCounts counts[2];
    const float sizes[2] = {0.4f, 1.4f};
    for (int k = 0; k < 2; ++k) {
        Light light;
        light.type = LightType::Area;
        light.position = {0.5f, 2.2f, -1.2f};
        light.size = {sizes[k], sizes[k]};
        light.samples = {8, 8};
        light.intensity = 9.0f;
        light.attenuation = Attenuation::InverseSquare;
        counts[k] = checkAgainstGeometry(sphereOverPlane(light), k == 0 ? "area_small" : "area_large");
    }
    EXPECT_GT(counts[0].umbra, 500);
    EXPECT_GT(counts[1].between, counts[0].between * 3 / 2) << "the penumbra must widen with the light";
    EXPECT_LT(counts[1].umbra, counts[0].umbra);

    // Inside the penumbra the image is really partial: pixels whose CPU visible fraction (on a 64 x 64
    // grid over the rectangle) is between 25% and 75% are more than a tenth of the way from ambient to
    // fully lit, and from fully lit to ambient.
    Light light;
    light.type = LightType::Area;
    light.position = {0.5f, 2.2f, -1.2f};
    light.size = {1.4f, 1.4f};
    light.samples = {8, 8};
    light.intensity = 9.0f;
    light.attenuation = Attenuation::InverseSquare;
    const Scene scene = sphereOverPlane(light);
    const Rendered r = renderScene(scene);
    const Pane pane = layoutPanes(scene.layout, scene.shading, scene.width, scene.height)[0];
    const LightingEnvironment env = lightingEnvironment(scene);
    const AreaFrame f = areaFrame(light);
    int partial = 0;
    for (int y = 0; y < scene.height; y += 2)
        for (int x = 0; x < scene.width; x += 2) {
            glm::vec3 p;
            if (!planePoint(scene, pane, x, y, p)) continue;
            int visible = 0;
            for (int j = 0; j < 64; ++j)
                for (int i = 0; i < 64; ++i)
                    visible += segmentDistance(p, light.position + ((float(i) + 0.5f) / 64.0f - 0.5f) * f.u +
                                                      ((float(j) + 0.5f) / 64.0f - 0.5f) * f.v) > kRadius;
            const float fraction = float(visible) / 4096.0f;
            if (fraction < 0.25f || fraction > 0.75f) continue;
            const ShadingTerms t = shadeTerms(scene.objects[0].material, env, p, {0, 1, 0});
            const int got = quantize(color(r.image, x, y)).x, lo = quantize(t.ambient).x, hi = quantize(t.total).x;
            if (hi - lo < 20) continue;  // too dim out there for a tenth of the span to be measurable
            EXPECT_GT(got, lo + (hi - lo) / 10) << x << "," << y << " fraction " << fraction;
            EXPECT_LT(got, hi - (hi - lo) / 10) << x << "," << y << " fraction " << fraction;
            ++partial;
        }
    EXPECT_GT(partial, 100);
}

// Occlusion is per light: with two lights and one of them hidden, a shadowed pixel keeps the other
// light's share exactly.
TEST(Shadows, EachLightIsOccludedOnItsOwn) {
    Light hidden;
    hidden.position = {0.5f, 2.2f, -1.2f};
    hidden.intensity = 9.0f;
    hidden.attenuation = Attenuation::InverseSquare;
    Light side;
    side.type = LightType::Directional;
    side.direction = {1.0f, -0.4f, 0.0f};
    side.intensity = 0.5f;
    Scene scene = sphereOverPlane(hidden);
    scene.lights.push_back(side);
    const Pane pane = layoutPanes(scene.layout, scene.shading, scene.width, scene.height)[0];
    const glm::vec3 l = hidden.position;
    const glm::vec3 p = l + (kPlaneY - l.y) / (0.0f - l.y) * (glm::vec3(0.0f) - l);
    ASSERT_EQ(classify(p, {l}), Region::Umbra);
    ASSERT_EQ(classify(p, {p - 1000.0f * glm::normalize(side.direction)}), Region::Lit);
    glm::vec3 seen;
    const glm::vec2 at = projectToImage(scene, pane, p);
    ASSERT_TRUE(planePoint(scene, pane, int(at.x), int(at.y), seen)) << "the camera must see the plane there";
    const Rendered r = renderScene(scene);
    Scene onlySide = scene;
    onlySide.lights = {side};
    const glm::vec3 expected = shade(scene.objects[0].material, lightingEnvironment(onlySide), p, {0, 1, 0});
    const glm::vec2 px = projectToImage(scene, pane, p);
    EXPECT_LE(maxChannelDifference(quantize(color(r.image, int(px.x), int(px.y))), quantize(expected)), 2);
}

// Area lights and range windows without shadows: Phong pixels of a fine sphere against the CPU
// reference on the true sphere (as PhongVersusRayCast in analytic_test.cpp, same 2/255 tolerance):
// the GLSL jitter hash, sample weights and the window agree with core/shading/lighting.cpp.
TEST(AreaLights, PhongPixelsMatchTheReference) {
    Scene s;
    s.objects[0].mesh.slices = 256;
    s.objects[0].mesh.stacks = 128;
    Light area;
    area.type = LightType::Area;
    area.position = {1.5f, 2.0f, 2.0f};
    area.normal = {-0.5f, -0.6f, -0.7f};
    area.size = {2.0f, 1.2f};
    area.samples = {5, 3};
    area.intensity = 6.0f;
    area.attenuation = Attenuation::InverseSquare;
    Light windowed;
    windowed.position = {-2.0f, 0.5f, 1.5f};
    windowed.color = {0.3f, 0.5f, 1.0f};
    windowed.intensity = 5.0f;
    windowed.attenuation = Attenuation::InverseSquare;
    windowed.range = 3.5f;
    s.lights = {area, windowed};
    s.ambient = {0.3f, 0.3f, 0.3f};
    s.camera.eye = {0.3f, 0.8f, 3.2f};
    s.cameraGiven = true;
    s.width = s.height = 128;
    const Rendered r = renderScene(s);
    const Pane pane = layoutPanes(s.layout, s.shading, s.width, s.height)[0];
    const LightingEnvironment env = lightingEnvironment(s);
    int checked = 0;
    for (int y = 0; y < s.height; ++y)
        for (int x = 0; x < s.width; ++x) {
            const Ray ray = pixelRay(s, pane, float(x) + 0.5f, float(y) + 0.5f);
            const float b = glm::dot(ray.origin, ray.direction);
            const float c = glm::dot(ray.origin, ray.origin) - 1.0f;
            if (b * b - c < 0.06f * 0.06f * 4.0f) continue;  // off the sphere or near its silhouette
            const glm::vec3 p = ray.origin + (-b - std::sqrt(b * b - c)) * ray.direction;
            const glm::ivec3 expected = quantize(shade(s.objects[0].material, env, p, glm::normalize(p)));
            EXPECT_LE(maxChannelDifference(quantize(color(r.image, x, y)), expected), 2) << x << "," << y;
            ++checked;
        }
    EXPECT_GT(checked, 5000);
    if (HasFailure()) saveForInspection("area_light_reference", r.image);
}
