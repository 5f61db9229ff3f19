#include "viewer/viewer.hpp"

#include "core/base/error.hpp"
#include "core/base/file_io.hpp"
#include "core/figures/plot.hpp"
#include "core/figures/shader_listing.hpp"
#include "core/geometry/camera.hpp"
#include "core/image/image.hpp"
#include "core/scene/parameters.hpp"
#include "core/scene/scene_json.hpp"
#include "core/ui/controls.hpp"
#include "platform/platform.hpp"
#include "viewer/formula_view.hpp"
#include "viewer/orbit.hpp"
#include "viewer/probe_view.hpp"
#include "viewer/shader_view.hpp"
#include "viewer/view_overlays.hpp"

#include <glad/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <utility>

namespace shadelab {
namespace {

// The viewer draws its meshes every frame: reordering them for the driver's vertex cache once, at
// upload, pays for itself within a few frames (Renderer::MeshOrder). It draws the programs the Shader
// view lists (phong.vert and phong.frag, not the interpolated-inputs variant; flat.vert, not the
// packed one), so F5 after an edit of those files changes the picture (bench/README.md:
// what that costs a coarse mesh's Phong frame).
std::unique_ptr<Renderer> makeRenderer(const ShaderLibrary& shaders) {
    RendererOptions options;
    options.meshOrder = RendererOptions::MeshOrder::VertexCache;  // many frames of one mesh
    options.phongInputs = RendererOptions::PhongInputs::Uniform;  // the readable phong.frag
    auto renderer = std::make_unique<Renderer>(glfwGetProcAddress, shaders, options);
    return renderer;
}

// Panel width in font heights (16 px at scale 1: 480 px): room for the widgets and their labels. It
// grows with the UI scale up to half the window, so the view keeps at least half of it.
constexpr float kPanelEms = 30.0f;
constexpr float kFontPixels = 16.0f;
// The status strip above the view, in font heights.
constexpr float kStripEms = 1.5f;
// The text over the view with the presentation setting: this share of the window's
// height (26 px of 1080; the caption 1.25 times it, 3% of the height; the formula's main line too,
// its values as large as its symbols), never smaller than the panel's text.
constexpr float kViewTextShare = 0.024f;
constexpr float kFormulaOfViewText = 1.25f;  // the formula's main line, in view text sizes
// How long a message stays over the view (an error longer), in seconds.
constexpr double kMessageSeconds = 5.0, kErrorSeconds = 12.0;
// Orbit speed: dragging across ~400 screen units turns the model half way round.
constexpr float kOrbitRadPerUnit = 0.008f;

// "shadelab-20250131-142512-034.png": sortable, and distinct for two F12 presses in one second.
std::string timestampedName() {
    const auto now = std::chrono::system_clock::now();
    const std::time_t t = std::chrono::system_clock::to_time_t(now);
    const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000;
    const std::tm local = platform::localTime(t);
    char name[64];
    std::strftime(name, sizeof name, "shadelab-%Y%m%d-%H%M%S", &local);
    char suffix[16];
    std::snprintf(suffix, sizeof suffix, "-%03d.png", int(ms));
    return std::string(name) + suffix;
}

// The default framebuffer's alpha is whatever blending left there; a screenshot is opaque.
Image opaque(Image image) {
    for (std::size_t i = 3; i < image.rgba.size(); i += 4) image.rgba[i] = 255;
    return image;
}

// A person's last layout (view_prefs.hpp), unless this is a scripted run or --reset-layout.
ViewPrefs startPrefs(const ViewerOptions& o, const std::string& path) {
    if (path.empty()) return {};
    if (o.resetLayout) {
        std::error_code ignored;
        std::filesystem::remove(path, ignored);
        return {};
    }
    return loadViewPrefs(path);
}

float startUiScale(const ViewerOptions& o, const ViewPrefs& prefs) {
    return o.uiScale > 0.0f ? o.uiScale : prefs.uiScale.value_or(1.0f);
}

// Samples per pixel: --msaa, else 1 for a scripted run (its view equals the headless image), else the
// last session's (4 at first).
int startMsaa(const ViewerOptions& o, const ViewPrefs& prefs) {
    return o.msaa >= 0 ? std::max(o.msaa, 1) : o.frames > 0 ? 1 : std::max(prefs.msaa.value_or(4), 1);
}

bool isSoftwareGl(const std::string& glRenderer) {
    for (const char* software : {"llvmpipe", "softpipe", "SwiftShader", "Software Rasterizer"})
        if (glRenderer.find(software) != std::string::npos) return true;
    return false;
}

// A new recording's file: "shadelab-20250131-142512-034.mp4".
std::string recordingName() {
    std::string path = timestampedName();
    return path.replace(path.size() - 4, 4, ".mp4");
}

}  // namespace

Viewer::Viewer(Scene scene, std::shared_ptr<const SceneGeometry> geometry, ViewerOptions options)
    : options_(std::move(options)),
      prefsPath_(options_.frames > 0 ? std::string() : viewPrefsPath()),
      prefs_(startPrefs(options_, prefsPath_)),
      // Room for the scene's size beside the panel and under the status strip: at content scale 1
      // the 3D view starts as the image --output writes. Or where the last session left it.
      window_(scene.width, scene.height + int(std::ceil(kStripEms * kFontPixels * startUiScale(options_, prefs_))),
              options_.hidePanel ? 0.0f : kPanelEms * kFontPixels * startUiScale(options_, prefs_), "shadelab",
              prefs_.window),
      imgui_(window_.handle(), window_.contentScale() * startUiScale(options_, prefs_)),
      renderer_(makeRenderer(ShaderLibrary(options_.shaderDir))),
      overlays_(std::make_unique<OverlayRenderer>(ShaderLibrary(options_.shaderDir))),
      document_(std::move(scene), std::move(geometry)),
      playlist_(std::move(options_.playlist), options_.adjustPreset),
      progressive_(options_.progressiveStride),
      animation_(std::move(options_.animations), options_.frames > 0, std::chrono::steady_clock::now()),
      recording_(recordingName, [this](const std::string& message, bool isError) { setStatus(message, isError); }),
      probe_(options_.probe) {
    settings_.showPanel = !options_.hidePanel;
    settings_.overlays = options_.overlays;
    settings_.plots = options_.plots;
    settings_.startSections = options_.panelSections;
    settings_.selectedLight = options_.selectedLight;
    uiScale_ = startUiScale(options_, prefs_);
    if (!settings_.startSections && prefs_.openSections) settings_.startSections = prefs_.openSections;
    if (options_.noLabels) settings_.paneLabels = settings_.lightLabels = false;
    settings_.showFormula = options_.formula;
    settings_.showIntersection = options_.intersection;
    readShaderSources(ShaderLibrary(options_.shaderDir));
    status_.glRenderer = renderer_->glRenderer();
    quality_ = ViewQuality(startMsaa(options_, prefs_), isSoftwareGl(status_.glRenderer));
    imgui_.setBackBufferKept(quality_.softwareGl() && status_.glRenderer.find("SwiftShader") == std::string::npos);
    openAsSlide(document_.scene().viewer, options_.probe.has_value(), options_.panelSections.has_value());
    settings_.scenePath = document_.scene().sourcePath.empty() ? "scene.json" : document_.scene().sourcePath;
    status_.trueTypeFont = imgui_.trueTypeFont();
    // Scripted runs go as fast as they can; a person gets frames at the display's refresh rate.
    window_.setSwapInterval(options_.frames > 0 ? 0 : 1);
    if (options_.fullscreen || prefs_.fullscreen) window_.setFullscreen(true);
    if (playlist_.active()) settings_.scenePath = playlist_.preset(0).path;
    if (options_.verbose) std::cerr << "shadelab: viewer on " << status_.glRenderer << "\n";
}

Viewer::~Viewer() = default;

void Viewer::run() {
    for (int n = 1;; ++n) {
        // Render on demand: with nothing to draw, sleep until an event or until a message over the view
        // is due to go (a person's session only; scripted runs draw every frame).
        while (options_.frames == 0 && idle()) {
            const double untilMessageGoes =
                std::chrono::duration<double>(messageUntil_ - std::chrono::steady_clock::now()).count();
            if (messageShown_ && untilMessageGoes <= 0.0) break;
            window_.waitEvents(messageShown_ ? untilMessageGoes + 0.01 : 10.0);
        }
        if (options_.frames == 0 && (animation_.playing() || recording_.active())) waitForRefresh();
        pacing_.frameBegins(std::chrono::steady_clock::now());
        if (frame(options_.frames > 0 && n >= options_.frames)) break;
    }
    recording_.stop();  // quitting while recording keeps the video
    savePrefs();
}

// A playing animation or a recording draws at most one frame a display refresh (FramePacing). Events
// wake the wait; they are handled by the frame that follows, when it is due.
int Viewer::frameCapHz() const { return FramePacing::capHz(window_.refreshRate()); }

void Viewer::waitForRefresh() {
    const auto due = pacing_.nextDue(frameCapHz());
    for (auto now = std::chrono::steady_clock::now(); now < due; now = std::chrono::steady_clock::now())
        window_.waitEvents(std::chrono::duration<double>(due - now).count());
}

// The layout as the session leaves it, for the next one (a person's sessions only).
void Viewer::savePrefs() {
    if (prefsPath_.empty()) return;
    ViewPrefs p;
    p.window = window_.placement();
    p.fullscreen = window_.fullscreen();
    // The panel's sections as last drawn; a session that never showed the panel keeps the old ones.
    p.openSections = panelDrawn_ ? std::optional(settings_.openSections) : prefs_.openSections;
    p.uiScale = uiScale_;
    p.msaa = quality_.msaaSamples();
    saveViewPrefs(prefsPath_, p);
}

bool Viewer::idle() const {
    if (pacing_.pending(window_.eventCount())) return false;
    if (animation_.playing() || recording_.active()) return false;  // an animation keeps drawing; a paused one does not
    if (quality_.wantsStillFrame()) return false;  // one more frame: the still view anti-aliased, at full size
    if (progressive_.refining()) return false;     // sampling goes on
    const ImGuiIO& io = ImGui::GetIO();
    for (bool down : io.MouseDown)
        if (down) return false;
    return true;
}

// One frame, in the order the panel's edits need: they land in the scene before it is drawn. Returns
// true when it was the last: the frame count is reached, or the window was closed or Q pressed
// (so the scripted files are also written when a person ends the session).
bool Viewer::frame(bool last) {
    imgui_.releaseTappedKeys();
    window_.pollEvents();
    const auto start = std::chrono::steady_clock::now();
    const std::vector<KeyPress> keys = window_.takePressedKeys();
    imgui_.holdTappedKeys(keys);
    const bool still = pacing_.countEvents(window_.eventCount());
    imgui_.setScale(window_.contentScale() * uiScale_);  // rebuilds the font only when it changed
    {
        const float panelText = std::round(kFontPixels * imgui_.scale()), windowText = windowTextSize();
        imgui_.setViewTextSize(std::max(panelText, windowText),
                               std::max(kFormulaSize * panelText, kFormulaOfViewText * windowText));
    }
    imgui_.newFrame();
    const FrameLayout l = layout();
    document_.setViewSize(std::max(l.viewWidth, 1), std::max(l.viewHeight, 1));
    if (const auto pending = probe_.takePending()) setProbe(pending->x, pending->y);
    if (slideProbe_) {
        const glm::ivec2 at = slideProbe_->probeIn(l.viewWidth, l.viewHeight);
        setProbe(at.x, at.y, false);
        slideProbe_.reset();
    }
    handleInput(l, keys);
    probe_.evaluate(document_.scene(), document_.geometry());
    apply(panelEdits(l));
    last = last || window_.shouldClose();
    uploadGeometryIfChanged();
    const float labelsBottom = followView(l);
    advanceAnimation();
    const std::vector<OverlayArrow> arrows = probeOverlays(l, drawViewText(l, labelsBottom));
    const Image view = drawView(l, still, last, arrows);
    // The mean of the frames drawn in the last second; "idle" where this is the last frame before the
    // viewer sleeps (a scripted run never does).
    status_.frameMs = frameRate_.meanMs(std::chrono::steady_clock::now()).value_or(0.0);
    status_.idle = options_.frames == 0 && idle();
    drawStatusStrip(status_, l.strip);  // after: it shows this frame's pass
    imgui_.render(settings_.showPanel ? l.panel.x : -1.0f);
    if (screenshotRequested_) saveScreenshot(view);
    record(view);
    if (last) writeLastFrameFiles(l, view);
    window_.swapBuffers();
    recordFrameTime(start, last);
    return last;
}

// The panel, when shown, with what it edited: the scene is marked edited, and the camera stops
// following the view where a camera value or a transform was typed in.
PanelRequests Viewer::panelEdits(const FrameLayout& l) {
    status_.presetTitles.clear();
    for (std::size_t i = 0; i < playlist_.size(); ++i)
        status_.presetTitles.push_back(lectureNotation(presetTitle(playlist_.preset(i))));
    status_.currentPreset = int(playlist_.current());
    status_.uiScale = uiScale_;
    status_.msaa = quality_.msaaSamples();
    const Camera before = document_.scene().camera;
    PlacedGeometry placedBefore;
    placedBefore.remember(document_.scene(), document_.geometry());
    const PanelRequests requests =
        settings_.showPanel ? drawPanel(document_.sceneForWidgets(), settings_, status_, l.panel, probe_.result())
                            : PanelRequests{};
    if (requests.sceneEdited) document_.markEdited();
    if (settings_.showPanel) {  // the list has scrolled to it
        status_.scrollToPreset = false;
        panelDrawn_ = true;
    }
    const Camera& after = document_.scene().camera;
    if (before.eye != after.eye || before.target != after.target || before.fovYDeg != after.fovYDeg)
        document_.stopFollowing();  // typed into the Camera section
    // A transform edited in the Mesh section: the camera stays, so the change shows.
    if (!placedBefore.same(document_.scene(), document_.geometry())) document_.stopFollowing();
    return requests;
}

// The camera follows the view (size, layout, bands, pane labels) until zoomed or panned; near and far
// follow the eye. Draws the pane labels first, since they push the framing down; returns where they end.
float Viewer::followView(const FrameLayout& l) {
    drawPaneSeparators(document_.scene(), l.view, l.scale);
    ImGui::PushFont(imgui_.viewFont());
    const float labelSize = std::max(1.4f * ImGui::GetIO().Fonts->Fonts[0]->FontSize, 1.1f * l.windowText);
    const float labelsBottom =
        settings_.paneLabels ? drawPaneLabels(document_.scene(), l.view, l.scale, labelSize) : l.view.y;
    ImGui::PopFont();
    const auto panes = layoutPanes(document_.scene().layout, document_.scene().shading, document_.scene().width,
                                   document_.scene().height, document_.scene().diff);
    const float paneUnits = float(std::max(panes.front().height, 1)) / l.scale;
    document_.setLabelInset((labelsBottom - l.view.y) / paneUnits);
    document_.followView();
    document_.fitClipPlanes();
    return labelsBottom;
}

// The text over the view below the pane labels: the light labels, the caption, the status message and
// the help. Returns the light labels' boxes (the probe's labels keep off them).
std::vector<UiRect> Viewer::drawViewText(const FrameLayout& l, float labelsBottom) {
    ImGui::PushFont(imgui_.viewFont());
    std::vector<UiRect> lightBoxes =  // returned: moved, not copied
        settings_.lightLabels ? drawLightLabels(shownScene(), l.view, l.scale, settings_.selectedLight, labelsBottom,
                                                modelSpheres_.of(document_.scene(), document_.geometry()))
                              : std::vector<UiRect>{};
    UiRect messageArea = l.view;
    if (l.formula.height > 0.0f) formulaBand(l, l.formula.width, true);
    if (l.captionText.height > 0.0f) {
        const std::string counter =
            playlist_.active() ? std::to_string(playlist_.current() + 1) + " / " + std::to_string(playlist_.size())
                               : std::string();
        drawCaption(document_.scene(), counter, l.captionText, l.caption);
    }
    if (settings_.shaderOverView) {  // the message beside the shader view, not over its lines
        const float shader = std::round(messageArea.width * kShaderOverViewShare);
        messageArea.x += shader;
        messageArea.width -= shader;
    }
    messageShown_ = std::chrono::steady_clock::now() < messageUntil_;
    if (messageShown_) drawMessage(status_, messageArea);
    drawReadout(l, labelsBottom);
    if (recording_.active()) {  // a red dot and REC at the view's top right while recording, after the message fades
        const float size = l.viewText, r = 0.4f * size;
        const ImVec2 at(l.view.x + l.view.width - 3.5f * size, labelsBottom + 0.6f * size);
        ImDrawList* draw = ImGui::GetForegroundDrawList();
        draw->AddRectFilled(ImVec2(at.x - 0.5f * size, at.y - 0.3f * size),
                            ImVec2(at.x + 3.2f * size, at.y + 1.3f * size), IM_COL32(0, 0, 0, 170), 0.3f * size);
        draw->AddCircleFilled(ImVec2(at.x + r, at.y + 0.5f * size), r, IM_COL32(230, 30, 30, 255));
        draw->AddText(ImGui::GetFont(), size, ImVec2(at.x + 2.6f * r, at.y), IM_COL32(255, 255, 255, 255), "REC");
    }
    ImGui::PopFont();
    if (settings_.shaderOverView)
        drawShaderOverView(shownScene(), settings_, status_, probe_.result(), l.view, imgui_.viewFont(),
                           imgui_.viewMonoFont());
    if (showHelp_) drawHelpOverlay(l.view);
    return lightBoxes;
}

namespace {
// What a playing ramp sets, as the readout says it ("k_e = 37.2"); empty for orbits and names.
std::string rampReadout(const Scene& scene, const std::vector<Animation>& animations, int selectedObject) {
    const auto object = std::size_t(std::max(selectedObject, 0));
    const Material* m = object < scene.objects.size() ? &scene.objects[object].material : nullptr;
    for (const Animation& a : animations) {
        if (a.kind != Animation::Kind::Ramp) continue;
        const Parameter* p = parameterNamed(a.parameter);
        if (!p) continue;
        const std::string name = std::string(p->symbol) + " = ";
        if (m && p->field.material) return name + formulaNumber(materialValue(*p, *m));
        if (p->field.scene) return name + formulaNumber(sceneValue(*p, scene));
        if (p->field.light && !scene.lights.empty()) return name + formulaNumber(lightValue(*p, scene.lights[0]));
    }
    return "";
}
}  // namespace

void Viewer::drawReadout(const FrameLayout& l, float labelsBottom) {
    std::string text = settings_.readout;
    if (text.empty() && animation_.scene() && (animation_.playing() || options_.frames > 0))
        text = rampReadout(*animation_.scene(), animation_.animations(), settings_.selectedObject);
    status_.readout = text;
    if (text.empty() || l.view.width <= 0.0f) return;
    // Twice the view text (52 px in a 1080-px window), on a dark box in the specular colour, at the
    // top left below the pane labels (lights are most often up and to the right).
    const float size = 2.0f * l.viewText, pad = 0.3f * size;
    ImFont* font = imgui_.formulaFont() ? imgui_.formulaFont() : ImGui::GetFont();  // rasterised larger
    const ImVec2 extent = font->CalcTextSizeA(size, 1e9f, 0.0f, text.c_str());
    const ImVec2 at(std::round(l.view.x + 2.0f * pad), std::round(labelsBottom + 2.0f * pad));
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    draw->AddRectFilled(ImVec2(at.x - pad, at.y - pad), ImVec2(at.x + extent.x + pad, at.y + extent.y + pad),
                        IM_COL32(0, 0, 0, kFormulaBackingAlpha), pad);
    const Rgba8 c = termColor(FormulaTerm::Specular);
    draw->AddText(font, size, at, IM_COL32(c.r, c.g, c.b, 255), text.c_str());
}

// The 3D view, anti-aliased where it pays and reduced while it moves (ViewQuality). Returns it as
// drawn when it is captured (a screenshot, a file).
Image Viewer::drawView(const FrameLayout& l, bool still, bool last, const std::vector<OverlayArrow>& arrows) {
    ViewQuality::Frame frame;
    frame.still = still;
    for (bool down : ImGui::GetIO().MouseDown) frame.mouseDown = frame.mouseDown || down;
    frame.playing = animation_.playing();
    frame.capture = screenshotRequested_ || recording_.capturing() || (last && !options_.viewScreenshotPath.empty());
    frame.last = last;
    frame.scripted = options_.frames > 0;
    frame.lastFrameMs = frameMs_;
    quality_.plan(frame);
    renderer_->setMovingFrames(quality_.movingThisFrame());  // one shadow lookup per light (renderScene: area lights)
    status_.movingScale = quality_.reducedThisFrame() ? quality_.movingScale() : 1.0f;
    Image view = renderView(l, frame.capture, last, arrows);  // returned: moved, not copied
    quality_.drawn();
    return view;
}

// The frame's own time (polling to swap, no waiting), for the status strip and -v's median.
void Viewer::recordFrameTime(std::chrono::steady_clock::time_point start, bool last) {
    const auto end = std::chrono::steady_clock::now();
    frameMs_ = std::chrono::duration<double, std::milli>(end - start).count();
    frameRate_.add(end, frameMs_);
    if (frameTimes_.size() < 100000) frameTimes_.push_back(frameMs_);
    if (last && options_.verbose && !frameTimes_.empty()) {
        // The median frame's own time: bench/README.md's panel figures.
        std::vector<double> sorted = frameTimes_;
        std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(sorted.size() / 2), sorted.end());
        std::cerr << "shadelab: " << frameTimes_.size() << " frames, median " << sorted[sorted.size() / 2] << " ms\n";
    }
}

