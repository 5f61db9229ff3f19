#pragma once
// The readback: a rendered frame back from GL as an Image (for PNG files, tests and screenshots).
#include "core/image/image.hpp"
#include "render/render_target.hpp"

namespace shadelab {

// Reads the colour buffer of `target` (bottom-up in GL) into a top-down RGBA image; a multisampled
// target (render/multisample_target.hpp) is resolved into a temporary copy first.
Image readPixels(const RenderTarget& target);
// The same into `image`, whose storage is reused when it already has the target's size: a run of
// frames (a video) then reads every frame into the same pixels rather than fresh pages each time.
void readPixelsInto(const RenderTarget& target, Image& image);

}  // namespace shadelab
