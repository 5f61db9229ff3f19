#include "cli/options.hpp"

#include "core/error.hpp"
#include "core/memory_budget.hpp"
#include "core/message.hpp"
#include "core/file_io.hpp"
#include "core/plot_image.hpp"
#include "core/scene_json.hpp"
#include "core/controls.hpp"
#include "core/panel_sections.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace shadelab {
namespace {

float parseFloat(const std::string& flag, const std::string& v) {
    char* end = nullptr;
    const float x = std::strtof(v.c_str(), &end);
    if (v.empty() || end != v.c_str() + v.size() || !std::isfinite(x))
        throw InputError(flag + ": \"" + quoteInput(v) + "\" is not a number");
    return x;
}

int parseInt(const std::string& flag, const std::string& v, long lo, long hi) {
    char* end = nullptr;
    const long x = std::strtol(v.c_str(), &end, 10);
    if (v.empty() || end != v.c_str() + v.size()) throw InputError(flag + ": \"" + quoteInput(v) + "\" is not an integer");
    if (x < lo || x > hi)
        throw InputError(flag + ": " + v + " is out of range (" + std::to_string(lo) + ".." + std::to_string(hi) + ")");
    return int(x);
}

template <typename E, std::size_t N>
E parseChoice(const std::string& flag, const std::string& v, const std::pair<const char*, E> (&options)[N]) {
    std::string allowed;
    for (const auto& o : options) {
        if (v == o.first) return o.second;
        allowed += std::string(allowed.empty() ? "" : ", ") + o.first;
    }
    throw InputError(flag + ": unknown value \"" + quoteInput(v) + "\" (expected one of " + allowed + ")");
}

}  // namespace

