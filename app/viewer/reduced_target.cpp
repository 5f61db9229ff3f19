#include "viewer/reduced_target.hpp"

namespace shadelab {

RenderTarget ReducedTarget::begin(int width, int height) {
    return target_.ensure(width, height, 0, "the reduced moving frame");
}

void ReducedTarget::magnifyInto(const RenderTarget& view) const {
    glDisable(GL_SCISSOR_TEST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, target_.framebuffer());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, view.framebuffer);
    glBlitFramebuffer(0, 0, target_.width(), target_.height(), 0, 0, view.width, view.height, GL_COLOR_BUFFER_BIT,
                      GL_LINEAR);
    glBindFramebuffer(GL_FRAMEBUFFER, view.framebuffer);
}

}  // namespace shadelab
