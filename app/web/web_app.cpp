// The web page's program: the renderer on the page's WebGL2 canvas, driven by the page (app/web/
// index.html, panel.js) through the functions below. The page keeps the state as a command line
// (the panel's fields are named like the options, and so are the link's parameters); sl_apply()
// reads it with the same parser as `shadelab`, so a page and `shadelab ... --output` given the same
// options draw the same scene. The camera (orbit, pan, zoom, F, R) is the program's, as in the
// desktop viewer, through the viewer's GL-free scene document (viewer/scene_document.hpp).
//
// Every function returns at once; nothing blocks the browser. Strings go in as UTF-8 and come back
// as JSON, valid until the next call.
#include "core/base/error.hpp"
#include "core/base/message.hpp"
#include "core/figures/formula.hpp"
#include "core/figures/formula_image.hpp"
#include "core/figures/plot.hpp"
#include "core/figures/plot_image.hpp"
#include "core/geometry/camera.hpp"
#include "core/geometry/ray_cast.hpp"
#include "core/geometry/scene_geometry.hpp"
#include "core/probe/probe.hpp"
#include "core/scene/panel_sections.hpp"
#include "core/scene/parameters.hpp"
#include "core/scene/playlist.hpp"
#include "core/scene/scene_json.hpp"
#include "core/scene/scene_limits.hpp"
#include "core/scene/scene_names.hpp"
#include "core/ui/controls.hpp"
#include "core/ui/view_names.hpp"
#include "options/option_table.hpp"
#include "options/options.hpp"
#include "options/shorthand.hpp"
#include "render/multisample_target.hpp"
#include "render/offscreen_target.hpp"
#include "render/overlay_renderer.hpp"
#include "render/readback.hpp"
#include "render/renderer.hpp"
#include "render/shader_library.hpp"
#include "viewer/orbit.hpp"
#include "viewer/probe_arrows.hpp"
#include "viewer/scene_document.hpp"
#include "web/web_names.hpp"