Options parseOptions(const std::vector<std::string>& args) {
    Options o;
    for (std::size_t i = 0; i < args.size(); ++i) {
        std::string arg = args[i], value;
        bool hasInlineValue = false;
        if (arg.rfind("--", 0) == 0) {
            const std::size_t eq = arg.find('=');
            if (eq != std::string::npos) {
                value = arg.substr(eq + 1);
                arg = arg.substr(0, eq);
                hasInlineValue = true;
            }
        }
        auto next = [&]() -> std::string {
            if (hasInlineValue) return value;
            if (i + 1 >= args.size()) throw InputError(arg + ": needs a value");
            return args[++i];
        };
        auto noValue = [&]() {
            if (hasInlineValue) throw InputError(arg + ": takes no value");
        };
        static const std::pair<const char*, ShadingMode> kShading[] = {
            {"flat", ShadingMode::Flat}, {"gouraud", ShadingMode::Gouraud}, {"phong", ShadingMode::Phong}};
        static const std::pair<const char*, Layout> kLayout[] = {
            {"single", Layout::Single}, {"compare", Layout::Compare}, {"diff", Layout::Diff}};
        static const std::pair<const char*, SpecularNormalization> kNorm[] = {
            {"none", SpecularNormalization::None}, {"energy", SpecularNormalization::Energy}};
        static const std::pair<const char*, FresnelMode> kFresnel[] = {
            {"none", FresnelMode::None}, {"schlick", FresnelMode::Schlick}, {"exact", FresnelMode::Exact}};
        static const std::pair<const char*, ReflectionModel> kRefl[] = {{"phong", ReflectionModel::Phong},
                                                                         {"blinn-phong", ReflectionModel::BlinnPhong}};
        if (arg == "--help" || arg == "-h") noValue(), o.help = true;
        else if (arg == "--version") noValue(), o.version = true;
        else if (arg == "--verbose" || arg == "-v") noValue(), o.verbose = true;
        else if (arg == "--info") noValue(), o.info = true;
        else if (arg == "--output" || arg == "-o") o.output = next();
        else if (arg == "--playlist") {
            o.playlist = next();
            if (o.playlist->empty()) throw InputError(arg + ": empty folder name");
        }
        else if (arg == "--captions") noValue(), o.captions = true;
        else if (arg == "--shading") o.shading = parseChoice(arg, next(), kShading);
        else if (arg == "--layout") o.layout = parseChoice(arg, next(), kLayout);
        else if (arg == "--reflection") o.reflection = parseChoice(arg, next(), kRefl);
        else if (arg == "--ka") o.ka = parseFloat(arg, next());
        else if (arg == "--kd") o.kd = parseFloat(arg, next());
        else if (arg == "--ks") o.ks = parseFloat(arg, next());
        else if (arg == "--ke") o.ke = parseFloat(arg, next());
        else if (arg == "--mesh") o.mesh = parseMeshShorthand(next(), arg);
        else if (arg == "--light") {
            o.lights.push_back(parseLightShorthand(next(), arg));
            if (o.lights.size() > std::size_t(kMaxLights))
                throw InputError(arg + ": at most " + std::to_string(kMaxLights) + " lights");
        }
        else if (arg == "--specular-normalization") o.specularNormalization = parseChoice(arg, next(), kNorm);
        else if (arg == "--fresnel") o.fresnel = parseChoice(arg, next(), kFresnel);
        else if (arg == "--ior") {
            const std::string v = next();
            const float x = parseFloat(arg, v);
            if (x < kIorRange.lo || x > kIorRange.hi) throw InputError(arg + ": must be between 1 and 10 (got " + v + ")");
            o.ior = x;
        }
        else if (arg == "--show") o.show = parseTermView(next(), arg);
        else if (arg == "--diff") {
            const std::string v = next();
            const std::size_t comma = v.find(',');
            if (comma == std::string::npos)
                throw InputError(arg + ": expected two shading modes A,B, e.g. gouraud,phong (got \"" + quoteInput(v) + "\")");
            o.diffA = parseChoice(arg, v.substr(0, comma), kShading);
            o.diffB = parseChoice(arg, v.substr(comma + 1), kShading);
        }
        else if (arg == "--diff-factor") {
            const std::string v = next();
            const float f = parseFloat(arg, v);
            if (f < 1.0f || f > kDiffFactorRange.hi) throw InputError(arg + ": must be between 1 and 1000 (got " + v + ")");
            o.diffFactor = f;
        }
        else if (arg == "--sweep") {
            o.sweeps.push_back(parseSweep(next(), arg));
            if (o.sweeps.size() > std::size_t(kMaxSweeps))
                throw InputError(arg + ": at most two sweeps (columns and rows)");
            if (o.sweeps.size() == 2 && o.sweeps[0].parameter == o.sweeps[1].parameter)
                throw InputError(arg + ": " + o.sweeps[1].parameter + " is swept twice");
        }
        else if (arg == "--plot") {
            static const std::pair<const char*, PlotKind> kPlots[] = {{"lobe", PlotKind::Lobe}, {"fresnel", PlotKind::Fresnel}};
            o.plot = parseChoice(arg, next(), kPlots);
        }
        else if (arg == "--incidence") {
            const std::string v = next();
            const float deg = parseFloat(arg, v);
            if (deg < 0.0f || deg > kIncidenceDegRange.hi)
                throw InputError(arg + ": must be between 0 and 89 degrees (got " + v + ")");
            o.incidenceDeg = deg;
        }
        else if (arg == "--from-inside") noValue(), o.fromInside = true;
        else if (arg == "--panel-sections") {
            std::vector<std::string> sections;
            std::stringstream list(next());
            for (std::string name; std::getline(list, name, ',');) {
                if (std::find_if(std::begin(kPanelSections), std::end(kPanelSections),
                                 [&](const char* s) { return name == s; }) == std::end(kPanelSections)) {
                    std::string allowed;
                    for (const char* s : kPanelSections) allowed += std::string(allowed.empty() ? "" : ", ") + s;
                    throw InputError(arg + ": unknown section \"" + quoteInput(name) + "\" (expected some of " + allowed + ")");
                }
                sections.push_back(name);
            }
            o.panelSections = sections;
        }
        else if (arg == "--shadows") noValue(), o.shadows = true;
        else if (arg == "--no-shadows") noValue(), o.shadows = false;
        else if (arg == "--no-textures") noValue(), o.noTextures = true;
        else if (arg == "--shader-dir") o.shaderDir = next();
        else if (arg == "--backend") {
            o.backend = next();
            if (o.backend != "auto" && o.backend != "osmesa" && o.backend != "egl")
                throw InputError(arg + ": unknown value \"" + quoteInput(o.backend) + "\" (expected one of auto, osmesa, egl)");
        }
        else if (arg == "--probe") {
            const std::string v = next();
            const std::size_t comma = v.find(',');
            if (comma == std::string::npos)
                throw InputError(arg + ": expected the pixel as X,Y, e.g. 640,360 (got \"" + quoteInput(v) + "\")");
            const int x = parseInt(arg, v.substr(0, comma), 0, kImageSideRange.hi - 1);  // x first: it is named first
            o.probe = glm::ivec2(x, parseInt(arg, v.substr(comma + 1), 0, kImageSideRange.hi - 1));
        }
        else if (arg == "--select-light") o.selectLight = parseInt(arg, next(), 0, kMaxLights - 1);
        else if (arg == "--benchmark") o.benchmarkFrames = parseInt(arg, next(), 1, 1000000);
        else if (arg == "--frames") o.frames = parseInt(arg, next(), 1, 100000000);
        else if (arg == "--progressive") o.progressiveStride = parseInt(arg, next(), 1, kAreaSamplesPerSideRange.hi);
        else if (arg == "--msaa") {
            static const std::pair<const char*, int> kSamples[] = {{"0", 0}, {"1", 1}, {"2", 2}, {"4", 4}, {"8", 8}};
            o.msaa = parseChoice(arg, next(), kSamples);
        }
        else if (arg == "--camera") o.camera = parseInt(arg, next(), 0, 100000);
        else if (arg == "--max-memory") {
            const std::string v = next();
            const auto bytes = parseByteSize(v);
            if (!bytes) throw InputError(arg + ": \"" + quoteInput(v) + "\" is not a size (e.g. 2G, 512M)");
            if (*bytes < (std::uint64_t(64) << 20)) throw InputError(arg + ": at least 64M");
            o.maxMemory = *bytes;
        }
        else if (arg == "--screenshot") o.screenshot = next();
        else if (arg == "--screenshot-view") o.screenshotView = next();
        else if (arg == "--save-scene") o.saveScene = next();
        else if (arg == "--hide-panel") noValue(), o.hidePanel = true;
        else if (arg == "--ui-scale") {
            const std::string v = next();
            const float scale = parseFloat(arg, v);
            if (!(scale >= kUiScaleRange.lo && scale <= kUiScaleRange.hi))
                throw InputError(arg + ": must be between 0.75 and 4 (got " + v + ")");
            o.uiScale = scale;
        }
        else if (arg == "--fullscreen") noValue(), o.fullscreen = true;
        else if (arg == "--no-labels") noValue(), o.noLabels = true;
        else if (arg == "--reset-layout") noValue(), o.resetLayout = true;
        else if (arg == "--overlays") {
            static const std::pair<const char*, int> kOverlays[] = {
                {"wireframe", 0}, {"vertex-normals", 1}, {"face-normals", 2}, {"lights", 3}};
            std::stringstream list(next());
            for (std::string name; std::getline(list, name, ',');) {
                parseChoice(arg, name, kOverlays);
                o.overlays.push_back(name);
            }
        }
        else if (arg == "--size") {
            const std::string v = next();
            const std::size_t x = v.find('x');
            if (x == std::string::npos) throw InputError(arg + ": expected WIDTHxHEIGHT, e.g. 1280x720 (got \"" + quoteInput(v) + "\")");
            const int w = parseInt(arg, v.substr(0, x), -1000000000, 1000000000);
            const int h = parseInt(arg, v.substr(x + 1), -1000000000, 1000000000);
            checkImageSize(w, h, arg);
            o.width = w;
            o.height = h;
        } else if (arg.size() > 1 && arg[0] == '-') {
            throw InputError(arg + ": unknown option (see shadelab --help)");
        } else {
            if (!o.input.empty()) throw InputError(arg + ": only one scene or model file can be given");
            o.input = arg;
        }
    }
    if (o.playlist) {
        if (!o.input.empty())
            throw InputError("--playlist: shows the scene files of a folder; give no scene file (" + o.input + ") with it");
        if (!o.sweeps.empty()) throw InputError("--sweep: not with --playlist (sweep one preset file instead)");
        if (o.benchmarkFrames) throw InputError("--benchmark: not with --playlist (benchmark one preset file instead)");
        if (o.info) throw InputError("--info: not with --playlist");
        if (o.plot) throw InputError("--plot: not with --playlist (a plot is of one scene)");
        if (o.probe) throw InputError("--probe: not with --playlist (probe one preset file instead)");
    }
    if (o.captions && (!o.output || !o.sweeps.empty()))
        throw InputError("--captions: adds a title strip to --output images (not to sweep sheets); give --output");
    if (o.output && !o.playlist && !hasExtension(*o.output, ".png"))
        throw InputError("--output: " + *o.output + ": only .png output is supported");
    if (o.screenshot && !hasExtension(*o.screenshot, ".png"))
        throw InputError("--screenshot: " + *o.screenshot + ": only .png is supported");
    if (o.screenshotView && !hasExtension(*o.screenshotView, ".png"))
        throw InputError("--screenshot-view: " + *o.screenshotView + ": only .png is supported");
    if (o.saveScene && !hasExtension(*o.saveScene, ".json"))
        throw InputError("--save-scene: " + *o.saveScene + ": scene files end in .json");
    if (!o.sweeps.empty() && (!o.output || o.benchmarkFrames))
        throw InputError("--sweep: renders a sheet to a PNG: give --output FILE.png (and no --benchmark)");
    if (o.probe && (!o.sweeps.empty() || o.benchmarkFrames || o.info))
        throw InputError(std::string("--probe: probes one pixel of one frame (with --output, or in the viewer); not with ") +
                         (!o.sweeps.empty() ? "--sweep" : o.benchmarkFrames ? "--benchmark" : "--info"));
    if (o.progressiveStride && o.output)
        throw InputError("--progressive: --output always renders every area-light sample; it is for the viewer and --benchmark");
    // The viewer's scripting flags mean nothing to a headless run; say so rather than ignore them.
    const bool viewerFlags = o.frames || o.screenshot || o.screenshotView || o.saveScene || o.hidePanel ||
                             !o.overlays.empty() || o.panelSections || o.selectLight || o.uiScale || o.fullscreen ||
                             o.noLabels || o.resetLayout;
    if (viewerFlags && (o.output || o.benchmarkFrames))
        throw InputError(std::string(o.output ? "--output" : "--benchmark") +
                         ": --frames, --screenshot, --screenshot-view, --save-scene, --hide-panel, --overlays, "
                         "--panel-sections, --select-light, --ui-scale, --fullscreen, --no-labels and --reset-layout are for the "
                         "viewer, which --output/--benchmark do not open");
    if (o.plot) {
        if (!o.output) throw InputError("--plot: writes a PNG: give --output FILE.png");
        if (!o.sweeps.empty() || o.benchmarkFrames)
            throw InputError("--plot: draws one plot: not with --sweep or --benchmark");
        if (o.width && (*o.width < kPlotMinWidth || *o.height < kPlotMinHeight || *o.width > kPlotMaxSide ||
                        *o.height > kPlotMaxSide))
            throw InputError("--size: a plot is " + std::to_string(kPlotMinWidth) + "x" + std::to_string(kPlotMinHeight) +
                             " to " + std::to_string(kPlotMaxSide) + "x" + std::to_string(kPlotMaxSide) + " pixels");
    } else if ((o.incidenceDeg || o.fromInside) && (o.output || o.benchmarkFrames)) {
        // They set up the plots (--plot, or the viewer's Plots section); a render has no use for them.
        throw InputError(std::string(o.incidenceDeg ? "--incidence" : "--from-inside") +
                         ": sets up the plots: use it with --plot, or in the viewer");
    }
    return o;
}

