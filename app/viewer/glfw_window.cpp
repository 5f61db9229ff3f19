#include "viewer/glfw_window.hpp"

#include "core/error.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
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

}  // namespace

GlfwWindow::GlfwWindow(int width, int height, float sideWidth, const std::string& title) {
    if (!glfwInit())
        throw InputError("no display available for the viewer (" + lastGlfwError() +
                         "); use --output FILE.png to render headless");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    // No multisampling: the 3D view must give the same pixels as the headless render of the scene.
    glfwWindowHint(GLFW_SAMPLES, 0);
    glfwWindowHint(GLFW_DEPTH_BITS, 24);
    if (GLFWmonitor* monitor = glfwGetPrimaryMonitor()) {
        float scaleX = 1.0f, scaleY = 1.0f;
        glfwGetMonitorContentScale(monitor, &scaleX, &scaleY);
        width += int(sideWidth * std::max(1.0f, std::max(scaleX, scaleY)) + 0.5f);
        int x = 0, y = 0, areaWidth = 0, areaHeight = 0;
        glfwGetMonitorWorkarea(monitor, &x, &y, &areaWidth, &areaHeight);
        if (areaWidth > 0 && areaHeight > 0) {
            width = std::min(width, areaWidth);
            height = std::min(height, areaHeight);
        }
    } else {
        width += int(sideWidth + 0.5f);
    }
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window_) {
        const std::string reason = lastGlfwError();
        glfwTerminate();
        throw std::runtime_error("could not open a window with an OpenGL 3.3 core context: " + reason);
    }
    glfwMakeContextCurrent(window_);
    // The callbacks find this object through the window's user pointer. Dear ImGui's GLFW backend,
    // initialised after this, installs its own callbacks and calls these from them.
    glfwSetWindowUserPointer(window_, this);
    glfwSetDropCallback(window_, [](GLFWwindow* w, int count, const char** paths) {
        auto* self = static_cast<GlfwWindow*>(glfwGetWindowUserPointer(w));
        for (int i = 0; i < count; ++i) self->dropped_.emplace_back(paths[i]);
    });
    glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int) {
        if (action == GLFW_PRESS) static_cast<GlfwWindow*>(glfwGetWindowUserPointer(w))->pressed_.push_back(key);
    });
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
void GlfwWindow::swapBuffers() { glfwSwapBuffers(window_); }
void GlfwWindow::setSwapInterval(int interval) { glfwSwapInterval(interval); }

std::vector<std::string> GlfwWindow::takeDroppedPaths() { return std::exchange(dropped_, {}); }
std::vector<int> GlfwWindow::takePressedKeys() { return std::exchange(pressed_, {}); }

}  // namespace shadelab
