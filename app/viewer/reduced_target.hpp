#pragma once
// The framebuffer a reduced moving frame is drawn into (ViewQuality): RGBA8 colour and 24-bit depth
// of the reduced size, then magnified into the view (GL_LINEAR). Kept while the size stays.
#include "render/gl_handles.hpp"
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
    gl::Framebuffer framebuffer_;
    gl::Renderbuffer color_, depth_;
    int width_ = 0, height_ = 0;
};

}  // namespace shadelab
