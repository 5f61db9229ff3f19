#pragma once
// The framebuffer a reduced moving frame is drawn into (ViewQuality): an OffscreenTarget (RGBA8 colour,
// 24-bit depth) of the reduced size, then magnified into the view (GL_LINEAR). Kept while the size stays.
#include "render/offscreen_target.hpp"
#include "render/render_target.hpp"

namespace shadelab {

class ReducedTarget {
public:
    // The target to draw a width x height moving frame into (made or remade when the size changed).
    // Throws std::runtime_error when the GL cannot complete the framebuffer.
    RenderTarget begin(int width, int height);
    // Magnifies what was drawn into `view` (the window's framebuffer), which is bound afterwards.
    void magnifyInto(const RenderTarget& view) const;

private:
    OffscreenTarget target_;
};

}  // namespace shadelab