// The values drawn this frame (an animated k_e moves under its symbol), the selected object's
// material, the probe's where it hits.
float Viewer::formulaBand(const FrameLayout& l, float viewWidth, bool draw) const {
    const Scene& scene = shownScene();
    const auto selected = std::size_t(std::max(settings_.selectedObject, 0));
    const Material material = selected < scene.objects.size() ? scene.objects[selected].material : Material{};
    ImFont* font = imgui_.formulaFont();
    const FormulaBandStyle style{l.scale, font, font ? font->FontSize / kFormulaSize : 0.0f};
    if (draw) drawFormulaBand(scene, material, probe_.result(), l.formula, style);
    return formulaBandHeight(scene, material, probe_.result(), viewWidth, style);
}

float Viewer::windowTextSize() const {
    int windowWidth = 0, windowHeight = 0;
    window_.windowSize(windowWidth, windowHeight);
    return settings_.presentationText ? std::round(kViewTextShare * float(windowHeight)) : 0.0f;
}

Viewer::FrameLayout Viewer::layout() const {
    FrameLayout l;
    l.windowText = windowTextSize();
    l.viewText = std::max(ImGui::GetFontSize(), l.windowText);
    window_.framebufferSize(l.framebufferWidth, l.framebufferHeight);
    int windowWidth = 0, windowHeight = 0;
    window_.windowSize(windowWidth, windowHeight);
    l.scale = windowWidth > 0 ? float(l.framebufferWidth) / float(windowWidth) : 1.0f;
    const float ems = ImGui::GetFontSize();  // ImGui units; follows content and UI scale
    const int panelPixels =
        settings_.showPanel ? std::min(int(std::lround(kPanelEms * ems * l.scale)), l.framebufferWidth / 2) : 0;
    l.viewWidth = l.framebufferWidth - panelPixels;
    const float viewUnits = float(l.viewWidth) / l.scale;
    // From the top: the status strip, the caption band (at most a sixth of the window: a fifth of the view), the view.
    const bool strip = settings_.showHud && (settings_.showPanel || settings_.readoutWhenHidden);
    const float stripUnits = strip ? std::round(kStripEms * ems) : 0.0f;
    const float captionMax = std::floor((float(windowHeight) - stripUnits) / 6.0f);
    l.captionText = settings_.showCaption ? layoutCaption(document_.scene(), playlist_.active() ? "00 / 00" : "",
                                                          viewUnits, captionMax, 0, l.windowText)
                                          : CaptionLayout{};
    // With a playlist every preset's caption has the same text size, the smallest any of them needs
    // to fit, and the band is as high as the longest caption of the playlist takes at that size: the
    // 3D view's rectangle (and so the framing) is the same on every preset, a caption that wraps to one
    // more line does not push the view down.
    if (settings_.showCaption && playlist_.size() > 1) {
        const auto sceneOf = [&](std::size_t i) -> const Scene& {
            return i == playlist_.current() ? document_.scene() : playlist_.preset(i).scene;  // its title may be edited
        };
        int step = 0;
        for (std::size_t i = 0; i < playlist_.size(); ++i) {
            const CaptionLayout c = layoutCaption(sceneOf(i), "00 / 00", viewUnits, captionMax, 0, l.windowText);
            if (c.height > 0.0f) step = std::max(step, c.step);
        }
        float height = 0.0f;
        for (std::size_t i = 0; i < playlist_.size(); ++i)
            height = std::max(height,
                              layoutCaption(sceneOf(i), "00 / 00", viewUnits, captionMax, step, l.windowText).height);
        l.captionText =
            layoutCaption(sceneOf(playlist_.current()), "00 / 00", viewUnits, captionMax, step, l.windowText);
        if (height > 0.0f) {
            if (l.captionText.height <= 0.0f) {  // an empty band with the position, as the others
                static const Scene blank = [] {
                    Scene s;
                    s.title = " ";
                    return s;
                }();
                l.captionText = layoutCaption(blank, "00 / 00", viewUnits, captionMax, step, l.windowText);
            }
            l.captionText.height = height;
        }
    }
    const float captionUnits = l.captionText.height;
    // E's formula in a band of its own below the caption, never over the model; at most a third of the window.
    const float formulaUnits = settings_.showFormula
                                   ? std::min(formulaBand(l, viewUnits, false), std::floor(float(windowHeight) / 3.0f))
                                   : 0.0f;
    const int bandPixels =
        std::min(int(std::lround((stripUnits + captionUnits + formulaUnits) * l.scale)), l.framebufferHeight);
    l.viewHeight = l.framebufferHeight - bandPixels;
    l.strip = UiRect{0.0f, 0.0f, viewUnits, stripUnits};
    l.caption = UiRect{0.0f, stripUnits, viewUnits, captionUnits};
    l.formula = UiRect{0.0f, stripUnits + captionUnits, viewUnits, formulaUnits};
    const float top = float(bandPixels) / l.scale;
    l.view = UiRect{0.0f, top, viewUnits, float(windowHeight) - top};
    l.panel = UiRect{viewUnits, 0.0f, float(panelPixels) / l.scale, float(windowHeight)};
    return l;
}

