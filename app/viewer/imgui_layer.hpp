#pragma once
// Dear ImGui for one GLFW window: the context, the GLFW and OpenGL 3 backends, and a font sized for
// the monitor's content scale. Created after the window's context is current; destroyed before it.
struct GLFWwindow;

namespace shadelab {

class ImGuiLayer {
public:
    // Throws std::runtime_error if the OpenGL 3 backend cannot load its GL entry points.
    ImGuiLayer(GLFWwindow* window, float contentScale);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    void newFrame();  // after polling events, before any ImGui:: call of the frame
    void render();    // draws the frame's ImGui windows into the current framebuffer
};

}  // namespace shadelab
