#include "core/scene/parameters.hpp"

#include <cmath>
#include <iterator>
#include <limits>

namespace shadelab {
namespace {

using S = PanelSection;
using Scale = SliderScale;
constexpr double kVaries = std::numeric_limits<double>::quiet_NaN();  // a default that differs per component

template <typename T>
constexpr Range<double> wide(const Range<T>& r) {
    return {double(r.lo), double(r.hi)};
}

// Accessors, one per kind of field.
constexpr ParameterField material(float* (*f)(Material&)) { return {f, nullptr, nullptr, nullptr, nullptr}; }
constexpr ParameterField scene(float* (*f)(Scene&)) { return {nullptr, f, nullptr, nullptr, nullptr}; }
constexpr ParameterField sceneInteger(int* (*f)(Scene&)) { return {nullptr, nullptr, f, nullptr, nullptr}; }
constexpr ParameterField light(float* (*f)(Light&)) { return {nullptr, nullptr, nullptr, f, nullptr}; }
constexpr ParameterField mesh(MeshSpec::Type type, int* (*f)(MeshSpec&)) {
    return {nullptr, nullptr, nullptr, nullptr, f, type};
}

// Each row: id, name, option, symbol, label, section, range, slider, scale, decimals, components,
// default, help, field. The help texts are the command line's (--help, README): "{range}" and
// "{default}" are filled in from the row.
// (a table, read row by row: clang-format leaves it as written)
// clang-format off
constexpr Parameter kParameters[] = {
    {Param::Ka, "ka", "--ka", "k_a", "k_a ambient", S::Material, wide(kCoefficientRange), {0, 1}, Scale::Linear, 3, 1,
     0.1, "ambient weight ({range}) of every object", material([](Material& m) { return &m.ka; })},
    {Param::Kd, "kd", "--kd", "k_d", "k_d diffuse", S::Material, wide(kCoefficientRange), {0, 1}, Scale::Linear, 3, 1,
     0.7, "diffuse weight ({range}) of every object", material([](Material& m) { return &m.kd; })},
    {Param::Ks, "ks", "--ks", "k_s", "k_s specular", S::Material, wide(kCoefficientRange), {0, 1}, Scale::Linear, 3, 1,
     0.5, "specular weight ({range}) of every object", material([](Material& m) { return &m.ks; })},
    // The exponent is what the lecture sweeps: its slider is logarithmic, and ends at the lecture's 1000.
    {Param::Ke, "ke", "--ke", "k_e", "k_e exponent", S::Material, wide(kExponentRange), {1, 1000}, Scale::Log, 1, 1,
     32, "specular exponent ({range}) of every object", material([](Material& m) { return &m.ke; })},
    {Param::Anisotropy, "anisotropy", "--anisotropy", "k_t,k_b", "anisotropy k_t, k_b", S::Material,
     wide(kExponentRange), {1, 1000}, Scale::Log, 1, 2, 32,
     "anisotropic (brushed-metal) highlights on every object: Ashikhmin and Shirley's exponent, k_t along the "
     "surface's tangent and k_b along its bitangent ({range} each) instead of k_e; k_t = k_b = k_e is Blinn-Phong. "
     "Needs `--reflection blinn-phong` (see *What is drawn*)",
     material([](Material& m) { return &m.anisotropy.x; }), {"k_t along T", "k_b along B"}},
    {Param::Mirror, "mirror", "--mirror", "k_r", "k_r mirror", S::Material, wide(kUnitRange), wide(kUnitRange),
     Scale::Linear, 2, 1, 0,
     "k_r ({range}) of every object: the mirror term k_r F env(R) added after the lecture's sum (needs "
     "`--environment`; F by `--fresnel`, 1 with none)",
     material([](Material& m) { return &m.mirror; })},
    {Param::Transmission, "transmission", "--transmission", "k_t", "k_t transmission", S::Material, wide(kUnitRange),
     wide(kUnitRange), Scale::Linear, 2, 1, 0,
     "k_t ({range}) of every object: glass, k_t (1 - F) env(T) with T refracted by Snell's law at the surface "
     "(`--ior`; needs `--environment`)",
     material([](Material& m) { return &m.transmission; })},
    {Param::Color, "color", "--color", "C", "colour C", S::Material, wide(kColorRange), wide(kColorRange),
     Scale::Linear, 3, 3, kVaries,
     "C, the diffuse and ambient colour of every object, linear RGB ({range} each); replaces a glTF model's base "
     "colours",
     material([](Material& m) { return &m.color.x; })},
    {Param::SpecularColor, "specular_color", "--specular-color", "S", "specular S", S::Material, wide(kColorRange),
     wide(kColorRange), Scale::Linear, 3, 3, 1, "S, the highlight's colour of every object, linear RGB ({range} each)",
     material([](Material& m) { return &m.specularColor.x; })},

    {Param::Ior, "ior", "--ior", "ior", "ior \u03b7\u2082/\u03b7\u2081", S::Shading, wide(kIorRange), {kIorRange.lo, 4},
     Scale::Linear, 3, 1, 1.5,
     "relative index of refraction eta2/eta1 for `--fresnel` and for glass's refraction ({range}, default "
     "{default}): from air into the material; below 1 the light comes from inside it (total internal reflection "
     "past the critical angle)",
     scene([](Scene& s) { return &s.ior; })},
    {Param::DiffFactor, "factor", "--diff-factor", "factor", "factor", S::Shading, wide(kDiffFactorRange),
     wide(kDiffFactorRange), Scale::Log, 1, 1, 4,
     "layout diff: |A - B| is multiplied by X ({range}, default {default})",
     scene([](Scene& s) { return &s.diff.factor; })},
    {Param::Ambient, "ambient", "--ambient", "A", "ambient A", S::Lights, wide(kColorRange), wide(kColorRange),
     Scale::Linear, 3, 3, 1, "A, the ambient light, linear RGB ({range} each)",
     scene([](Scene& s) { return &s.ambient.x; })},
    {Param::Background, "background", "--background", "background", "background", S::Background, wide(kColorRange),
     wide(kColorRange), Scale::Linear, 3, 3, kVaries, "the background, linear RGB ({range} each)",
     scene([](Scene& s) { return &s.background.x; })},
    {Param::FovY, "fov_y_deg", "", "fov y", "fov y (deg)", S::Camera, wide(kFovYDegRange), {5, 120}, Scale::Linear, 1,
     1, 45, "the camera's vertical field of view of each pane, degrees ({range})",
     scene([](Scene& s) { return &s.camera.fovYDeg; })},

    {Param::Incidence, "incidence", "--incidence", "theta_i", "incidence", S::Plots, wide(kIncidenceDegRange),
     wide(kIncidenceDegRange), Scale::Linear, 1, 1, 45,
     "the lobe, lobe3d and brdf-slice plots' angle between the incoming light I and N ({range}, default {default})"},

    {Param::Intensity, "intensity", "", "intensity", "intensity", S::Lights, wide(kIntensityRange), {0, 1e6},
     Scale::Linear, 3, 1, 1, "a light's intensity (an area light's: of the whole rectangle)",
     light([](Light& l) { return &l.intensity; })},
    {Param::OuterCone, "outer_cone_deg", "", "outer", "outer cone (deg)", S::Lights, wide(kSpotOuterConeDegRange),
     {1, kSpotConeDegRange.hi}, Scale::Linear, 1, 1, 30,
     "a spot light's outer cone half-angle, degrees: no light beyond it",
     light([](Light& l) { return &l.outerConeDeg; })},
    {Param::InnerCone, "inner_cone_deg", "", "inner", "inner cone (deg)", S::Lights, wide(kSpotConeDegRange),
     wide(kSpotConeDegRange), Scale::Linear, 1, 1, 15,
     "a spot light's inner cone half-angle, degrees: full light within it (less than the outer; half of it when "
     "not given)",
     light([](Light& l) { return &l.innerConeDeg; })},

    // The mesh's tessellation: the sliders stop where a lecture still sees facets change.
    {Param::UvSphereSlices, "slices", "", "slices", "slices", S::Mesh, wide(kUvSphereSlicesRange), {3, 256},
     Scale::Linear, 0, 1, 64, "a UV sphere's slices around its axis",
     mesh(MeshSpec::Type::UvSphere, [](MeshSpec& m) { return &m.slices; })},
    {Param::UvSphereStacks, "stacks", "", "stacks", "stacks", S::Mesh, wide(kUvSphereStacksRange), {2, 128},
     Scale::Linear, 0, 1, 32, "a UV sphere's stacks from pole to pole",
     mesh(MeshSpec::Type::UvSphere, [](MeshSpec& m) { return &m.stacks; })},
    {Param::IcoSphereSubdivisions, "subdivisions", "", "subdivisions", "subdivisions", S::Mesh,
     // 20 * 4^7 = 327,680 triangles is still interactive on llvmpipe; the file format allows 8.
     wide(kIcoSphereSubdivisionsRange), {0, 7}, Scale::Linear, 0, 1, 3,
     "an icosphere's subdivisions: each splits every triangle in four",
     mesh(MeshSpec::Type::IcoSphere, [](MeshSpec& m) { return &m.subdivisions; })},
    {Param::TorusMajorSegments, "major_segments", "", "major", "major segments", S::Mesh, wide(kTorusSegmentsRange),
     {3, 256}, Scale::Linear, 0, 1, 48, "a torus's segments around its axis",
     mesh(MeshSpec::Type::Torus, [](MeshSpec& m) { return &m.majorSegments; })},
    {Param::TorusMinorSegments, "minor_segments", "", "minor", "minor segments", S::Mesh, wide(kTorusSegmentsRange),
     {3, 128}, Scale::Linear, 0, 1, 24, "a torus's segments around its tube",
     mesh(MeshSpec::Type::Torus, [](MeshSpec& m) { return &m.minorSegments; })},
    {Param::PlaneSubdivisions, "subdivisions", "", "subdivisions", "subdivisions", S::Mesh,
     wide(kPlaneSubdivisionsRange),
     {1, 128}, Scale::Linear, 0, 1, 1, "a plane's subdivisions per side",
     mesh(MeshSpec::Type::Plane, [](MeshSpec& m) { return &m.planeSubdivisions; })},

    {Param::NormalBias, "normal_bias", "", "normal bias", "normal bias (texels)", S::Shadows, wide(kShadowBiasRange),
     {0, 8}, Scale::Linear, 2, 1, 1.5, "the looked-up point moves along its normal by this many shadow-map texels",
     scene([](Scene& s) { return &s.shadows.normalBias; })},
    {Param::DepthBias, "depth_bias", "", "depth bias", "depth bias (slope)", S::Shadows, wide(kShadowBiasRange), {0, 8},
     Scale::Linear, 2, 1, 1.5, "slope-scaled depth offset of the shadow pass",
     scene([](Scene& s) { return &s.shadows.depthBias; })},
    {Param::Pcf, "pcf", "", "PCF", "PCF radius", S::Shadows, wide(kPcfRadiusRange), wide(kPcfRadiusRange),
     Scale::Linear, 0, 1, 1, "percentage-closer filtering radius: (2r+1)^2 lookups",
     sceneInteger([](Scene& s) { return &s.shadows.pcf; })},
};
// clang-format on

static_assert(std::size(kParameters) == std::size_t(Param::Pcf) + 1, "a row for every Param, in its order");

}  // namespace

const Parameter* parametersBegin() { return std::begin(kParameters); }
const Parameter* parametersEnd() { return std::end(kParameters); }

const Parameter& parameter(Param p) { return kParameters[std::size_t(p)]; }

const Parameter* parameterNamed(const std::string& name) {
    for (const Parameter& p : kParameters)
        if (!p.field.mesh && name == p.name) return &p;
    return nullptr;
}

const Parameter* meshParameter(MeshSpec::Type type, const std::string& name) {
    for (const Parameter& p : kParameters)
        if (p.field.mesh && p.field.meshType == type && name == p.name) return &p;
    return nullptr;
}

const Parameter* parameterOfOption(const std::string& option) {
    for (const Parameter& p : kParameters)
        if (*p.option && option == p.option) return &p;
    return nullptr;
}

std::string parameterHelp(const Parameter& p) {
    std::string text = p.help;
    auto fill = [&text](const std::string& key, const std::string& value) {
        for (std::size_t at; (at = text.find(key)) != std::string::npos;) text.replace(at, key.size(), value);
    };
    fill("{range}", rangeText(p.range));
    fill("{default}", defaultText(p));
    return text;
}

std::string defaultText(const Parameter& p) {
    return std::isnan(p.defaultValue) ? std::string() : formatNumber(p.defaultValue);
}

}  // namespace shadelab
