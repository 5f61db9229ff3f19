#include "core/geometry/camera.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadelab {

glm::mat4 viewFromWorld(const Camera& c) { return glm::lookAt(c.eye, c.target, c.up); }

glm::mat4 clipFromView(const Camera& c, float aspect) {
    return glm::perspective(glm::radians(c.fovYDeg), aspect, c.nearPlane, c.farPlane);
}

glm::mat4 worldFromObject(const Transform& t) {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), t.translation);
    m = glm::rotate(m, glm::radians(t.rotationDeg.z), glm::vec3(0, 0, 1));
    m = glm::rotate(m, glm::radians(t.rotationDeg.y), glm::vec3(0, 1, 0));
    m = glm::rotate(m, glm::radians(t.rotationDeg.x), glm::vec3(1, 0, 0));
    return glm::scale(m, t.scale);
}

glm::mat3 normalWorldFromObject(const glm::mat4& m) { return glm::transpose(glm::inverse(glm::mat3(m))); }

std::vector<Pane> layoutPanes(Layout layout, ShadingMode mode, int width, int height, const DiffSettings& diff) {
    if (layout == Layout::Single) return {Pane{0, 0, width, height, mode, false}};
    std::vector<Pane> panes;
    if (layout == Layout::Diff) {
        const int w = width / 3;
        panes.push_back(Pane{0, 0, w, height, diff.a, false});
        panes.push_back(Pane{w, 0, w, height, diff.b, false});
        panes.push_back(Pane{2 * w, 0, w, height, diff.b, true});
        return panes;
    }
    const ShadingMode modes[3] = {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong};
    for (int i = 0; i < 3; ++i) {
        // Pane edges at floor(i * W / 3): the three panes cover the image exactly, widths differ by <= 1.
        const int x0 = i * width / 3, x1 = (i + 1) * width / 3;
        panes.push_back(Pane{x0, 0, x1 - x0, height, modes[i], false});
    }
    return panes;
}

std::size_t scenePaneCount(Layout layout) {
    const std::vector<Pane> panes = layoutPanes(layout, ShadingMode::Phong, 3, 1);
    return std::size_t(std::count_if(panes.begin(), panes.end(), [](const Pane& p) { return !p.difference; }));
}

glm::vec3 pixelDirectionWorld(const Camera& c, const Pane& pane, float px, float py) {
    const float aspect = float(pane.width) / float(std::max(pane.height, 1));
    const glm::mat4 worldFromClip = glm::inverse(clipFromView(c, aspect) * viewFromWorld(c));
    const float ndcX = 2.0f * (px - float(pane.x)) / float(pane.width) - 1.0f;
    const float ndcY = 1.0f - 2.0f * (py - float(pane.y)) / float(pane.height);
    glm::vec4 nearWorld = worldFromClip * glm::vec4(ndcX, ndcY, -1.0f, 1.0f);
    glm::vec4 farWorld = worldFromClip * glm::vec4(ndcX, ndcY, 1.0f, 1.0f);
    return glm::normalize(glm::vec3(farWorld) / farWorld.w - glm::vec3(nearWorld) / nearWorld.w);
}

namespace {
glm::mat4 paneClipFromWorld(const Camera& c, const Pane& pane) {
    return clipFromView(c, float(pane.width) / float(std::max(pane.height, 1))) * viewFromWorld(c);
}
glm::vec3 imageFromClip(const Pane& pane, const glm::vec4& clip) {
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {float(pane.x) + (ndc.x + 1.0f) * 0.5f * float(pane.width),
            float(pane.y) + (1.0f - ndc.y) * 0.5f * float(pane.height), clip.w};
}
}  // namespace

glm::vec3 projectToImage(const Camera& c, const Pane& pane, const glm::vec3& posWorld) {
    return imageFromClip(pane, paneClipFromWorld(c, pane) * glm::vec4(posWorld, 1.0f));
}

float projectedBoxPixels(const Camera& c, const Pane& pane, const glm::vec3& lo, const glm::vec3& hi) {
    const float paneArea = float(pane.width) * float(pane.height);
    const glm::mat4 clipFromWorld = paneClipFromWorld(c, pane);
    glm::vec2 a(std::numeric_limits<float>::max()), b(-std::numeric_limits<float>::max());
    for (int k = 0; k < 8; ++k) {
        const glm::vec3 corner((k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z);
        const glm::vec3 image = imageFromClip(pane, clipFromWorld * glm::vec4(corner, 1.0f));
        if (!(image.z > 0.0f)) return paneArea;
        a = glm::min(a, glm::vec2(image));
        b = glm::max(b, glm::vec2(image));
    }
    a = glm::max(a, glm::vec2(float(pane.x), float(pane.y)));
    b = glm::min(b, glm::vec2(float(pane.x + pane.width), float(pane.y + pane.height)));
    return std::min(paneArea, std::max(0.0f, b.x - a.x) * std::max(0.0f, b.y - a.y));
}

void frameBounds(Scene& scene, const BoundingSphere& b, float paneAspect) {
    const Camera defaults;
    const float radius = b.radius > 0.0f ? b.radius : 1.0f;
    const float halfY = glm::radians(scene.camera.fovYDeg) / 2.0f;
    const float halfX = std::atan(std::tan(halfY) * paneAspect);
    // The sphere's silhouette subtends asin(r / d); leave 10% room on the tighter side.
    const float dist = radius / std::sin(0.9f * std::min(halfX, halfY));
    const glm::vec3 dir = glm::normalize(defaults.eye - defaults.target);
    scene.camera.target = b.center;
    scene.camera.eye = b.center + dist * dir;
    scene.camera.up = defaults.up;
    scene.camera.nearPlane = std::max(dist - 2.0f * radius, dist * 1e-3f);
    scene.camera.farPlane = dist + 4.0f * radius;
    if (!scene.lightsGiven)
        for (Light& l : scene.lights)
            if (l.type == LightType::Point) l.position = b.center + radius * Light{}.position;
}

}  // namespace shadelab
