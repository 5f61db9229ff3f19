#include "headless/egl_context.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <dlfcn.h>

#include <cstring>
#include <stdexcept>
#include <string>

namespace shadelab {
namespace {

// An entry point of libEGL, looked up by name: converts to the function pointer type it initialises
// (null where the library or the entry point is missing).
struct EglEntry {
    PFNEGLGETPROCADDRESSPROC lookup;
    const char* name;
    template <typename Function>
    operator Function() const {
        return lookup ? reinterpret_cast<Function>(lookup(name)) : nullptr;
    }
};

// The EGL functions shadelab calls: one row each, loaded in this order when the table is made.
struct EglApi {
    void* library = dlopen("libEGL.so.1", RTLD_NOW | RTLD_LOCAL);  // never dlclose'd: drivers keep global state
    PFNEGLGETPROCADDRESSPROC getProcAddress =
        library ? reinterpret_cast<PFNEGLGETPROCADDRESSPROC>(dlsym(library, "eglGetProcAddress")) : nullptr;
    PFNEGLQUERYSTRINGPROC queryString = EglEntry{getProcAddress, "eglQueryString"};
    PFNEGLGETPLATFORMDISPLAYEXTPROC getPlatformDisplay = EglEntry{getProcAddress, "eglGetPlatformDisplayEXT"};
    PFNEGLQUERYDEVICESEXTPROC queryDevices = EglEntry{getProcAddress, "eglQueryDevicesEXT"};
    PFNEGLQUERYDEVICESTRINGEXTPROC queryDeviceString = EglEntry{getProcAddress, "eglQueryDeviceStringEXT"};
    PFNEGLINITIALIZEPROC initialize = EglEntry{getProcAddress, "eglInitialize"};
    PFNEGLTERMINATEPROC terminate = EglEntry{getProcAddress, "eglTerminate"};
    PFNEGLBINDAPIPROC bindApi = EglEntry{getProcAddress, "eglBindAPI"};
    PFNEGLCREATECONTEXTPROC createContext = EglEntry{getProcAddress, "eglCreateContext"};
    PFNEGLDESTROYCONTEXTPROC destroyContext = EglEntry{getProcAddress, "eglDestroyContext"};
    PFNEGLMAKECURRENTPROC makeCurrent = EglEntry{getProcAddress, "eglMakeCurrent"};
    PFNEGLGETERRORPROC getError = EglEntry{getProcAddress, "eglGetError"};
};

const EglApi& api() {
    static const EglApi loaded;
    if (!loaded.getProcAddress || !loaded.getPlatformDisplay || !loaded.initialize || !loaded.createContext ||
        !loaded.makeCurrent)
        throw std::runtime_error(
            "EGL headless rendering needs libEGL.so.1 with EGL_EXT_platform_base "
            "(Debian packages libegl1 and libegl-mesa0)");
    return loaded;
}

bool hasExtension(const char* list, const char* name) {
    if (!list) return false;
    const size_t n = std::strlen(name);
    for (const char* p = std::strstr(list, name); p; p = std::strstr(p + 1, name))
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

GLADapiproc loadGlFunction(const char* name) { return reinterpret_cast<GLADapiproc>(api().getProcAddress(name)); }

std::string eglError(const char* what) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04x", api().getError ? unsigned(api().getError()) : 0u);
    return std::string("EGL: ") + what + " failed (error " + code + ")";
}

}  // namespace

EglContext::EglContext(int width, int height) {
    const EglApi& egl = api();
    const char* clientExtensions = egl.queryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    // An initialised display: a hardware EGL device first (NVIDIA's driver offers its GPUs only this
    // way, and with Mesa installed beside it the surfaceless platform would quietly be llvmpipe), then
    // Mesa's surfaceless platform (Mesa's GPU driver if it has one, else llvmpipe), then any device.
    EGLint major = 0, minor = 0;
    auto initialised = [&](EGLDisplay d) { return d != EGL_NO_DISPLAY && egl.initialize(d, &major, &minor); };
    EGLDeviceEXT devices[16];
    EGLint deviceCount = 0;
    if (hasExtension(clientExtensions, "EGL_EXT_platform_device") && egl.queryDevices &&
        !egl.queryDevices(16, devices, &deviceCount))
        deviceCount = 0;
    auto firstDevice = [&](bool hardwareOnly) {
        for (EGLint i = 0; i < deviceCount; ++i) {
            const char* extensions =
                egl.queryDeviceString ? egl.queryDeviceString(devices[i], EGL_EXTENSIONS) : nullptr;
            if (hardwareOnly && hasExtension(extensions, "EGL_MESA_device_software")) continue;
            const EGLDisplay d = egl.getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
            if (initialised(d)) return d;
        }
        return EGLDisplay(EGL_NO_DISPLAY);
    };
    EGLDisplay display = firstDevice(true);
    if (display == EGL_NO_DISPLAY && hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
        const EGLDisplay d = egl.getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (initialised(d)) display = d;
    }
    if (display == EGL_NO_DISPLAY) display = firstDevice(false);
    if (display == EGL_NO_DISPLAY)
        throw std::runtime_error(deviceCount == 0 && !hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")
                                     ? "EGL: no surfaceless platform and no EGL device"
                                     : eglError("eglInitialize (every EGL device and the surfaceless platform)"));
    display_ = display;
    if (!egl.bindApi(EGL_OPENGL_API)) throw std::runtime_error(eglError("eglBindAPI(OpenGL)"));
    // No config and no surface (EGL_KHR_no_config_context, EGL_KHR_surfaceless_context): the
    // renderer draws into the FBO made below.
    const EGLint attribs[] = {
        EGL_CONTEXT_MAJOR_VERSION,           3,       EGL_CONTEXT_MINOR_VERSION, 3, EGL_CONTEXT_OPENGL_PROFILE_MASK,
        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    context_ = egl.createContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
    if (!context_) throw std::runtime_error(eglError("eglCreateContext (OpenGL 3.3 core)"));
    if (!egl.makeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
        throw std::runtime_error(eglError("eglMakeCurrent (surfaceless)"));
    if (!gladLoadGL(&loadGlFunction)) throw std::runtime_error("EGL: could not load OpenGL entry points");
    resize(width, height);
}

EglContext::~EglContext() {
    frame_ = OffscreenTarget();
    const EglApi& egl = api();
    if (context_) {
        egl.makeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        egl.destroyContext(display_, context_);
    }
    if (display_) egl.terminate(display_);
}

GLADloadfunc EglContext::getProcAddress() const { return &loadGlFunction; }

void EglContext::resize(int width, int height) { frame_.ensure(width, height, 0, "EGL"); }

}  // namespace shadelab
