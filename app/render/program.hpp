#pragma once
// Compiling and linking one GLSL program from files in a ShaderLibrary. Errors are ShaderErrors whose
// message names the program, the stage, and the file and line of each driver message.
#include "core/base/error.hpp"  // ShaderError
#include "render/gl_handles.hpp"
#include "render/shader_library.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace shadelab {

// Builds `<name>.vert` (or `<vertexName>.vert`) + `<name>.frag`, with `<geometryName>.geom` between
// them when given, with `defines` ("NAME VALUE") after #version, and binds the uniform blocks to their
// SL_BINDING_* points.
gl::Program buildProgram(const std::string& name, const ShaderLibrary& library,
                         const std::vector<std::string>& defines = {}, const std::string& vertexName = "",
                         const std::string& geometryName = "");

// Throws on a pending GL error: GlOutOfMemory (an input error: ask for less) or std::runtime_error,
// naming `where`.
void checkGl(const char* where);

// The vertex stage of the image passes: one triangle over the viewport (shaders/fullscreen.vert).
inline const char* const kFullscreenVertex = "fullscreen";

}  // namespace shadelab
