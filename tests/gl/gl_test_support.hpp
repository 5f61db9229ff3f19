#pragma once
// Helpers for the GL tests: headless renders and the pixel <-> world mapping that lets a test
// compare a pixel with the CPU reference at the surface point that pixel sees.
#include "core/geometry/camera.hpp"
#include "core/image/image.hpp"
#include "core/scene/scene.hpp"
#include "core/geometry/scene_geometry.hpp"
#include "headless/headless_context.hpp"
#include "core/geometry/ray_cast.hpp"
#include "core/probe/probe.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <memory>
#include <string>

namespace shadelab::test {

// The headless backend the GL tests run on: SHADELAB_TEST_BACKEND=osmesa|egl (CTest registers the GL
// tests once for each backend the build has), else OSMesa where the build has it, else EGL.
HeadlessBackend backendUnderTest();

// The default object at the origin under three lights of the kinds a scene can mix, so the GPU loop
// over lights is checked, not just one: a white point light, a blue inverse-square one and a warm
// directional one; a bluish ambient; the camera at (0.3, 0.8, 3.2) looking at the origin.
Scene threeLightScene();

struct Rendered {
    Scene scene;
    std::shared_ptr<SceneGeometry> geometry;
    Image image;
};
Rendered renderScene(const Scene& scene);

// A pixel's colour as floats in [0, 1].
glm::vec3 color(const Image& image, int x, int y);
// The 8-bit value GL stores for a float colour (round to nearest).
glm::ivec3 quantize(const glm::vec3& c);
// A w x h image of one opaque colour (8-bit RGB, alpha 255): what a blank render is compared with.
Image filled(int w, int h, const glm::ivec3& rgb = glm::ivec3(0));

struct Ray {
    glm::vec3 origin;
    glm::vec3 direction;  // unit
};
// The ray through image point (px, py) (pixel centres at +0.5) of a pane.
Ray pixelRay(const Scene& scene, const Pane& pane, float px, float py);
// Where a world point lands in the image (continuous pixel coordinates, y down).
glm::vec2 projectToImage(const Scene& scene, const Pane& pane, const glm::vec3& world);

// Whether probed pixel (x, y) of a flat pane lies inside its triangle: the pixels 2 away in each
// direction hit the same triangle in the same pane (a flat colour is exact only there: the rasteriser
// and the probe may give an edge pixel to different triangles).
bool flatInterior(const Scene& scene, const SceneGeometry& geometry, const SceneRayCaster& caster, const ProbeResult& probe,
                  int x, int y);

// Writes an image under the test output folder so a person can look at it; returns the path.
std::string saveForInspection(const std::string& name, const Image& image);

}  // namespace shadelab::test
