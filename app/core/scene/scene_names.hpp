#pragma once
// The name of every value of the scene's enums, defined once: the scene files' strings, the command
// line's values, the sweep's values, the panel's combo boxes and toString() all come from these
// tables (in the order the panel and --help list them). GL-free, header-only.
#include "core/scene/scene.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <utility>

namespace shadelab {

template <typename E>
using EnumName = std::pair<const char*, E>;

inline constexpr EnumName<ShadingMode> kShadingModeNames[] = {
    {"flat", ShadingMode::Flat}, {"gouraud", ShadingMode::Gouraud}, {"phong", ShadingMode::Phong}};
inline constexpr EnumName<Layout> kLayoutNames[] = {
    {"single", Layout::Single}, {"compare", Layout::Compare}, {"diff", Layout::Diff}};
inline constexpr EnumName<ReflectionModel> kReflectionModelNames[] = {{"phong", ReflectionModel::Phong},
                                                                      {"blinn-phong", ReflectionModel::BlinnPhong}};
inline constexpr EnumName<OutputEncoding> kOutputEncodingNames[] = {{"linear", OutputEncoding::Linear},
                                                                    {"srgb", OutputEncoding::Srgb}};
inline constexpr EnumName<LightType> kLightTypeNames[] = {{"point", LightType::Point},
                                                          {"directional", LightType::Directional},
                                                          {"area", LightType::Area},
                                                          {"spot", LightType::Spot}};
inline constexpr EnumName<Attenuation> kAttenuationNames[] = {{"none", Attenuation::None},
                                                              {"inverse-square", Attenuation::InverseSquare}};
inline constexpr EnumName<SpecularNormalization> kSpecularNormalizationNames[] = {
    {"none", SpecularNormalization::None}, {"energy", SpecularNormalization::Energy}};
inline constexpr EnumName<FresnelMode> kFresnelModeNames[] = {
    {"none", FresnelMode::None}, {"schlick", FresnelMode::Schlick}, {"exact", FresnelMode::Exact}};
// "environment": the procedural ones by name; anything else names an image file ("image" is not a value).
inline constexpr EnumName<EnvironmentKind> kEnvironmentNames[] = {
    {"none", EnvironmentKind::None}, {"room", EnvironmentKind::Room}, {"sky", EnvironmentKind::Sky}};
inline constexpr EnumName<MeshSpec::Type> kMeshTypeNames[] = {
    {"uvsphere", MeshSpec::Type::UvSphere}, {"icosphere", MeshSpec::Type::IcoSphere}, {"torus", MeshSpec::Type::Torus},
    {"cube", MeshSpec::Type::Cube},         {"plane", MeshSpec::Type::Plane},         {"gltf", MeshSpec::Type::Gltf}};
// "show": one term of the formula; ShowTerm::Light is written "light:N", N the light's index.
inline constexpr EnumName<ShowTerm> kShowTermNames[] = {
    {"all", ShowTerm::All},           {"ambient", ShowTerm::Ambient}, {"diffuse", ShowTerm::Diffuse},
    {"specular", ShowTerm::Specular}, {"light:N", ShowTerm::Light},   {"unlit", ShowTerm::Unlit},
    {"emissive", ShowTerm::Emissive}};

// The name of `value` in `names` ("?" when it has none).
template <typename E, std::size_t N>
constexpr const char* nameOf(const EnumName<E> (&names)[N], E value) {
    for (const auto& n : names)
        if (n.second == value) return n.first;
    return "?";
}

// KHR_lights_punctual's light types (glTF): the point, directional and spot lights under the names
// above, which shadelab's scene format took from glTF; glTF has no area lights.
inline constexpr EnumName<LightType> kPunctualLightTypeNames[] = {
    {nameOf(kLightTypeNames, LightType::Point), LightType::Point},
    {nameOf(kLightTypeNames, LightType::Directional), LightType::Directional},
    {nameOf(kLightTypeNames, LightType::Spot), LightType::Spot}};

// The value named `text`, if any.
template <typename E, std::size_t N>
std::optional<E> valueNamed(const EnumName<E> (&names)[N], const std::string& text) {
    for (const auto& n : names)
        if (text == n.first) return n.second;
    return std::nullopt;
}

// "flat, gouraud, phong"; with last = " or ": "flat, gouraud or phong"; with quote: "\"flat\", ...".
template <typename E, std::size_t N>
std::string namesList(const EnumName<E> (&names)[N], const char* separator = ", ", const char* last = nullptr,
                      bool quote = false) {
    std::string list;
    for (std::size_t i = 0; i < N; ++i) {
        if (i > 0) list += i + 1 == N && last ? last : separator;
        list += quote ? std::string("\"") + names[i].first + "\"" : std::string(names[i].first);
    }
    return list;
}

}  // namespace shadelab
