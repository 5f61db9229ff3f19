#include "gl/gl_test_support.hpp"

#include "headless/headless.hpp"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <utility>

namespace shadelab::test {

HeadlessBackend backendUnderTest() {
    const char* b = std::getenv("SHADELAB_TEST_BACKEND");
    if (b) return std::string(b) == "egl" ? HeadlessBackend::Egl : HeadlessBackend::OsMesa;
    return SHADELAB_HAVE_OSMESA ? HeadlessBackend::OsMesa : HeadlessBackend::Egl;  // what this build has
}

Scene threeLightScene() {
    Scene s;
    Light key;
    key.position = {2.0f, 3.0f, 4.0f};
    Light fill;
    fill.position = {-2.5f, 0.5f, 1.5f};
    fill.color = {0.3f, 0.5f, 1.0f};
    fill.intensity = 6.0f;
    fill.attenuation = Attenuation::InverseSquare;
    Light rim;
    rim.type = LightType::Directional;
    rim.direction = {0.5f, -0.2f, -1.0f};
    rim.color = {1.0f, 0.9f, 0.6f};
    rim.intensity = 0.4f;
    s.lights = {key, fill, rim};
    s.ambient = {0.6f, 0.6f, 0.7f};
    s.camera.eye = {0.3f, 0.8f, 3.2f};
    s.camera.target = {0.0f, 0.0f, 0.0f};
    s.cameraGiven = true;
    return s;
}

Rendered renderScene(const Scene& scene) {
    Rendered r;
    r.scene = scene;
    r.geometry = std::make_shared<SceneGeometry>(buildSceneGeometry(scene));
    r.image = renderHeadless(scene, r.geometry, ShaderLibrary(), backendUnderTest());
    return r;
}

glm::vec3 color(const Image& image, int x, int y) {
    const std::uint8_t* p = image.pixel(x, y);
    return glm::vec3(p[0], p[1], p[2]) / 255.0f;
}

glm::ivec3 quantize(const glm::vec3& c) {
    return glm::ivec3(int(std::lround(c.x * 255.0f)), int(std::lround(c.y * 255.0f)), int(std::lround(c.z * 255.0f)));
}

Image filled(int w, int h, const glm::ivec3& rgb) {
    Image img(w, h);
    for (std::size_t i = 0; i < img.rgba.size(); i += 4) {
        img.rgba[i] = std::uint8_t(rgb.x), img.rgba[i + 1] = std::uint8_t(rgb.y), img.rgba[i + 2] = std::uint8_t(rgb.z);
        img.rgba[i + 3] = 255;
    }
    return img;
}

Ray pixelRay(const Scene& s, const Pane& pane, float px, float py) {
    const glm::mat4 clipFromWorld = clipFromView(s.camera, float(pane.width) / float(pane.height)) * viewFromWorld(s.camera);
    const glm::mat4 worldFromClip = glm::inverse(clipFromWorld);
    const float ndcX = 2.0f * (px - float(pane.x)) / float(pane.width) - 1.0f;
    const float ndcY = 1.0f - 2.0f * (py - float(pane.y)) / float(pane.height);
    glm::vec4 nearPt = worldFromClip * glm::vec4(ndcX, ndcY, -1.0f, 1.0f);
    glm::vec4 farPt = worldFromClip * glm::vec4(ndcX, ndcY, 1.0f, 1.0f);
    nearPt /= nearPt.w;
    farPt /= farPt.w;
    return Ray{s.camera.eye, glm::normalize(glm::vec3(farPt) - glm::vec3(nearPt))};
}

glm::vec2 projectToImage(const Scene& s, const Pane& pane, const glm::vec3& world) {
    const glm::mat4 clipFromWorld = clipFromView(s.camera, float(pane.width) / float(pane.height)) * viewFromWorld(s.camera);
    const glm::vec4 clip = clipFromWorld * glm::vec4(world, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {float(pane.x) + (ndc.x + 1.0f) * 0.5f * float(pane.width),
            float(pane.y) + (1.0f - ndc.y) * 0.5f * float(pane.height)};
}

std::string saveForInspection(const std::string& name, const Image& image) {
    const std::string path = std::string(SHADELAB_TEST_OUTPUT_DIR) + "/" + name + ".png";
    std::filesystem::create_directories(std::filesystem::path(path).parent_path());
    writePng(path, image);
    return path;
}

bool flatInterior(const Scene& scene, const SceneGeometry& geometry, const SceneRayCaster& caster, const ProbeResult& probe,
                  int x, int y) {
    for (const auto& [dx, dy] : {std::pair{-2, 0}, std::pair{2, 0}, std::pair{0, -2}, std::pair{0, 2}}) {
        const ProbeResult n = probePixel(scene, geometry, caster, x + dx, y + dy);
        if (n.miss || n.pane != probe.pane || n.anchor.triangle != probe.anchor.triangle) return false;
    }
    return true;
}

}  // namespace shadelab::test
