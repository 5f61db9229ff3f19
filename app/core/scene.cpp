#include "core/scene.hpp"

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

const char* toString(ShadingMode m) {
    switch (m) {
    case ShadingMode::Flat: return "flat";
    case ShadingMode::Gouraud: return "gouraud";
    case ShadingMode::Phong: return "phong";
    }
    return "?";
}
const char* toString(Layout l) {
    switch (l) {
    case Layout::Single: return "single";
    case Layout::Compare: return "compare";
    case Layout::Diff: return "diff";
    }
    return "?";
}
const char* toString(ReflectionModel r) { return r == ReflectionModel::Phong ? "phong" : "blinn-phong"; }
const char* toString(MeshSpec::Type t) {
    switch (t) {
    case MeshSpec::Type::UvSphere: return "uvsphere";
    case MeshSpec::Type::IcoSphere: return "icosphere";
    case MeshSpec::Type::Torus: return "torus";
    case MeshSpec::Type::Cube: return "cube";
    case MeshSpec::Type::Plane: return "plane";
    case MeshSpec::Type::Gltf: return "gltf";
    }
    return "?";
}
const char* toString(Attenuation a) { return a == Attenuation::None ? "none" : "inverse-square"; }
const char* toString(LightType t) {
    switch (t) {
    case LightType::Point: return "point";
    case LightType::Directional: return "directional";
    case LightType::Area: return "area";
    case LightType::Spot: return "spot";
    }
    return "?";
}

bool ShadowSettings::operator==(const ShadowSettings& o) const {
    return enabled == o.enabled && normalBias == o.normalBias && depthBias == o.depthBias && pcf == o.pcf &&
           mapSize == o.mapSize && areaMapSize == o.areaMapSize;
}
const char* toString(OutputEncoding e) { return e == OutputEncoding::Linear ? "linear" : "srgb"; }
const char* toString(SpecularNormalization n) { return n == SpecularNormalization::None ? "none" : "energy"; }
const char* toString(FresnelMode f) {
    switch (f) {
    case FresnelMode::None: return "none";
    case FresnelMode::Schlick: return "schlick";
    case FresnelMode::Exact: return "exact";
    }
    return "?";
}
std::string toString(const TermView& t) {
    switch (t.term) {
    case ShowTerm::All: return "all";
    case ShowTerm::Ambient: return "ambient";
    case ShowTerm::Diffuse: return "diffuse";
    case ShowTerm::Specular: return "specular";
    case ShowTerm::Light: return "light:" + std::to_string(t.light);
    case ShowTerm::Unlit: return "unlit";
    }
    return "?";
}

}  // namespace shadelab
