#include "render/offscreen_target.hpp"

#include <stdexcept>
#include <string>

namespace shadelab {
namespace {

gl::Renderbuffer makeStorage(GLenum format, int width, int height, int samples) {
    gl::Renderbuffer r = gl::makeRenderbuffer();
    glBindRenderbuffer(GL_RENDERBUFFER, r.get());
    if (samples > 0) glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
    else glRenderbufferStorage(GL_RENDERBUFFER, format, width, height);
    return r;
}

}  // namespace

OffscreenTarget::OffscreenTarget(int width, int height, int samples, const char* what)
    : framebuffer_(gl::makeFramebuffer()),
      color_(makeStorage(GL_RGBA8, width, height, samples)),
      depth_(makeStorage(GL_DEPTH_COMPONENT24, width, height, samples)),
      width_(width),
      height_(height),
      requestedSamples_(samples) {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_.get());
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.get());
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error(std::string(what) + ": the " + std::to_string(width) + "x" + std::to_string(height) +
                                 " framebuffer" + (samples > 0 ? " with " + std::to_string(samples) + " samples" : "") +
                                 " is not complete on this GL");
    if (samples > 0) {
        GLint actual = 0;
        glBindRenderbuffer(GL_RENDERBUFFER, color_.get());
        glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES, &actual);
        samples_ = int(actual);
    }
}

RenderTarget OffscreenTarget::ensure(int width, int height, int samples, const char* what) {
    if (!framebuffer_ || width != width_ || height != height_ || samples != requestedSamples_) {
        *this = OffscreenTarget();
        *this = OffscreenTarget(width, height, samples, what);
    }
    return target();
}

}  // namespace shadelab
