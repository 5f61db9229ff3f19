#pragma once
// A framebuffer of shadelab's own to draw a frame into: RGBA8 colour and 24-bit depth renderbuffers of
// one size, optionally multisampled. The one way shadelab makes such a target: the EGL context's frame,
// the viewer's reduced moving frames, MSAA (MultisampleTarget) and the web page's view all hold one.
// Move-only, like the handles it owns; an empty one (default-constructed) owns nothing.
#include "render/gl_handles.hpp"
#include "render/render_target.hpp"

namespace shadelab {

class OffscreenTarget {
public:
    OffscreenTarget() = default;
    // A complete width x height framebuffer. `samples` 0: single-sampled storage; more: that many
    // samples asked of the driver, which may round up (samples() says what it gave; both attachments
    // get the same request, so they end up with the same count, as completeness requires). Leaves the
    // framebuffer bound. Throws std::runtime_error naming `what` when this GL cannot complete it.
    OffscreenTarget(int width, int height, int samples, const char* what);

    // The target to draw into at this size and `samples`: the buffers are kept when they were made for
    // them, else deleted and made again (deleted first: a large frame's memory is not held twice).
    // Throws as the constructor, leaving this empty.
    RenderTarget ensure(int width, int height, int samples, const char* what);

    // Where the renderer draws: this framebuffer and its size ({0, 0, 0} when empty).
    RenderTarget target() const { return RenderTarget{framebuffer_.get(), width_, height_}; }
    GLuint framebuffer() const { return framebuffer_.get(); }
    int width() const { return width_; }
    int height() const { return height_; }
    // Samples per pixel the driver gave; 0 when single-sampled or empty.
    int samples() const { return samples_; }
    explicit operator bool() const { return bool(framebuffer_); }

private:
    gl::Framebuffer framebuffer_;
    gl::Renderbuffer color_, depth_;
    int width_ = 0, height_ = 0;
    int requestedSamples_ = 0;  // what the driver was asked for
    int samples_ = 0;
};

}  // namespace shadelab
