#pragma once
// The command line: `shadelab [SCENE.json | MODEL.gltf | MODEL.glb] [options]`. Parsing is GL-free so
// it is unit-tested (and fuzzed) on its own. Options override what the scene file says.
#include "core/figures/plot.hpp"
#include "core/image/image.hpp"
#include "core/scene/animation.hpp"
#include "core/scene/scene.hpp"
#include "core/scene/sweep.hpp"
#include "core/ui/view_names.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace shadelab {

// What a run does, decided once by parseOptions from the options given (main.cpp acts on it).
// In order of precedence: the run is the first of those the options given ask for (options/option_table.hpp,
// OptionRules::mode).
enum class RunMode {
    Help,            // --help: print usage()
    Version,         // --version
    TestSuite,       // --test DIR: every DIR/*.json against its reference (run/test_suite.hpp)
    PlaylistImages,  // --playlist DIR --output OUT/: one PNG per preset
    PlaylistViewer,  // --playlist DIR: the viewer stepping through the presets
    Info,            // --info: what was loaded
    Plot,            // --plot KIND --output FILE.png: drawn on the CPU, no GL
    SweepSheet,      // --sweep ... --output FILE.png: a contact sheet
    ProbeImage,      // --probe X,Y --output FILE.png: the frame and the pixel's terms as JSON
    Video,           // --animate SPEC --output FILE.gif|.mp4|.webm: the animation, frame by frame
    Benchmark,       // --benchmark N: frame times as JSON lines
    Image,           // --output FILE.png: one frame
    Viewer,          // anything else: the interactive viewer
};

// --reference-missing: what a reference that does not exist does.
enum class MissingReference {
    Fail,   // one line, exit status 2 (the default)
    Write,  // the render becomes the reference, exit status 0
};

