#include "cli/options.hpp"

#include "cli/option_table.hpp"
#include "core/ui/controls.hpp"
#include "core/base/error.hpp"
#include "core/base/file_io.hpp"
#include "core/figures/plot_image.hpp"
#include "core/scene/scene_json.hpp"

#include <algorithm>
#include <sstream>

namespace shadelab {
namespace {

bool isVideoPath(const std::string& path) {
    return hasExtension(path, ".gif") || hasExtension(path, ".mp4") || hasExtension(path, ".webm");
}

bool anyGiven(const std::vector<const OptionSpec*>& given, OptionGroup group) {
    return std::any_of(given.begin(), given.end(), [group](const OptionSpec* s) { return s->group == group; });
}

// "--a, --b and --c": the options of a group, as a refusal lists them.
std::string groupNames(OptionGroup group) {
    std::vector<std::string> names;
    for (const OptionSpec* s = optionsBegin(); s != optionsEnd(); ++s)
        if (s->group == group) names.push_back(s->name);
    std::string list;
    for (std::size_t i = 0; i < names.size(); ++i)
        list += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
    return list;
}

// The first option given that asks for a run other than one image (--reference and --animate refuse them;
// --animate plays on a playlist's presets in the viewer: `playlist` false leaves it out).
const char* otherRun(const Options& o, bool playlist = true) {
    return o.playlist && playlist ? "--playlist"
           : !o.sweeps.empty()   ? "--sweep"
           : o.probe             ? "--probe"
           : o.benchmarkFrames   ? "--benchmark"
           : o.info              ? "--info"
                                 : nullptr;
}

void checkPlaylist(const Options& o) {
    if (!o.playlist) return;
    if (!o.input.empty())
        throw InputError("--playlist: shows the scene files of a folder; give no scene file (" + o.input + ") with it");
    if (!o.sweeps.empty()) throw InputError("--sweep: not with --playlist (sweep one preset file instead)");
    if (o.benchmarkFrames) throw InputError("--benchmark: not with --playlist (benchmark one preset file instead)");
    if (o.info) throw InputError("--info: not with --playlist");
    if (o.plot) throw InputError("--plot: not with --playlist (a plot is of one scene)");
    if (o.probe) throw InputError("--probe: not with --playlist (probe one preset file instead)");
}

void checkOutputs(const Options& o) {
    if (o.captions && (!o.output || !o.sweeps.empty()))
        throw InputError("--captions: adds a title strip to --output images (not to sweep sheets); give --output");
    if (o.formula && (!o.sweeps.empty() || o.benchmarkFrames || o.plot || o.info))
        throw InputError(std::string("--formula: draws over a frame (the viewer's or --output's); not with ") +
                         (!o.sweeps.empty() ? "--sweep" : o.benchmarkFrames ? "--benchmark" : o.plot ? "--plot" : "--info"));
    if (o.intersection && !o.probe)
        throw InputError("--intersection: draws the diagram at a probed point: give --probe X,Y");
    if (o.output && !o.playlist && !hasExtension(*o.output, ".png") && !isVideoPath(*o.output))
        throw InputError("--output: " + *o.output + ": only .png output is supported (and .gif, .mp4, .webm with --animate)");
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
}

// --animate renders a video: --output names it, and the video's settings need --animate.
void checkAnimation(const Options& o) {
    const bool video = o.output && !o.playlist && isVideoPath(*o.output);
    if (o.animations.empty()) {
        if (video) throw InputError("--output: " + *o.output + ": a video needs --animate SPEC (e.g. --animate light-orbit)");
        const char* flag = o.fps ? "--fps" : o.duration ? "--duration" : o.dither ? "--dither" : nullptr;
        if (flag) throw InputError(std::string(flag) + ": sets up the --animate video: give --animate SPEC and --output FILE.gif|.mp4|.webm");
        return;
    }
    // With --playlist the viewer plays the animation on every preset; a video is of one scene.
    if (o.playlist && o.output)
        throw InputError("--animate: with --playlist the viewer plays it on every preset; a video (--output) is of one "
                         "scene: give that preset's file instead of --playlist");
    const char* other = otherRun(o, false) ? otherRun(o, false)
                        : o.plot        ? "--plot"
                        : o.reference   ? "--reference"
                        : o.captions    ? "--captions"
                                        : nullptr;
    if (other) throw InputError(std::string("--animate: renders a video of one scene; not with ") + other);
    if (!o.output) {  // the viewer plays it; the video's settings mean nothing there
        const char* flag = o.fps ? "--fps" : o.duration ? "--duration" : o.dither ? "--dither" : nullptr;
        if (flag) throw InputError(std::string(flag) + ": sets up the video: give --output FILE.gif, .mp4 or .webm");
        for (const Animation& a : o.animations)
            if (a.parameter == "tessellation")
                throw InputError("--animate: " + a.text + ": a tessellation ramp is for videos (--output); the "
                                 "viewer would rebuild the mesh every frame");
        return;
    }
    if (!video) throw InputError("--animate: writes a video: give --output FILE.gif, .mp4 or .webm (not " + *o.output + ")");
    if (o.dither && !hasExtension(*o.output, ".gif"))
        throw InputError("--dither: dithers a GIF's palette; " + *o.output + " is not a .gif");
}

void checkViewerAndPlot(const Options& o, const std::vector<const OptionSpec*>& given) {
    // The viewer's scripting flags mean nothing to a headless run; say so rather than ignore them.
    if (anyGiven(given, OptionGroup::Viewer) && (o.output || o.benchmarkFrames))
        throw InputError(std::string(o.output ? "--output" : "--benchmark") + ": " + groupNames(OptionGroup::Viewer) +
                         " are for the viewer, which --output/--benchmark do not open");
    if (o.plot) {
        if (!o.output) throw InputError("--plot: writes a PNG: give --output FILE.png");
        if (!o.sweeps.empty() || o.benchmarkFrames)
            throw InputError("--plot: draws one plot: not with --sweep or --benchmark");
        if (o.width && (*o.width < kPlotMinWidth || *o.height < kPlotMinHeight || *o.width > kPlotMaxSide ||
                        *o.height > kPlotMaxSide))
            throw InputError("--size: a plot is " + plotSizesText() + " pixels");
    } else if ((o.incidenceDeg || o.fromInside) && (o.output || o.benchmarkFrames)) {
        // They set up the plots (--plot, or the viewer's Plots section); a render has no use for them.
        throw InputError(std::string(o.incidenceDeg ? "--incidence" : "--from-inside") +
                         ": sets up the plots: use it with --plot, or in the viewer");
    }
}

// --test DIR runs a folder of its own: the one-image modes and the viewer have no place in it, and its
// settings need it.
void checkTestSuite(const Options& o, const std::vector<const OptionSpec*>& given) {
    if (!o.testDir) {
        const char* flag = o.referencesDir ? "--references" : o.junit ? "--junit" : o.report ? "--report"
                           : o.update             ? "--update"
                           : o.artifacts          ? "--artifacts"
                           : o.list               ? "--list"
                           : !o.filters.empty()   ? "--filter"
                           : o.shard              ? "--shard"
                                                  : nullptr;
        if (flag) throw InputError(std::string(flag) + ": belongs to a folder of screenshot tests: give --test DIR");
        return;
    }
    if (!o.input.empty())
        throw InputError("--test: renders the scene files of its folder; give no scene file (" + o.input + ") with it");
    const char* other = o.output              ? "--output"
                        : o.playlist          ? "--playlist"
                        : o.reference         ? "--reference"
                        : o.referenceMissing  ? "--reference-missing (--update writes missing references)"
                        : o.diffOutput        ? "--diff-output (--report shows the differences)"
                        : !o.sweeps.empty()   ? "--sweep"
                        : o.probe             ? "--probe"
                        : o.benchmarkFrames   ? "--benchmark"
                        : o.info              ? "--info"
                        : o.plot              ? "--plot"
                        : o.captions          ? "--captions"
                        : !o.animations.empty() ? "--animate"
                        : anyGiven(given, OptionGroup::Viewer) ? "the viewer's options"
                                                               : nullptr;
    if (other) throw InputError(std::string("--test: compares its folder's scenes with their references; not with ") + other);
    if (o.junit && !hasExtension(*o.junit, ".xml"))
        throw InputError("--junit: " + *o.junit + ": JUnit reports end in .xml");
    if (o.report && !hasExtension(*o.report, ".html"))
        throw InputError("--report: " + *o.report + ": the report is a page: end its name in .html");
}

// --reference compares one image: a frame (--output) or a plot (--plot --output). Its settings need it
// (the thresholds, or --test).
void checkReference(const Options& o) {
    if (!o.reference) {
        const char* flag = o.referenceMissing           ? "--reference-missing"
                           : o.maxDiff && !o.testDir    ? "--max-diff"
                           : o.meanDiff && !o.testDir   ? "--mean-diff"
                           : o.maxDiffPixels && !o.testDir ? "--max-diff-pixels"
                           : o.diffOutput               ? "--diff-output"
                                                        : nullptr;
        if (!flag) return;
        const bool threshold = flag == std::string("--max-diff") || flag == std::string("--mean-diff") ||
                               flag == std::string("--max-diff-pixels");
        throw InputError(std::string(flag) + ": sets up the comparison with a reference: give --reference REF.png" +
                         (threshold ? " (or --test DIR)" : ""));
    }
    const char* other = otherRun(o);
    if (other)
        throw InputError(std::string("--reference: compares one --output image (a frame or a --plot); not with ") + other);
    if (!o.output) throw InputError("--reference: compares the --output image with it: give --output FILE.png");
    if (!hasExtension(*o.reference, ".png"))
        throw InputError("--reference: " + *o.reference + ": only .png references are supported");
    if (o.diffOutput && !hasExtension(*o.diffOutput, ".png"))
        throw InputError("--diff-output: " + *o.diffOutput + ": only .png output is supported");
}

// The one place the run mode is worked out (the checks above have refused what does not go together).
RunMode runMode(const Options& o) {
    if (o.help) return RunMode::Help;
    if (o.version) return RunMode::Version;
    if (o.testDir) return RunMode::TestSuite;
    if (o.playlist) return o.output ? RunMode::PlaylistImages : RunMode::PlaylistViewer;
    if (o.plot && !o.info) return RunMode::Plot;
    if (o.output && !o.sweeps.empty() && !o.info) return RunMode::SweepSheet;
    if (o.output && o.probe) return RunMode::ProbeImage;
    if (o.output && !o.animations.empty() && !o.info) return RunMode::Video;
    if (o.output && !o.info && o.benchmarkFrames == 0) return RunMode::Image;
    if (o.info) return RunMode::Info;
    if (o.benchmarkFrames > 0) return RunMode::Benchmark;
    return RunMode::Viewer;
}

}  // namespace

Options parseOptions(const std::vector<std::string>& args) {
    Options o;
    std::vector<const OptionSpec*> given;
    for (std::size_t i = 0; i < args.size(); ++i) {
        std::string arg = args[i], value;
        bool hasInlineValue = false;
        const std::size_t eq = arg.rfind("--", 0) == 0 ? arg.find('=') : std::string::npos;
        if (eq != std::string::npos) {
            value = arg.substr(eq + 1);
            arg = arg.substr(0, eq);
            hasInlineValue = true;
        }
        const OptionSpec* spec = findOption(arg);
        if (!spec) {
            if (arg.size() > 1 && arg[0] == '-') throw InputError(arg + ": unknown option (see shadelab --help)");
            if (!o.input.empty()) throw InputError(arg + ": only one scene or model file can be given");
            o.input = arg;
            continue;
        }
        if (!*spec->argument && hasInlineValue) throw InputError(arg + ": takes no value");
        if (*spec->argument && !hasInlineValue) {
            if (i + 1 >= args.size()) throw InputError(arg + ": needs a value");
            value = args[++i];
        }
        spec->apply(o, *spec, value);
        given.push_back(spec);
    }
    checkTestSuite(o, given);
    checkPlaylist(o);
    checkOutputs(o);
    checkViewerAndPlot(o, given);
    checkReference(o);
    checkAnimation(o);
    o.mode = runMode(o);
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
        if (o.color) obj.material.color = *o.color, obj.material.colorSet = true;
        if (o.specularColor) obj.material.specularColor = *o.specularColor;
        if (o.anisotropy) obj.material.anisotropic = true, obj.material.anisotropy = *o.anisotropy;
        if (o.mirror) obj.material.mirror = *o.mirror;
        if (o.transmission) obj.material.transmission = *o.transmission;
        checkCoefficients(obj.material, "--");
    }
    checkAnisotropy(s, o.anisotropy ? "--" : o.reflection ? "--reflection: " : "");
    if (o.ambient) s.ambient = *o.ambient;
    if (o.background) s.background = *o.background;
    if (o.width) s.width = *o.width, s.height = *o.height;
    if (!o.lights.empty()) {
        s.lights = o.lights;
        s.lightsGiven = true;
    }
    if (o.shadows) s.shadows.enabled = *o.shadows;
    if (o.specularNormalization) s.specularNormalization = *o.specularNormalization;
    if (o.fresnel) s.fresnel = *o.fresnel;
    if (o.outputEncoding) {
        s.outputEncoding = *o.outputEncoding;
        s.outputEncodingGiven = true;
    }
    if (o.ior) s.ior = *o.ior;
    if (o.environment) s.environment = *o.environment;
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

Image plotImage(const Options& options, const Scene& scene) {
    const Material material = scene.objects.empty() ? Material{} : scene.objects.front().material;
    return renderPlotImage(scenePlot(*options.plot, scene, material, plotSettings(options)),
                           options.width.value_or(kPlotDefaultWidth), options.height.value_or(kPlotDefaultHeight));
}

namespace {

// `text` wrapped at 100 columns, its first line after `lead` (padded to the help column), the rest indented
// to that column. Backticks, which mark code in the README, are left out.
std::string wrapped(const std::string& lead, std::string text) {
    constexpr std::size_t kColumn = 26, kWidth = 100;
    text.erase(std::remove(text.begin(), text.end(), '`'), text.end());
    std::string out = lead + (lead.size() + 2 <= kColumn ? std::string(kColumn - lead.size(), ' ') : "  ");
    std::size_t lineStart = 0;  // where the current line begins in `out`
    bool lineEmpty = true;      // no word on the current line yet
    std::istringstream words(text);
    for (std::string word; words >> word;) {
        if (!lineEmpty && out.size() - lineStart + 1 + word.size() > kWidth) {
            out += "\n" + std::string(kColumn, ' ');
            lineStart = out.size() - kColumn;
            lineEmpty = true;
        }
        if (!lineEmpty) out += ' ';
        out += word;
        lineEmpty = false;
    }
    return out + "\n";
}

std::string optionLines(OptionGroup group) {
    std::string out;
    for (const OptionSpec* s = optionsBegin(); s != optionsEnd(); ++s)
        if (s->group == group) out += wrapped("  " + optionSynopsis(*s), optionHelp(*s));
    return out;
}

// A Markdown table cell: a pipe would end it.
std::string cell(const std::string& text) {
    std::string out;
    for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
    return out;
}

}  // namespace

std::string usage() {
    return R"(usage: shadelab [SCENE.json | MODEL.gltf | MODEL.glb] [options]
       shadelab --playlist DIR [options]

Shows flat, Gouraud and Phong shading side by side. With no file, the built-in default scene.
Without --output (or --benchmark) it opens the interactive viewer.

)" + optionLines(OptionGroup::General) +
           "\nViewer (the window; its keys and mouse are listed below, in its panel under \"Keys\" and by F1):\n" +
           optionLines(OptionGroup::Viewer) +
           "\nBad input (a file, a field, a flag) prints one line and exits with status 2.\n\nViewer keys and mouse:\n" +
           controlsText();
}

std::string optionsMarkdown() {
    std::string out = "| option | values | scene field | meaning |\n|---|---|---|---|\n";
    for (const OptionSpec* s = optionsBegin(); s != optionsEnd(); ++s) {
        std::string values = s->names ? s->names() : "";
        if (s->bounds.given && !s->names) values = rangeText(Range<double>{s->bounds.lo, s->bounds.hi});
        const std::string field = *s->sets ? "`" + std::string(s->sets) + "`" : "";
        out += "| `" + cell(optionSynopsis(*s)) + "` | " + cell(values) + " | " + field + " | " +
               cell(optionHelp(*s)) + (s->group == OptionGroup::Viewer ? " (viewer only)" : "") + " |\n";
    }
    return out;
}

}  // namespace shadelab
