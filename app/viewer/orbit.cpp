#include "viewer/orbit.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadelab {

void orbitCamera(Camera& c, float yawRad, float pitchRad) {
    const glm::vec3 up = glm::normalize(c.up);
    glm::vec3 offset = c.eye - c.target;  // target -> eye
    const float dist = glm::length(offset);
    if (dist <= 0.0f) return;
    offset = glm::angleAxis(yawRad, up) * offset;
    // Pitch about the right vector, clamped so the eye never reaches the pole of `up`.
    const float polar = std::acos(std::clamp(glm::dot(offset / dist, up), -1.0f, 1.0f));  // 0: straight above
    const float minPolar = glm::radians(1.0f), maxPolar = glm::radians(179.0f);
    const float newPolar = std::clamp(polar - pitchRad, minPolar, maxPolar);
    const glm::vec3 right = glm::normalize(glm::cross(up, offset));
    offset = glm::angleAxis(newPolar - polar, right) * offset;
    c.eye = c.target + offset;
}

void panCamera(Camera& c, float dx, float dy, float viewHeight) {
    const glm::vec3 forward = c.target - c.eye;
    const float dist = glm::length(forward);
    if (dist <= 0.0f || viewHeight <= 0.0f) return;
    const glm::vec3 right = glm::normalize(glm::cross(forward, c.up));
    const glm::vec3 up = glm::cross(right, forward / dist);
    // World units per pixel at the target's depth.
    const float perPixel = 2.0f * dist * std::tan(glm::radians(c.fovYDeg) / 2.0f) / viewHeight;
    const glm::vec3 move = (-dx * right + dy * up) * perPixel;
    c.eye += move;
    c.target += move;
}

void zoomCamera(Camera& c, float wheelSteps, float minDistance, float maxDistance) {
    const glm::vec3 offset = c.eye - c.target;
    const float dist = glm::length(offset);
    if (dist <= 0.0f) return;
    const float newDist =
        std::clamp(dist * std::pow(0.9f, wheelSteps), minDistance, std::max(minDistance, maxDistance));
    c.eye = c.target + offset * (newDist / dist);
}

void fitClipPlanes(Camera& c, const BoundingSphere& b, const std::vector<glm::vec3>& points) {
    const glm::vec3 forward = c.target - c.eye;
    if (glm::length(forward) <= 0.0f) return;
    const glm::vec3 f = glm::normalize(forward);
    // Depths along the viewing axis: the sphere spans its centre's depth +- its radius.
    const float centre = glm::dot(b.center - c.eye, f);
    const float modelFar = std::max((centre + b.radius) * 1.5f, 1e-3f);
    float lightsFar = 0.0f, nearest = centre - b.radius;
    for (const glm::vec3& p : points) {
        const float z = glm::dot(p - c.eye, f);
        lightsFar = std::max(lightsFar, z * 1.01f);
        if (z > 0.0f) nearest = std::min(nearest, z);
    }
    // Near from the model (and lights nearer than it), with slack for what is drawn beyond the surfaces:
    // the probe's arrows (a share of the distance to the eye), normals, markers; at least 1/10^4 of the
    // model's far side (24-bit depth). Far takes in the lights, but a very distant light never pushes
    // near into the model: far stops at 10^5 times near (its marker is then not drawn).
    c.nearPlane = std::max(nearest * 0.5f, modelFar * 1e-4f);
    c.farPlane = std::min(std::max(modelFar, lightsFar), c.nearPlane * 1e5f);
}

float fitDistance(const Camera& c, const BoundingSphere& b, float paneAspect, float margin) {
    glm::vec3 dir = c.eye - c.target;
    dir = glm::length(dir) > 0.0f ? glm::normalize(dir) : glm::vec3(0.0f, 0.0f, 1.0f);
    const float radius = b.radius > 0.0f ? b.radius : 1.0f;
    // Half angles shrunk by the margin: a narrower field of view to fit into.
    Camera probe = c;
    probe.fovYDeg = glm::degrees(2.0f * std::atan(std::tan(glm::radians(c.fovYDeg) / 2.0f) * margin));
    const float aspect = paneAspect;
    auto fits = [&](float d) {
        probe.eye = c.target + d * dir;
        probe.nearPlane = 0.0f;
        probe.farPlane = std::numeric_limits<float>::max();
        return sphereInView(probe, b, aspect);
    };
    // Far enough to fit from any target within reach, then bisect: fitting only gets easier with distance.
    float lo = 0.0f, hi = glm::length(b.center - c.target) + radius;
    while (!fits(hi) && hi < 1e12f) hi *= 2.0f;
    for (int i = 0; i < 60; ++i) {
        const float mid = 0.5f * (lo + hi);
        (fits(mid) ? hi : lo) = mid;
    }
    return hi;
}

void frameCamera(Camera& c, const BoundingSphere& b, float paneAspect) {
    const float radius = b.radius > 0.0f ? b.radius : 1.0f;
    const float halfY = glm::radians(c.fovYDeg) / 2.0f;
    const float halfX = std::atan(std::tan(halfY) * std::max(paneAspect, 1e-3f));
    // Same rule as frameBounds() in core/geometry/camera.cpp: the silhouette subtends asin(r / d).
    const float dist = radius / std::sin(0.9f * std::min(halfX, halfY));
    glm::vec3 dir = c.eye - c.target;
    dir = glm::length(dir) > 0.0f ? glm::normalize(dir) : glm::vec3(0.0f, 0.0f, 1.0f);
    c.target = b.center;
    c.eye = b.center + dist * dir;
    c.nearPlane = std::max(dist - 2.0f * radius, dist * 1e-3f);
    c.farPlane = dist + 4.0f * radius;
}

bool sphereInView(const Camera& c, const BoundingSphere& b, float paneAspect) {
    const glm::vec3 forward = c.target - c.eye;
    if (glm::length(forward) <= 0.0f) return false;
    const glm::vec3 f = glm::normalize(forward);
    const glm::vec3 r = glm::normalize(glm::cross(f, c.up));
    const glm::vec3 u = glm::cross(r, f);
    const glm::vec3 d = b.center - c.eye;
    const float x = glm::dot(d, r), y = glm::dot(d, u), z = glm::dot(d, f);  // view space, z forward
    if (z - b.radius < c.nearPlane || z + b.radius > c.farPlane) return false;
    // Distance from the centre to each side plane of the frustum must be at least the radius.
    const float tanY = std::tan(glm::radians(c.fovYDeg) / 2.0f), tanX = tanY * paneAspect;
    const auto inside = [&](float offAxis, float tanHalf) {
        return (tanHalf * z - std::fabs(offAxis)) / std::sqrt(1.0f + tanHalf * tanHalf) >= b.radius;
    };
    return inside(x, tanX) && inside(y, tanY);
}

}  // namespace shadelab
