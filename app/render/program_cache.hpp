#pragma once
// The shading programs, by mode and specialisation: what the scene compiles in (programDefines) and
// what a draw needs besides (Variant), each built on first use (an LLVM compile on llvmpipe) and kept.
#include "core/scene/scene.hpp"
#include "render/gl_handles.hpp"
#include "render/gpu_blocks.hpp"
#include "render/shader_library.hpp"

#include <map>
#include <string>
#include <vector>

namespace shadelab {

class ProgramCache {
public:
    // The switches of one draw: a progressive pass (SL_ACCUMULATE), Phong's interpolated inputs
    // (the program phong_interpolated instead of phong), a colour that varies over the surface (SL_TEXTURED), GPU
    // instances (SL_INSTANCED), a double-sided glTF material (SL_DOUBLE_SIDED: not culled, the back lit with its normal
    // flipped; single-sided draws get the programs they had before it existed).
    struct Variant {
        bool accumulate = false, interpolatedInputs = false, textured = false, instanced = false;
        bool doubleSided = false;  // SL_DOUBLE_SIDED: a back face lit with its normal flipped
        // What a glTF material adds (shaders/object_color.glsl): SL_ALPHA_MODE, and E with or without its texture.
        int alphaMode = SL_ALPHA_OPAQUE;
        bool emissive = false, emissiveTexture = false;
        // SL_ANISOTROPY: an anisotropic material, its vertices with tangents (flat: flat.vert, never packed).
        bool anisotropic = false;
        // SL_ENVIRONMENT: mirror and glass (k_r or k_t) in a scene with an environment: SL_ENVIRONMENT_*.
        int environment = SL_ENVIRONMENT_NONE;
        // A moving frame's shadows (Renderer::setMovingFrames): one shadow-map lookup per light, SL_SHADOW_PCF
        // compiled as 0 whatever the scene's radius (shaders/shadows.glsl, shadowLookup).
        bool singleShadowTap = false;
    };
    // `packedFlatVertices`: flat shading's vertex stage is flat_packed.vert (RendererOptions).
    ProgramCache(ShaderLibrary shaders, bool packedFlatVertices);
    // Builds the program on first use. Throws ShaderError.
    GLuint get(ShadingMode mode, const Scene& scene, const Variant& variant);
    const ShaderLibrary& shaders() const { return shaders_; }

private:
    ShaderLibrary shaders_;
    bool packedFlatVertices_;
    std::map<std::string, gl::Program> programs_;  // by vertex stage + defines
};

// What the shading programs are specialised for (shaders/lighting.glsl): the number of lights and,
// as constant lists, each light's kind, attenuation and area samples; the reflection model, the
// output encoding, the options and "show"; with shadows on, SL_SHADOWS, the PCF radius and each
// light's first shadow-map layer. "NAME VALUE" each. Everything else is a uniform, so editing values
// never recompiles.
std::vector<std::string> programDefines(const Scene& scene);
// The output encoding's define ("SL_ENCODING SL_ENCODING_SRGB"), shared by the shading programs and
// progressive sampling's resolve.
std::string encodingDefine(OutputEncoding encoding);

// The constants the shaders know a light by (shaders/shared_defs.glsl): SL_LIGHT_* and SL_ATTENUATION_*.
int lightKind(const Light& light);
int attenuationKind(const Light& light);

}  // namespace shadelab