void Viewer::handleInput(const FrameLayout& l, const std::vector<KeyPress>& keys) {
    for (const std::string& path : window_.takeDroppedPaths()) loadFile(path);
    handleKeys(keys);
    // Mouse: ImGui's view of it, so a drag that starts on the panel moves a slider, not the camera.
    const ImGuiIO& io = ImGui::GetIO();
    // Released, also over the panel; a release in this frame still moves the light to where the button
    // came up (at a low frame rate the last moves and the release arrive in one frame).
    if (!io.MouseDown[0] && !io.MouseReleased[0]) lightDrag_.reset();
    if (io.WantCaptureMouse) return;
    // A press on a light's marker drags the light (until the release), instead of orbiting or probing.
    const auto inView = [&](const ImVec2& p) { return p.x >= 0.0f && p.x < l.view.width && p.y >= l.view.y; };
    if (io.MouseClicked[0] && inView(io.MousePos) && settings_.lightLabels) {
        const Scene& scene = document_.scene();
        const glm::vec2 pixel((io.MousePos.x - l.view.x) * l.scale, (io.MousePos.y - l.view.y) * l.scale);
        for (const Pane& pane : layoutPanes(scene.layout, scene.shading, scene.width, scene.height, scene.diff)) {
            if (pixel.x < float(pane.x) || pixel.x >= float(pane.x + pane.width)) continue;
            const int light = lightAtPixel(scene, pane, pixel, l.viewText * l.scale);
            if (light >= 0) lightDrag_ = LightDrag{light, pane};
        }
    }
    if (lightDrag_) {
        dragLight(l);
        if (!io.MouseDown[0]) lightDrag_.reset();
        return;
    }
    // A click (press and release without a drag) probes the pixel it was pressed on.
    const float threshold = io.MouseDragThreshold;
    if (io.MouseReleased[0] && io.MouseDragMaxDistanceSqr[0] < threshold * threshold) {
        const int x = int(std::floor(io.MouseClickedPos[0].x * l.scale));
        const int y = int(std::floor((io.MouseClickedPos[0].y - l.view.y) * l.scale));
        if (x >= 0 && x < l.viewWidth && y >= 0 && y < l.viewHeight) setProbe(x, y);
    }
    // Only drags and wheel steps that start over the 3D view (not its bands) move the camera.
    const auto dragging = [&](int button) { return io.MouseDown[button] && inView(io.MouseClickedPos[button]); };
    const bool moved = io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f;
    if (dragging(0) && moved)
        orbitCamera(document_.edit().camera, -io.MouseDelta.x * kOrbitRadPerUnit, io.MouseDelta.y * kOrbitRadPerUnit);
    if ((dragging(1) || dragging(2)) && moved) {
        panCamera(document_.edit().camera, io.MouseDelta.x, io.MouseDelta.y, l.view.height);
        document_.stopFollowing();
    }
    if (io.MouseWheel != 0.0f && inView(io.MousePos)) {
        zoomCamera(document_.edit().camera, io.MouseWheel, document_.minZoomDistance(), document_.maxZoomDistance());
        document_.stopFollowing();
    }
}