#include <emscripten/emscripten.h>
#include <emscripten/html5.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace shadelab {
namespace {

using nlohmann::json;

constexpr const char* kCanvas = "#canvas";
constexpr const char* kPresetFolder = "/share/shadelab/scenes/lecture";
constexpr float kOrbitRadPerPixel = 0.008f;  // as the desktop viewer's drag

// What the page shows: the scene document, the options it came from, and the GL objects.
struct WebApp {
    EMSCRIPTEN_WEBGL_CONTEXT_HANDLE context = 0;
    std::unique_ptr<Renderer> renderer;
    std::unique_ptr<OverlayRenderer> overlays;
    MultisampleTarget msaa;
    std::unique_ptr<SceneDocument> document;
    Options options;
    std::string input;  // options.input of the scene shown, to know when it changes
    std::uint64_t uploadedGeometry = ~std::uint64_t(0);
    int canvasWidth = 640, canvasHeight = 480;  // the canvas's pixels when --size does not pin them
    bool pinned = false;                        // --size: the canvas is the scene's size, the camera the scene's
    std::optional<ProbeResult> probe;
    std::string reply;                   // the last JSON handed to the page
    Image frame;                         // the last sl_read_pixels()
    Image figure;                        // the last sl_plot()
    gl::Framebuffer formulaFramebuffer;  // the formula overlay's pixels, blitted over the frame
    gl::Texture formulaTexture;
    // The frame is drawn into a framebuffer of its own (RGBA8, like the headless context's) and then
    // copied onto the canvas: ES 3.0 resolves a multisampled frame only into the same format, and the
    // canvas's is the browser's choice.
    OffscreenTarget view;
    // Sampled area lights refine over frames, as in the desktop viewer (Renderer::renderProgressive):
    // what the sum was started for, and whether it is complete.
    std::array<std::uint64_t, 5> progressiveFrom{};
    std::uint64_t documents = 0;  // scenes loaded so far: a new one restarts the sum
    bool progressiveComplete = true;
    Renderer::ProgressiveStatus progress;
};

WebApp& app() {
    static WebApp instance;
    return instance;
}

const char* reply(const json& j) {
    app().reply = j.dump();
    return app().reply.c_str();
}

// What the web page lacks, said where a message names it: the compressed glTF extensions are decoded
// by Debian's Linux libraries, which are not compiled to WebAssembly.
std::string withWebNote(const std::string& message) {
    for (const char* extension : {"KHR_draco_mesh_compression", "EXT_meshopt_compression"})
        if (message.find(extension) != std::string::npos)
            return message + " (the web page does not decode " + extension + "; the desktop shadelab does)";
    return message;
}

const char* errorReply(const std::string& message) { return reply(json{{"error", oneLine(withWebNote(message))}}); }

// A parameter of the table (core/scene/parameters.hpp): what the page's control of it shows.
json describeParameter(const Parameter& p) {
    json entry{{"name", p.name},
               {"option", p.option},
               {"symbol", p.symbol},
               {"label", p.label},
               {"section", nameOf(kPanelSections, p.section)},
               {"range", {p.range.lo, p.range.hi}},
               {"slider", {p.slider.lo, p.slider.hi}},
               {"scale", p.scale == SliderScale::Log ? "log" : "linear"},
               {"decimals", p.decimals},
               {"components", p.components},
               {"help", parameterHelp(p)}};
    if (!std::isnan(p.defaultValue)) entry["default"] = p.defaultValue;
    if (p.parts[0]) entry["parts"] = {p.parts[0], p.parts[1]};
    if (p.field.mesh) entry["mesh"] = toString(p.field.meshType);
    return entry;
}

json describeParameters() {
    json parameters = json::array();
    for (const Parameter* p = parametersBegin(); p != parametersEnd(); ++p) parameters.push_back(describeParameter(*p));
    return parameters;
}

// The option table: each option's name, argument, help, what it sets, its panel section and, for a
// parameter's option, the parameter (its slider).
json describeOptions() {
    json options = json::array();
    for (const OptionSpec* o = optionsBegin(); o != optionsEnd(); ++o) {
        json entry{{"name", o->name},
                   {"argument", o->argument},
                   {"group", o->group == OptionGroup::Viewer ? "viewer" : "general"},
                   {"sets", o->sets},
                   {"help", optionHelp(*o)},
                   {"synopsis", optionSynopsis(*o)}};
        if (o->bounds.given) entry["range"] = {o->bounds.lo, o->bounds.hi};
        if (o->names) entry["names"] = o->names();
        if (const std::optional<PanelSection> section = optionSection(*o))
            entry["section"] = nameOf(kPanelSections, *section);
        if (const Parameter* p = parameterOfOption(o->name)) entry["parameter"] = describeParameter(*p);
        options.push_back(entry);
    }
    return options;
}

// The key table: each control's input, action and the keys that do it.
json describeControls() {
    json controls = json::array();
    for (const Control& c : kControls) {
        json keys = json::array();
        for (const KeyBinding& b : c.keys) {
            if (b.command == ViewerCommand::None) continue;
            keys.push_back({{"characters", b.characters ? b.characters : ""},
                            {"key", webKeyName(b.key)},
                            {"ctrl", b.mods == KeyMods::Ctrl},
                            {"anyMods", b.mods == KeyMods::Any},
                            {"whileTyping", b.focus == KeyFocus::UnlessTyping},
                            {"command", commandName(b.command)}});
        }
        controls.push_back({{"input", c.input}, {"action", c.action}, {"keys", keys}});
    }
    return controls;
}

// The lecture presets, in playlist order (none, with a line on stderr, where they cannot be read).
json describePresets() {
    json presets = json::array();
    try {
        for (const Preset& p : loadPlaylist(kPresetFolder))
            presets.push_back({{"path", p.path},
                               {"name", p.name},
                               {"title", lectureNotation(presetTitle(p))},
                               {"caption", lectureNotation(p.scene.caption)}});
    } catch (const std::exception& e) {
        std::fprintf(stderr, "shadelab: %s\n", oneLine(e.what()).c_str());
    }
    return presets;
}

// A range of the scene's limits as [lo, hi].
template <typename T>
json range(const Range<T>& r) {
    return json::array({r.lo, r.hi});
}

// The procedural meshes and their --mesh shorthands' parts, in the shorthand's order (the parameter
// table's mesh rows), for the page's Mesh section.
json describeMeshes() {
    json meshes = json::array();
    for (const auto& [name, type] : kMeshTypeNames) {
        if (type == MeshSpec::Type::Gltf) continue;
        json parameters = json::array();
        for (const Parameter* p = parametersBegin(); p != parametersEnd(); ++p)
            if (p->field.mesh && p->field.meshType == type) parameters.push_back(describeParameter(*p));
        meshes.push_back({{"name", name}, {"parameters", parameters}});
    }
    return meshes;
}

// The option table, the key table, the panel's sections and the lecture presets: what the page
// builds its panel, its keys and its help from.
json describe() {
    json overlays = json::array();
    for (const auto& [name, overlay] : kOverlayNames)
        overlays.push_back({{"name", name}, {"label", nameOf(kOverlayLabels, overlay)}});
    json sections = json::array();
    for (const auto& section : kPanelSections) sections.push_back(section.first);
    json plots = json::array();
    for (const auto& [name, kind] : kPlotKindNames) plots.push_back(name);
    // The --light shorthand's parts (scene_names.hpp), for the page's Lights section.
    json lightTypes = json::array(), attenuations = json::array();
    for (const auto& [name, type] : kLightTypeNames) lightTypes.push_back(name);
    for (const auto& [name, attenuation] : kAttenuationNames) attenuations.push_back(name);
    return {{"options", describeOptions()},
            {"parameters", describeParameters()},
            {"controls", describeControls()},
            {"overlays", overlays},
            {"presets", describePresets()},
            {"sections", sections},
            {"plots", plots},
            {"meshes", describeMeshes()},
            {"lights", {{"types", lightTypes}, {"attenuation", attenuations}, {"intensity", range(kIntensityRange)}}},
            {"version", SHADELAB_VERSION}};
}

// What the page shows around the canvas, from the scene as drawn.
json describeScene() {
    const WebApp& a = app();
    const Scene& s = a.document->scene();
    json panes = json::array();
    for (const Pane& p : layoutPanes(s.layout, s.shading, s.width, s.height, s.diff))
        panes.push_back({{"x", p.x},
                         {"y", p.y},
                         {"width", p.width},
                         {"height", p.height},
                         {"mode", toString(p.mode)},
                         {"difference", p.difference}});
    // What `shadelab` says on stderr as "warning: ..." (a model's texture that could not be read).
    json warnings = json::array();
    const SceneGeometry& geometry = *a.document->geometry();
    for (std::size_t i = 0; i < geometry.gltfInfo.size() && i < s.objects.size(); ++i)
        for (const std::string& w : geometry.gltfInfo[i].warnings)
            warnings.push_back(oneLine(s.objects[i].mesh.path + ": " + w));
    return {{"scene", json::parse(sceneToJson(s, "/"))},
            {"title", lectureNotation(s.title)},
            {"caption", lectureNotation(s.caption)},
            {"width", s.width},
            {"height", s.height},
            {"pinned", a.pinned},
            {"panes", panes},
            {"warnings", warnings}};
}

// Options the page cannot honour: anything that writes files or runs without the view.
void refuseWhatThePageCannotDo(const Options& o) {
    if (o.mode == RunMode::Viewer) return;
    const char* what = o.playlist          ? "--playlist: the page's own playlist is the lecture's presets (preset=N)"
                       : o.testDir         ? "--test: screenshot tests run with the shadelab program, not in a browser"
                       : o.benchmarkFrames ? "--benchmark: not in a browser"
                       : o.output          ? "--output: a web page writes no files (use the screenshot button)"
                                           : "this option is not in the web page";
    throw InputError(what);
}

void applyArguments(const std::vector<std::string>& args) {
    WebApp& a = app();
    Options o = parseOptions(args);
    refuseWhatThePageCannotDo(o);
    Scene scene = sceneFromOptions(o);
    const bool pinned = o.width.has_value();
    if (!pinned) {
        scene.width = a.canvasWidth;
        scene.height = a.canvasHeight;
    }
    if (!a.document || o.input != a.input || pinned != a.pinned || o.camera != a.options.camera) {
        // Another scene (or another of its model's cameras): built, framed as --output frames it, the
        // camera its own.
        auto geometry = std::make_shared<SceneGeometry>(buildSceneGeometry(scene));
        frameIfNeeded(scene, *geometry);
        a.document = std::make_unique<SceneDocument>(std::move(scene), std::move(geometry));
        ++a.documents;
        a.uploadedGeometry = ~std::uint64_t(0);  // a new document counts its geometry from 0 again
        if (!pinned) a.document->followView();
    } else {
        // The same scene with other values: the camera stays where the user put it.
        scene.camera = a.document->scene().camera;
        scene.modelCamera = a.document->scene().modelCamera;
        Scene previous = a.document->scene();
        a.document->sceneForWidgets() = std::move(scene);
        a.document->markEdited();
        try {
            a.document->syncGeometry();
        } catch (...) {
            a.document->sceneForWidgets() = std::move(previous);
            throw;
        }
    }
    a.options = std::move(o);
    a.input = a.options.input;
    a.pinned = pinned;
    a.probe.reset();
    if (pinned) emscripten_set_canvas_element_size(kCanvas, a.document->scene().width, a.document->scene().height);
}

// The formula over the frame, as `--formula` draws it into a PNG: the frame read back, the overlay
// drawn on the CPU (core/figures/formula_image.hpp) and the result put back.
void drawFormula(const Scene& scene, const RenderTarget& target) {
    WebApp& a = app();
    Image image = readPixels(target);
    const bool hit = a.probe && !a.probe->miss;
    const Material material = hit ? a.probe->material : scene.objects.empty() ? Material{} : scene.objects[0].material;
    FormulaInput in = formulaInput(scene, material);
    if (hit) {
        in.probed = probedTerms(*a.probe);
        in.probedAt = probedPlace(*a.probe);
    }
    std::vector<FormulaPane> panes;
    for (const Pane& p : layoutPanes(scene.layout, scene.shading, scene.width, scene.height, scene.diff))
        panes.push_back({float(p.x), float(p.y), float(p.width), float(p.height), p.mode, p.difference});
    drawFormulaOverlay(image, in, panes);
    if (!a.formulaTexture) {
        a.formulaTexture = gl::makeTexture();
        a.formulaFramebuffer = gl::makeFramebuffer();
    }
    glBindTexture(GL_TEXTURE_2D, a.formulaTexture.get());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 image.rgba.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, a.formulaFramebuffer.get());
    glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, a.formulaTexture.get(), 0);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target.framebuffer);
    // The image is top-down, GL's rows bottom-up: the blit flips it.
    glBlitFramebuffer(0, 0, image.width, image.height, 0, image.height, image.width, 0, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

RenderTarget viewTarget(int width, int height) { return app().view.ensure(width, height, 0, "the page's view"); }

// The scene into `target`: in one go, or with sampled area lights one pass of the progressive sum a
// call (all of them when `complete`), so that a drag stays fluid and a still view converges to the
// one-pass image. A pass evaluates every stride-th sample on both axes: about four samples a pass.
void drawScene(const Scene& scene, const RenderTarget& target, bool complete) {
    WebApp& a = app();
    int samples = 1;
    for (const Light& light : scene.lights)
        if (light.type == LightType::Area) samples = std::max(samples, light.samples.x * light.samples.y);
    if (samples <= 1) {
        a.progressiveComplete = true;
        a.progress = {};
        a.renderer->render(scene, target);
        return;
    }
    const std::array<std::uint64_t, 5> from = {a.documents, a.document->revision(), a.document->geometryRevision(),
                                               std::uint64_t(target.width), std::uint64_t(target.height)};
    const bool restart = from != a.progressiveFrom;
    a.progressiveFrom = from;
    const int stride = a.options.progressiveStride > 0 ? a.options.progressiveStride
                                                       : std::max(1, int(std::ceil(std::sqrt(samples / 4.0))));
    a.progress = a.renderer->renderProgressive(scene, target, stride, restart);
    while (complete && !a.progress.complete()) a.progress = a.renderer->renderProgressive(scene, target, stride, false);
    a.progressiveComplete = a.progress.complete();
}

void renderFrame(bool complete = false) {
    WebApp& a = app();
    if (!a.document || !a.renderer) return;
    SceneDocument& doc = *a.document;
    if (!a.pinned) {
        doc.setViewSize(a.canvasWidth, a.canvasHeight);
        if (doc.following()) doc.followView();
        doc.fitClipPlanes();
    }
    if (doc.geometryRevision() != a.uploadedGeometry) {
        a.renderer->setGeometry(doc.geometry());
        a.overlays->setGeometry(doc.geometry());
        a.uploadedGeometry = doc.geometryRevision();
    }
    const Scene& scene = doc.scene();
    const RenderTarget view = viewTarget(scene.width, scene.height);
    const RenderTarget target = a.msaa.begin(view, a.options.msaa.value_or(4));
    drawScene(scene, target, complete);
    OverlayOptions overlays;
    for (Overlay o : a.options.overlays) overlays.shown(o) = true;
    std::vector<OverlayArrow> arrows;
    if (a.probe)
        for (const ProbeArrow& p : probeArrows(scene, *a.probe, -1, false)) arrows.push_back(p.arrow);
    if (overlays.any() || !arrows.empty()) a.overlays->render(scene, target, overlays, arrows);
    a.msaa.resolveInto(view);
    if (a.options.formula) drawFormula(scene, view);
    blitColor(view.framebuffer, 0, 0, 0, 0, 0, view.width, view.height);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

std::vector<std::string> argumentsFrom(const char* text) {
    const json j = json::parse(text ? text : "[]");
    if (!j.is_array()) throw InputError("the page's options must be a list");
    std::vector<std::string> args;
    for (const json& item : j) {
        if (!item.is_string()) throw InputError("the page's options must be strings");
        args.push_back(item.get<std::string>());
    }
    return args;
}

// What a JSON error in sl_apply() is about: the page's list of options when it does not parse, else the
// file the list names (a glTF's loader lets nlohmann's exception through here, where the desktop
// build's tinygltf reports it with the file's name), as `shadelab FILE` would say.
std::string jsonErrorLabel(const char* argumentsJson) {
    const json j = json::parse(argumentsJson ? argumentsJson : "", nullptr, false);
    if (j.is_array() && !j.empty() && j[0].is_string()) {
        const std::string first = j[0].get<std::string>();
        if (!first.empty() && first[0] != '-') return first + ": ";
    }
    return "the page's options: ";
}

}  // namespace
}  // namespace shadelab

