#pragma once
// The viewer's window: GLFW initialised, one window with a current OpenGL 3.3 core (forward-compatible)
// context, and both torn down again in the destructor. Nothing here draws.
#include <optional>
#include <string>
#include <vector>

struct GLFWwindow;

namespace shadelab {

// A key pressed, with the modifiers (GLFW_MOD_*) held at that moment: a quick Ctrl+= can be released
// before the frame that reads it, so the Ctrl must travel with the key.
struct KeyPress {
    int key = 0;
    int mods = 0;
};

// Where the window was and how large, to open it there again (viewer/view_prefs.hpp).
struct WindowPlacement {
    int x = 0, y = 0, width = 0, height = 0;  // screen units
};

class GlfwWindow {
public:
    // Opens a window for `width` x `height` pixels of content at content scale 1 (scaled by the
    // monitor's content scale) plus `sideWidth` screen units beside it for the panel, shrunk to fit the
    // monitor's work area; or at `placement` when given and on a monitor. Throws InputError "no display
    // ..." when GLFW cannot reach a display, std::runtime_error when it gets no GL 3.3 core context.
    GlfwWindow(int width, int height, float sideWidth, const std::string& title,
               const std::optional<WindowPlacement>& placement = std::nullopt);
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
    // Sleeps until an event arrives or `timeoutSeconds` pass (render on demand: no CPU while idle).
    void waitEvents(double timeoutSeconds);
    void swapBuffers();
    // 0: as fast as possible (scripted runs), 1: follow the display's refresh.
    void setSwapInterval(int interval);
    // The refresh rate of the monitor the window is on (the primary one when windowed), in Hz; 0 when
    // unknown.
    int refreshRate() const;

    // F11: the whole primary monitor, and back to where the window was.
    void setFullscreen(bool on);
    bool fullscreen() const;
    // Position and size while windowed (the size it returns to from fullscreen).
    WindowPlacement placement() const;

    // Counts every input and window event (keys, characters, mouse, wheel, resize, focus, expose,
    // drops); the viewer redraws when it changed.
    unsigned long eventCount() const { return events_; }

    // Paths of files dropped on the window since the last call.
    std::vector<std::string> takeDroppedPaths();
    // GLFW key codes pressed since the last call, in order (presses, not repeats). Dear ImGui 1.86
    // only sees a key that is still down when a frame starts, so a key pressed and released during
    // one slow frame (an 8x8 area light takes seconds on a software renderer) would be lost.
    std::vector<KeyPress> takePressedKeys();

private:
    // Input, drops, resizes and focus changes count as events (and keys and drops are kept).
    void installCallbacks();

    GLFWwindow* window_ = nullptr;
    std::vector<std::string> dropped_;
    std::vector<KeyPress> pressed_;
    unsigned long events_ = 0;
    WindowPlacement windowed_;  // before fullscreen
};

}  // namespace shadelab
