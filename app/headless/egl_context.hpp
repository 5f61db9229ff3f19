#pragma once
// A headless OpenGL 3.3 core context through EGL, drawing into an FBO (an OffscreenTarget). libEGL is
// dlopen'ed (like OSMesa, and for the same reason: no GL provider in the executable's link map).
#include "headless/headless_context.hpp"
#include "render/offscreen_target.hpp"

namespace shadelab {

class EglContext : public HeadlessContext {
public:
    // Uses the surfaceless platform (Mesa) when offered, else the first EGL device (a GPU driver).
    EglContext(int width, int height);
    ~EglContext() override;
    GLADloadfunc getProcAddress() const override;
    RenderTarget target() const override { return frame_.target(); }
    void resize(int width, int height) override;
    const char* backendName() const override { return "egl"; }

private:
    void* display_ = nullptr;
    void* context_ = nullptr;
    OffscreenTarget frame_;  // released before the context
};

}  // namespace shadelab