// Moves the dragged light's handle (lightHandleWorld) with the mouse: in the plane through it that
// faces the camera, so it stays under the cursor; with Shift along the viewing axis (a view height of
// drag moves it by twice its depth). A directional light turns to come from the handle.
void Viewer::dragLight(const FrameLayout& l) {
    const Scene& scene = document_.scene();
    if (lightDrag_->light >= int(scene.lights.size())) return lightDrag_.reset();
    const ImGuiIO& io = ImGui::GetIO();
    const Camera& c = scene.camera;
    const Pane& pane = lightDrag_->pane;
    const glm::vec3 handle = lightHandleWorld(scene, std::size_t(lightDrag_->light));
    const glm::vec3 forward = glm::normalize(c.target - c.eye);
    const float depth = glm::dot(handle - c.eye, forward);
    glm::vec3 moved = handle;
    if (io.KeyShift) {
        moved +=
            forward * (-io.MouseDelta.y * l.scale / float(std::max(pane.height, 1)) * 2.0f * std::max(depth, 1e-3f));
    } else {
        const glm::vec2 pixel((io.MousePos.x - l.view.x) * l.scale, (io.MousePos.y - l.view.y) * l.scale);
        const glm::vec3 ray = pixelDirectionWorld(c, pane, pixel.x, pixel.y);
        const float along = glm::dot(ray, forward);
        if (depth <= 0.0f || along <= 1e-4f) return;  // behind the eye: nothing to follow
        moved = c.eye + ray * (depth / along);
    }
    Light& light = document_.edit().lights[std::size_t(lightDrag_->light)];
    if (light.type != LightType::Directional) light.position = moved;
    else if (glm::length(c.target - moved) > 1e-4f) light.direction = glm::normalize(c.target - moved);
}