Scene sceneFromOptions(const Options& o) {
    Scene s;
    if (o.input.empty()) s = defaultScene();
    else if (hasModelExtension(o.input)) s = sceneForModel(o.input);
    else s = loadSceneFile(o.input);
    applyOverrides(s, o);
    return s;
}

void applyOverrides(Scene& s, const Options& o) {
    if (o.shading) s.shading = *o.shading;
    if (o.layout) s.layout = *o.layout;
    if (o.camera) s.modelCamera = *o.camera;
    if (o.reflection) s.reflection = *o.reflection;
    for (SceneObject& obj : s.objects) {
        if (o.ka) obj.material.ka = *o.ka;
        if (o.kd) obj.material.kd = *o.kd;
        if (o.ks) obj.material.ks = *o.ks;
        if (o.ke) obj.material.ke = *o.ke;
        checkCoefficients(obj.material, "--");
    }
    if (o.width) s.width = *o.width, s.height = *o.height;
    if (!o.lights.empty()) {
        s.lights = o.lights;
        s.lightsGiven = true;
    }
    if (o.shadows) s.shadows.enabled = *o.shadows;
    if (o.specularNormalization) s.specularNormalization = *o.specularNormalization;
    if (o.fresnel) s.fresnel = *o.fresnel;
    if (o.ior) s.ior = *o.ior;
    if (o.noTextures) s.textures = false;
    if (o.diffA) s.diff.a = *o.diffA, s.diff.b = *o.diffB;
    if (o.diffFactor) s.diff.factor = *o.diffFactor;
    if (o.show) s.show = *o.show;
    if (s.show.term == ShowTerm::Light && s.show.light >= int(s.lights.size()))
        throw InputError(std::string(o.show ? "--show" : "--light") + ": light " + std::to_string(s.show.light) +
                         " does not exist (the scene has " + std::to_string(s.lights.size()) + " light(s))");
    if (o.mesh) {
        if (s.objects.empty()) s.objects.emplace_back();
        s.objects.front().mesh = *o.mesh;
    }
    if (o.selectLight && *o.selectLight >= int(s.lights.size()))
        throw InputError("--select-light: light " + std::to_string(*o.selectLight) + " does not exist (the scene has " +
                         std::to_string(s.lights.size()) + " light(s))");
}

