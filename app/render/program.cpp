#include "render/program.hpp"

#include "core/base/error.hpp"

#include "render/cpu/glsl_include.hpp"
#include "render/gpu_blocks.hpp"

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace shadelab {
namespace {

gl::Shader compileStage(GLenum stage, const std::string& programName, const std::string& file,
                        const ShaderLibrary& library, const std::vector<std::string>& defines) {
    // Which stage is being compiled, for files that several stages include (shaders/object_color.glsl).
    std::vector<std::string> stageDefines = defines;
    stageDefines.push_back(stage == GL_VERTEX_SHADER     ? "SL_VERTEX_STAGE 1"
                           : stage == GL_GEOMETRY_SHADER ? "SL_GEOMETRY_STAGE 1"
                                                         : "SL_FRAGMENT_STAGE 1");
    ExpandedGlsl src;
    try {
        src = expandGlsl(
            file, [&](const std::string& n) { return library.load(n); }, stageDefines);
    } catch (const std::exception& e) {
        throw ShaderError("program " + programName + ": " + e.what());
    }
    gl::Shader shader(glCreateShader(stage));
    const char* text = src.text.c_str();
    glShaderSource(shader.get(), 1, &text, nullptr);
    glCompileShader(shader.get());
    GLint ok = GL_FALSE, logLength = 0;
    glGetShaderiv(shader.get(), GL_COMPILE_STATUS, &ok);
    glGetShaderiv(shader.get(), GL_INFO_LOG_LENGTH, &logLength);
    if (!ok) {
        std::vector<char> log(size_t(logLength > 1 ? logLength : 1), '\0');
        glGetShaderInfoLog(shader.get(), GLsizei(log.size()), nullptr, log.data());
        const char* stageName = stage == GL_VERTEX_SHADER     ? "vertex"
                                : stage == GL_GEOMETRY_SHADER ? "geometry"
                                                              : "fragment";
        throw ShaderError("program " + programName + ", " + stageName + " stage (" + file + ", " + kGlslVersionName +
                          ") failed to compile:\n" + locateGlslLog(log.data(), src.files));
    }
    return shader;
}

}  // namespace

gl::Program buildProgram(const std::string& name, const ShaderLibrary& library, const std::vector<std::string>& defines,
                         const std::string& vertexName, const std::string& geometryName) {
    gl::Shader vs =
        compileStage(GL_VERTEX_SHADER, name, (vertexName.empty() ? name : vertexName) + ".vert", library, defines);
    gl::Shader gs;
    if (!geometryName.empty()) gs = compileStage(GL_GEOMETRY_SHADER, name, geometryName + ".geom", library, defines);
    gl::Shader fs = compileStage(GL_FRAGMENT_SHADER, name, name + ".frag", library, defines);
    gl::Program program(glCreateProgram());
    glAttachShader(program.get(), vs.get());
    if (gs) glAttachShader(program.get(), gs.get());
    glAttachShader(program.get(), fs.get());
    glLinkProgram(program.get());
    GLint ok = GL_FALSE, logLength = 0;
    glGetProgramiv(program.get(), GL_LINK_STATUS, &ok);
    if (!ok) {
        glGetProgramiv(program.get(), GL_INFO_LOG_LENGTH, &logLength);
        std::vector<char> log(size_t(logLength > 1 ? logLength : 1), '\0');
        glGetProgramInfoLog(program.get(), GLsizei(log.size()), nullptr, log.data());
        throw ShaderError("program " + name + " failed to link:\n" + std::string(log.data()));
    }
    glDetachShader(program.get(), vs.get());
    if (gs) glDetachShader(program.get(), gs.get());
    glDetachShader(program.get(), fs.get());
    // GL 3.3 has no layout(binding = N) for blocks: bind them here, from the shared definitions.
    const GLuint frame = glGetUniformBlockIndex(program.get(), "FrameBlock");
    const GLuint object = glGetUniformBlockIndex(program.get(), "ObjectBlock");
    if (frame != GL_INVALID_INDEX) glUniformBlockBinding(program.get(), frame, SL_BINDING_FRAME);
    if (object != GL_INVALID_INDEX) glUniformBlockBinding(program.get(), object, SL_BINDING_OBJECT);
    // Nor for samplers: each has its own texture unit (shaders/shared_defs.glsl).
    GLint previous = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &previous);
    glUseProgram(program.get());
    const std::pair<const char*, int> samplers[] = {{"u_shadowMaps", SL_TEXTURE_SHADOW_MAPS},
                                                    {"u_areaShadowMaps", SL_TEXTURE_AREA_SHADOW_MAPS},
                                                    {"u_baseColorTexture", SL_TEXTURE_BASE_COLOR},
                                                    {"u_emissiveTexture", SL_TEXTURE_EMISSIVE}};
    for (const auto& [sampler, unit] : samplers)
        if (const GLint location = glGetUniformLocation(program.get(), sampler); location >= 0)
            glUniform1i(location, unit);
    glUseProgram(GLuint(previous));
    return program;
}

void checkGl(const char* where) {
    const GLenum e = glGetError();
    if (e == GL_OUT_OF_MEMORY)  // the request was too big for this GL: an input error, like the budget's
        throw GlOutOfMemory(std::string("the GL ran out of memory in ") + where +
                            " (ask for less: a smaller --size, fewer shadowed lights or smaller shadow maps)");
    if (e != GL_NO_ERROR) {
        char code[16];
        std::snprintf(code, sizeof code, "0x%04x", e);
        throw std::runtime_error(std::string("GL error ") + code + " in " + where);
    }
}

}  // namespace shadelab
