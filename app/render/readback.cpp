#include "render/readback.hpp"

#include "render/image_pass.hpp"
#include "render/multisample_target.hpp"
#include "render/program.hpp"

#include <cstdint>
#include <cstring>
#include <vector>

namespace shadelab {

Image readPixels(const RenderTarget& target) {
    Image img(target.width, target.height);
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
    std::vector<std::uint8_t> bottomUp(img.rgba.size());
    glReadPixels(0, 0, target.width, target.height, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
    const std::size_t row = std::size_t(target.width) * 4;
    for (int y = 0; y < target.height; ++y)
        std::memcpy(img.pixel(0, y), bottomUp.data() + std::size_t(target.height - 1 - y) * row, row);
    checkGl("readPixels");
    return img;
}

}  // namespace shadelab