using namespace shadelab;

extern "C" {

// {"options": [...], "controls": [...], "presets": [...], ...}: see describe().
EMSCRIPTEN_KEEPALIVE const char* sl_describe() { return reply(describe()); }

// A command line as a JSON list of strings (["/share/.../06-exponent-32.json", "--ke", "128"]).
// {"scene": the scene as JSON, "title", "caption", "panes": [...], "warnings": [...], ...}, or {"error": "one line"}
// and nothing changes.
EMSCRIPTEN_KEEPALIVE const char* sl_apply(const char* argumentsJson) {
    try {
        applyArguments(argumentsFrom(argumentsJson));
        return reply(describeScene());
    } catch (const json::exception& e) {
        return errorReply(jsonErrorLabel(argumentsJson) + e.what());
    } catch (const ShaderError& e) {
        return errorReply(joinedLines(e.what()));
    } catch (const std::exception& e) {
        return errorReply(e.what());
    }
}

// The canvas's size in pixels (CSS size x device pixel ratio), unless --size pins it.
EMSCRIPTEN_KEEPALIVE const char* sl_resize(int width, int height) {
    WebApp& a = app();
    a.canvasWidth = std::max(width, 16);
    a.canvasHeight = std::max(height, 16);
    if (!a.pinned) emscripten_set_canvas_element_size(kCanvas, a.canvasWidth, a.canvasHeight);
    if (!a.document) return reply(json::object());
    if (!a.pinned) a.document->setViewSize(a.canvasWidth, a.canvasHeight);
    return reply(describeScene());
}

// Draws the frame: {}, or {"progress": [pass, passes]} while sampled area lights still refine (the page
// asks for another frame), or {"error": ...} (a shader that does not compile, a GL error).
EMSCRIPTEN_KEEPALIVE const char* sl_render() {
    try {
        renderFrame();
        json r = json::object();
        if (!app().progressiveComplete)  // the page asks for the next frame until the sum is complete
            r["progress"] = {app().progress.passesDone, app().progress.passCount};
        return reply(r);
    } catch (const ShaderError& e) {
        return errorReply(joinedLines(e.what()));
    } catch (const std::exception& e) {
        return errorReply(e.what());
    }
}

// The camera: a drag of (dx, dy) canvas pixels orbits or pans; a wheel of `steps` zooms; "frame" (F)
// or "reset" (R).
EMSCRIPTEN_KEEPALIVE void sl_orbit(float dx, float dy) {
    WebApp& a = app();
    if (!a.document) return;
    orbitCamera(a.document->edit().camera, -dx * kOrbitRadPerPixel, dy * kOrbitRadPerPixel);
    a.document->stopFollowing();
}
EMSCRIPTEN_KEEPALIVE void sl_pan(float dx, float dy) {
    WebApp& a = app();
    if (!a.document) return;
    panCamera(a.document->edit().camera, dx, dy, float(a.document->scene().height));
    a.document->stopFollowing();
}
EMSCRIPTEN_KEEPALIVE void sl_zoom(float steps) {
    WebApp& a = app();
    if (!a.document) return;
    zoomCamera(a.document->edit().camera, steps, a.document->minZoomDistance(), a.document->maxZoomDistance());
    a.document->stopFollowing();
}
EMSCRIPTEN_KEEPALIVE void sl_camera(const char* what) {
    WebApp& a = app();
    if (!a.document) return;
    if (std::string(what) == "frame") a.document->frameModel();
    else a.document->resetCamera();
}

// The probe at canvas pixel (x, y), top-left origin: the --probe JSON, or {"error": ...}. Shown by
// the formula overlay too until the scene changes or sl_clear_probe().
EMSCRIPTEN_KEEPALIVE const char* sl_probe(int x, int y) {
    WebApp& a = app();
    if (!a.document) return errorReply("nothing is loaded");
    try {
        const Scene& s = a.document->scene();
        checkProbePixel(s, x, y, "probe");
        const SceneRayCaster caster(s, *a.document->geometry());
        a.probe = probePixel(s, *a.document->geometry(), caster, x, y);
        return reply(json::parse(probeToJson(s, *a.probe)));
    } catch (const std::exception& e) {
        return errorReply(e.what());
    }
}
EMSCRIPTEN_KEEPALIVE void sl_clear_probe() { app().probe.reset(); }

// The lecture's plot `kind` ("lobe", "fresnel") for the scene as shown, `width` x `height` RGBA pixels
// at sl_image_data(); {"width", "height"} or {"error": ...}.
EMSCRIPTEN_KEEPALIVE const char* sl_plot(const char* kind, int width, int height) {
    WebApp& a = app();
    if (!a.document) return errorReply("nothing is loaded");
    try {
        const std::optional<PlotKind> k = valueNamed(kPlotKindNames, std::string(kind));
        if (!k) throw InputError(std::string("--plot: unknown plot \"") + kind + "\"");
        const Scene& s = a.document->scene();
        const Material material = s.objects.empty() ? Material{} : s.objects.front().material;
        a.figure = renderPlotImage(scenePlot(*k, s, material, plotSettings(a.options)), width, height);
        return reply(json{{"width", a.figure.width}, {"height", a.figure.height}});
    } catch (const std::exception& e) {
        return errorReply(e.what());
    }
}
EMSCRIPTEN_KEEPALIVE const std::uint8_t* sl_image_data() { return app().figure.rgba.data(); }

// The frame drawn now and read back: width x height top-down RGBA pixels at sl_frame_data(), as
// `shadelab --output` would write them. {"width", "height"} or {"error": ...}.
EMSCRIPTEN_KEEPALIVE const char* sl_read_pixels() {
    WebApp& a = app();
    try {
        renderFrame(true);
        if (!a.document) return errorReply("nothing is loaded");
        a.frame = readPixels(viewTarget(a.document->scene().width, a.document->scene().height));
        return reply(json{{"width", a.frame.width}, {"height", a.frame.height}});
    } catch (const std::exception& e) {
        return errorReply(e.what());
    }
}
EMSCRIPTEN_KEEPALIVE const std::uint8_t* sl_frame_data() { return app().frame.rgba.data(); }

// The GLSL file `name` ("phong.frag", "lighting.glsl") as the program compiles it (built in):
// {"name", "source"} or {"error": ...}. The page's Shader section.
EMSCRIPTEN_KEEPALIVE const char* sl_shader(const char* name) {
    try {
        return reply(json{{"name", name}, {"source", ShaderLibrary().load(name)}});
    } catch (const std::exception& e) {
        return errorReply(e.what());
    }
}

// A light or the first object's mesh as the scene's JSON gives it ({"type": "point", "position": [...], ...}),
// as the --light or --mesh option that sets it: {"option": "point:1,2,3:intensity=2"} or {"error": ...}. The
// page edits lights and meshes as JSON and keeps them in its state (and its link) as these options.
EMSCRIPTEN_KEEPALIVE const char* sl_light_option(const char* lightJson) {
    try {
        return reply(json{{"option", lightShorthand(lightFromJson(lightJson, "light"))}});
    } catch (const std::exception& e) {
        return errorReply(e.what());
    }
}
EMSCRIPTEN_KEEPALIVE const char* sl_mesh_option(const char* meshJson) {
    try {
        return reply(json{{"option", meshShorthand(meshFromJson(meshJson, "mesh"))}});
    } catch (const std::exception& e) {
        return errorReply(e.what());
    }
}

// {"renderer": GL_RENDERER, "version": GL_VERSION}
EMSCRIPTEN_KEEPALIVE const char* sl_gl_info() {
    WebApp& a = app();
    if (!a.renderer) return errorReply("no WebGL2 context");
    return reply(json{{"renderer", a.renderer->glRenderer()}, {"version", a.renderer->glVersion()}});
}

}  // extern "C"

