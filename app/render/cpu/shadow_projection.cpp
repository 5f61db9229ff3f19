#include "render/cpu/shadow_projection.hpp"

#include "core/shading/lighting.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadelab {
namespace {

// A light-space frame: rows x, y, z (z points away from the light into the scene).
struct Frame {
    glm::vec3 x, y, z;
};

std::vector<glm::vec3> corners(const std::vector<Aabb>& boxes) {
    std::vector<glm::vec3> out;
    for (const Aabb& b : boxes)
        for (int k = 0; k < 8; ++k)
            out.push_back({(k & 1) ? b.hi.x : b.lo.x, (k & 2) ? b.hi.y : b.lo.y, (k & 4) ? b.hi.z : b.lo.z});
    return out;
}

float distanceToBox(const glm::vec3& p, const Aabb& b) {
    return glm::length(glm::max(glm::max(b.lo - p, p - b.hi), glm::vec3(0.0f)));
}

// A matrix from four row vectors (GLM is column-major).
glm::mat4 fromRows(const glm::vec4& r0, const glm::vec4& r1, const glm::vec4& r2, const glm::vec4& r3) {
    return glm::transpose(glm::mat4(r0, r1, r2, r3));
}

// OpenGL depth of a perspective view with near n and far f: clip.z = A' * d - B' with w = d.
void perspectiveDepth(float n, float f, float& a, float& b) {
    a = (f + n) / (f - n);
    b = 2.0f * f * n / (f - n);
}

// Point lights: six faces. Face k looks along axis k/2 with sign +, - ; its (u, v) are the other two
// axes in the order (y, z), (z, x), (x, y): the same order pointVisibility() uses in GLSL.
void pointProjection(const Light& light, const std::vector<Aabb>& objects, ShadowProjection& sp, int pcf) {
    float farD = 0.0f, nearD = std::numeric_limits<float>::max();
    for (const glm::vec3& c : corners(objects)) farD = std::max(farD, glm::length(c - light.position));
    for (const Aabb& b : objects) nearD = std::min(nearD, distanceToBox(light.position, b));
    farD = std::max(farD * 1.01f, 1e-3f);
    nearD = std::clamp(nearD * 0.9f, farD * 2e-3f, farD * 0.5f);
    // Margin: pcf + 2 texels on each side are rendered beyond the face's 90 degrees.
    const float margin = float(pcf + 2);
    sp.tanHalf = float(sp.size) / (float(sp.size) - 2.0f * margin);
    float a, b;
    perspectiveDepth(nearD, farD, a, b);
    sp.depthA = 0.5f * a + 0.5f;
    sp.depthB = 0.5f * b;
    sp.texelWorld = 2.0f * sp.tanHalf / float(sp.size);
    static const int kUv[3][2] = {{1, 2}, {2, 0}, {0, 1}};
    for (int face = 0; face < 6; ++face) {
        const int axis = face / 2;
        const float sign = face % 2 == 0 ? 1.0f : -1.0f;
        glm::vec3 w(0.0f), u(0.0f), v(0.0f);
        w[axis] = sign;
        u[kUv[axis][0]] = 1.0f / sp.tanHalf;
        v[kUv[axis][1]] = 1.0f / sp.tanHalf;
        // Rows act on d = p - light: row . p - row . light.
        auto row = [&](const glm::vec3& r, float constant) {
            return glm::vec4(r, constant - glm::dot(r, light.position));
        };
        sp.clipFromWorld.push_back(fromRows(row(u, 0.0f), row(v, 0.0f), row(a * w, -b), row(w, 0.0f)));
    }
}

void directionalProjection(const Light& light, const std::vector<Aabb>& objects, ShadowProjection& sp) {
    const glm::vec3 z = glm::normalize(light.direction);
    const glm::vec3 ref = std::fabs(z.y) > 0.99f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    const glm::vec3 x = glm::normalize(glm::cross(ref, z));
    const glm::vec3 y = glm::cross(z, x);
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const glm::vec3& c : corners(objects)) {
        const glm::vec3 l(glm::dot(c, x), glm::dot(c, y), glm::dot(c, z));
        lo = glm::min(lo, l);
        hi = glm::max(hi, l);
    }
    if (objects.empty()) {
        lo = glm::vec3(-1.0f);
        hi = glm::vec3(1.0f);
    }
    // Square texels: the larger extent sets the scale; a little slack so nothing sits on the border.
    const float half = 0.5f * std::max({hi.x - lo.x, hi.y - lo.y, 1e-3f}) * 1.02f;
    const glm::vec2 mid = 0.5f * (glm::vec2(lo) + glm::vec2(hi));
    const float depthPad = 0.01f * (hi.z - lo.z) + 1e-3f;
    const float n = lo.z - depthPad, f = hi.z + depthPad;
    // clip.x = (x.p - mid.x) / half; clip.z = 2 (z.p - n) / (f - n) - 1
    sp.clipFromWorld.push_back(fromRows(glm::vec4(x / half, -mid.x / half), glm::vec4(y / half, -mid.y / half),
                                        glm::vec4(2.0f * z / (f - n), -2.0f * n / (f - n) - 1.0f),
                                        glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)));
    sp.texelWorld = 2.0f * half / float(sp.size);
}

