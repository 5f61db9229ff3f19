#pragma once
// Multisample anti-aliasing as a render target: a multisampled OffscreenTarget (RGBA8 colour, 24-bit
// depth) that a frame is drawn into and then resolved into the real target. Per frame:
//   RenderTarget t = msaa.begin(view, samples);  // `view` itself when samples <= 1 (no MSAA)
//   renderer.render(scene, t); overlays.render(scene, t, ...);
//   msaa.resolveInto(view);                      // a blit; nothing to do when t was `view`
#include "render/offscreen_target.hpp"
#include "render/render_target.hpp"

namespace shadelab {

class MultisampleTarget {
public:
    // The target to draw this frame into: a multisampled framebuffer of `destination`'s size,
    // created or recreated when the size or `samples` changed (clamped to GL_MAX_SAMPLES). With
    // samples 0 or 1 (or a GL without multisampling) the buffers are released and `destination` is
    // returned, so the frame is drawn straight into it. Throws std::runtime_error.
    RenderTarget begin(const RenderTarget& destination, int samples);
    // Resolves the colour drawn since begin() into `destination` (glBlitFramebuffer, GL_NEAREST;
    // the sizes must match). Does nothing when begin() returned its destination.
    void resolveInto(const RenderTarget& destination) const;

    bool active() const { return bool(target_); }
    // Samples per pixel the driver gave (it may round up what was asked); 0 when not active.
    int samples() const { return target_.samples(); }

private:
    OffscreenTarget target_;
};

// Whether `framebuffer` has sample buffers: it cannot be read (glReadPixels, glCopyTexSubImage2D)
// before it is resolved. Leaves it bound as the draw framebuffer.
bool isMultisampled(GLuint framebuffer);

// Copies the width x height rectangle at `from`'s (x, y) to `to`'s (toX, toY), one pixel for one
// (GL_NEAREST), resolving the samples when `from` is multisampled. Scissor off, colour mask all on
// (both apply to blits).
void blitColor(GLuint from, int x, int y, GLuint to, int toX, int toY, int width, int height);

}  // namespace shadelab
