#include "options/options.hpp"

#include "core/base/error.hpp"
#include "core/base/file_io.hpp"
#include "core/figures/plot_image.hpp"
#include "core/scene/scene_json.hpp"
#include "core/ui/controls.hpp"
#include "options/option_table.hpp"

#include <algorithm>
#include <sstream>

namespace shadelab {
namespace {

bool isVideoPath(const std::string& path) {
    return hasExtension(path, ".gif") || hasExtension(path, ".mp4") || hasExtension(path, ".webm");
}

// Whether `name` ("--test") is among the options given; kViewerOptions: any of the viewer's group.
bool isGiven(const std::vector<const OptionSpec*>& given, const char* name) {
    const bool viewer = name == std::string(kViewerOptions);
    return std::any_of(given.begin(), given.end(), [&](const OptionSpec* s) {
        return viewer ? s->group == OptionGroup::Viewer : s->name == std::string(name);
    });
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

// Which options go together, as each row of the table declares it (OptionSpec::rules): first, for every
// option given in the table's order, the first option it refuses; then the first it needs and lacks
// (so "--test DIR --reference R" names what --test refuses rather than what --reference lacks).
void checkRules(const std::vector<const OptionSpec*>& given) {
    const auto isSet = [&](const OptionSpec* spec) {
        return std::find(given.begin(), given.end(), spec) != given.end();
    };
    for (const OptionSpec* spec = optionsBegin(); spec != optionsEnd(); ++spec) {
        if (!isSet(spec)) continue;
        for (const Conflict& c : spec->rules.conflicts) {
            if (!isGiven(given, c.other) || (c.unless && isGiven(given, c.unless))) continue;
            if (!c.message)
                throw InputError(std::string(spec->name) + ": " + spec->rules.does + "; not with " +
                                 (c.shownAs ? c.shownAs : c.other));
            std::string message = c.message;
            const std::size_t at = message.find("{viewer}");
            if (at != std::string::npos) message.replace(at, 8, groupNames(OptionGroup::Viewer));
            throw InputError(message);
        }
    }
    for (const OptionSpec* spec = optionsBegin(); spec != optionsEnd(); ++spec)
        for (const Need& n : spec->rules.needs)
            if (isSet(spec) &&
                std::none_of(n.anyOf.begin(), n.anyOf.end(), [&](const char* o) { return isGiven(given, o); }))
                throw InputError(std::string(spec->name) + ": " + n.text);
}

// The run the options ask for: the first in RunMode's order of those the options given ask for.
RunMode runMode(const Options& o, const std::vector<const OptionSpec*>& given) {
    RunMode mode = RunMode::Viewer;
    for (const OptionSpec* spec : given)
        mode = std::min(mode, o.output ? spec->rules.modeWithOutput : spec->rules.mode);
    return mode;
}

// What the table's rules cannot say: a scene file given to a run of a folder, file names' endings, a
// plot's size, and the video's (its output's name and a tessellation ramp).
void checkInput(const Options& o) {
    if (o.testDir && !o.input.empty())
        throw InputError("--test: renders the scene files of its folder; give no scene file (" + o.input + ") with it");
    if (o.playlist && !o.input.empty())
        throw InputError("--playlist: shows the scene files of a folder; give no scene file (" + o.input + ") with it");
}

// The files whose name must end in one way: "NAME: FILE: refusal" otherwise (--output, which also
// takes a video or a playlist's folder, is checked on its own).
struct FileEnding {
    std::optional<std::string> Options::*file;
    const char* flag;
    const char* ending;
    const char* refusal;
};
const FileEnding kFileEndings[] = {
    {&Options::screenshot, "--screenshot", ".png", "only .png is supported"},
    {&Options::screenshotView, "--screenshot-view", ".png", "only .png is supported"},
    {&Options::saveScene, "--save-scene", ".json", "scene files end in .json"},
    {&Options::junit, "--junit", ".xml", "JUnit reports end in .xml"},
    {&Options::report, "--report", ".html", "the report is a page: end its name in .html"},
    {&Options::reference, "--reference", ".png", "only .png references are supported"},
    {&Options::diffOutput, "--diff-output", ".png", "only .png output is supported"}};

void checkFileNames(const Options& o) {
    if (o.output && !o.playlist && !hasExtension(*o.output, ".png") && !isVideoPath(*o.output))
        throw InputError("--output: " + *o.output +
                         ": only .png output is supported (and .gif, .mp4, .webm with --animate)");
    for (const FileEnding& f : kFileEndings)
        if (const std::optional<std::string>& file = o.*f.file; file && !hasExtension(*file, f.ending))
            throw InputError(std::string(f.flag) + ": " + *file + ": " + f.refusal);
}

void checkPlotSize(const Options& o) {
    if (o.plot && o.width &&
        (*o.width < kPlotMinWidth || *o.height < kPlotMinHeight || *o.width > kPlotMaxSide || *o.height > kPlotMaxSide))
        throw InputError("--size: a plot is " + plotSizesText() + " pixels");
}

// --animate renders a video: --output names it (a .gif, .mp4 or .webm), and only a video ramps the
// tessellation.
void checkAnimation(const Options& o) {
    const bool video = o.output && !o.playlist && isVideoPath(*o.output);
    if (o.animations.empty()) {
        if (video)
            throw InputError("--output: " + *o.output + ": a video needs --animate SPEC (e.g. --animate light-orbit)");
        return;
    }
    // With --playlist the viewer plays the animation on every preset; a video is of one scene.
    if (o.playlist && o.output)
        throw InputError(
            "--animate: with --playlist the viewer plays it on every preset; a video (--output) is of one "
            "scene: give that preset's file instead of --playlist");
    if (!o.output) {  // the viewer plays it
        for (const Animation& a : o.animations)
            if (a.parameter == "tessellation")
                throw InputError("--animate: " + a.text +
                                 ": a tessellation ramp is for videos (--output); the "
                                 "viewer would rebuild the mesh every frame");
        return;
    }
    if (!video)
        throw InputError("--animate: writes a video: give --output FILE.gif, .mp4 or .webm (not " + *o.output + ")");
    if (o.dither && !hasExtension(*o.output, ".gif"))
        throw InputError("--dither: dithers a GIF's palette; " + *o.output + " is not a .gif");
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
    checkInput(o);
    checkRules(given);
    checkFileNames(o);
    checkPlotSize(o);
    checkAnimation(o);
    o.mode = runMode(o, given);
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
        if (o.color) {
            obj.material.color = *o.color;
            obj.material.colorSet = true;
        }
        if (o.specularColor) obj.material.specularColor = *o.specularColor;
        if (o.anisotropy) {
            obj.material.anisotropic = true;
            obj.material.anisotropy = *o.anisotropy;
        }
        if (o.mirror) obj.material.mirror = *o.mirror;
        if (o.transmission) obj.material.transmission = *o.transmission;
        checkCoefficients(obj.material, "--");
    }
    checkAnisotropy(s, o.anisotropy ? "--" : o.reflection ? "--reflection: " : "");
    if (o.ambient) s.ambient = *o.ambient;
    if (o.background) s.background = *o.background;
    if (o.width) {
        s.width = *o.width;
        s.height = *o.height;
    }
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
    if (o.diffA) {
        s.diff.a = *o.diffA;
        s.diff.b = *o.diffB;
    }
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
           "\nBad input (a file, a field, a flag) prints one line and exits with status 2.\n\nViewer keys and "
           "mouse:\n" +
           controlsText();
}

std::string optionsMarkdown() {
    std::string out = "| option | values | scene field | meaning |\n|---|---|---|---|\n";
    for (const OptionSpec* s = optionsBegin(); s != optionsEnd(); ++s) {
        std::string values = s->names ? s->names() : "";
        if (s->bounds.given && !s->names) values = rangeText(Range<double>{s->bounds.lo, s->bounds.hi});
        const std::string field = !s->sets.empty() ? "`" + s->sets + "`" : "";
        out += "| `" + cell(optionSynopsis(*s)) + "` | " + cell(values) + " | " + field + " | " + cell(optionHelp(*s)) +
               (s->group == OptionGroup::Viewer ? " (viewer only)" : "") + " |\n";
    }
    return out;
}

}  // namespace shadelab
