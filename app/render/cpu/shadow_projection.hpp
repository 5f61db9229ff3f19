#pragma once
// Where each light's shadow maps look (GL-free, so it is unit-tested and the analytic tests can
// reason about texel sizes). Every light gets one depth texture array; each layer is a view with its
// own clipFromWorld:
//   point        six cube faces around the light (90 degrees plus a margin of a few texels, so
//                filtering near a face edge stays inside the face); the shader picks the face by the
//                major axis of p - light and needs no matrices (ShadowProjection::depthA/B, tanHalf)
//   directional  one orthographic view along the light, fitted to the objects' bounds
//   spot         one perspective view down the light's axis, as wide as its outer cone
//   area         one perspective view per sample, all with the same orientation and field of view
//                (fitted so that the objects in front of the light are inside from every sample):
//                sample (a, b) sees p as centreClipFromWorld * p - a * uClip - b * vClip
#include "core/scene/scene.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <vector>

namespace shadelab {

struct Aabb {
    glm::vec3 lo{0.0f};
    glm::vec3 hi{0.0f};
};
// The world-space box around an object-space box after a transform (its eight corners transformed).
Aabb transformAabb(const Aabb& objectBox, const glm::mat4& worldFromObject);

struct ShadowProjection {
    int size = 0;                          // texels per side of each layer
    std::vector<glm::mat4> clipFromWorld;  // one per layer; what the depth pass renders
    // A texel's world-space size: per unit of distance from the light (point, spot, area), or absolute
    // (directional). The normal bias is given in texels and multiplied by this.
    float texelWorld = 0.0f;
    // Point lights: stored depth = depthA - depthB / d, with d the major-axis distance from the light;
    // a face's half field of view has tangent tanHalf (slightly over 1: the margin).
    float depthA = 0.0f, depthB = 0.0f, tanHalf = 1.0f;
    // Area lights: the view of the rectangle's centre and the clip-space images of its edges.
    glm::mat4 centreClipFromWorld{1.0f};
    glm::vec4 uClip{0.0f}, vClip{0.0f};
};

// How many layers a light's shadow map has: six cube faces (point), one view (spot, directional), one
// per sample (area): the length of shadowProjection(light, ...).clipFromWorld.
int shadowLayerCount(const Light& light);

// Where the lights' layers go: point, spot and directional lights share one depth texture array
// (ShadowSettings::mapSize), area lights a second (areaMapSize); each light's layers are consecutive,
// from firstLayer[l] in its array. The shaders take firstLayer as constants (shaders/shadows.glsl).
struct ShadowLayout {
    std::vector<int> firstLayer;  // per light
    int layers = 0;               // in the point/spot/directional array
    int areaLayers = 0;           // in the area array
};
ShadowLayout shadowLayout(const std::vector<Light>& lights, std::size_t count);  // the first `count` lights

// `objects` are the world-space boxes of everything that casts or receives shadows.
ShadowProjection shadowProjection(const Light& light, const std::vector<Aabb>& objects, const ShadowSettings& settings);

// Which cube face (0..5: +x, -x, +y, -y, +z, -z) a point light's map uses for direction d = p - light,
// as the shader picks it (shaders/lighting.glsl, pointVisibility).
int cubeFace(const glm::vec3& d);

}  // namespace shadelab