struct Options {
    std::string input;                    // scene or model file; empty: the built-in default scene
    std::optional<std::string> output;    // --output FILE.png: render one frame headless (a folder with --playlist)
    std::optional<std::string> playlist;  // --playlist DIR: the lecture presets in DIR (core/scene/playlist.hpp)
    bool captions = false;                // --captions: --output PNGs get a strip with the title and caption
    bool formula = false;                 // --formula: the lecture's formula over the view (viewer: key E)
    bool intersection = false;            // --intersection: with --probe, the intersection diagram (viewer: key I)
    // --reference REF.png: the --output image compared with REF.png (run/reference.hpp); the thresholds,
    // what a missing reference does and where the amplified difference goes. Unset: the defaults
    // (core/image/image.hpp, ImageTolerance); each is refused without --reference.
    std::optional<std::string> reference;
    std::optional<MissingReference> referenceMissing;
    std::optional<int> maxDiff;             // --max-diff D (0..255)
    std::optional<float> meanDiff;          // --mean-diff M (0..255)
    std::optional<std::string> diffOutput;  // --diff-output DIFF.png
    // --test DIR: a folder of scenes, each compared with its reference (run/test_suite.hpp): where the
    // references are (default DIR), the reports, and whether the failing references are rewritten.
    // --max-diff and --mean-diff apply to every scene; the others are refused without --test.
    std::optional<std::string> testDir;
    std::optional<std::string> referencesDir;    // --references DIR2
    std::optional<std::string> junit;            // --junit FILE.xml
    std::optional<std::string> report;           // --report FILE.html
    bool update = false;                         // --update
    std::optional<std::string> artifacts;        // --artifacts DIR: each failing case's PNGs, for the CI to keep
    std::vector<std::string> filters;            // --filter GLOB (repeatable): only the cases whose name matches one
    std::optional<std::pair<int, int>> shard;    // --shard K/N: the K-th (1-based) of N parts of the cases
    bool list = false;                           // --list: print the case names, render nothing
    std::optional<std::uint64_t> maxDiffPixels;  // --max-diff-pixels P (with --reference or --test)
    std::optional<ShadingMode> shading;
    std::optional<Layout> layout;
    std::optional<ReflectionModel> reflection;
    std::optional<float> ka, kd, ks, ke;
    std::optional<int> width, height;  // --size WxH
    std::optional<MeshSpec> mesh;      // --mesh: replaces the first object's mesh
    std::vector<Light> lights;         // --light (repeatable): replace the scene's lights
    std::optional<bool> shadows;       // --shadows / --no-shadows
    bool noTextures = false;           // --no-textures: glTF models in their base colour factors alone
    std::optional<SpecularNormalization> specularNormalization;  // --specular-normalization none|energy
    std::optional<FresnelMode> fresnel;                          // --fresnel none|schlick|exact
    std::optional<OutputEncoding> outputEncoding;                // --output-encoding linear|srgb
    std::optional<float> ior;                                    // --ior X (0.2..10)
    // --color, --specular-color R,G,B: C and S of every object; --ambient, --background R,G,B: the
    // scene's A and background (linear RGB, 0..1).
    std::optional<glm::vec3> color, specularColor, ambient, background;
    std::optional<glm::vec2> anisotropy;         // --anisotropy KT,KB: every object's k_t, k_b
    std::optional<float> mirror, transmission;   // --mirror K, --transmission K: every object's k_r, k_t
    std::optional<EnvironmentSpec> environment;  // --environment room|sky|none|FILE (the image read when parsed)
    std::optional<TermView> show;                // --show all|ambient|diffuse|specular|light:N|unlit
    std::optional<ShadingMode> diffA, diffB;     // --diff A,B: the two modes of layout diff
    std::optional<float> diffFactor;             // --diff-factor X (1..1000)
    std::vector<Sweep> sweeps;                   // --sweep PARAM=V1,V2,... (at most two: columns, rows), with --output
    // --animate SPEC (repeatable) with --output FILE.gif|.mp4|.webm: a video (core/scene/animation.hpp),
    // --fps frames a second, --duration seconds (default: the longest animation's), --dither (GIF only).
    std::vector<Animation> animations;
    std::optional<int> fps;
    std::optional<double> duration;
    bool dither = false;
    std::optional<PlotKind> plot;       // --plot lobe|fresnel|lobe3d|brdf-slice: write that plot (no GL) to --output
    std::optional<float> incidenceDeg;  // --incidence DEG (0..89): the lobe plot's incoming direction
    bool fromInside = false;            // --from-inside: Fresnel plot with eta1 = ior, eta2 = 1
    // --probe X,Y: with --output, print every term of the formula at that pixel as JSON; in the viewer,
    // start with the probe set there.
    std::optional<glm::ivec2> probe;
    int benchmarkFrames = 0;    // --benchmark N
    int progressiveStride = 0;  // --progressive S (1..16): area-light samples over S*S frames (viewer, benchmark)
    // --msaa N (0, 1, 2, 4, 8): multisample anti-aliasing, samples per pixel (0 and 1: off). Unset, each
    // front end picks its own default: 1 for --output/--benchmark (golden images stay pixel-exact), 4 in the viewer.
    std::optional<int> msaa;
    std::optional<int> camera;               // --camera N: the glTF model's camera N
    std::optional<std::uint64_t> maxMemory;  // --max-memory SIZE: the memory budget (core/scene/memory_budget.hpp)
    std::string shaderDir;                   // --shader-dir DIR: GLSL files read from DIR when present
    std::string backend = "auto";            // --backend osmesa|egl|auto: the headless GL context
    bool info = false;                       // --info: print what was loaded, render nothing
    // Viewer only (not with --output/--benchmark); these make the window scriptable:
    int frames = 0;                             // --frames N: quit after N frames (0: when the window closes)
    std::optional<std::string> screenshot;      // --screenshot FILE.png: whole window, panel included, last frame
    std::optional<std::string> screenshotView;  // --screenshot-view FILE.png: the 3D view alone (as F12)
    std::optional<std::string> saveScene;       // --save-scene FILE.json: the scene as "save scene" writes it
    bool hidePanel = false;                     // --hide-panel: start with the panel hidden (as Tab)
    std::vector<Overlay> overlays;              // --overlays a,b: wireframe, vertex-normals, face-normals, lights
    std::optional<std::vector<std::string>> panelSections;  // --panel-sections a,b: open exactly these panel sections
    std::optional<int> selectLight;  // --select-light N: start with light N selected in the panel
    std::optional<float> uiScale;    // --ui-scale S (0.75..4): panel, captions, labels, HUD (x the monitor's scale)
    bool fullscreen = false;         // --fullscreen: the viewer covers the whole monitor (F11)
    bool noLabels = false;           // --no-labels: start without pane and light labels (a clean view)
    bool resetLayout = false;        // --reset-layout: forget the remembered window and panel layout
    bool verbose = false;
    bool help = false;
    bool version = false;
    RunMode mode = RunMode::Viewer;  // from all of the above (parseOptions)
};

// Reads the arguments through the option table (options/option_table.hpp), checks the options against each
// other and decides the run mode. Throws InputError "--flag: what is wrong" for unknown flags, missing
// or malformed values and options that do not go together.
Options parseOptions(const std::vector<std::string>& args);

// Loads the input named by the options (scene file, model, or the default scene) and applies every
// override. Throws InputError.
Scene sceneFromOptions(const Options& options);
// The overrides alone (--shading, --size, --ke, --light, ...), as applied to a scene file's scene and
// to every preset of a playlist. Throws InputError (e.g. --show light:N for a scene with fewer lights).
void applyOverrides(Scene& scene, const Options& options);

// The plot --plot asks for, from the scene and --incidence/--from-inside (see scenePlot).
PlotSettings plotSettings(const Options& options);

// --plot's image (the options' --plot, --size, --incidence, --from-inside; the scene's first material), drawn
// on the CPU: no GL.
Image plotImage(const Options& options, const Scene& scene);

// --help: the synopsis, every option of the table, and the viewer's keys.
std::string usage();
// The README's option table (Markdown), made from the same table: a unit test compares the two.
std::string optionsMarkdown();

}  // namespace shadelab