void Viewer::setUiScale(float uiScale) {
    uiScale_ = std::clamp(uiScale, kUiScaleRange.lo, kUiScaleRange.hi);
    setStatus("UI scale " + std::to_string(int(std::lround(uiScale_ * 100.0f))) + "%", false);
}

namespace {
// The table's named keys (core/ui/controls.hpp) by GLFW's key codes.
ViewerKey viewerKey(int glfwKey) {
    static constexpr std::pair<int, ViewerKey> kGlfwKeys[] = {
        {GLFW_KEY_TAB, ViewerKey::Tab},
        {GLFW_KEY_ESCAPE, ViewerKey::Escape},
        {GLFW_KEY_BACKSPACE, ViewerKey::Backspace},
        {GLFW_KEY_F1, ViewerKey::F1},
        {GLFW_KEY_F5, ViewerKey::F5},
        {GLFW_KEY_F11, ViewerKey::F11},
        {GLFW_KEY_F12, ViewerKey::F12},
        {GLFW_KEY_PAGE_DOWN, ViewerKey::PageDown},
        {GLFW_KEY_PAGE_UP, ViewerKey::PageUp},
        {GLFW_KEY_RIGHT, ViewerKey::Right},
        {GLFW_KEY_LEFT, ViewerKey::Left},
        {GLFW_KEY_HOME, ViewerKey::Home},
        {GLFW_KEY_END, ViewerKey::End},
        {GLFW_KEY_EQUAL, ViewerKey::Plus},
        {GLFW_KEY_KP_ADD, ViewerKey::Plus},
        {GLFW_KEY_MINUS, ViewerKey::Minus},
        {GLFW_KEY_KP_SUBTRACT, ViewerKey::Minus},
        {GLFW_KEY_0, ViewerKey::Zero},
        {GLFW_KEY_KP_0, ViewerKey::Zero},
        {GLFW_KEY_Q, ViewerKey::Q},
        {GLFW_KEY_R, ViewerKey::R},
    };
    for (const auto& [code, key] : kGlfwKeys)
        if (code == glfwKey) return key;
    return ViewerKey::None;
}
}  // namespace

// The keys of this frame, looked up in the key table (kControls, core/ui/controls.hpp).
void Viewer::handleKeys(const std::vector<KeyPress>& keys) {
    const ImGuiIO& io = ImGui::GetIO();
    const auto binding = [](const KeyPress& k) {
        return keyBinding(viewerKey(k.key), (k.mods & GLFW_MOD_CONTROL) != 0);
    };
    // Page Down / Page Up (a presenter's remote) and Esc act over the panel too, unless text is typed;
    // a text field gives the keyboard back on Esc itself (ImGui), and nothing quits on Esc.
    for (const KeyPress& k : keys) {
        const KeyBinding* b = binding(k);
        if (b && b->focus == KeyFocus::UnlessTyping && !io.WantTextInput) runCommand(b->command);
    }
    if (io.WantCaptureKeyboard) return;  // typing in a field or dragging a slider
    // Letters come as characters, so they follow the keyboard layout; with Ctrl held there are none.
    for (int i = 0; i < io.InputQueueCharacters.Size; ++i)
        if (const KeyBinding* b = characterBinding(io.InputQueueCharacters[i])) runCommand(b->command);
    // Keys without characters, and Ctrl+ shortcuts, by key code; Ctrl as it was when the key went down.
    for (const KeyPress& k : keys) {
        const KeyBinding* b = binding(k);
        if (b && b->focus == KeyFocus::View) runCommand(b->command);
    }
}

