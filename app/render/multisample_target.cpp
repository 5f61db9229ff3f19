#include "render/multisample_target.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace shadelab {

RenderTarget MultisampleTarget::begin(const RenderTarget& destination, int samples) {
    GLint maxSamples = 0;
    glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
    samples = std::min(samples, int(maxSamples));
    if (samples <= 1) {
        target_ = OffscreenTarget();
        return destination;
    }
    return target_.ensure(destination.width, destination.height, samples, "MSAA");
}

void MultisampleTarget::resolveInto(const RenderTarget& destination) const {
    if (!target_) return;
    const int width = target_.width(), height = target_.height();
    // A multisample resolve cannot scale: the rectangles must be the same size.
    if (destination.width != width || destination.height != height)
        throw std::runtime_error("MSAA: cannot resolve " + std::to_string(width) + "x" + std::to_string(height) +
                                 " into a " + std::to_string(destination.width) + "x" +
                                 std::to_string(destination.height) + " target");
    blitColor(target_.framebuffer(), 0, 0, destination.framebuffer, 0, 0, width, height);
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
    glBlitFramebuffer(x, y, x + width, y + height, toX, toY, toX + width, toY + height, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
}

}  // namespace shadelab
