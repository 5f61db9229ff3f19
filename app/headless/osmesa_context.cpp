#include "headless/osmesa_context.hpp"

#include <GL/osmesa.h>
#include <dlfcn.h>

#include <stdexcept>
#include <string>

namespace shadelab {
namespace {

// The few OSMesa entry points shadelab uses, resolved once from the dlopen'ed library.
struct OsMesaApi {
    decltype(&OSMesaCreateContextAttribs) createContextAttribs = nullptr;
    decltype(&OSMesaMakeCurrent) makeCurrent = nullptr;
    decltype(&OSMesaDestroyContext) destroyContext = nullptr;
    decltype(&OSMesaGetProcAddress) getProcAddress = nullptr;
};

const OsMesaApi& api() {
    static const OsMesaApi loaded = [] {
        OsMesaApi a;
        // Never dlclose'd: Mesa keeps global state that does not survive being unloaded.
        void* lib = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL);
        if (!lib) lib = dlopen("libOSMesa.so", RTLD_NOW | RTLD_LOCAL);
        if (!lib) return a;
        a.createContextAttribs =
            reinterpret_cast<decltype(a.createContextAttribs)>(dlsym(lib, "OSMesaCreateContextAttribs"));
        a.makeCurrent = reinterpret_cast<decltype(a.makeCurrent)>(dlsym(lib, "OSMesaMakeCurrent"));
        a.destroyContext = reinterpret_cast<decltype(a.destroyContext)>(dlsym(lib, "OSMesaDestroyContext"));
        a.getProcAddress = reinterpret_cast<decltype(a.getProcAddress)>(dlsym(lib, "OSMesaGetProcAddress"));
        return a;
    }();
    if (!loaded.createContextAttribs || !loaded.makeCurrent || !loaded.destroyContext || !loaded.getProcAddress)
        throw std::runtime_error("headless rendering needs libOSMesa.so.8 (Debian package libosmesa6)");
    return loaded;
}

GLADapiproc loadGlFunction(const char* name) { return reinterpret_cast<GLADapiproc>(api().getProcAddress(name)); }

}  // namespace

OsMesaContext::OsMesaContext(int width, int height) {
    const int attribs[] = {OSMESA_FORMAT,
                           OSMESA_RGBA,
                           OSMESA_DEPTH_BITS,
                           24,
                           OSMESA_STENCIL_BITS,
                           0,
                           OSMESA_ACCUM_BITS,
                           0,
                           OSMESA_PROFILE,
                           OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION,
                           3,
                           OSMESA_CONTEXT_MINOR_VERSION,
                           3,
                           0};
    context_ = api().createContextAttribs(attribs, nullptr);
    if (!context_) throw std::runtime_error("OSMesa could not create an OpenGL 3.3 core context");
    resize(width, height);
}

OsMesaContext::~OsMesaContext() {
    if (context_) api().destroyContext(static_cast<OSMesaContext>(context_));
}

void OsMesaContext::resize(int width, int height) {
    colorBuffer_.assign(std::size_t(width) * std::size_t(height) * 4, 0);
    if (!api().makeCurrent(static_cast<OSMesaContext>(context_), colorBuffer_.data(), GL_UNSIGNED_BYTE, width, height))
        throw std::runtime_error("OSMesa could not make a " + std::to_string(width) + "x" + std::to_string(height) +
                                 " context current");
    width_ = width;
    height_ = height;
}

GLADloadfunc OsMesaContext::loader() {
    api();  // fail early with the clear message
    return &loadGlFunction;
}

}  // namespace shadelab
