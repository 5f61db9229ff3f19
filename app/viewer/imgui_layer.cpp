#include "viewer/imgui_layer.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace shadelab {
namespace {

// Debian's fonts-dejavu-core. DejaVu Sans has every letter the lecture writes: θ, η₁, k_e, N·I, →.
constexpr const char* kFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
// Text size at scale 1, in pixels: larger than ImGui's 13 px default, for a projector.
constexpr float kFontPixels = 16.0f;

// Latin with Latin-1 (·, ², ×), Greek, punctuation (–, …, ′), super- and subscripts (ᵢ, ₁, ₂),
// arrows and mathematical operators (≤, ∑, ∠).
const ImWchar kGlyphRanges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2010, 0x205E,
                                0x2070, 0x209F, 0x2190, 0x21FF, 0x2200, 0x22FF, 0};

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
    trueType_ = io.Fonts->AddFontFromFileTTF(kFontPath, pixels, &config, kGlyphRanges) != nullptr;
    if (!trueType_) {
        std::fprintf(stderr, "shadelab: %s not found (Debian: fonts-dejavu-core): using ImGui's bitmap font\n", kFontPath);
        ImFontConfig fallback;
        fallback.SizePixels = std::round(13.0f * scale_);
        io.Fonts->AddFontDefault(&fallback);
    }
    ImGui::GetStyle() = ImGuiStyle();
    ImGui::StyleColorsDark();
    ImGuiStyle& style = ImGui::GetStyle();
    style.WindowRounding = 0.0f;
    style.ScaleAllSizes(scale_);
}

void ImGuiLayer::setScale(float scale) {
    if (std::fabs(scale - scale_) < 1e-3f) return;
    scale_ = scale;
    buildFonts();
    ImGui_ImplOpenGL3_DestroyFontsTexture();
    ImGui_ImplOpenGL3_CreateFontsTexture();
}

void ImGuiLayer::holdTappedKeys(const std::vector<int>& pressed) {
    ImGuiIO& io = ImGui::GetIO();
    for (int key : pressed) {
        if (key < 0 || key >= int(IM_ARRAYSIZE(io.KeysDown)) || io.KeysDown[key]) continue;
        io.KeysDown[key] = true;
        held_.push_back(key);
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

void ImGuiLayer::render() {
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace shadelab