void areaProjection(const Light& light, const std::vector<Aabb>& objects, ShadowProjection& sp) {
    const AreaFrame af = areaFrame(light);
    // Looks along the emitting normal. A two-sided light looks toward the side the objects are on
    // (its other side gets no shadows: README, "not supported").
    glm::vec3 z = af.n;
    if (light.twoSided) {
        float side = 0.0f;
        for (const glm::vec3& c : corners(objects)) side += glm::dot(c - light.position, z);
        if (side < 0.0f) z = -z;
    }
    const glm::vec3 x = glm::normalize(af.u), y = glm::cross(z, x);
    const float halfW = 0.5f * light.size.x, halfH = 0.5f * light.size.y;
    // Every corner in front of the light must be inside the frustum seen from any sample: the
    // tangents are taken from the nearest edge of the rectangle. Capped at 75 degrees half-angle:
    // points beyond it (nearly in the light's plane, where cos at the light is ~0) count as lit.
    const float maxTan = 3.73f;
    float tanX = 0.05f, tanY = 0.05f, farZ = 0.0f, nearZ = std::numeric_limits<float>::max();
    for (const glm::vec3& c : corners(objects)) {
        const glm::vec3 d = c - light.position;
        const float cz = glm::dot(d, z);
        farZ = std::max(farZ, cz);
        if (cz <= 0.0f) continue;
        tanX = std::max(tanX, (std::fabs(glm::dot(d, x)) + halfW) / cz);
        tanY = std::max(tanY, (std::fabs(glm::dot(d, y)) + halfH) / cz);
    }
    for (const Aabb& b : objects) nearZ = std::min(nearZ, distanceToBox(light.position, b));
    tanX = std::min(tanX * 1.02f, maxTan);
    tanY = std::min(tanY * 1.02f, maxTan);
    farZ = std::max(farZ * 1.01f, 1e-3f);
    // Seen from a sample off the centre, points can be nearer than they are to the centre.
    const float nearD =
        std::clamp(0.9f * (nearZ - std::sqrt(halfW * halfW + halfH * halfH)), farZ * 2e-3f, farZ * 0.5f);
    float a, b;
    perspectiveDepth(nearD, farZ, a, b);
    // View space: (x, y, -z) (OpenGL looks down -z); clip = P * view.
    auto row = [&](const glm::vec3& r, float constant) { return glm::vec4(r, constant - glm::dot(r, light.position)); };
    sp.centreClipFromWorld = fromRows(row(x / tanX, 0.0f), row(y / tanY, 0.0f), row(a * z, -b), row(z, 0.0f));
    sp.uClip = sp.centreClipFromWorld * glm::vec4(af.u, 0.0f);
    sp.vClip = sp.centreClipFromWorld * glm::vec4(af.v, 0.0f);
    sp.texelWorld = 2.0f * std::max(tanX, tanY) / float(sp.size);
    for (int j = 0; j < light.samples.y; ++j)
        for (int i = 0; i < light.samples.x; ++i) {
            const glm::vec2 o = areaSampleOffset(i, j, light.samples);
            sp.clipFromWorld.push_back(sp.centreClipFromWorld *
                                       glm::translate(glm::mat4(1.0f), -(o.x * af.u + o.y * af.v)));
        }
}