void Viewer::runCommand(ViewerCommand command) {
    const auto scene = [this]() -> Scene& { return document_.edit(); };  // the commands that change the scene
    const auto single = [&](ShadingMode mode) {
        scene().shading = mode;
        scene().layout = Layout::Single;
    };
    // C and D toggle: pressed again, back to the layout before (D twice from compare: compare again).
    const auto toggle = [&](Layout layout) {
        const Layout now = document_.scene().layout;
        if (now != layout) layoutBeforeToggle_ = now;
        scene().layout =
            now == layout ? (layoutBeforeToggle_ == layout ? Layout::Single : layoutBeforeToggle_) : layout;
    };
    OverlayOptions& overlays = settings_.overlays;
    switch (command) {
    case ViewerCommand::None: break;
    case ViewerCommand::Flat: single(ShadingMode::Flat); break;
    case ViewerCommand::Gouraud: single(ShadingMode::Gouraud); break;
    case ViewerCommand::Phong: single(ShadingMode::Phong); break;
    case ViewerCommand::Compare: toggle(Layout::Compare); break;
    case ViewerCommand::Difference: toggle(Layout::Diff); break;
    case ViewerCommand::Wireframe: overlays.wireframe = !overlays.wireframe; break;
    case ViewerCommand::VertexNormals: overlays.vertexNormals = !overlays.vertexNormals; break;
    case ViewerCommand::FaceNormals: overlays.faceNormals = !overlays.faceNormals; break;
    case ViewerCommand::LightMarkers: settings_.lightLabels = !settings_.lightLabels; break;
    case ViewerCommand::Formula: settings_.showFormula = !settings_.showFormula; break;
    case ViewerCommand::Intersection: settings_.showIntersection = !settings_.showIntersection; break;
    case ViewerCommand::ShaderSection: settings_.shaderOverView = !settings_.shaderOverView; break;
    case ViewerCommand::ResetCamera:
        document_.resetCamera();
        cameraMoved();
        break;
    case ViewerCommand::FrameModel:
        document_.frameModel();
        cameraMoved();
        break;
    case ViewerCommand::NextPreset:
    case ViewerCommand::PreviousPreset:
    case ViewerCommand::FirstPreset:
    case ViewerCommand::LastPreset:
    case ViewerCommand::ResetPreset: runPlaylistCommand(command); break;
    case ViewerCommand::UiLarger: setUiScale(uiScale_ * 1.25f); break;
    case ViewerCommand::UiSmaller: setUiScale(uiScale_ / 1.25f); break;
    case ViewerCommand::UiAsMonitor: setUiScale(1.0f); break;
    case ViewerCommand::TogglePanel: settings_.showPanel = !settings_.showPanel; break;
    case ViewerCommand::Fullscreen: window_.setFullscreen(!window_.fullscreen()); break;
    case ViewerCommand::Help: showHelp_ = !showHelp_; break;
    case ViewerCommand::ReloadShaders: reloadShaders(); break;
    case ViewerCommand::Screenshot: screenshotRequested_ = true; break;
    case ViewerCommand::PlayPause: animation_.togglePlay(); break;
    case ViewerCommand::Record: recording_.toggle(); break;
    case ViewerCommand::Escape:  // closes the help, else clears the probe
        if (showHelp_) showHelp_ = false;
        else probe_.clear();
        break;
    case ViewerCommand::Quit: window_.requestClose(); break;
    }
}

// The playlist's keys do nothing without a playlist.
void Viewer::runPlaylistCommand(ViewerCommand command) {
    if (!playlist_.active()) return;
    const std::size_t current = playlist_.current();
    if (command == ViewerCommand::NextPreset) goToPreset(current + 1);
    if (command == ViewerCommand::PreviousPreset && current > 0) goToPreset(current - 1);
    if (command == ViewerCommand::FirstPreset) goToPreset(0);
    if (command == ViewerCommand::LastPreset) goToPreset(playlist_.size() - 1);
    if (command == ViewerCommand::ResetPreset) resetPreset();
}

// --animate (AnimationPlayback): the scene drawn this frame, and the panel's line about it.
void Viewer::advanceAnimation() {
    status_.animation.clear();
    if (!animation_.any()) return;
    if (const auto error = animation_.advance(document_.scene(), std::chrono::steady_clock::now()))
        setStatus(*error, true);
    char text[96];
    const double t = animation_.shownSeconds(), loop = animation_.loopSeconds();
    if (options_.frames > 0)
        std::snprintf(text, sizeof text, "%.2f s of %.2f s", t, loop);  // a scripted run: 1/30 s a frame
    else std::snprintf(text, sizeof text, "%.2f s of %.2f s (at most %d frames/s)", t, loop, frameCapHz());
    status_.animation = text;
    status_.playing = animation_.playing();
}

const Scene& Viewer::shownScene() const { return animation_.scene() ? *animation_.scene() : document_.scene(); }

// The frame as shown goes to the recording (RecordingSession), started or stopped when asked.
void Viewer::record(const Image& view) {
    recording_.frame(view, std::chrono::steady_clock::now());
    status_.recording = recording_.active();
    status_.lastRecording = recording_.lastSaved();
}

void Viewer::apply(const PanelRequests& r) {
    if (r.toggleRecording) recording_.toggle();
    if (r.togglePlay) animation_.togglePlay();
    if (r.uiScale > 0.0f) uiScale_ = std::clamp(r.uiScale, kUiScaleRange.lo, kUiScaleRange.hi);
    if (r.msaa > 0) quality_.setMsaaSamples(r.msaa);
    if (r.toggleFullscreen) window_.setFullscreen(!window_.fullscreen());
    if (r.resetCamera) {
        document_.resetCamera();
        cameraMoved();
    }
    if (r.frameModel) {
        document_.frameModel();
        cameraMoved();
    }
    if (r.modelCamera >= 0) {
        // Through the model's camera, as --camera N: no longer framed by shadelab (F or R frame again).
        document_.edit().modelCamera = r.modelCamera;
        try {
            frameIfNeeded(document_.edit(), *document_.geometry());
            document_.stopFollowing();
        } catch (const InputError& e) {
            document_.edit().modelCamera = -1;
            setStatus(e.what(), true);
        }
    } else if (r.modelCamera == -1) {
        document_.frameModel();
    }
    if (r.screenshot) screenshotRequested_ = true;  // taken after this frame's render
    if (r.load) loadFile(settings_.scenePath);
    if (r.gotoPreset >= 0) goToPreset(std::size_t(r.gotoPreset));
    if (r.resetPreset) resetPreset();
    if (r.reloadShaders) reloadShaders();
    if (r.quit) window_.requestClose();
    if (r.clearProbe) probe_.clear();
    if (r.save) {
        try {
            document_.save(settings_.scenePath);
            setStatus("saved " + settings_.scenePath, false);
        } catch (const std::exception& e) {
            setStatus(std::string("save failed: ") + e.what(), true);
        }
    }
}

