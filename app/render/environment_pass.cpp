#include "render/environment_pass.hpp"

#include "core/base/error.hpp"
#include "render/gpu_blocks.hpp"
#include "render/program.hpp"
#include "render/program_cache.hpp"

#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

namespace shadelab {

int environmentDefine(EnvironmentKind kind) {
    switch (kind) {
    case EnvironmentKind::None: return SL_ENVIRONMENT_NONE;
    case EnvironmentKind::Room: return SL_ENVIRONMENT_ROOM;
    case EnvironmentKind::Sky: return SL_ENVIRONMENT_SKY;
    case EnvironmentKind::Image: return SL_ENVIRONMENT_IMAGE;
    }
    return SL_ENVIRONMENT_NONE;
}

void EnvironmentPass::bindTexture(const Scene& scene) {
    const EnvironmentSpec& env = scene.environment;
    if (env.kind != EnvironmentKind::Image || !env.image) return;
    if (uploaded_ != env.image) {
        const EnvironmentImage& img = *env.image;
        GLint maxSide = 0;
        glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSide);
        if (img.width > maxSide || img.height > maxSide)
            throw InputError(env.resolvedPath + ": the environment image is larger than this GL's textures (" +
                             std::to_string(maxSide) + " pixels a side)");
        texture_ = makeImageTexture(GL_RGB32F, GL_RGB, GL_FLOAT, img.width, img.height);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);  // rows of 3 floats a texel: always a multiple of 4 bytes
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, img.width, img.height, GL_RGB, GL_FLOAT, img.rgb.data());
        uploaded_ = env.image;
    }
    glActiveTexture(GL_TEXTURE0 + SL_TEXTURE_ENVIRONMENT);
    glBindTexture(GL_TEXTURE_2D, texture_.get());
    glActiveTexture(GL_TEXTURE0);
}

void EnvironmentPass::drawBackground(const Scene& scene, const Pane& pane, const RenderTarget& target,
                                     const ShaderLibrary& shaders, bool uncoveredOnly) {
    if (scene.environment.kind == EnvironmentKind::None || pane.width <= 0 || pane.height <= 0) return;
    const std::string define = "SL_ENVIRONMENT " + std::to_string(environmentDefine(scene.environment.kind));
    const std::string encoding = encodingDefine(scene.outputEncoding);
    gl::Program& program = programs_[define + ";" + encoding];
    if (!program) {
        program = buildProgram("background", shaders, {define, encoding}, kFullscreenVertex);
        glUseProgram(program.get());
        glUniform1i(glGetUniformLocation(program.get(), "u_environmentMap"), SL_TEXTURE_ENVIRONMENT);
    }
    const int originY = target.height - pane.y - pane.height;
    glViewport(pane.x, originY, pane.width, pane.height);
    const float aspect = float(pane.width) / float(pane.height);
    const glm::mat4 worldFromClip = glm::inverse(clipFromView(scene.camera, aspect) * viewFromWorld(scene.camera));
    glUseProgram(program.get());
    glUniformMatrix4fv(glGetUniformLocation(program.get(), "u_worldFromClip"), 1, GL_FALSE,
                       glm::value_ptr(worldFromClip));
    glUniform3f(glGetUniformLocation(program.get(), "u_eyeWorld"), scene.camera.eye.x, scene.camera.eye.y,
                scene.camera.eye.z);
    glUniform4f(glGetUniformLocation(program.get(), "u_paneRect"), float(pane.x), float(originY), float(pane.width),
                float(pane.height));
    glDepthMask(GL_FALSE);
    if (uncoveredOnly) {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);  // background.frag's depth is the far plane's, 1: only where nothing was drawn
    } else {
        glDisable(GL_DEPTH_TEST);
    }
    fullscreen_.draw(program.get());
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glEnable(GL_DEPTH_TEST);
}

}  // namespace shadelab
