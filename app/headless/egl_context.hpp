#pragma once
// A headless OpenGL 3.3 core context through EGL, drawing into an FBO. libEGL is dlopen'ed (like
// OSMesa, and for the same reason: no GL provider in the executable's link map).
#include "headless/headless_context.hpp"
#include "render/gl_handles.hpp"

namespace shadelab {

class EglContext : public HeadlessContext {
public:
    // Uses the surfaceless platform (Mesa) when offered, else the first EGL device (a GPU driver).
    EglContext(int width, int height);
    ~EglContext() override;
    GLADloadfunc getProcAddress() const override;
    RenderTarget target() const override { return RenderTarget{framebuffer_.get(), width_, height_}; }
    void resize(int width, int height) override;
    const char* backendName() const override { return "egl"; }

private:
    void* display_ = nullptr;
    void* context_ = nullptr;
    gl::Framebuffer framebuffer_;
    gl::Renderbuffer color_, depth_;
    int width_ = 0, height_ = 0;
};

}  // namespace shadelab