void Viewer::loadFile(const std::string& path) {
    if (!hasExtension(path, ".json") && !hasModelExtension(path)) {
        setStatus(path + ": not a scene (.json) or model (.gltf, .glb); kept the current scene", true);
        return;
    }
    try {
        document_.load(path);
        playlist_.detach();  // the next step must not keep this file as the preset's edits
        settings_.scenePath = hasExtension(path, ".json") ? path : "scene.json";
        settings_.selectedObject = 0;
        setStatus("loaded " + path, false);
    } catch (const std::exception& e) {
        setStatus(std::string(e.what()) + " (kept the current scene)", true);
    }
}

void Viewer::goToPreset(std::size_t index) {
    try {
        if (!playlist_.goTo(index, document_)) return;
    } catch (const std::exception& e) {
        setStatus(std::string(e.what()) + " (stayed on this preset)", true);
        return;
    }
    status_.scrollToPreset = true;
    showingPreset("preset " + std::to_string(playlist_.current() + 1) + "/" + std::to_string(playlist_.size()) + ": ");
}

void Viewer::resetPreset() {
    try {
        playlist_.reset(document_);
    } catch (const std::exception& e) {
        setStatus(std::string(e.what()) + " (the preset was not reset)", true);
        return;
    }
    showingPreset("reset preset " + std::to_string(playlist_.current() + 1) + " from ");
    // A reset is asked for: a short word over the view (no path, the caption shows which preset).
    setStatus("preset reset to its file", false);
}

// The document shows the current preset now: the panel's File path is its file. A slide change shows
// no message over the view (the caption band has the position, "16 / 23"); the path is for -v only
// (the terminal, which the viewer tests read). A message of the preset left stays behind with it,
// errors excepted.
void Viewer::showingPreset(const std::string& what) {
    const Preset& p = playlist_.preset(playlist_.current());
    settings_.scenePath = p.path;
    settings_.selectedObject = 0;
    // --animate with a playlist: every preset plays it from its start (also after one it did not fit).
    animation_.restart();
    if (!status_.isError) messageUntil_ = std::chrono::steady_clock::now();
    if (options_.verbose) std::cerr << "shadelab: " << what << p.path << "\n";
    openAsSlide(document_.scene().viewer, false, false);
}

// A scene's "viewer" block (core/scene/scene.hpp, ViewerStart): the slide opens with its probe (set on
// the next frame, when the view has its size), the intersection diagram and the panel's sections, unless
// the command line gave its own for the first one. A slide without a block leaves them as they were.
void Viewer::openAsSlide(const ViewerStart& start, bool probeGiven, bool sectionsGiven) {
    if (start.probe && !probeGiven) {
        slideProbe_ = start;
        settings_.showIntersection = start.intersection;
    }
    if ((start.panelSections || !start.plot.empty()) && !sectionsGiven) {
        settings_.startSections = start.panelSections.value_or(std::vector<std::string>{});
        if (!start.plot.empty() && std::find(settings_.startSections->begin(), settings_.startSections->end(),
                                             "plots") == settings_.startSections->end())
            settings_.startSections->push_back("plots");
        settings_.scrollToPlot = start.plot;
        settings_.showPanel = true;  // the sections are the slide's figure
    }
}

// Mesh edits in the panel rebuild geometry here, once per change; every other frame only compares specs.
void Viewer::uploadGeometryIfChanged() {
    try {
        document_.syncGeometry();
    } catch (const std::exception& e) {
        setStatus(std::string("mesh not changed: ") + e.what(), true);
    }
    const auto& geometry = document_.geometry();
    if (uploadedGeometry_ != document_.geometryRevision()) {
        renderer_->setGeometry(geometry);
        overlays_->setGeometry(geometry);
        uploadedGeometry_ = document_.geometryRevision();
    }
    status_.frameTriangles = geometry ? geometry->triangleCount() * scenePaneCount(document_.scene().layout) : 0;
    const auto selected = std::size_t(settings_.selectedObject);
    status_.objectTriangles =
        geometry && selected < geometry->meshes.size() ? geometry->meshes[selected].triangleCount() : 0;
    status_.modelCameras.clear();
    for (std::size_t i = 0; geometry && i < geometry->gltfInfo.size(); ++i)
        if (!geometry->gltfInfo[i].cameras.empty()) {  // the first model's, as --camera N
            for (const GltfCamera& c : geometry->gltfInfo[i].cameras) status_.modelCameras.push_back(c.name);
            break;
        }
}

// Draws the scene and the overlays into the 3D view. With `capture`, returns the view as drawn, read
// before ImGui adds labels or panel (what F12 and --screenshot-view save); otherwise an empty image.
// A capture or the last frame completes a progressive image first: a file never holds a partial one.
Image Viewer::renderView(const FrameLayout& l, bool capture, bool last, const std::vector<OverlayArrow>& arrows) {
    if (l.viewWidth <= 0 || l.viewHeight <= 0) {  // minimised, or no room for the view
        progressive_.abandon();                   // nothing to refine: the viewer may sleep
        return {};
    }
    const RenderTarget view{0, l.viewWidth, l.viewHeight};
    try {
        if (quality_.reducedThisFrame()) {  // a moving frame, smaller, magnified into the view (no anti-aliasing)
            const float scale = quality_.movingScale();
            const RenderTarget small = reduced_.begin(std::max(int(std::lround(float(l.viewWidth) * scale)), 1),
                                                      std::max(int(std::lround(float(l.viewHeight) * scale)), 1));
            renderScene(small, false);
            OverlayOptions overlays = settings_.overlays;
            overlays.lineWidth = std::max(2.0f * imgui_.scale() * scale, 1.0f);
            overlays_->render(shownScene(), small, overlays, arrows);
            reduced_.magnifyInto(view);
            return {};
        }
        const RenderTarget target = msaa_.begin(view, quality_.antiAliasThisFrame() ? quality_.msaaSamples() : 1);
        renderScene(target, capture || last);
        // Lines 2 pixels wide at scale 1, thicker with the content and UI scale.
        OverlayOptions overlays = settings_.overlays;
        overlays.lineWidth = 2.0f * imgui_.scale();
        overlays_->render(shownScene(), target, overlays, arrows);
        msaa_.resolveInto(view);
        if (capture) return opaque(readPixels(view));
    } catch (const std::exception& e) {
        // The window's framebuffer again for ImGui, the view cleared, and no pass pending: a failing
        // program is not retried every frame (the next change of scene or shaders tries again).
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, l.viewWidth, l.viewHeight);
        glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
        glEnable(GL_SCISSOR_TEST);
        glScissor(0, 0, l.viewWidth, l.viewHeight);
        glClear(GL_COLOR_BUFFER_BIT);
        glDisable(GL_SCISSOR_TEST);
        progressive_.abandon();
        setStatus(e.what(), true);
    }
    return {};
}

// Everything the 3D view's image is drawn from (view_revision.hpp): the one list, for whatever must
// restart or redraw when the view changed.
ViewInputs Viewer::viewInputs(const RenderTarget& target) const {
    ViewInputs in;
    in.scene = document_.revision();
    in.geometry = document_.geometryRevision();
    in.renderer = rendererGeneration_;
    in.animation = animation_.step();
    in.width = std::uint64_t(target.width);
    in.height = std::uint64_t(target.height);
    in.moving = quality_.movingThisFrame() ? 1 : 0;
    return in;
}

