#include "render/image_pass.hpp"

#include <stdexcept>
#include <string>

namespace shadelab {

gl::Texture makeImageTexture(GLint internalFormat, GLenum format, GLenum type, int width, int height) {
    gl::Texture t = gl::makeTexture();
    glBindTexture(GL_TEXTURE_2D, t.get());
    glTexImage2D(GL_TEXTURE_2D, 0, internalFormat, width, height, 0, format, type, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    return t;
}

gl::Framebuffer makeFramebuffer(GLuint color, GLuint depth, const char* what) {
    gl::Framebuffer f = gl::makeFramebuffer();
    glBindFramebuffer(GL_FRAMEBUFFER, f.get());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color, 0);
    if (depth) glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth, 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error(std::string(what) + ": the framebuffer is not complete on this GL");
    return f;
}

void FullscreenTriangle::draw(GLuint program) {
    if (!emptyVao_) emptyVao_ = gl::makeVertexArray();
    glDisable(GL_CULL_FACE);
    glUseProgram(program);
    glBindVertexArray(emptyVao_.get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glEnable(GL_CULL_FACE);
}

}  // namespace shadelab
