#pragma once
// The interactive viewer: a GLFW window, the shared Renderer drawing the scene into its default
// framebuffer, the teaching overlays, and a Dear ImGui panel that edits the scene live. One object owns
// all of it; run() loops over frame(), which is the whole per-frame story:
//   poll -> ImGui frame -> keys/mouse/drops -> panel -> apply requests -> renderer -> ImGui -> swap.
#include "core/image/image.hpp"
#include "core/probe/probe.hpp"
#include "core/geometry/ray_cast.hpp"
#include "core/scene/animation.hpp"
#include "core/scene/playlist.hpp"
#include "core/scene/scene.hpp"
#include "core/ui/controls.hpp"
#include "core/geometry/scene_geometry.hpp"
#include "render/gl_handles.hpp"
#include "render/multisample_target.hpp"
#include "render/overlay_renderer.hpp"
#include "render/renderer.hpp"
#include "viewer/frame_rate.hpp"
#include "viewer/glfw_window.hpp"
#include "viewer/imgui_layer.hpp"
#include "viewer/panel.hpp"
#include "viewer/playlist_navigator.hpp"
#include "viewer/scene_document.hpp"
#include "viewer/view_prefs.hpp"
#include "viewer/view_recorder.hpp"

#include <chrono>
#include <glm/vec2.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace shadelab {

// How the viewer is started; the last four make it scriptable (tests, README screenshot).
struct ViewerOptions {
    std::string shaderDir;            // --shader-dir: GLSL read from here when present ("reload shaders")
    int frames = 0;                   // --frames N: quit after N frames; 0 runs until closed
    // Written on the last frame: the N-th with --frames, else the one in which the session ends.
    std::string screenshotPath;       // --screenshot: the whole window, panel included
    std::string viewScreenshotPath;   // --screenshot-view: the 3D view alone (what F12 saves)
    std::string saveScenePath;        // --save-scene: the scene JSON (what "save scene" writes)
    bool hidePanel = false;           // --hide-panel: start as if Tab had been pressed
    OverlayOptions overlays;          // --overlays: which overlays start switched on
    // --progressive S: with area lights, each frame evaluates every S-th sample per axis and the view
    // refines over S*S frames (Renderer::renderProgressive); 0 picks S from the measured frame time.
    int progressiveStride = 0;
    PlotSettings plots;               // --incidence, --from-inside: the Plots section's starting controls
    std::optional<std::vector<std::string>> panelSections;  // --panel-sections: exactly these open at start
    std::optional<glm::ivec2> probe;  // --probe X,Y: start with the pixel probe set at this 3D-view pixel
    int selectedLight = -1;           // --select-light N: start with light N selected in the panel
    // --playlist: the presets, the first of which is the scene the viewer starts with; `adjustPreset`
    // is applied again when "reset preset" reloads one from its file (the command line's overrides).
    std::vector<Preset> playlist;
    SceneAdjust adjustPreset;
    bool noLabels = false;            // --no-labels: pane and light labels start off
    bool formula = false;             // --formula: start with the formula over the view (E)
    bool intersection = false;        // --intersection: start with the intersection diagram at the probe (I)
    bool resetLayout = false;         // --reset-layout: forget (and overwrite) the remembered layout
    float uiScale = 0.0f;             // --ui-scale: on top of the monitor's content scale; 0: not given
    bool fullscreen = false;          // --fullscreen (F11)
    // --msaa N: samples per pixel of the anti-aliased view; -1 (not given): 4 for a person, 1 for a
    // scripted run (--frames), whose 3D view then equals the headless image.
    int msaa = -1;
    // --animate: played over the scene as it is drawn (the panel's values stay the scene's), looping over
    // the longest animation's length; Space and the panel play and pause. A scripted run (--frames) steps
    // 1/30 s a frame, so its frames do not depend on the machine's speed.
    std::vector<Animation> animations;
    bool verbose = false;
};

class Viewer {
public:
    // Opens the window (sized scene.width x scene.height) and makes everything ready to draw.
    // Throws InputError when there is no display, std::runtime_error when GL 3.3 is not available.
    Viewer(Scene scene, std::shared_ptr<const SceneGeometry> geometry, ViewerOptions options);
    ~Viewer();
    Viewer(const Viewer&) = delete;
    Viewer& operator=(const Viewer&) = delete;

