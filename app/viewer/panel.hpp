#pragma once
// The viewer's Dear ImGui side panel, which edits the Scene struct in place (every change shows on the
// next frame); what is drawn over the 3D view (pane labels, light markers, the HUD) is view_overlays.hpp.
// Immediate mode: drawPanel is called every frame, holds no state of its own, and reports button presses
// as requests that the viewer carries out, so file and GL work never happens inside a widget.
#include "core/figures/plot.hpp"
#include "core/probe/probe.hpp"
#include "core/scene/scene.hpp"
#include "render/overlay_renderer.hpp"

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace shadelab {

// View state that is not part of the scene (and so is not saved with it).
struct ViewSettings {
    OverlayOptions overlays;
    bool showPanel = true;    // Tab
    bool paneLabels = true;   // "flat" / "gouraud" / "phong" over each pane
    bool showHud = true;      // frame time, FPS, triangles, GL renderer
    bool showCaption = true;  // a scene's title and caption in a band above the 3D view
    bool lightLabels = true;  // L: each light's marker, number and kind drawn over the view
    bool showIntersection =
        false;                 // I, --intersection: the intersection diagram at the probe (viewer/probe_arrows.hpp)
    bool showFormula = false;  // E, --formula: the lecture's formula over the view (viewer/formula_view.hpp)
    bool readoutWhenHidden = true;  // Tab keeps the frame-time strip (a switch in the Overlays section)
    // The text over the view (caption, labels, formula, messages) sized from the window's height for
    // a lecture hall, whatever the panel's UI scale (a switch in the Overlays section); off: the panel's.
    bool presentationText = true;
    std::string readout;     // this frame's live value ("k_e = 37.2") of a slider being dragged
    std::string scenePath;   // the Save / Load field
    int selectedObject = 0;  // whose material, mesh and transform the panel shows
    PlotSettings plots;      // the Plots section's incidence angle and side of the surface
    // --panel-sections: on the first frame, exactly these sections (kPanelSections names) are opened.
    std::optional<std::vector<std::string>> startSections;
    std::vector<std::string> openSections;  // those open in the last frame (remembered between sessions)
    // The light selected in the panel (-1: none): an area light shows its samples, and the probe's
    // arrows show only this light's I, R and H.
    int selectedLight = -1;
    // The Shader section (viewer/shader_view.hpp): the pane whose mode it lists (-1: the probed one or
    // the first), and S's request to open or close it. After a failed reload (focusShaderError): the
    // file the error is in when no pane's mode runs it (shown as one more tab), and the error's file
    // and line, selected and scrolled to once shown.
    int shaderPane = -1;
    std::string shaderErrorFile;
    std::optional<std::pair<std::string, int>> shaderScrollTo;
    std::optional<bool> openShader;
    bool shaderOverView = false;  // S: the Shader view large over the 3D view (drawShaderOverView)
    bool scrollToProbe = false;   // a new probe: the panel scrolls to its Probe section once
    std::string scrollToPlot;     // a slide's "plot" (kPanelPlots): the panel scrolls to that plot once
};

// What the panel shows besides the scene.
struct PanelStatus {
    std::string message;  // last action's result or error
    bool isError = false;
    std::string lastScreenshot;  // path of the last 3D-view screenshot
    std::string glRenderer;
    std::size_t frameTriangles = 0;   // drawn per frame, all panes
    std::size_t objectTriangles = 0;  // of the selected object's mesh
    std::string progress;             // progressive area-light sampling: "pass k of n"; empty when off
    // --playlist: every preset's title (empty: no playlist), which one is shown, and whether the list
    // should scroll to it (once, after a step).
    std::vector<std::string> presetTitles;
    int currentPreset = 0;
    bool scrollToPreset = false;
    double frameMs = 0.0;      // the mean own time (no waiting for input) of the last second's frames; 0: none
    bool idle = false;         // nothing more is drawn after this frame until an event (render on demand)
    float movingScale = 1.0f;  // a moving frame drawn smaller (software GL): its share of the view per axis
    float uiScale = 1.0f;      // --ui-scale / Ctrl+= / Ctrl+-, shown in the Overlays section
    int msaa = 1;              // anti-aliasing samples of the view (1: off)
    bool trueTypeFont = true;
    std::vector<std::string> modelCameras;  // the first glTF model's cameras (GltfInfo::cameras), by name
    // The Shader section: each GLSL file's text as the programs were (re)built from it, by file name,
    // and the last failed reload's message (empty after a good one).
    std::map<std::string, std::string> shaderSources;
    std::string shaderError;
    std::string animation;  // --animate: "1.25 s of 4.00 s"; empty without animations
    std::string readout;    // the large readout over the view this frame ("k_e = 37.2")
    bool playing = false;
    bool recording = false;     // Ctrl+R: the view is being recorded
    std::string lastRecording;  // path of the last saved recording
};

// Buttons pressed this frame.
struct PanelRequests {
    bool save = false, load = false, screenshot = false;
    bool resetCamera = false, frameModel = false, reloadShaders = false, quit = false;
    bool clearProbe = false;
    int gotoPreset = -1;       // a preset clicked in the list, or the previous / next button
    bool resetPreset = false;  // reload the current preset from its file
    float uiScale = 0.0f;      // the UI-scale slider moved: the new scale (0: unchanged)
    int msaa = 0;              // anti-aliasing chosen: samples (1: off; 0: unchanged)
    bool toggleFullscreen = false;
    bool togglePlay = false;       // the animation's play / pause button
    bool toggleRecording = false;  // the record / stop button (Ctrl+R)
    int modelCamera = -2;      // a camera picked: the model's camera N, or -1 for shadelab's framing (-2: unchanged)
    bool sceneEdited = false;  // a widget changed the scene (or the panel's own settings) this frame
};

// A rectangle in ImGui's coordinates (window screen units, origin top-left).
struct UiRect {
    float x = 0, y = 0, width = 0, height = 0;
};

// `probe`: this frame's pixel probe, listed in a "Probe" section; null when none is set.
PanelRequests drawPanel(Scene& scene, ViewSettings& settings, const PanelStatus& status, const UiRect& area,
                        const ProbeResult* probe = nullptr);

}  // namespace shadelab
