#pragma once
// An offscreen OpenGL context from Mesa's OSMesa (llvmpipe), for rendering with no display.
//
// libOSMesa is loaded at run time (dlopen, RTLD_LOCAL) rather than linked: it exports the same gl*
// symbols as libGL, which the windowed viewer uses through GLFW, and keeping it out of the link map
// lets one executable serve both without the two providers shadowing each other. The renderer reaches
// GL only through the function pointers this context's getProcAddress hands out.
#include "headless/headless_context.hpp"

#include <cstdint>
#include <vector>

namespace shadelab {

class OsMesaContext : public HeadlessContext {
public:
    // Creates a core-profile context (3.3 or newer) with RGBA8 colour and a 24-bit depth buffer, and
    // makes it current on this thread. Throws std::runtime_error naming what is missing.
    OsMesaContext(int width, int height);
    ~OsMesaContext() override;
    OsMesaContext(const OsMesaContext&) = delete;
    OsMesaContext& operator=(const OsMesaContext&) = delete;

    // Gives the context a colour buffer of a new size (and makes it current).
    void resize(int width, int height) override;
    static GLADloadfunc loader();
    GLADloadfunc getProcAddress() const override { return loader(); }
    RenderTarget target() const override { return RenderTarget{0, width_, height_}; }
    const char* backendName() const override { return "osmesa"; }
    int width() const { return width_; }
    int height() const { return height_; }

private:
    void* context_ = nullptr;
    std::vector<std::uint8_t> colorBuffer_;
    int width_ = 0, height_ = 0;
};

}  // namespace shadelab
