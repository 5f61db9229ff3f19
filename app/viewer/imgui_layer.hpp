#pragma once
// Dear ImGui for one GLFW window: the context, the GLFW and OpenGL 3 backends, and a TrueType font
// (DejaVu Sans, with Greek, sub- and superscripts) rasterised at the UI's scale. Created after the
// window's context is current; destroyed before it.
#include "render/gl_handles.hpp"
#include "viewer/glfw_window.hpp"

#include <cstdint>
#include <vector>

struct ImDrawList;
struct ImFont;

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
    // DejaVu Sans Mono at about the text's size (the Shader section's code); null where the font
    // files are missing.
    ImFont* monoFont() const { return monoFont_; }
    // The text over the 3D view (captions, labels, the formula, the readout) has its own size, from
    // the window's height rather than the panel's scale: `text` is its size and `formulaMain` the
    // formula's main line (ImGui units). The fonts are rasterised again when a size changes by a
    // whole pixel (a resize). Between frames only.
    void setViewTextSize(float text, float formulaMain);
    // DejaVu Sans at the view text's size, its monospaced cut at the same size (the shader view over
    // the picture), and DejaVu Sans at the formula's main line; null where the font files are missing.
    ImFont* viewFont() const { return viewFont_; }
    ImFont* viewMonoFont() const { return viewMonoFont_; }
    ImFont* formulaFont() const { return formulaFont_; }

    // Dear ImGui 1.86 reads key state once a frame: a key pressed and released within one frame (a
    // short tap at a low frame rate) would never be seen down. `pressed` are the keys pressed since the
    // last frame; those already released again are held down for this one frame, with the modifiers
    // that were down when they were pressed. Call after polling events and before newFrame();
    // releaseTappedKeys() before the next poll.
    void holdTappedKeys(const std::vector<KeyPress>& pressed);
    void releaseTappedKeys();

    void newFrame();  // after polling events, before any ImGui:: call of the frame
    // Draws the frame's ImGui output into the default framebuffer. `panelLeft` (ImGui units; < 0: none)
    // is where the side panel starts: while every window lies right of it and their draw lists are
    // what they were last frame, the panel is copied from a cache instead of drawn again (a software
    // rasterizer spends more on the panel's hundreds of small draws than on the 3D view).
    void render(float panelLeft = -1.0f);
    // Whether the back buffer keeps its pixels from one frame to the next (Mesa's software rasterizers
    // on X11 copy it to the window and keep it). There the cached panel is not even copied again while
    // the back buffer still holds it; a stamp in its corner pixel says which copy is there.
    void setBackBufferKept(bool kept) { backBufferKept_ = kept; }

private:
    void buildFonts();
    bool panelFromCache(const std::vector<ImDrawList*>& windows, int left, int width, int height);
    std::uint64_t hash_ = 0;
    int cacheWidth_ = 0, cacheHeight_ = 0;
    gl::Framebuffer cacheFramebuffer_;  // draws into cacheColor_, a texture of the framebuffer's size
    gl::Texture cacheColor_;
    bool backBufferKept_ = false;
    std::uint64_t stampHash_[8] = {};  // the panel hash copied with stamp k (0: none)
    int nextStamp_ = 0;
    bool panelAlreadyThere(std::uint64_t hash, int width);
    void stampPanel(std::uint64_t hash, int width);
    float scale_ = 1.0f;
    bool trueType_ = false;
    ImFont* monoFont_ = nullptr;
    ImFont* formulaFont_ = nullptr;
    ImFont* viewFont_ = nullptr;
    ImFont* viewMonoFont_ = nullptr;
    float viewText_ = 16.0f, formulaMain_ = 24.0f;  // whole pixels
    std::vector<int> held_;
};

}  // namespace shadelab
