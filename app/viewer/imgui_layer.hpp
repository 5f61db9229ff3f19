#pragma once
// Dear ImGui for one GLFW window: the context, the GLFW and OpenGL 3 backends, and a TrueType font
// (DejaVu Sans, with Greek, sub- and superscripts) rasterised at the UI's scale. Created after the
// window's context is current; destroyed before it.
#include <vector>

struct GLFWwindow;

namespace shadelab {

class ImGuiLayer {
public:
    // `scale`: pixels per ImGui unit of text and widgets (the monitor's content scale times the UI
    // scale). Throws std::runtime_error if the OpenGL 3 backend cannot load its GL entry points.
    ImGuiLayer(GLFWwindow* window, float scale);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    // Rasterises the font again and rescales the style when `scale` differs from the current one
    // (crisp at every size, never a magnified bitmap). Between frames only.
    void setScale(float scale);
    float scale() const { return scale_; }
    // Whether the panel's font is DejaVu Sans (false: it was not found and ImGui's bitmap font is used).
    bool trueTypeFont() const { return trueType_; }

    // Dear ImGui 1.86 reads key state once a frame: a key pressed and released within one frame (a
    // short tap at a low frame rate) would never be seen down. `pressed` are the keys pressed since the
    // last frame; those already released again are held down for this one frame. Call after polling
    // events and before newFrame(); releaseTappedKeys() before the next poll.
    void holdTappedKeys(const std::vector<int>& pressed);
    void releaseTappedKeys();

    void newFrame();  // after polling events, before any ImGui:: call of the frame
    void render();    // draws the frame's ImGui windows into the current framebuffer

private:
    void buildFonts();
    float scale_ = 1.0f;
    bool trueType_ = false;
    std::vector<int> held_;
};

}  // namespace shadelab
