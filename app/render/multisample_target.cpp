#include "render/multisample_target.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace shadelab {
namespace {

gl::Renderbuffer makeRenderbuffer(GLenum format, int width, int height, int samples) {
    GLuint id = 0;
    glGenRenderbuffers(1, &id);
    gl::Renderbuffer r(id);
    glBindRenderbuffer(GL_RENDERBUFFER, id);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
    return r;
}

}  // namespace

RenderTarget MultisampleTarget::begin(const RenderTarget& destination, int samples) {
    GLint maxSamples = 0;
    glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
    samples = std::min(samples, int(maxSamples));
    if (samples <= 1) {
        release();
        return destination;
    }
    if (!framebuffer_ || samples != requestedSamples_ || destination.width != width_ || destination.height != height_)
        create(destination.width, destination.height, samples);
    return RenderTarget{framebuffer_.get(), width_, height_};
}

void MultisampleTarget::resolveInto(const RenderTarget& destination) const {
    if (!framebuffer_) return;
    // A multisample resolve cannot scale: the rectangles must be the same size.
    if (destination.width != width_ || destination.height != height_)
        throw std::runtime_error("MSAA: cannot resolve " + std::to_string(width_) + "x" + std::to_string(height_) +
                                 " into a " + std::to_string(destination.width) + "x" +
                                 std::to_string(destination.height) + " target");
    blitColor(framebuffer_.get(), 0, 0, destination.framebuffer, 0, 0, width_, height_);
}

void MultisampleTarget::create(int width, int height, int samples) {
    release();
    GLuint id = 0;
    glGenFramebuffers(1, &id);
    framebuffer_ = gl::Framebuffer(id);
    // Both attachments get the same request, so the driver rounds both to the same count (a
    // framebuffer whose attachments differ in samples is incomplete).
    color_ = makeRenderbuffer(GL_RGBA8, width, height, samples);
    depth_ = makeRenderbuffer(GL_DEPTH_COMPONENT24, width, height, samples);
    glBindFramebuffer(GL_FRAMEBUFFER, id);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_.get());
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.get());
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        release();
        throw std::runtime_error("MSAA: the " + std::to_string(width) + "x" + std::to_string(height) + " framebuffer with " +
                                 std::to_string(samples) + " samples is not complete on this GL");
    }
    GLint actual = 0;
    glBindRenderbuffer(GL_RENDERBUFFER, color_.get());
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES, &actual);
    width_ = width, height_ = height;
    requestedSamples_ = samples, actualSamples_ = int(actual);
}

void MultisampleTarget::release() {
    framebuffer_.reset();
    color_.reset();
    depth_.reset();
    width_ = height_ = requestedSamples_ = actualSamples_ = 0;
}

bool isMultisampled(GLuint framebuffer) {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);  // GL_SAMPLE_BUFFERS is the draw framebuffer's
    GLint sampleBuffers = 0;
    glGetIntegerv(GL_SAMPLE_BUFFERS, &sampleBuffers);
    return sampleBuffers > 0;
}

void blitColor(GLuint from, int x, int y, GLuint to, int toX, int toY, int width, int height) {
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, from);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, to);
    glBlitFramebuffer(x, y, x + width, y + height, toX, toY, toX + width, toY + height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

}  // namespace shadelab
