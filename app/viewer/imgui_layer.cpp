#include "viewer/imgui_layer.hpp"

#include <glad/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace shadelab {
namespace {

// Debian's fonts-dejavu-core. DejaVu Sans has every letter the lecture writes: θ, η₁, k_e, N·I, →.
constexpr const char* kFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
// Its monospaced cut, for GLSL in the Shader section (ImGui's second font, when present).
constexpr const char* kMonoFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf";
// Text size at scale 1, in pixels: larger than ImGui's 13 px default, for a projector.
constexpr float kFontPixels = 16.0f;

// Latin with Latin-1 (·, ², ×), Greek, punctuation (–, …, ′), super- and subscripts (ᵢ, ₁, ₂),
// arrows and mathematical operators (≤, ∑, ∠).
const ImWchar kGlyphRanges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2010, 0x205E, 0x2070,
                                0x209F, 0x2190, 0x21FF, 0x2200, 0x22FF, 0};

// The formula overlay's characters only (Latin-1 with ·, Σ, −, ∥, ⊥): its font is large.
const ImWchar kFormulaGlyphRanges[] = {0x0020, 0x00FF, 0x03A3, 0x03A3, 0x2212, 0x2212,
                                       0x2225, 0x2225, 0x22A5, 0x22A5, 0};

// The backend derives the modifiers from KeysDown in its key callback; a held Ctrl counts too.
void updateModifiers(ImGuiIO& io) {
    const auto down = [&](int a, int b) { return io.KeysDown[a] || io.KeysDown[b]; };
    io.KeyCtrl = down(GLFW_KEY_LEFT_CONTROL, GLFW_KEY_RIGHT_CONTROL);
    io.KeyShift = down(GLFW_KEY_LEFT_SHIFT, GLFW_KEY_RIGHT_SHIFT);
    io.KeyAlt = down(GLFW_KEY_LEFT_ALT, GLFW_KEY_RIGHT_ALT);
    io.KeySuper = down(GLFW_KEY_LEFT_SUPER, GLFW_KEY_RIGHT_SUPER);
}

}  // namespace

ImGuiLayer::ImGuiLayer(GLFWwindow* window, float scale) : scale_(scale) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    // No imgui.ini: the panel is laid out by code every frame, and a lecture machine's working folder
    // should not collect files (ImGui would also write it non-atomically).
    io.IniFilename = nullptr;
    buildFonts();
    if (!ImGui_ImplGlfw_InitForOpenGL(window, true)) {
        ImGui::DestroyContext();
        throw std::runtime_error("Dear ImGui: the GLFW backend failed to initialise");
    }
    if (!ImGui_ImplOpenGL3_Init("#version 330 core")) {
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
        throw std::runtime_error("Dear ImGui: the OpenGL 3 backend could not load OpenGL");
    }
}

