#include "headless/headless_context.hpp"

#include "core/base/error.hpp"

#if SHADELAB_HAVE_OSMESA
#include "headless/osmesa_context.hpp"
#endif
#if SHADELAB_HAVE_EGL
#include "headless/egl_context.hpp"
#endif

#include <stdexcept>
#include <string>

namespace shadelab {
namespace {

// A context of exactly this backend; a backend this build has not got is an input error.
std::unique_ptr<HeadlessContext> makeContext(HeadlessBackend backend, int width, int height) {
    if (backend == HeadlessBackend::OsMesa) {
#if SHADELAB_HAVE_OSMESA
        return std::make_unique<OsMesaContext>(width, height);
#else
        throw InputError("--backend osmesa: this shadelab was built without OSMesa (CMake option SHADELAB_OSMESA)");
#endif
    }
#if SHADELAB_HAVE_EGL
    return std::make_unique<EglContext>(width, height);
#else
    throw InputError("--backend egl: this shadelab was built without EGL (CMake option SHADELAB_EGL)");
#endif
}

}  // namespace

namespace {

// makeContext, its failures (other than the build's, an InputError) as GlUnavailable.
std::unique_ptr<HeadlessContext> makeAvailable(HeadlessBackend backend, int width, int height) {
    try {
        return makeContext(backend, width, height);
    } catch (const InputError&) {
        throw;
    } catch (const std::runtime_error& e) {
        throw GlUnavailable(e.what());
    }
}

}  // namespace

std::unique_ptr<HeadlessContext> makeHeadlessContext(HeadlessBackend backend, int width, int height) {
    if (backend != HeadlessBackend::Auto) return makeAvailable(backend, width, height);
    if (!SHADELAB_HAVE_OSMESA) return makeAvailable(HeadlessBackend::Egl, width, height);
    if (!SHADELAB_HAVE_EGL) return makeAvailable(HeadlessBackend::OsMesa, width, height);
    try {
        return makeContext(HeadlessBackend::OsMesa, width, height);
    } catch (const std::exception& osmesa) {
        try {
            return makeContext(HeadlessBackend::Egl, width, height);
        } catch (const std::exception& egl) {
            throw GlUnavailable(std::string("no headless OpenGL: ") + osmesa.what() + "; " + egl.what());
        }
    }
}

const char* toString(HeadlessBackend b) {
    switch (b) {
    case HeadlessBackend::Auto: return "auto";
    case HeadlessBackend::OsMesa: return "osmesa";
    case HeadlessBackend::Egl: return "egl";
    }
    return "?";
}

}  // namespace shadelab
