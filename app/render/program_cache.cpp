#include "render/program_cache.hpp"

#include "render/cpu/shadow_projection.hpp"
#include "render/gpu_blocks.hpp"
#include "render/program.hpp"

#include <algorithm>

namespace shadelab {

int attenuationKind(const Light& l) {
    if (l.type == LightType::Directional || l.attenuation != Attenuation::InverseSquare) return SL_ATTENUATION_NONE;
    return l.range > 0.0f ? SL_ATTENUATION_INVERSE_SQUARE_RANGE : SL_ATTENUATION_INVERSE_SQUARE;
}

int lightKind(const Light& l) {
    switch (l.type) {
    case LightType::Point: return SL_LIGHT_POINT;
    case LightType::Directional: return SL_LIGHT_DIRECTIONAL;
    case LightType::Area: return SL_LIGHT_AREA;
    case LightType::Spot: return SL_LIGHT_SPOT;
    }
    return SL_LIGHT_POINT;
}

std::string encodingDefine(OutputEncoding encoding) {
    return std::string("SL_ENCODING ") + (encoding == OutputEncoding::Srgb ? "SL_ENCODING_SRGB" : "SL_ENCODING_LINEAR");
}

std::vector<std::string> programDefines(const Scene& s) {
    const std::size_t count = std::min<std::size_t>(s.lights.size(), SL_MAX_LIGHTS);
    static const char* const kKinds[] = {"SL_LIGHT_POINT", "SL_LIGHT_DIRECTIONAL", "SL_LIGHT_AREA", "SL_LIGHT_SPOT"};
    static const char* const kAttenuations[] = {"SL_ATTENUATION_NONE", "SL_ATTENUATION_INVERSE_SQUARE",
                                                "SL_ATTENUATION_INVERSE_SQUARE_RANGE"};
    // Per light, as comma-separated lists that shaders/lighting.glsl reads into constant arrays.
    std::string kinds, attenuations, samplesX, samplesY;
    bool area = false;
    for (std::size_t l = 0; l < count; ++l) {
        const Light& light = s.lights[l];
        const char* comma = l > 0 ? ", " : "";
        kinds += comma + std::string(kKinds[lightKind(light)]);
        attenuations += comma + std::string(kAttenuations[attenuationKind(light)]);
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
    d.push_back(std::string("SL_REFLECTION ") +
                (s.reflection == ReflectionModel::Phong ? "SL_REFLECTION_PHONG" : "SL_REFLECTION_BLINN_PHONG"));
    d.push_back(encodingDefine(s.outputEncoding));
    // The model extensions and term isolation: only scenes that use them get these defines, so every
    // other scene compiles to the programs it always did.
    if (s.specularNormalization == SpecularNormalization::Energy)
        d.push_back("SL_SPECULAR_NORMALIZATION SL_NORMALIZATION_ENERGY");
    if (s.fresnel != FresnelMode::None)
        d.push_back(std::string("SL_FRESNEL ") +
                    (s.fresnel == FresnelMode::Schlick ? "SL_FRESNEL_SCHLICK" : "SL_FRESNEL_EXACT"));
    switch (s.show.term) {
    case ShowTerm::All: break;
    case ShowTerm::Ambient: d.push_back("SL_SHOW SL_SHOW_AMBIENT"); break;
    case ShowTerm::Diffuse: d.push_back("SL_SHOW SL_SHOW_DIFFUSE"); break;
    case ShowTerm::Specular: d.push_back("SL_SHOW SL_SHOW_SPECULAR"); break;
    case ShowTerm::Unlit: d.push_back("SL_SHOW SL_SHOW_UNLIT"); break;
    case ShowTerm::Emissive: d.push_back("SL_SHOW SL_SHOW_EMISSIVE"); break;
    case ShowTerm::Light:
        d.push_back("SL_SHOW SL_SHOW_LIGHT");
        d.push_back("SL_SHOW_LIGHT_INDEX " + std::to_string(s.show.light));
        break;
    }
    // Only scenes with shadows get these: without them the programs are the ones they always were.
    if (s.shadows.enabled && count > 0) {
        d.push_back("SL_SHADOWS 1");
        d.push_back("SL_SHADOW_PCF " + std::to_string(s.shadows.pcf));
        std::string layers;
        for (int first : shadowLayout(s.lights, count).firstLayer) layers += (layers.empty() ? "" : ", ") + std::to_string(first);
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
    if (variant.alphaMode == SL_ALPHA_MASK) defines.push_back("SL_ALPHA_MODE SL_ALPHA_MASK");
    if (variant.alphaMode == SL_ALPHA_BLEND) defines.push_back("SL_ALPHA_MODE SL_ALPHA_BLEND");
    if (variant.emissive) defines.push_back("SL_EMISSIVE 1");
    if (variant.emissive && variant.emissiveTexture && variant.textured) defines.push_back("SL_EMISSIVE_TEXTURE 1");
    if (variant.doubleSided) defines.push_back("SL_DOUBLE_SIDED 1");
    if (variant.anisotropic) defines.push_back("SL_ANISOTROPY 1");
    if (variant.environment != SL_ENVIRONMENT_NONE) defines.push_back("SL_ENVIRONMENT " + std::to_string(variant.environment));
    if (variant.singleShadowTap)
        for (std::string& d : defines)
            if (d.rfind("SL_SHADOW_PCF ", 0) == 0) d = "SL_SHADOW_PCF 0";
    // flat.vert + flat.frag, …; the speed variants are programs of their own (shaders/flat_packed.vert,
    // shaders/phong_interpolated.vert and .frag).
    const bool interpolated = variant.interpolatedInputs && mode == ShadingMode::Phong && !variant.anisotropic &&
                              variant.environment == SL_ENVIRONMENT_NONE;
    const std::string name = interpolated ? std::string("phong_interpolated") : toString(mode);
    const std::string vertex = mode == ShadingMode::Flat && packedFlatVertices_ && !variant.anisotropic ? "flat_packed" : name;
    std::string key = vertex;
    for (const std::string& d : defines) key += ";" + d;
    gl::Program& p = programs_[key];
    if (!p) p = buildProgram(name, shaders_, defines, vertex);
    return p.get();
}

}  // namespace shadelab