// Scenes with sampled area lights refine over frames (ProgressiveSampling): a frame draws one pass, and
// a sum restarts when the view's revision moved. `complete` (a capture, the last frame) draws every
// remaining pass: a file never holds a partial image.
void Viewer::renderScene(const RenderTarget& view, bool complete) {
    const Scene& scene = shownScene();
    progressive_.frameBegins(std::chrono::steady_clock::now());
    int samples = 1;
    for (const Light& light : scene.lights)
        if (light.type == LightType::Area) samples = std::max(samples, light.samples.x * light.samples.y);
    if (samples <= 1) {
        progressive_.off();
        status_.progress.clear();
        renderer_->render(scene, view);
        return;
    }
    const ProgressiveSampling::Pass pass =
        progressive_.begin(viewRevision_.of(viewInputs(view)), samples, quality_.movingThisFrame());
    Renderer::ProgressiveStatus status = renderer_->renderProgressive(scene, view, pass.stride, pass.restart);
    const bool finishNow = complete && !status.complete();
    while (!status.complete() && finishNow) status = renderer_->renderProgressive(scene, view, pass.stride, false);
    progressive_.drawn(status.complete(), finishNow);
    status_.progress = status.passCount > 1 ? "area-light samples: pass " + std::to_string(status.passesDone) + " of " +
                                                  std::to_string(status.passCount)
                                            : "";
}

void Viewer::saveScreenshot(const Image& view) {
    screenshotRequested_ = false;
    if (view.width == 0) return;  // nothing was drawn; renderView said why
    const std::string path = timestampedName();
    try {
        writePng(path, view);
        status_.lastScreenshot = path;
        setStatus("saved screenshot " + path, false);
    } catch (const std::exception& e) {
        setStatus(std::string("screenshot failed: ") + e.what(), true);
    }
}

// The scripted run's results. Unlike the panel's buttons these throw: a file that was asked for on the
// command line and not written is the run's failure.
void Viewer::writeLastFrameFiles(const FrameLayout& l, const Image& view) {
    auto wrote = [&](const std::string& path) {
        if (options_.verbose) std::cerr << "shadelab: wrote " << path << "\n";
    };
    if (!options_.viewScreenshotPath.empty()) {
        if (view.width == 0) throw std::runtime_error("the 3D view was not drawn: " + status_.message);
        writePng(options_.viewScreenshotPath, view);
        wrote(options_.viewScreenshotPath);
    }
    if (!options_.screenshotPath.empty()) {
        writePng(options_.screenshotPath, opaque(readPixels(RenderTarget{0, l.framebufferWidth, l.framebufferHeight})));
        wrote(options_.screenshotPath);
    }
    if (!options_.saveScenePath.empty()) {
        document_.save(options_.saveScenePath);
        wrote(options_.saveScenePath);
    }
}

// The files the Shader section lists, as they are now (a reload shows the text it compiled, also when
// it failed: the error's line is in it).
void Viewer::readShaderSources(const ShaderLibrary& shaders) {
    status_.shaderSources.clear();
    for (ShadingMode mode : {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong})
        for (const std::string& file : shaderFilesOf(mode)) {
            try {
                status_.shaderSources[file] = shaders.load(file);
            } catch (const std::exception&) {
                // Not there: the section says so.
            }
        }
}

void Viewer::reloadShaders() {
    // Build the new programs first; on any error the running ones stay (the lecture goes on).
    try {
        // A trial frame builds every program the scene needs (render() compiles on first use and
        // throws ShaderError); the frame's own render draws over it.
        const ShaderLibrary shaders(options_.shaderDir);
        readShaderSources(shaders);
        auto renderer = makeRenderer(shaders);
        auto overlays = std::make_unique<OverlayRenderer>(shaders);
        renderer->setGeometry(document_.geometry());
        overlays->setGeometry(document_.geometry());
        const Scene& scene = document_.scene();
        renderer->preparePrograms(scene);  // all three modes, so switching mode later cannot fail
        renderer->render(scene, RenderTarget{0, scene.width, scene.height});
        renderer_ = std::move(renderer);
        overlays_ = std::move(overlays);
        ++rendererGeneration_;
        uploadedGeometry_ = document_.geometryRevision();
        setStatus(options_.shaderDir.empty()
                      ? "reloaded the built-in shaders (no shaders/ folder: start with --shader-dir DIR to edit them)"
                      : "reloaded shaders from " + options_.shaderDir,
                  false);
        status_.shaderError.clear();
    } catch (const std::exception& e) {
        status_.shaderError = e.what();
        setStatus(std::string("shaders not reloaded, the previous ones stay:\n") + e.what(), true);
        // The Shader view shows the error's file and line, whichever pane or layout is up (each F5).
        if (focusShaderError(document_.scene(), settings_, status_.shaderError)) settings_.shaderOverView = true;
    }
}

void Viewer::setProbe(int x, int y, bool announce) {
    const ProbeState::Outcome outcome = probe_.set(document_.scene(), document_.geometry(), x, y);
    // A person's probe: the panel shows its Probe section, wherever it was scrolled, and the status line
    // says where; a slide's probe (openAsSlide) says nothing.
    if (outcome.set && announce) settings_.scrollToProbe = true;
    if (announce || !outcome.set) setStatus(outcome.message, outcome.isError);
}

std::vector<OverlayArrow> Viewer::probeOverlays(const FrameLayout& l, const std::vector<UiRect>& avoid) {
    const Scene& scene = document_.scene();
    if (settings_.selectedLight >= int(scene.lights.size())) settings_.selectedLight = -1;  // fewer lights now
    settings_.overlays.sampleMarkersLight = settings_.selectedLight;
    std::vector<OverlayArrow> arrows;
    if (!probe_.result()) return arrows;
    const std::vector<ProbeArrow> labelled =
        probeArrows(scene, *probe_.result(), settings_.selectedLight, settings_.showIntersection);
    ImGui::PushFont(imgui_.viewFont());
    drawProbeLabels(scene, labelled, l.view, l.scale, avoid);
    ImGui::PopFont();
    for (const ProbeArrow& a : labelled) arrows.push_back(a.arrow);
    return arrows;
}

// The camera jumped (R, F): a message about the old view ("probe at pixel ...") would lie over the new
// one (the probe's arrows run through it), so it goes; errors stay.
void Viewer::cameraMoved() {
    if (!status_.isError) messageUntil_ = std::chrono::steady_clock::now();
}

void Viewer::setStatus(std::string message, bool isError) {
    if (isError && message != status_.message) std::cerr << "shadelab: " << message << "\n";
    status_.message = std::move(message);
    status_.isError = isError;
    // Shown over the view for a while, where the lecturer looks (and at the end of the File section);
    // a frame is drawn to show it, also when the message comes late in a frame.
    pacing_.drawAnother();
    messageUntil_ = std::chrono::steady_clock::now() +
                    std::chrono::milliseconds(int((isError ? kErrorSeconds : kMessageSeconds) * 1000.0));
}

}  // namespace shadelab