int main() {
    WebApp& a = app();
    EmscriptenWebGLContextAttributes attributes;
    emscripten_webgl_init_context_attributes(&attributes);
    attributes.majorVersion = 2;
    attributes.minorVersion = 0;
    attributes.alpha = false;      // the scene's background is opaque
    attributes.antialias = false;  // --msaa's multisampled target does it, as on the desktop
    attributes.depth = true;
    attributes.premultipliedAlpha = false;
    attributes.preserveDrawingBuffer = true;  // the screenshot, the recorder and the tests read the canvas
    a.context = emscripten_webgl_create_context(kCanvas, &attributes);
    if (a.context <= 0) {
        std::fprintf(stderr, "shadelab: this browser offers no WebGL2 context\n");
        return 0;
    }
    emscripten_webgl_make_context_current(a.context);
    try {
        RendererOptions options;
        options.phongInputs = RendererOptions::PhongInputs::Uniform;  // the readable phong.frag, as the viewer
        a.renderer = std::make_unique<Renderer>(nullptr, ShaderLibrary(), options);
        a.overlays = std::make_unique<OverlayRenderer>(ShaderLibrary());
    } catch (const std::exception& e) {
        a.renderer.reset();
        std::fprintf(stderr, "shadelab: %s\n", oneLine(e.what()).c_str());
    }
    return 0;
}