// Spot light: one perspective view down its axis, wide enough for the outer cone plus a few texels
// (so filtering at the cone's edge stays inside), capped at 85 degrees half-angle: an outer cone
// beyond that is lit without shadows past 85 degrees (README, "not supported").
void spotProjection(const Light& light, const std::vector<Aabb>& objects, ShadowProjection& sp, int pcf) {
    const glm::vec3 z = glm::normalize(light.direction);
    const glm::vec3 ref = std::fabs(z.y) > 0.99f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    const glm::vec3 x = glm::normalize(glm::cross(ref, z));
    const glm::vec3 y = glm::cross(z, x);
    const float coneDeg = std::min(light.outerConeDeg, 85.0f), cone = std::tan(glm::radians(coneDeg));
    sp.tanHalf = cone * float(sp.size) / (float(sp.size) - 2.0f * float(pcf + 2));
    float farZ = 0.0f, nearZ = std::numeric_limits<float>::max();
    for (const glm::vec3& c : corners(objects)) farZ = std::max(farZ, glm::dot(c - light.position, z));
    for (const Aabb& b : objects) nearZ = std::min(nearZ, distanceToBox(light.position, b));
    farZ = std::max(farZ * 1.01f, 1e-3f);
    // The nearest object may lie off the axis, inside the cone: its depth along the axis is as small as
    // its distance times the cosine of the cone.
    const float nearD = std::clamp(0.9f * nearZ * std::cos(glm::radians(coneDeg)), farZ * 2e-3f, farZ * 0.5f);
    float a, b;
    perspectiveDepth(nearD, farZ, a, b);
    // View space: (x, y, -z) (OpenGL looks down -z); clip = P * view, w = the distance along the axis.
    auto row = [&](const glm::vec3& r, float constant) { return glm::vec4(r, constant - glm::dot(r, light.position)); };
    sp.clipFromWorld.push_back(
        fromRows(row(x / sp.tanHalf, 0.0f), row(y / sp.tanHalf, 0.0f), row(a * z, -b), row(z, 0.0f)));
    sp.texelWorld = 2.0f * sp.tanHalf / float(sp.size);
}

}  // namespace

Aabb transformAabb(const Aabb& box, const glm::mat4& m) {
    Aabb out{glm::vec3(std::numeric_limits<float>::max()), glm::vec3(-std::numeric_limits<float>::max())};
    for (const glm::vec3& c : corners({box})) {
        const glm::vec3 w(m * glm::vec4(c, 1.0f));
        out.lo = glm::min(out.lo, w);
        out.hi = glm::max(out.hi, w);
    }
    return out;
}

int cubeFace(const glm::vec3& d) {
    const glm::vec3 a = glm::abs(d);
    if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0f ? 0 : 1;
    if (a.y >= a.z) return d.y >= 0.0f ? 2 : 3;
    return d.z >= 0.0f ? 4 : 5;
}

ShadowProjection shadowProjection(const Light& light, const std::vector<Aabb>& objects, const ShadowSettings& s) {
    ShadowProjection sp;
    switch (light.type) {
    case LightType::Point:
        sp.size = s.mapSize;
        pointProjection(light, objects, sp, s.pcf);
        break;
    case LightType::Directional:
        sp.size = s.mapSize;
        directionalProjection(light, objects, sp);
        break;
    case LightType::Area:
        sp.size = s.areaMapSize;
        areaProjection(light, objects, sp);
        break;
    case LightType::Spot:
        sp.size = s.mapSize;
        spotProjection(light, objects, sp, s.pcf);
        break;
    }
    return sp;
}

int shadowLayerCount(const Light& light) {
    switch (light.type) {
    case LightType::Point: return 6;
    case LightType::Area: return light.samples.x * light.samples.y;
    case LightType::Directional:
    case LightType::Spot: return 1;
    }
    return 1;
}

ShadowLayout shadowLayout(const std::vector<Light>& lights, std::size_t count) {
    ShadowLayout layout;
    for (std::size_t l = 0; l < count && l < lights.size(); ++l) {
        int& next = lights[l].type == LightType::Area ? layout.areaLayers : layout.layers;
        layout.firstLayer.push_back(next);
        next += shadowLayerCount(lights[l]);
    }
    return layout;
}

}  // namespace shadelab
