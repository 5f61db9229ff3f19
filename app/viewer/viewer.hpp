#pragma once
// The interactive viewer: a GLFW window, the shared Renderer drawing the scene into its default
// framebuffer, the teaching overlays, and a Dear ImGui panel that edits the scene live. One object owns
// all of it; run() loops over frame(), which is the whole per-frame story:
//   poll -> ImGui frame -> keys/mouse/drops -> panel -> apply requests -> renderer -> ImGui -> swap.
#include "core/geometry/scene_geometry.hpp"
#include "core/image/image.hpp"
#include "core/scene/animation.hpp"
#include "core/scene/playlist.hpp"
#include "core/scene/scene.hpp"
#include "core/ui/controls.hpp"
#include "render/gl_handles.hpp"
#include "render/multisample_target.hpp"
#include "render/overlay_renderer.hpp"
#include "render/renderer.hpp"
#include "viewer/animation_playback.hpp"
#include "viewer/frame_pacing.hpp"
#include "viewer/frame_rate.hpp"
#include "viewer/glfw_window.hpp"
#include "viewer/imgui_layer.hpp"
#include "viewer/panel.hpp"
#include "viewer/placed_geometry.hpp"
#include "viewer/playlist_navigator.hpp"
#include "viewer/probe_state.hpp"
#include "viewer/progressive_sampling.hpp"
#include "viewer/recording_session.hpp"
#include "viewer/reduced_target.hpp"
#include "viewer/scene_document.hpp"
#include "viewer/view_overlays.hpp"
#include "viewer/view_prefs.hpp"
#include "viewer/view_quality.hpp"
#include "viewer/view_revision.hpp"

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
    std::string shaderDir;  // --shader-dir: GLSL read from here when present ("reload shaders")
    int frames = 0;         // --frames N: quit after N frames; 0 runs until closed
    // Written on the last frame: the N-th with --frames, else the one in which the session ends.
    std::string screenshotPath;      // --screenshot: the whole window, panel included
    std::string viewScreenshotPath;  // --screenshot-view: the 3D view alone (what F12 saves)
    std::string saveScenePath;       // --save-scene: the scene JSON (what "save scene" writes)
    bool hidePanel = false;          // --hide-panel: start as if Tab had been pressed
    OverlayOptions overlays;         // --overlays: which overlays start switched on
    // --progressive S: with area lights, each frame evaluates every S-th sample per axis and the view
    // refines over S*S frames (Renderer::renderProgressive); 0 picks S from the measured frame time.
    int progressiveStride = 0;
    PlotSettings plots;  // --incidence, --from-inside: the Plots section's starting controls
    std::optional<std::vector<std::string>> panelSections;  // --panel-sections: exactly these open at start
    std::optional<glm::ivec2> probe;  // --probe X,Y: start with the pixel probe set at this 3D-view pixel
    int selectedLight = -1;           // --select-light N: start with light N selected in the panel
    // --playlist: the presets, the first of which is the scene the viewer starts with; `adjustPreset`
    // is applied again when "reset preset" reloads one from its file (the command line's overrides).
    std::vector<Preset> playlist;
    SceneAdjust adjustPreset;
    bool noLabels = false;      // --no-labels: pane and light labels start off
    bool formula = false;       // --formula: start with the formula over the view (E)
    bool intersection = false;  // --intersection: start with the intersection diagram at the probe (I)
    bool resetLayout = false;   // --reset-layout: forget (and overwrite) the remembered layout
    float uiScale = 0.0f;       // --ui-scale: on top of the monitor's content scale; 0: not given
    bool fullscreen = false;    // --fullscreen (F11)
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
        int viewWidth = 0, viewHeight = 0;            // pixels; the 3D view is the bottom-left viewWidth x viewHeight
        float scale = 1.0f;                           // framebuffer pixels per ImGui unit
        UiRect strip, caption, formula, view, panel;  // ImGui units; formula: E's band (0 high: none)
        CaptionLayout captionText;
        // The text over the view (ImGui units): the window-height size (0 with the presentation
        // setting off) and the size drawn, never below the panel's text.
        float windowText = 0.0f, viewText = 0.0f;
    };
    float windowTextSize() const;  // FrameLayout::windowText, before the frame's layout
    // The formula's band (FrameLayout::formula) for a view `viewWidth` wide: its height, or draws it.
    float formulaBand(const FrameLayout& layout, float viewWidth, bool draw) const;

    bool frame(bool last);
    // frame()'s steps.
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
    // The pixel probe (ProbeState) set at a pixel of the 3D view, the outcome on the status line;
    // `announce`: the message and the panel scrolled to its Probe section (not for a slide's probe).
    void setProbe(int x, int y, bool announce = true);
    void openAsSlide(const ViewerStart& start, bool probeGiven, bool sectionsGiven);
    std::optional<ViewerStart> slideProbe_;  // a slide's "viewer" probe, set on the next frame
    // This frame's probe arrows (their labels go on ImGui's list now; renderView draws the arrows),
    // and the selected light's sample markers switched on.
    std::vector<OverlayArrow> probeOverlays(const FrameLayout& layout, const std::vector<UiRect>& avoid);

    ViewerOptions options_;
    // What a person's last session left (view_prefs.hpp); the defaults for scripted runs. Before
    // window_: the window opens where it was.
    std::string prefsPath_;
    ViewPrefs prefs_;
    void savePrefs();
    GlfwWindow window_;  // before every GL user: the context outlives them
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
    bool showHelp_ = false;                               // F1 / ?: every key and mouse action over the view
    bool panelDrawn_ = false;                             // the panel was shown at least once this session
    std::chrono::steady_clock::time_point messageUntil_;  // the status message shows over the view until then
    bool messageShown_ = false;                           // ... and the last frame drew it
    bool screenshotRequested_ = false;
    // The viewer's parts, each with its own state: when to draw (render on demand, the frame cap), how
    // (anti-aliased, reduced while moving), the progressive sum, --animate, the recording, the probe.
    FramePacing pacing_;
    double frameMs_ = 0.0;            // the last frame's own time (not the wait before it)
    std::vector<double> frameTimes_;  // every frame's own time, for -v's median at the end
    FrameRate frameRate_;             // the status strip's mean of the last second's frames
    ViewQuality quality_{1, false};
    MultisampleTarget msaa_;  // the anti-aliased frames' target
    ReducedTarget reduced_;   // the reduced moving frames' target
    // "The view changed" (view_revision.hpp): viewInputs() is the one list of what the image is drawn
    // from; a progressive sum restarts when its revision moves.
    ViewRevision viewRevision_;
    ViewInputs viewInputs(const RenderTarget& target) const;
    ProgressiveSampling progressive_;
    AnimationPlayback animation_;
    void advanceAnimation();
    const Scene& shownScene() const;  // the document's scene as --animate makes it this frame
    // The frame cap while an animation plays or a recording runs (FramePacing::capHz of the display's).
    int frameCapHz() const;
    void waitForRefresh();
    RecordingSession recording_;
    void record(const Image& view);
    // A light marker being dragged: which light, in which pane (the plane facing the camera, or with
    // Shift the view axis).
    struct LightDrag {
        int light = -1;
        Pane pane;
    };
    std::optional<LightDrag> lightDrag_;
    void dragLight(const FrameLayout& layout);
    ProbeState probe_;
    ModelSpheres modelSpheres_;  // the light labels keep off them
};

}  // namespace shadelab
