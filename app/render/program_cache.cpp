#include "render/program_cache.hpp"

#include "render/cpu/shadow_projection.hpp"
#include "render/gpu_blocks.hpp"
#include "render/program.hpp"

#include <algorithm>
#include <utility>

namespace shadelab {

namespace {

// A constant of shaders/shared_defs.glsl as a program's defines name it: its value and its name, both
// made by the preprocessor from the one token, so a table of them cannot say another name than the
// value's (the GLSL file stays the one definition; nothing mirrors it by hand).
struct SharedDefine {
    int value;
    const char* name;
};
#define SL_SHARED_DEFINE(name) \
    SharedDefine { name, #name }

// Each scene value's constant: one row per value, the scene's enum beside the shaders' name.
template <typename E>
using DefineOf = std::pair<E, SharedDefine>;
constexpr DefineOf<LightType> kLightKinds[] = {{LightType::Point, SL_SHARED_DEFINE(SL_LIGHT_POINT)},
                                               {LightType::Directional, SL_SHARED_DEFINE(SL_LIGHT_DIRECTIONAL)},
                                               {LightType::Area, SL_SHARED_DEFINE(SL_LIGHT_AREA)},
                                               {LightType::Spot, SL_SHARED_DEFINE(SL_LIGHT_SPOT)}};
constexpr SharedDefine kAttenuations[] = {SL_SHARED_DEFINE(SL_ATTENUATION_NONE),
                                          SL_SHARED_DEFINE(SL_ATTENUATION_INVERSE_SQUARE),
                                          SL_SHARED_DEFINE(SL_ATTENUATION_INVERSE_SQUARE_RANGE)};
constexpr DefineOf<ReflectionModel> kReflections[] = {
    {ReflectionModel::Phong, SL_SHARED_DEFINE(SL_REFLECTION_PHONG)},
    {ReflectionModel::BlinnPhong, SL_SHARED_DEFINE(SL_REFLECTION_BLINN_PHONG)}};
constexpr DefineOf<OutputEncoding> kEncodings[] = {{OutputEncoding::Linear, SL_SHARED_DEFINE(SL_ENCODING_LINEAR)},
                                                   {OutputEncoding::Srgb, SL_SHARED_DEFINE(SL_ENCODING_SRGB)}};
constexpr DefineOf<SpecularNormalization> kNormalizations[] = {
    {SpecularNormalization::None, SL_SHARED_DEFINE(SL_NORMALIZATION_NONE)},
    {SpecularNormalization::Energy, SL_SHARED_DEFINE(SL_NORMALIZATION_ENERGY)}};
constexpr DefineOf<FresnelMode> kFresnels[] = {{FresnelMode::None, SL_SHARED_DEFINE(SL_FRESNEL_NONE)},
                                               {FresnelMode::Schlick, SL_SHARED_DEFINE(SL_FRESNEL_SCHLICK)},
                                               {FresnelMode::Exact, SL_SHARED_DEFINE(SL_FRESNEL_EXACT)}};
constexpr DefineOf<ShowTerm> kShowTerms[] = {
    {ShowTerm::All, SL_SHARED_DEFINE(SL_SHOW_ALL)},          {ShowTerm::Ambient, SL_SHARED_DEFINE(SL_SHOW_AMBIENT)},
    {ShowTerm::Diffuse, SL_SHARED_DEFINE(SL_SHOW_DIFFUSE)},  {ShowTerm::Specular, SL_SHARED_DEFINE(SL_SHOW_SPECULAR)},
    {ShowTerm::Light, SL_SHARED_DEFINE(SL_SHOW_LIGHT)},      {ShowTerm::Unlit, SL_SHARED_DEFINE(SL_SHOW_UNLIT)},
    {ShowTerm::Emissive, SL_SHARED_DEFINE(SL_SHOW_EMISSIVE)}};
constexpr SharedDefine kAlphaModes[] = {SL_SHARED_DEFINE(SL_ALPHA_OPAQUE), SL_SHARED_DEFINE(SL_ALPHA_MASK),
                                        SL_SHARED_DEFINE(SL_ALPHA_BLEND)};
#undef SL_SHARED_DEFINE

template <typename E, std::size_t N>
const SharedDefine& defineOf(const DefineOf<E> (&table)[N], E value) {
    for (const auto& row : table)
        if (row.first == value) return row.second;
    return table[0].second;  // (every value has its row)
}
template <std::size_t N>
const char* nameOf(const SharedDefine (&table)[N], int value) {
    for (const SharedDefine& d : table)
        if (d.value == value) return d.name;
    return table[0].name;
}

// "SL_SHOW SL_SHOW_AMBIENT": `name` defined as the constant.
std::string defineAs(const char* name, const SharedDefine& value) { return std::string(name) + " " + value.name; }

}  // namespace

int attenuationKind(const Light& l) {
    if (l.type == LightType::Directional || l.attenuation != Attenuation::InverseSquare) return SL_ATTENUATION_NONE;
    return l.range > 0.0f ? SL_ATTENUATION_INVERSE_SQUARE_RANGE : SL_ATTENUATION_INVERSE_SQUARE;
}

int lightKind(const Light& l) { return defineOf(kLightKinds, l.type).value; }

std::string encodingDefine(OutputEncoding encoding) { return defineAs("SL_ENCODING", defineOf(kEncodings, encoding)); }

std::vector<std::string> programDefines(const Scene& s) {
    const std::size_t count = std::min<std::size_t>(s.lights.size(), SL_MAX_LIGHTS);
    // Per light, as comma-separated lists that shaders/lighting.glsl reads into constant arrays.
    std::string kinds, attenuations, samplesX, samplesY;
    bool area = false;
    for (std::size_t l = 0; l < count; ++l) {
        const Light& light = s.lights[l];
        const char* comma = l > 0 ? ", " : "";
        kinds += comma + std::string(defineOf(kLightKinds, light.type).name);
        attenuations += comma + std::string(nameOf(kAttenuations, attenuationKind(light)));
        samplesX += comma + std::to_string(light.type == LightType::Area ? light.samples.x : 1);
        samplesY += comma + std::to_string(light.type == LightType::Area ? light.samples.y : 1);
        area = area || light.type == LightType::Area;
    }
    std::vector<std::string> d;
    d.push_back("SL_LIGHT_COUNT " + std::to_string(count));
    if (count > 0) {
        d.push_back("SL_LIGHT_KINDS " + kinds);
        d.push_back("SL_LIGHT_ATTENUATIONS " + attenuations);
        d.push_back("SL_AREA_SAMPLES_X " + samplesX);
        d.push_back("SL_AREA_SAMPLES_Y " + samplesY);
    }
    if (area) d.push_back("SL_AREA_LIGHTS 1");
    d.push_back(defineAs("SL_REFLECTION", defineOf(kReflections, s.reflection)));
    d.push_back(encodingDefine(s.outputEncoding));
    // The model extensions and term isolation: only scenes that use them get these defines, so every
    // other scene compiles to the programs it always did.
    if (s.specularNormalization != SpecularNormalization::None)
        d.push_back(defineAs("SL_SPECULAR_NORMALIZATION", defineOf(kNormalizations, s.specularNormalization)));
    if (s.fresnel != FresnelMode::None) d.push_back(defineAs("SL_FRESNEL", defineOf(kFresnels, s.fresnel)));
    if (s.show.term != ShowTerm::All) d.push_back(defineAs("SL_SHOW", defineOf(kShowTerms, s.show.term)));
    if (s.show.term == ShowTerm::Light) d.push_back("SL_SHOW_LIGHT_INDEX " + std::to_string(s.show.light));
    // Only scenes with shadows get these: without them the programs are the ones they always were.
    if (s.shadows.enabled && count > 0) {
        d.push_back("SL_SHADOWS 1");
        d.push_back("SL_SHADOW_PCF " + std::to_string(s.shadows.pcf));
        std::string layers;
        for (int first : shadowLayout(s.lights, count).firstLayer)
            layers += (layers.empty() ? "" : ", ") + std::to_string(first);
        d.push_back("SL_SHADOW_LAYERS " + layers);
    }
    return d;
}

ProgramCache::ProgramCache(ShaderLibrary shaders, bool packedFlatVertices)
    : shaders_(std::move(shaders)), packedFlatVertices_(packedFlatVertices) {}

GLuint ProgramCache::get(ShadingMode mode, const Scene& scene, const Variant& variant) {
    std::vector<std::string> defines = programDefines(scene);
    if (variant.accumulate) defines.push_back("SL_ACCUMULATE 1");
    if (variant.textured) defines.push_back("SL_TEXTURED 1");
    if (variant.instanced) defines.push_back("SL_INSTANCED 1");
    // Only draws that use them get these: an opaque draw without E compiles to the programs it always did.
    if (variant.alphaMode != SL_ALPHA_OPAQUE)
        defines.push_back(std::string("SL_ALPHA_MODE ") + nameOf(kAlphaModes, variant.alphaMode));
    if (variant.emissive) defines.push_back("SL_EMISSIVE 1");
    if (variant.emissive && variant.emissiveTexture && variant.textured) defines.push_back("SL_EMISSIVE_TEXTURE 1");
    if (variant.doubleSided) defines.push_back("SL_DOUBLE_SIDED 1");
    if (variant.anisotropic) defines.push_back("SL_ANISOTROPY 1");
    if (variant.environment != SL_ENVIRONMENT_NONE)
        defines.push_back("SL_ENVIRONMENT " + std::to_string(variant.environment));
    if (variant.singleShadowTap)
        for (std::string& d : defines)
            if (d.rfind("SL_SHADOW_PCF ", 0) == 0) d = "SL_SHADOW_PCF 0";
    // flat.vert + flat.frag, …; the speed variants are programs of their own (shaders/flat_packed.vert,
    // shaders/phong_interpolated.vert and .frag).
    const bool interpolated = variant.interpolatedInputs && mode == ShadingMode::Phong && !variant.anisotropic &&
                              variant.environment == SL_ENVIRONMENT_NONE;
    const std::string name = interpolated ? std::string("phong_interpolated") : toString(mode);
    const std::string vertex =
        mode == ShadingMode::Flat && packedFlatVertices_ && !variant.anisotropic ? "flat_packed" : name;
    std::string key = vertex;
    for (const std::string& d : defines) key += ";" + d;
    gl::Program& p = programs_[key];
    if (!p) p = buildProgram(name, shaders_, defines, vertex);
    return p.get();
}

}  // namespace shadelab