PlotSettings plotSettings(const Options& o) {
    PlotSettings s;
    if (o.incidenceDeg) s.incidenceDeg = *o.incidenceDeg;
    s.fromInside = o.fromInside;
    return s;
}

std::string usage() {
    return R"(usage: shadelab [SCENE.json | MODEL.gltf | MODEL.glb] [options]
       shadelab --playlist DIR [options]

Shows flat, Gouraud and Phong shading side by side. With no file, the built-in default scene.
Without --output (or --benchmark) it opens the interactive viewer.

  -o, --output FILE.png   render one frame offscreen (OSMesa, no display needed) and write it
  --playlist DIR          the lecture presets: every DIR/*.json in file-name order (e.g.
                          assets/scenes/lecture). In the viewer Page Down / Page Up step through them;
                          with --output OUT/ one PNG per preset, OUT/NAME.png (OUT is created when
                          it ends in / and is missing). Every other option applies to each preset.
  --captions              with --output: a strip under each image with the scene's title (a preset's
                          file name when it has none) and caption
  --shading MODE          flat | gouraud | phong
  --layout LAYOUT         single | compare (three panes: flat | gouraud | phong) | diff (A | B | |A-B| x factor)
  --diff A,B              the two shading modes of layout diff (default gouraud,phong)
  --diff-factor X         layout diff: |A - B| is multiplied by X (1..1000, default 4)
  --reflection MODEL      phong | blinn-phong
  --specular-normalization none | energy   energy-normalised lobes ((k_e+2)/2pi, (k_e+8)/8pi; diffuse 1/pi)
  --fresnel MODE          none | schlick | exact: the specular term weighted by the Fresnel reflectance at V.H
  --ior X                 index of refraction eta2/eta1 for --fresnel (1..10, default 1.5)
  --show TERM             all | ambient | diffuse | specular | light:N | unlit: draw one term of the formula
  --ka X --kd X --ks X    ambient, diffuse, specular weights (>= 0) of every object
  --ke X                  specular exponent (1..10000) of every object
  --size WxH              image size in pixels, e.g. 1280x720
  --mesh SPEC             replace the first object's mesh: uvsphere[:slices[:stacks]], icosphere[:n],
                          torus[:major[:minor]], cube, plane[:n], or a .gltf/.glb file
  --light SPEC            replace the scene's lights (repeat for more, up to 16): TYPE:X,Y,Z[:KEY=VALUE]...
                          point:X,Y,Z (position), directional:X,Y,Z (travel direction), area:X,Y,Z (centre),
                          spot:X,Y,Z (position); keys color=R,G,B intensity=I attenuation=none|inverse-square
                          range=R (point, spot, area), normal=X,Y,Z size=W,H samples=NXxNY two-sided (area),
                          direction=X,Y,Z outer=DEG inner=DEG (spot: axis and cone half-angles), e.g.
                          --light area:0,3,0:size=1.6,1.6:samples=8x8:intensity=9:attenuation=inverse-square
                          --light spot:0,4,2:direction=0,-2,-1:outer=25:inner=15
  --shadows, --no-shadows shadows (occlusion toward every light) on or off
  --no-textures           glTF models without their base colour textures and vertex colours
                          (C is each material's base colour factor alone)
  --sweep PARAM=V1,V2,... with --output: a contact sheet, one labelled tile (of --size) per value;
                          a second --sweep makes a grid (rows). PARAM: ke, ks, kd, ka, intensity (every
                          light), tessellation (first mesh), ior, shading, reflection,
                          specular_normalization, fresnel. E.g. --sweep ke=1,8,32,128,512 --sweep shading=gouraud,phong
  --plot lobe|fresnel     with --output: the lecture's plot for the scene's parameters, drawn on the CPU
                          (800x600 unless --size): lobe = Phong and Blinn-Phong spec in the plane of
                          incidence for k_e; fresnel = R_par, R_perp, their average and Schlick over the
                          angle of incidence, from air (eta_1 = 1) into eta_2 = --ior
  --incidence DEG         the lobe plot's angle between the incoming light I and N (0..89, default 45)
  --from-inside           the Fresnel plot from inside the material (eta_1 = --ior, eta_2 = 1): total
                          internal reflection past the critical angle
  --probe X,Y             with --output: also print, as JSON, every term of the formula at pixel X,Y
                          (top-left origin) the way that pixel's shading mode evaluates it; without
                          --output: open the viewer with the probe set at X,Y of the 3D view
  --benchmark N           render N frames offscreen per shading mode; print one JSON line per mode
  --progressive S         area lights in the viewer (and --benchmark): a frame evaluates every S-th
                          sample per axis, the view refines over S*S frames (1..16; default: the
                          viewer picks S from its frame time; --benchmark times one such frame)
  --backend NAME          headless OpenGL for --output/--benchmark: osmesa, egl, or auto (OSMesa,
                          else EGL)
  --msaa N                multisample anti-aliasing, N samples per pixel: 0, 1, 2, 4 or 8 (0 and 1:
                          off; the driver may round up, and caps it at its maximum). --output and
                          --benchmark default to 1, pixel-exact with the golden images; the
                          viewer to 4 (a software renderer: the still view only), --frames runs to 1
  --camera N              look through the glTF model's camera N (--info lists them; 0 = the first the
                          scene reaches) instead of shadelab's framing
  --max-memory SIZE       refuse a --output, --sweep or --playlist that needs more memory than SIZE
                          (K, M, G: e.g. 2G; default half of the machine's memory)
  --shader-dir DIR        read GLSL files from DIR when present (default: the checkout's shaders/
                          when it exists, else the built-in copies)
  --info                  print what was loaded (meshes, triangles, bounds, normals) and exit

Viewer (the window; its keys and mouse are listed below, in its panel under "Keys" and by F1):
  --ui-scale S            panel, captions, pane labels, HUD and probe labels S times larger (0.75..4,
                          on top of the monitor's content scale); Ctrl+= / Ctrl+- / Ctrl+0 in the viewer
  --fullscreen            cover the whole monitor (F11 toggles)
  --no-labels             start without the pane labels and light labels (a clean view for slides)
  --reset-layout          forget the remembered window size and position, fullscreen, panel sections,
                          UI scale and anti-aliasing ($XDG_CONFIG_HOME/shadelab/viewer.json)
  --frames N              quit after N frames
  --screenshot FILE.png   on the last frame (N-th, or when you quit), save the whole window, panel included
  --screenshot-view FILE.png  on the last frame, save the 3D view alone (what F12 saves)
  --save-scene FILE.json  on the last frame, save the scene as the panel's "save scene" does
  --hide-panel            start with the panel hidden (Tab shows it)
  --overlays LIST         start with overlays on: wireframe,vertex-normals,face-normals,lights
  --panel-sections LIST   start with exactly these panel sections open, e.g. plots or shading,material
                          (shading, material, plots, mesh, lights, shadows, overlays, camera, background,
                          file, keys); --incidence and --from-inside set the Plots section's controls
  --select-light N        start with light N selected in the panel (an area light shows its samples)
  -v, --verbose           say what was loaded and written
  -h, --help              this text
  --version               print the version

Bad input (a file, a field, a flag) prints one line and exits with status 2.

Viewer keys and mouse:
)" + controlsText();
}

}  // namespace shadelab
