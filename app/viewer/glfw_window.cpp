#include "viewer/glfw_window.hpp"

#include "core/base/error.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace shadelab {
namespace {

// GLFW reports the reason for a failure through glfwGetError; no error callback (a global) is needed.
std::string lastGlfwError() {
    const char* description = nullptr;
    glfwGetError(&description);
    return description ? description : "unknown GLFW error";
}

GlfwWindow& self(GLFWwindow* w) { return *static_cast<GlfwWindow*>(glfwGetWindowUserPointer(w)); }

void hintContext() {
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    // No multisampled default framebuffer: the viewer anti-aliases in its own multisampled target,
    // only where asked, so the 3D view can give the same pixels as the headless render.
    glfwWindowHint(GLFW_SAMPLES, 0);
    glfwWindowHint(GLFW_DEPTH_BITS, 24);
}

// The primary monitor's work area (empty where there is none) and content scale (at least 1).
struct WorkArea {
    int x = 0, y = 0, width = 0, height = 0;
    float scale = 1.0f;
};
WorkArea primaryWorkArea() {
    WorkArea area;
    if (GLFWmonitor* monitor = glfwGetPrimaryMonitor()) {
        float scaleX = 1.0f, scaleY = 1.0f;
        glfwGetMonitorContentScale(monitor, &scaleX, &scaleY);
        area.scale = std::max(1.0f, std::max(scaleX, scaleY));
        glfwGetMonitorWorkarea(monitor, &area.x, &area.y, &area.width, &area.height);
    }
    return area;
}

}  // namespace

GlfwWindow::GlfwWindow(int width, int height, float sideWidth, const std::string& title,
                       const std::optional<WindowPlacement>& placement) {
    if (!glfwInit())
        throw InputError("no display available for the viewer (" + lastGlfwError() +
                         "); use --output FILE.png to render headless");
    hintContext();
    const WorkArea area = primaryWorkArea();
    // The content keeps its size on the screen: at 2x, twice the pixels.
    width = int(std::lround(float(width) * area.scale + sideWidth * area.scale));
    height = int(std::lround(float(height) * area.scale));
    if (placement && placement->width > 0 && placement->height > 0) {
        width = placement->width;
        height = placement->height;
    }
    if (area.width > 0 && area.height > 0) {
        width = std::min(width, area.width);
        height = std::min(height, area.height);
    }
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window_) {
        const std::string reason = lastGlfwError();
        glfwTerminate();
        throw std::runtime_error("could not open a window with an OpenGL 3.3 core context: " + reason);
    }
    if (placement && area.width > 0) {
        // Only where the window is still on the work area (a monitor may have gone since).
        const int x = std::clamp(placement->x, area.x, area.x + area.width - std::min(width, area.width));
        const int y = std::clamp(placement->y, area.y, area.y + area.height - std::min(height, area.height));
        glfwSetWindowPos(window_, x, y);
    }
    glfwMakeContextCurrent(window_);
    installCallbacks();
    windowed_ = placement ? *placement : WindowPlacement{};
}

void GlfwWindow::installCallbacks() {
    // The callbacks find this object through the window's user pointer. Dear ImGui's GLFW backend,
    // initialised after this, installs its own key, character, mouse, wheel and focus callbacks and
    // calls these from them.
    glfwSetWindowUserPointer(window_, this);
    glfwSetDropCallback(window_, [](GLFWwindow* w, int count, const char** paths) {
        for (int i = 0; i < count; ++i) self(w).dropped_.emplace_back(paths[i]);
        ++self(w).events_;
    });
    glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int mods) {
        if (action == GLFW_PRESS) self(w).pressed_.push_back(KeyPress{key, mods});
        ++self(w).events_;
    });
    glfwSetCharCallback(window_, [](GLFWwindow* w, unsigned) { ++self(w).events_; });
    glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int, int, int) { ++self(w).events_; });
    glfwSetScrollCallback(window_, [](GLFWwindow* w, double, double) { ++self(w).events_; });
    glfwSetCursorPosCallback(window_, [](GLFWwindow* w, double, double) { ++self(w).events_; });
    glfwSetCursorEnterCallback(window_, [](GLFWwindow* w, int) { ++self(w).events_; });
    glfwSetWindowFocusCallback(window_, [](GLFWwindow* w, int) { ++self(w).events_; });
    glfwSetWindowSizeCallback(window_, [](GLFWwindow* w, int, int) { ++self(w).events_; });
    glfwSetFramebufferSizeCallback(window_, [](GLFWwindow* w, int, int) { ++self(w).events_; });
    glfwSetWindowRefreshCallback(window_, [](GLFWwindow* w) { ++self(w).events_; });
    glfwSetWindowContentScaleCallback(window_, [](GLFWwindow* w, float, float) { ++self(w).events_; });
    glfwSetWindowCloseCallback(window_, [](GLFWwindow* w) { ++self(w).events_; });
}

GlfwWindow::~GlfwWindow() {
    glfwDestroyWindow(window_);
    glfwTerminate();
}

void GlfwWindow::framebufferSize(int& width, int& height) const { glfwGetFramebufferSize(window_, &width, &height); }
void GlfwWindow::windowSize(int& width, int& height) const { glfwGetWindowSize(window_, &width, &height); }

float GlfwWindow::contentScale() const {
    float x = 1.0f, y = 1.0f;
    glfwGetWindowContentScale(window_, &x, &y);
    return std::max(1.0f, std::max(x, y));
}

bool GlfwWindow::shouldClose() const { return glfwWindowShouldClose(window_); }
void GlfwWindow::requestClose() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }
void GlfwWindow::pollEvents() { glfwPollEvents(); }
void GlfwWindow::waitEvents(double timeoutSeconds) { glfwWaitEventsTimeout(timeoutSeconds); }
void GlfwWindow::swapBuffers() { glfwSwapBuffers(window_); }
void GlfwWindow::setSwapInterval(int interval) { glfwSwapInterval(interval); }

int GlfwWindow::refreshRate() const {
    GLFWmonitor* monitor = glfwGetWindowMonitor(window_);
    if (!monitor) monitor = glfwGetPrimaryMonitor();
    const GLFWvidmode* mode = monitor ? glfwGetVideoMode(monitor) : nullptr;
    return mode ? mode->refreshRate : 0;
}

bool GlfwWindow::fullscreen() const { return glfwGetWindowMonitor(window_) != nullptr; }

WindowPlacement GlfwWindow::placement() const {
    if (fullscreen()) return windowed_;
    WindowPlacement p;
    glfwGetWindowPos(window_, &p.x, &p.y);
    glfwGetWindowSize(window_, &p.width, &p.height);
    return p;
}

void GlfwWindow::setFullscreen(bool on) {
    if (on == fullscreen()) return;
    if (on) {
        GLFWmonitor* monitor = glfwGetPrimaryMonitor();
        const GLFWvidmode* mode = monitor ? glfwGetVideoMode(monitor) : nullptr;
        if (!mode) return;
        windowed_ = placement();
        glfwSetWindowMonitor(window_, monitor, 0, 0, mode->width, mode->height, mode->refreshRate);
    } else {
        const WindowPlacement& p = windowed_;
        glfwSetWindowMonitor(window_, nullptr, p.x, p.y, std::max(p.width, 320), std::max(p.height, 240), 0);
    }
    ++events_;
}

std::vector<std::string> GlfwWindow::takeDroppedPaths() { return std::exchange(dropped_, {}); }
std::vector<KeyPress> GlfwWindow::takePressedKeys() { return std::exchange(pressed_, {}); }

}  // namespace shadelab
