#pragma once
// An offscreen OpenGL context for rendering with no display: OSMesa (Mesa's software renderer, Debian
// 12's default) or EGL (surfaceless, or a GPU through EGL_EXT_platform_device; Mesa 25.1 removed
// OSMesa). The renderer sees only getProcAddress() and target().
#include "render/renderer.hpp"

#include <memory>
#include <stdexcept>
#include <string>

namespace shadelab {

enum class HeadlessBackend { Auto, OsMesa, Egl };

// No OpenGL context could be made: the libraries are missing or broken, or the driver refused. What
// failed, per backend tried. (`--test` tells it apart from a failing case: exit status 2.)
class GlUnavailable : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class HeadlessContext {
public:
    virtual ~HeadlessContext() = default;
    virtual GLADloadfunc getProcAddress() const = 0;
    // Where to draw: OSMesa's own framebuffer (0), or an FBO for EGL.
    virtual RenderTarget target() const = 0;
    virtual void resize(int width, int height) = 0;
    virtual const char* backendName() const = 0;
};

// Auto tries OSMesa, then EGL (of those this build has). Throws GlUnavailable saying what is missing
// for each; asking for a backend the build has not got (CMake options SHADELAB_OSMESA, SHADELAB_EGL) is an
// InputError.
std::unique_ptr<HeadlessContext> makeHeadlessContext(HeadlessBackend backend, int width, int height);

const char* toString(HeadlessBackend b);

}  // namespace shadelab