    // Runs until the window closes, Esc/Q, or options.frames frames. Errors during the session are
    // shown in the panel; only the scripted last-frame writes throw (their failure is the run's result).
    void run();

private:
    // Pixel layout of this frame: the panel on the right; on the left, from the top, the status strip
    // (frame time), the caption band (a preset's title and caption) and the 3D view, so neither band
    // ever covers what the camera frames.
    struct FrameLayout {
        int framebufferWidth = 0, framebufferHeight = 0;
        int viewWidth = 0, viewHeight = 0;  // pixels; the 3D view is the bottom-left viewWidth x viewHeight
        float scale = 1.0f;                 // framebuffer pixels per ImGui unit
        UiRect strip, caption, view, panel; // ImGui units
        CaptionLayout captionText;
        // The text over the view (ImGui units): the window-height size (0 with the presentation
        // setting off) and the size drawn, never below the panel's text.
        float windowText = 0.0f, viewText = 0.0f;
    };
    float windowTextSize() const;  // FrameLayout::windowText, before the frame's layout

    bool frame(bool last);
    // frame()'s steps.
    bool countEvents();
    PanelRequests panelEdits(const FrameLayout& layout);
    float followView(const FrameLayout& layout);
    std::vector<UiRect> drawViewText(const FrameLayout& layout, float labelsBottom);
    // The value being changed, large over the view's top left: a slider dragged in the panel, else
    // the number a playing --animate ramp sets (k_e while it sweeps).
    void drawReadout(const FrameLayout& layout, float labelsBottom);
    Image drawView(const FrameLayout& layout, bool still, bool last, const std::vector<OverlayArrow>& arrows);
    void recordFrameTime(std::chrono::steady_clock::time_point start, bool last);
    // Whether the next frame can wait for an event: nothing moves, nothing is pending.
    bool idle() const;
    FrameLayout layout() const;
    void handleInput(const FrameLayout& layout, const std::vector<KeyPress>& keys);
    void handleKeys(const std::vector<KeyPress>& keys);
    void runCommand(ViewerCommand command);          // what a key of the table (kControls) does
    void runPlaylistCommand(ViewerCommand command);  // the playlist's keys
    void setUiScale(float uiScale);
    void apply(const PanelRequests& requests);
    void uploadGeometryIfChanged();
    Image renderView(const FrameLayout& layout, bool capture, bool last, const std::vector<OverlayArrow>& arrows);
    void renderScene(const RenderTarget& view, bool complete);
    void saveScreenshot(const Image& view);
    void writeLastFrameFiles(const FrameLayout& layout, const Image& view);
    void loadFile(const std::string& path);
    void goToPreset(std::size_t index);
    void resetPreset();
    void showingPreset(const std::string& what);
    void reloadShaders();
    void readShaderSources(const ShaderLibrary& shaders);  // for the panel's Shader section
    void setStatus(std::string message, bool isError);
    void cameraMoved();
    Layout layoutBeforeToggle_ = Layout::Single;  // what C or D pressed again goes back to
    // The pixel probe: set at a pixel of the 3D view (a click, --probe), re-evaluated every frame at
    // the same surface point with the scene as it is then.
    // `announce`: a message over the view and the panel scrolled to its Probe section (not for a slide's).
    void setProbe(int x, int y, bool announce = true);
    void openAsSlide(const ViewerStart& start, bool probeGiven, bool sectionsGiven);
    static glm::ivec2 slidePixel(const ViewerStart& start, int viewWidth, int viewHeight);
    std::optional<ViewerStart> slideProbe_;  // a slide's "viewer" probe, set on the next frame
    void evaluateProbe();
    const SceneRayCaster& rayCaster();
    // This frame's probe arrows (their labels go on ImGui's list now; renderView draws the arrows),
    // and the selected light's sample markers switched on.
    std::vector<OverlayArrow> probeOverlays(const FrameLayout& layout, const std::vector<UiRect>& avoid);

