#include "core/scene/scene.hpp"

#include "core/scene/scene_names.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <sstream>

namespace shadelab {

bool MeshSpec::operator==(const MeshSpec& o) const {
    if (type != o.type) return false;
    switch (type) {
    case Type::UvSphere: return slices == o.slices && stacks == o.stacks && radius == o.radius;
    case Type::IcoSphere: return subdivisions == o.subdivisions && radius == o.radius;
    case Type::Torus:
        return majorRadius == o.majorRadius && minorRadius == o.minorRadius && majorSegments == o.majorSegments &&
               minorSegments == o.minorSegments;
    case Type::Cube: return size == o.size;
    case Type::Plane: return size == o.size && planeSubdivisions == o.planeSubdivisions;
    case Type::Gltf: return resolvedPath == o.resolvedPath;
    }
    return false;
}

const char* toString(ShadingMode m) { return nameOf(kShadingModeNames, m); }
const char* toString(Layout l) { return nameOf(kLayoutNames, l); }
const char* toString(ReflectionModel r) { return nameOf(kReflectionModelNames, r); }
const char* toString(MeshSpec::Type t) { return nameOf(kMeshTypeNames, t); }
const char* toString(Attenuation a) { return nameOf(kAttenuationNames, a); }
const char* toString(LightType t) { return nameOf(kLightTypeNames, t); }

bool ShadowSettings::operator==(const ShadowSettings& o) const {
    return enabled == o.enabled && normalBias == o.normalBias && depthBias == o.depthBias && pcf == o.pcf &&
           mapSize == o.mapSize && areaMapSize == o.areaMapSize;
}
const char* toString(OutputEncoding e) { return nameOf(kOutputEncodingNames, e); }
const char* toString(SpecularNormalization n) { return nameOf(kSpecularNormalizationNames, n); }
const char* toString(FresnelMode f) { return nameOf(kFresnelModeNames, f); }
const char* toString(EnvironmentKind k) { return k == EnvironmentKind::Image ? "image" : nameOf(kEnvironmentNames, k); }
std::string toString(const TermView& t) {
    return t.term == ShowTerm::Light ? "light:" + std::to_string(t.light) : nameOf(kShowTermNames, t.term);
}

float directionalHandleDistance(const Camera& camera) { return 0.6f * glm::length(camera.eye - camera.target); }

glm::vec3 lightHandle(const Light& light, const Camera& camera) {
    if (light.type != LightType::Directional) return light.position;
    return camera.target - glm::normalize(light.direction) * directionalHandleDistance(camera);
}

std::string formatNumber(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

// The camera keeps its vertical field of view, so the picture scales with the view's height about its
// centre.
glm::ivec2 ViewerStart::probeIn(int width, int height) const {
    const glm::vec2 of(probeOf);
    const glm::vec2 view{float(width), float(height)};
    const glm::vec2 p = 0.5f * view + (glm::vec2(*probe) + 0.5f - 0.5f * of) * (view.y / of.y);
    return glm::clamp(glm::ivec2(glm::floor(p)), glm::ivec2(0), glm::ivec2(width - 1, height - 1));
}

}  // namespace shadelab
