#include "viewer/reduced_target.hpp"

#include <stdexcept>

namespace shadelab {

RenderTarget ReducedTarget::begin(int width, int height) {
    if (!framebuffer_ || width_ != width || height_ != height) {
        GLuint ids[3] = {};
        glGenFramebuffers(1, &ids[0]);
        glGenRenderbuffers(2, &ids[1]);
        *this = ReducedTarget{};
        framebuffer_ = gl::Framebuffer(ids[0]), color_ = gl::Renderbuffer(ids[1]), depth_ = gl::Renderbuffer(ids[2]);
        width_ = width, height_ = height;
        glBindRenderbuffer(GL_RENDERBUFFER, ids[1]);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
        glBindRenderbuffer(GL_RENDERBUFFER, ids[2]);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
        glBindFramebuffer(GL_FRAMEBUFFER, ids[0]);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, ids[1]);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, ids[2]);
        if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
            *this = ReducedTarget{};
            throw std::runtime_error("the reduced moving-frame framebuffer is not complete on this GL");
        }
    }
    return RenderTarget{framebuffer_.get(), width, height};
}

void ReducedTarget::magnifyInto(const RenderTarget& view) const {
    glDisable(GL_SCISSOR_TEST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.get());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, view.framebuffer);
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, view.width, view.height, GL_COLOR_BUFFER_BIT, GL_LINEAR);
    glBindFramebuffer(GL_FRAMEBUFFER, view.framebuffer);
}

}  // namespace shadelab
