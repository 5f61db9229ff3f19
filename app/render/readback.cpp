#include "render/readback.hpp"

#include "render/image_pass.hpp"
#include "render/multisample_target.hpp"
#include "render/program.hpp"

#include <algorithm>
#include <cstdint>

namespace shadelab {

Image readPixels(const RenderTarget& target) {
    Image img;
    readPixelsInto(target, img);
    return img;
}

void readPixelsInto(const RenderTarget& target, Image& img) {
    if (img.width != target.width || img.height != target.height) img = Image(target.width, target.height);
    // glReadPixels cannot read a multisampled framebuffer (MSAA): resolve it into a plain one first.
    gl::Framebuffer resolved;
    gl::Texture resolvedColor;
    if (isMultisampled(target.framebuffer)) {
        resolvedColor = makeImageTexture(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, target.width, target.height);
        resolved = makeFramebuffer(resolvedColor.get(), 0, "readPixels (MSAA resolve)");
        blitColor(target.framebuffer, 0, 0, resolved.get(), 0, 0, target.width, target.height);
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, resolved ? resolved.get() : target.framebuffer);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, target.width, target.height, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
    // GL's rows are bottom-up: swapped in place, row y with row height-1-y.
    const std::size_t row = std::size_t(target.width) * 4;
    for (int y = 0; y < target.height / 2; ++y)
        std::swap_ranges(img.pixel(0, y), img.pixel(0, y) + row, img.pixel(0, target.height - 1 - y));
    checkGl("readPixels");
}

}  // namespace shadelab