    ViewerOptions options_;
    // What a person's last session left (view_prefs.hpp); the defaults for scripted runs. Before
    // window_: the window opens where it was.
    std::string prefsPath_;
    ViewPrefs prefs_;
    void savePrefs();
    GlfwWindow window_;   // before every GL user: the context outlives them
    ImGuiLayer imgui_;
    std::unique_ptr<Renderer> renderer_;
    std::unique_ptr<OverlayRenderer> overlays_;
    // The document's geometry revision the renderers were last given (none yet: the first frame uploads).
    std::optional<std::uint64_t> uploadedGeometry_;
    std::uint64_t rendererGeneration_ = 0;  // counts the renderers (F5 makes a new one)
    SceneDocument document_;
    PlaylistNavigator playlist_;
    ViewSettings settings_;
    PanelStatus status_;
    float uiScale_ = 1.0f;
    bool showHelp_ = false;                     // F1 / ?: every key and mouse action over the view
    bool panelDrawn_ = false;                   // the panel was shown at least once this session
    std::chrono::steady_clock::time_point messageUntil_;  // the status message shows over the view until then
    bool messageShown_ = false;                 // ... and the last frame drew it
    // Render on demand: events seen so far, frames still to draw after the last one, the last
    // frame's own time (not the wait before it).
    unsigned long eventsSeen_ = 0;
    int framesToDraw_ = 2;
    double frameMs_ = 0.0;
    std::vector<double> frameTimes_;            // every frame's own time, for -v's median at the end
    FrameRate frameRate_;                       // the status strip's mean of the last second's frames
    // Anti-aliasing: the multisampled target, its samples, whether the GL is a software rasterizer
    // (there only a still view is drawn anti-aliased: 4x costs several times a frame on llvmpipe), and
    // whether the last frame was.
    MultisampleTarget msaa_;
    // Moving frames on a software rasterizer (issue 31, item 12): while the view is dragged, a slider
    // held or an animation plays, the scene is drawn into a framebuffer `movingScale_` of the view's
    // size per axis and magnified into it; the scale follows the moving frames' time (aiming at 30
    // FPS); a still view is drawn at full size (and anti-aliased) again.
    struct ReducedTarget {
        gl::Framebuffer framebuffer;
        gl::Renderbuffer color, depth;
        int width = 0, height = 0;
    };
    ReducedTarget reduced_;
    float movingScale_ = 1.0f;
    bool movingLastFrame_ = false;
    bool reducedThisFrame_ = false;
    RenderTarget beginReduced(int width, int height);
    int msaaSamples_ = 1;
    bool softwareGl_ = false;
    bool antiAliased_ = false;
    bool antiAliasThisFrame_ = false;
    bool screenshotRequested_ = false;
    // Progressive sampling: what the sum so far was drawn from (the scene's and the geometry's
    // revisions, the renderer, the view's size; none while the scene needs no sampling), the stride,
    // and the last pass's time.
    std::optional<std::array<std::uint64_t, 6>> progressiveFrom_;
    // --animate: whether it plays, its clock, and the scene it makes of the document's for this frame.
    bool playing_ = false;
    double animationSeconds_ = 0.0;
    std::uint64_t animationStep_ = 0;  // counts the frames the animation changed (restarts a progressive sum)
    std::chrono::steady_clock::time_point animationTick_;
    std::optional<Scene> animatedScene_;
    void advanceAnimation();
    // The frame cap while an animation plays or a recording runs (the display's refresh, else 60 Hz).
    int frameCapHz() const;
    void waitForRefresh();
    std::chrono::steady_clock::time_point frameBegun_;
    // Ctrl+R / the record button: recording the view as shown to a timestamped MP4 (viewer/view_recorder.hpp).
    std::unique_ptr<ViewRecorder> recording_;
    bool recordToggled_ = false;  // start or stop at this frame's end, once the view is drawn
    std::chrono::steady_clock::time_point recordingStart_;
    void record(const FrameLayout& l, const Image& view);
    void stopRecording();
    int progressiveStride_ = 0;
    double lastPassMs_ = 0.0;
    bool passDrawnLastFrame_ = false;
    bool progressiveComplete_ = false;
    std::chrono::steady_clock::time_point lastFrameStart_;
    // A light marker being dragged: which light, in which pane (the plane facing the camera, or with
    // Shift the view axis).
    struct LightDrag {
        int light = -1;
        Pane pane;
    };
    std::optional<LightDrag> lightDrag_;
    void dragLight(const FrameLayout& layout);
    std::optional<ProbeAnchor> probeAnchor_;
    // The meshes probeAnchor_'s triangle is in, and those caster_ was built from. Weak: a rebuilt
    // geometry may reuse a freed one's address, an expired pointer cannot be mistaken for it.
    std::weak_ptr<const SceneGeometry> probeGeometry_;
    std::optional<ProbeResult> probe_;         // this frame's evaluation of probeAnchor_
    std::optional<glm::ivec2> pendingProbe_;   // --probe: set on the first frame, once the view has its size
    // Rebuilt when the geometry or an object's transform changes (what it was built from is kept).
    std::unique_ptr<SceneRayCaster> caster_;
    std::weak_ptr<const SceneGeometry> casterGeometry_;
    std::vector<Transform> casterTransforms_;
    const SceneRayCaster noTriangles_;         // what probeAnchor() gets when shadows are off (it is not used)
    // Each object's world-space bounding sphere (a plane, a floor, left out): the light labels keep
    // off them. Recomputed when the geometry or a transform changes.
    const std::vector<BoundingSphere>& modelSpheres();
    std::vector<BoundingSphere> modelSpheres_;
    std::optional<std::uint64_t> spheresGeometry_;
    std::vector<Transform> spheresTransforms_;
};

}  // namespace shadelab
