#pragma once
// The viewer's window: GLFW initialised, one window with a current OpenGL 3.3 core (forward-compatible)
// context, and both torn down again in the destructor. Nothing here draws.
#include <functional>
#include <string>
#include <vector>

struct GLFWwindow;

namespace shadelab {

class GlfwWindow {
public:
    // Opens a window of `width` + `sideWidth` * (the monitor's content scale) by `height` screen units,
    // shrunk to fit the monitor's work area: `width` x `height` is room for the content, `sideWidth`
    // for a side panel whose size follows the UI scale. Throws InputError "no display ..." when GLFW
    // cannot reach a display, std::runtime_error when it gets no GL 3.3 core context.
    GlfwWindow(int width, int height, float sideWidth, const std::string& title);
    ~GlfwWindow();
    GlfwWindow(const GlfwWindow&) = delete;
    GlfwWindow& operator=(const GlfwWindow&) = delete;

    GLFWwindow* handle() const { return window_; }
    void framebufferSize(int& width, int& height) const;  // pixels: what glViewport wants (high-DPI)
    void windowSize(int& width, int& height) const;       // screen units: what the mouse reports
    float contentScale() const;                           // the monitor's UI scale (1 on a plain X server)
    bool shouldClose() const;
    void requestClose();
    void pollEvents();
    void swapBuffers();
    // 0: as fast as possible (scripted runs), 1: follow the display's refresh.
    void setSwapInterval(int interval);

    // Paths of files dropped on the window since the last call.
    std::vector<std::string> takeDroppedPaths();
    // GLFW key codes pressed since the last call, in order (presses, not repeats). Dear ImGui 1.86
    // only sees a key that is still down when a frame starts, so a key pressed and released during
    // one slow frame (an 8x8 area light takes seconds on a software renderer) would be lost.
    std::vector<int> takePressedKeys();

private:
    GLFWwindow* window_ = nullptr;
    std::vector<std::string> dropped_;
    std::vector<int> pressed_;
};

}  // namespace shadelab