ImGuiLayer::~ImGuiLayer() {
    cacheFramebuffer_.reset();
    cacheColor_.reset();
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

void ImGuiLayer::buildFonts() {
    ImGuiIO& io = ImGui::GetIO();
    io.Fonts->Clear();
    ImFontConfig config;
    config.OversampleH = 2;  // sharper glyph edges at small sizes, cheap in atlas space
    const float pixels = std::round(kFontPixels * scale_);
    // Checked first: Debian's Dear ImGui is built with asserts, and a missing file aborts in it.
    trueType_ = std::filesystem::is_regular_file(kFontPath) &&
                io.Fonts->AddFontFromFileTTF(kFontPath, pixels, &config, kGlyphRanges) != nullptr;
    monoFont_ = formulaFont_ = viewFont_ = viewMonoFont_ = nullptr;
    const bool mono = trueType_ && std::filesystem::is_regular_file(kMonoFontPath);
    if (mono) monoFont_ = io.Fonts->AddFontFromFileTTF(kMonoFontPath, std::round(0.9f * pixels), &config, kGlyphRanges);
    // The view's text and the formula's main line: rasterised at their sizes, so they are crisp on a
    // projector rather than a magnified bitmap.
    if (trueType_) {
        viewFont_ = io.Fonts->AddFontFromFileTTF(kFontPath, viewText_, &config, kGlyphRanges);
        formulaFont_ = io.Fonts->AddFontFromFileTTF(kFontPath, formulaMain_, &config, kFormulaGlyphRanges);
    }
    if (mono) viewMonoFont_ = io.Fonts->AddFontFromFileTTF(kMonoFontPath, viewText_, &config, kGlyphRanges);
    if (!trueType_) {
        std::fprintf(stderr, "shadelab: %s not found (Debian: fonts-dejavu-core): using ImGui's bitmap font\n",
                     kFontPath);
        ImFontConfig fallback;
        fallback.SizePixels = std::round(13.0f * scale_);
        io.Fonts->AddFontDefault(&fallback);
    }
    ImGui::GetStyle() = ImGuiStyle();
    ImGui::StyleColorsDark();
    ImGuiStyle& style = ImGui::GetStyle();
    style.WindowRounding = 0.0f;
    // Opaque and borderless (a border's anti-aliased edge reaches a pixel left of the panel): the
    // panel's pixels do not depend on what is under it, so it can be cached (see render).
    style.Colors[ImGuiCol_WindowBg].w = 1.0f;
    style.WindowBorderSize = 0.0f;
    // A slider's handle half transparent and narrow, so the digits of the value under it stay readable.
    style.Colors[ImGuiCol_SliderGrab].w = 0.55f;
    style.Colors[ImGuiCol_SliderGrabActive].w = 0.7f;
    style.GrabMinSize = 6.0f;
    style.ScaleAllSizes(scale_);
}

void ImGuiLayer::setViewTextSize(float text, float formulaMain) {
    text = std::max(std::round(text), 1.0f);
    formulaMain = std::max(std::round(formulaMain), 1.0f);
    if (text == viewText_ && formulaMain == formulaMain_) return;
    viewText_ = text;
    formulaMain_ = formulaMain;
    buildFonts();
    ImGui_ImplOpenGL3_DestroyFontsTexture();
    ImGui_ImplOpenGL3_CreateFontsTexture();
}

void ImGuiLayer::setScale(float scale) {
    if (std::fabs(scale - scale_) < 1e-3f) return;
    scale_ = scale;
    buildFonts();
    ImGui_ImplOpenGL3_DestroyFontsTexture();
    ImGui_ImplOpenGL3_CreateFontsTexture();
}

void ImGuiLayer::holdTappedKeys(const std::vector<KeyPress>& pressed) {
    ImGuiIO& io = ImGui::GetIO();
    const auto hold = [&](int key) {
        if (key < 0 || key >= int(IM_ARRAYSIZE(io.KeysDown)) || io.KeysDown[key]) return;
        io.KeysDown[key] = true;
        held_.push_back(key);
    };
    for (const KeyPress& p : pressed) {
        hold(p.key);
        if (p.mods & GLFW_MOD_CONTROL) hold(GLFW_KEY_LEFT_CONTROL);
        if (p.mods & GLFW_MOD_SHIFT) hold(GLFW_KEY_LEFT_SHIFT);
        if (p.mods & GLFW_MOD_ALT) hold(GLFW_KEY_LEFT_ALT);
        if (p.mods & GLFW_MOD_SUPER) hold(GLFW_KEY_LEFT_SUPER);
    }
    updateModifiers(io);
}

void ImGuiLayer::releaseTappedKeys() {
    ImGuiIO& io = ImGui::GetIO();
    for (int key : held_) io.KeysDown[key] = false;
    held_.clear();
    updateModifiers(io);
}

void ImGuiLayer::newFrame() {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

namespace {

// ImGui's draw data restricted to some of its lists, for the OpenGL backend to draw.
void renderLists(const ImDrawData& all, std::vector<ImDrawList*> lists) {
    if (lists.empty()) return;
    ImDrawData part = all;
    part.CmdLists = lists.data();
    part.CmdListsCount = int(lists.size());
    part.TotalVtxCount = part.TotalIdxCount = 0;
    for (const ImDrawList* l : lists) {
        part.TotalVtxCount += l->VtxBuffer.Size;
        part.TotalIdxCount += l->IdxBuffer.Size;
    }
    ImGui_ImplOpenGL3_RenderDrawData(&part);
}

// A hash of the lists' vertices, indices and commands, 8 bytes at a step (it runs every frame over
// tens of thousands of vertices): equal draw lists draw equal pixels.
std::uint64_t hashLists(const std::vector<ImDrawList*>& lists) {
    std::uint64_t h = 1469598103934665603ull;
    auto mix = [&h](std::uint64_t word) {
        h = (h ^ word) * 0x9E3779B97F4A7C15ull;
        h ^= h >> 29;
    };
    auto add = [&mix](const void* data, std::size_t size) {
        const auto* bytes = static_cast<const unsigned char*>(data);
        std::size_t i = 0;
        for (; i + 8 <= size; i += 8) {
            std::uint64_t word;
            std::memcpy(&word, bytes + i, 8);
            mix(word);
        }
        std::uint64_t tail = 0;
        std::memcpy(&tail, bytes + i, size - i);
        mix(tail ^ (std::uint64_t(size) << 56));
    };
    for (const ImDrawList* l : lists) {
        add(l->VtxBuffer.Data, std::size_t(l->VtxBuffer.Size) * sizeof(ImDrawVert));
        add(l->IdxBuffer.Data, std::size_t(l->IdxBuffer.Size) * sizeof(ImDrawIdx));
        for (const ImDrawCmd& c : l->CmdBuffer) {
            add(&c.ClipRect, sizeof c.ClipRect);
            add(&c.TextureId, sizeof c.TextureId);
            mix(std::uint64_t(c.VtxOffset) << 32 | c.IdxOffset);
            mix(c.ElemCount);
        }
    }
    return h;
}

}  // namespace

void ImGuiLayer::render(float panelLeft) {
    ImGui::Render();
    const ImDrawData& data = *ImGui::GetDrawData();
    const ImGuiIO& io = ImGui::GetIO();
    const int width = int(io.DisplaySize.x * io.DisplayFramebufferScale.x);
    const int height = int(io.DisplaySize.y * io.DisplayFramebufferScale.y);
    // Behind the windows: labels over the view; in front: the status strip, caption and messages.
    ImDrawList* back = ImGui::GetBackgroundDrawList();
    ImDrawList* front = ImGui::GetForegroundDrawList();
    std::vector<ImDrawList*> windows;
    bool insidePanel = panelLeft >= 0.0f;
    for (int i = 0; i < data.CmdListsCount; ++i) {
        ImDrawList* l = data.CmdLists[i];
        if (l == back || l == front) continue;
        windows.push_back(l);
        // (Clip rects do not tell: a window's decorations are clipped to the whole display.)
        for (const ImDrawVert& v : l->VtxBuffer) insidePanel = insidePanel && v.pos.x >= panelLeft - 0.5f;
    }
    renderLists(data, {back});
    const int left = int(std::lround(panelLeft * io.DisplayFramebufferScale.x));
    if (!insidePanel || !panelFromCache(windows, left, width, height)) {
        renderLists(data, windows);
        // Drawn directly (or no panel): whatever is in the back buffer now is no stamped copy.
        for (std::uint64_t& h : stampHash_) h = 0;
    }
    renderLists(data, {front});
}

// The panel's windows drawn into a texture of the framebuffer's size when they changed, and their
// columns (x >= left) copied into the default framebuffer. The panel's background is opaque, so what
// was under it does not matter: the copy is the pixels a direct draw gives.
bool ImGuiLayer::panelFromCache(const std::vector<ImDrawList*>& windows, int left, int width, int height) {
    if (left <= 0 || left >= width || height <= 0) return false;
    const std::uint64_t hash = hashLists(windows);
    if (width != cacheWidth_ || height != cacheHeight_ || !cacheFramebuffer_) {
        cacheFramebuffer_.reset();
        cacheColor_ = gl::makeTexture();
        glBindTexture(GL_TEXTURE_2D, cacheColor_.get());
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
        cacheFramebuffer_ = gl::makeFramebuffer();
        glBindFramebuffer(GL_FRAMEBUFFER, cacheFramebuffer_.get());
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, cacheColor_.get(), 0);
        const bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        if (!complete) return false;
        cacheWidth_ = width;
        cacheHeight_ = height;
        hash_ = ~hash;                              // not drawn yet
        for (std::uint64_t& h : stampHash_) h = 0;  // a new size: no copy is in the back buffer
    }
    if (hash != hash_) {
        glBindFramebuffer(GL_FRAMEBUFFER, cacheFramebuffer_.get());
        glDisable(GL_SCISSOR_TEST);
        glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        renderLists(*ImGui::GetDrawData(), windows);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        hash_ = hash;
    }
    if (backBufferKept_ && panelAlreadyThere(hash, width)) return true;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, cacheFramebuffer_.get());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glDisable(GL_SCISSOR_TEST);
    glBlitFramebuffer(left, 0, width, height, left, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (backBufferKept_) stampPanel(hash, width);
    return true;
}

// The stamp: the panel's bottom-right pixel, the window background (15, 15, 15) with blue 16 + k, k
// the copy's number modulo 8 (invisible). Only the panel's copy writes there: when the pixel holds a
// stamp whose copy had this hash, the back buffer already shows this panel.
namespace {
constexpr int kStampGrey = 15, kStampBlue = 16, kStamps = 8;
}

bool ImGuiLayer::panelAlreadyThere(std::uint64_t hash, int width) {
    unsigned char pixel[4] = {};
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadPixels(width - 1, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
    const int k = int(pixel[2]) - kStampBlue;
    return pixel[0] == kStampGrey && pixel[1] == kStampGrey && k >= 0 && k < kStamps && stampHash_[k] == hash;
}

void ImGuiLayer::stampPanel(std::uint64_t hash, int width) {
    const int k = nextStamp_++ % kStamps;
    stampHash_[k] = hash;
    glEnable(GL_SCISSOR_TEST);
    glScissor(width - 1, 0, 1, 1);
    glClearColor(float(kStampGrey) / 255.0f, float(kStampGrey) / 255.0f, float(kStampBlue + k) / 255.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
}

}  // namespace shadelab
