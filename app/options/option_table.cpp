#include "options/option_table.hpp"

#include "core/base/error.hpp"
#include "core/base/file_io.hpp"
#include "core/base/message.hpp"
#include "core/figures/plot_image.hpp"
#include "core/image/image.hpp"
#include "core/scene/memory_budget.hpp"
#include "core/scene/panel_sections.hpp"
#include "core/scene/parameters.hpp"
#include "core/scene/scene_json.hpp"
#include "core/scene/scene_names.hpp"
#include "core/ui/view_names.hpp"
#include "options/shorthand.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iterator>
#include <sstream>
#include <vector>

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
    if (v.empty() || end != v.c_str() + v.size())
        throw InputError(flag + ": \"" + quoteInput(v) + "\" is not an integer");
    if (x < lo || x > hi)
        throw InputError(flag + ": " + v + " is out of range (" + std::to_string(lo) + ".." + std::to_string(hi) + ")");
    return int(x);
}

// The option's number, in its range; `unit` (" degrees") follows the range in the message.
float floatIn(const OptionSpec& spec, const std::string& v, const char* unit = "") {
    const float x = parseFloat(spec.name, v);
    if (!(x >= spec.bounds.lo && x <= spec.bounds.hi))
        throw InputError(std::string(spec.name) + ": must be " +
                         betweenText(Range<double>{spec.bounds.lo, spec.bounds.hi}) + unit + " (got " + v + ")");
    return x;
}

int intIn(const OptionSpec& spec, const std::string& v) {
    return parseInt(spec.name, v, long(spec.bounds.lo), long(spec.bounds.hi));
}

template <typename E, std::size_t N>
E choice(const std::string& flag, const std::string& v, const EnumName<E> (&names)[N]) {
    if (const std::optional<E> e = valueNamed(names, v)) return *e;
    throw InputError(flag + ": unknown value \"" + quoteInput(v) + "\" (expected one of " + namesList(names) + ")");
}

// A comma-separated list whose every item is one of `allowed` (an enum's names, core/scene/scene_names.hpp).
// `what` and `expected` word the refusal: "unknown section \"x\" (expected some of a, b)".
template <typename E, std::size_t N>
std::vector<std::string> listOf(const std::string& flag, const std::string& v, const EnumName<E> (&allowed)[N],
                                const char* what, const char* expected) {
    std::vector<std::string> items;
    std::stringstream list(v);
    for (std::string item; std::getline(list, item, ',');) {
        if (!valueNamed(allowed, item))
            throw InputError(flag + ": unknown " + what + " \"" + quoteInput(item) + "\" (expected " + expected + " " +
                             namesList(allowed) + ")");
        items.push_back(item);
    }
    return items;
}

// A repeatable option's list, refused with `tooMany` past `most` items.
template <typename T>
void addAtMost(std::vector<T>& list, T item, std::size_t most, const std::string& tooMany) {
    list.push_back(std::move(item));
    if (list.size() > most) throw InputError(tooMany);
}

// "A,B" split at the first comma; `expected` says what, e.g. "the pixel as X,Y, e.g. 640,360".
std::pair<std::string, std::string> pairOf(const std::string& flag, const std::string& v, char separator,
                                           const char* expected) {
    const std::size_t at = v.find(separator);
    if (at == std::string::npos) throw InputError(flag + ": expected " + expected + " (got \"" + quoteInput(v) + "\")");
    return {v.substr(0, at), v.substr(at + 1)};
}

const EnumName<int> kBackendNames[] = {{"auto", 0}, {"osmesa", 1}, {"egl", 2}};
const EnumName<MissingReference> kMissingReferenceNames[] = {{"fail", MissingReference::Fail},
                                                             {"write", MissingReference::Write}};

// The apply functions of the plainest rows: a switch, a number checked later, a file or folder name.
template <bool Options::*Field>
void setTrue(Options& o, const OptionSpec&, const std::string&) {
    o.*Field = true;
}
using ApplyOption = void (*)(Options& options, const OptionSpec& self, const std::string& value);

// The row of an option that sets a parameter of the table (core/scene/parameters.hpp): its name, range
// and help are the parameter's; `sets` the scene-file field it overrides.
OptionSpec parameterOption(Param id, const char* argument, std::string sets, ApplyOption apply,
                           OptionRules rules = {}) {
    const Parameter& p = parameter(id);
    return {p.option,        "",     argument, OptionGroup::General, Bounds{p.range.lo, p.range.hi, true}, nullptr,
            std::move(sets), p.help, apply,    std::move(rules)};
}
std::string materialField(Param id) { return std::string("objects[].material.") + parameter(id).name; }

// --ka, --kd, --ks, --ke, --mirror, --transmission: a number of every object's material, its range
// checked with the scene's (applyOverrides: checkCoefficients).
template <std::optional<float> Options::*Field>
OptionSpec materialOption(Param id) {
    return parameterOption(id, "X", materialField(id), [](Options& o, const OptionSpec& self, const std::string& v) {
        o.*Field = parseFloat(self.name, v);
    });
}
// "R,G,B", each channel in the option's range.
glm::vec3 colorIn(const OptionSpec& spec, const std::string& v) {
    std::vector<float> channels;
    std::stringstream list(v);
    for (std::string item; std::getline(list, item, ',');) channels.push_back(floatIn(spec, item));
    if (channels.size() != 3 || v.back() == ',')
        throw InputError(std::string(spec.name) + ": expected R,G,B, three numbers " +
                         betweenText(Range<double>{spec.bounds.lo, spec.bounds.hi}) + " (got \"" + quoteInput(v) +
                         "\")");
    return {channels[0], channels[1], channels[2]};
}
template <std::optional<glm::vec3> Options::*Field>
OptionSpec colorOption(Param id, std::string field) {
    return parameterOption(id, "R,G,B", std::move(field), [](Options& o, const OptionSpec& self, const std::string& v) {
        o.*Field = colorIn(self, v);
    });
}
template <std::optional<std::string> Options::*Field>
void setPath(Options& o, const OptionSpec&, const std::string& v) {
    o.*Field = v;
}

using G = OptionGroup;
constexpr Bounds kNoBounds{};

// The rules many rows share (OptionSpec::rules).
constexpr const char* kNeedsReference = "sets up the comparison with a reference: give --reference REF.png";
constexpr const char* kNeedsReferenceOrTest =
    "sets up the comparison with a reference: give --reference REF.png (or --test DIR)";
const OptionRules kNeedsTest{nullptr, {}, {{{"--test"}, "belongs to a folder of screenshot tests: give --test DIR"}}};
// --fps, --duration, --dither: the video's settings.
const OptionRules kVideoSetting{
    nullptr,
    {},
    {{{"--animate"}, "sets up the --animate video: give --animate SPEC and --output FILE.gif|.mp4|.webm"},
     {{"--output"}, "sets up the video: give --output FILE.gif, .mp4 or .webm"}}};
// --incidence, --from-inside: the plots' settings, which a render (--output, --benchmark) has no use for.
OptionRules plotSetting(const char* refusal) {
    return {nullptr, {{"--output", nullptr, refusal, "--plot"}, {"--benchmark", nullptr, refusal, "--plot"}}};
}

// Each row: name, alias, argument, group, range, names, scene field, help, apply, rules (what it goes with).
// (a table, read row by row: clang-format leaves it as written)
// clang-format off
const OptionSpec kOptions[] = {
    {"--output", "-o", "FILE.png", G::General, kNoBounds, nullptr, "",
     "render one frame offscreen (OSMesa or EGL, no display needed) and write it atomically; with `--animate`, "
     "a video: `.gif`, `.mp4` (H.264) or `.webm` (VP9)",
     setPath<&Options::output>,
     {nullptr,
      {{kViewerOptions, nullptr, "--output: {viewer} are for the viewer, which --output/--benchmark do not open"}},
      {}, RunMode::Image, RunMode::Image}},
    {"--playlist", "", "DIR", G::General, kNoBounds, nullptr, "",
     "the lecture presets: every `DIR/*.json` in file-name order (see *Lecture presets and the playlist*); a bare "
     "name that is no folder here (`lecture`) is the scene folder of that name beside the program; the "
     "viewer steps through them (Page Down / Page Up), `--output OUT/` writes `OUT/NAME.png` for each (`OUT` is "
     "created when it ends in / and is missing). Every other option applies to each preset",
     [](Options& o, const OptionSpec& self, const std::string& v) {
         if (v.empty()) throw InputError(std::string(self.name) + ": empty folder name");
         o.playlist = v;
     },
     {nullptr,
      {{"--sweep", nullptr, "--sweep: not with --playlist (sweep one preset file instead)"},
       {"--benchmark", nullptr, "--benchmark: not with --playlist (benchmark one preset file instead)"},
       {"--info", nullptr, "--info: not with --playlist"},
       {"--plot", nullptr, "--plot: not with --playlist (a plot is of one scene)"},
       {"--probe", nullptr, "--probe: not with --playlist (probe one preset file instead)"}},
      {}, RunMode::PlaylistViewer, RunMode::PlaylistImages}},
    {"--captions", "", "", G::General, kNoBounds, nullptr, "",
     "with `--output`: a strip under the image with the scene's title (for a preset without one, its file name) "
     "and caption",
     setTrue<&Options::captions>,
     {nullptr,
      {{"--sweep", nullptr, "--captions: adds a title strip to --output images (not to sweep sheets); give --output"}},
      {{{"--output"}, "adds a title strip to --output images (not to sweep sheets); give --output"}}}},
    // The formula overlay.
    {"--formula", "", "", G::General, kNoBounds, nullptr, "",
     "the lecture's formula over the bottom of the view, for the scene's reflection model, normalisation and "
     "Fresnel: the term `--show` isolates highlighted, the others dimmed; k_a, k_d, k_s, k_e's values under their "
     "symbols; with `--probe`, each term's value at that pixel; over each pane, where its mode evaluates the "
     "formula. The viewer starts with it on (key E), in a band above the view; with `--output` it is drawn into the "
     "PNG",
     setTrue<&Options::formula>,
     {"draws over a frame (the viewer's or --output's)", {{"--sweep"}, {"--benchmark"}, {"--plot"}, {"--info"}}},
     PanelSection::Overlays},
    // The intersection diagram.
    {"--intersection", "", "", G::General, kNoBounds, nullptr, "",
     "with `--probe` and `--output`: the lecture's \"At the Intersection\" drawn at the probed point into the PNG: "
     "arrows I, N, R and T (Snell's law at the surface, `--ior`), theta_i, theta_t, eta_i, eta_t and the Fresnel "
     "split R_par, R_perp, R and 1 - R. In the viewer: key I after a click",
     setTrue<&Options::intersection>,
     {nullptr, {}, {{{"--probe"}, "draws the diagram at a probed point: give --probe X,Y"}}}},
    {"--reference", "", "REF.png", G::General, kNoBounds, nullptr, "",
     "with `--output` (one frame, or a `--plot`): after writing the image, compare it with REF.png and print one "
     "line on stdout with the largest and the mean channel difference against `--max-diff` and `--mean-diff`, "
     "ending `matches` or `differs`; exit status 0 when they match, 1 when they differ or their sizes do, 2 when "
     "REF.png is missing or not a PNG (see *Screenshot tests in your CI*)",
     setPath<&Options::reference>,
     {"compares one --output image (a frame or a --plot)",
      {{"--playlist"}, {"--sweep"}, {"--probe"}, {"--benchmark"}, {"--info"}},
      {{{"--output"}, "compares the --output image with it: give --output FILE.png"}}}},
    {"--reference-missing", "", "ACTION", G::General, kNoBounds,
     [] { return namesList(kMissingReferenceNames, " | "); },
     "", "what a `--reference` that does not exist does: {names}: fail (the default: one line, exit status 2, "
     "nothing written) or write it from this render (exit status 0, and says so)",
     [](Options& o, const OptionSpec& self, const std::string& v) {
         o.referenceMissing = choice(self.name, v, kMissingReferenceNames);
     },
     {nullptr, {}, {{{"--reference"}, kNeedsReference}}}},
    {"--max-diff", "", "D", G::General, bounds(kMaxDiffRange), nullptr, "",
     "with `--reference` or `--test`: the largest difference allowed in any channel (R, G, B, A) of any pixel, in /255 "
     "({range}, default {max-diff})",
     [](Options& o, const OptionSpec& self, const std::string& v) { o.maxDiff = intIn(self, v); },
     {nullptr, {}, {{{"--reference", "--test"}, kNeedsReferenceOrTest}}}},
    {"--mean-diff", "", "M", G::General, bounds(kMeanDiffRange), nullptr, "",
     "with `--reference` or `--test`: the largest mean difference allowed, over every channel of every pixel, in /255 "
     "({range}, default {mean-diff})",
     [](Options& o, const OptionSpec& self, const std::string& v) { o.meanDiff = floatIn(self, v); },
     {nullptr, {}, {{{"--reference", "--test"}, kNeedsReferenceOrTest}}}},
    {"--max-diff-pixels", "", "P", G::General, bounds(kMaxDiffPixelsRange), nullptr, "",
     "with `--reference` or `--test`: at most P pixels may differ at all, in any channel (Playwright's "
     "maxDiffPixels; {range}, default no limit)",
     [](Options& o, const OptionSpec& self, const std::string& v) { o.maxDiffPixels = std::uint64_t(intIn(self, v)); },
     {nullptr, {}, {{{"--reference", "--test"}, kNeedsReferenceOrTest}}}},
    {"--diff-output", "", "DIFF.png", G::General, kNoBounds, nullptr, "",
     "with `--reference`: also write the difference as the diff layout's third pane draws it, per channel "
     "|image - reference| x the layout's factor (`--diff-factor`, default {diff-factor}); not written when the "
     "sizes differ",
     setPath<&Options::diffOutput>,
     {nullptr, {}, {{{"--reference"}, kNeedsReference}}}},
    {"--test", "", "DIR", G::General, kNoBounds, nullptr, "",
     "screenshot tests of a folder, in one process: render every `DIR/*.json` (file-name order) and compare it "
     "with `DIR/NAME.png` as `--reference` does (`--max-diff`, `--mean-diff`); one line per failing case and a "
     "summary on stdout. A scene that cannot be read, a missing or malformed reference, a size that differs or "
     "a shader that does not compile fails its case and the run goes on. Exit status 0 when every case "
     "matches, 1 when any fails, 2 when DIR is missing or holds no .json (see *Screenshot tests in your CI*)",
     [](Options& o, const OptionSpec& self, const std::string& v) {
         if (v.empty()) throw InputError(std::string(self.name) + ": empty folder name");
         o.testDir = v;
     },
     {"compares its folder's scenes with their references",
      {{"--output"}, {"--playlist"}, {"--reference"},
       {"--reference-missing", "--reference-missing (--update writes missing references)"},
       {"--diff-output", "--diff-output (--report shows the differences)"}, {"--sweep"}, {"--probe"}, {"--benchmark"},
       {"--info"}, {"--plot"}, {"--captions"}, {"--animate"}, {kViewerOptions}},
      {}, RunMode::TestSuite, RunMode::TestSuite}},
    {"--references", "", "DIR2", G::General, kNoBounds, nullptr, "",
     "with `--test`: the references are `DIR2/NAME.png` instead of beside the scenes",
     setPath<&Options::referencesDir>,
     kNeedsTest},
    {"--junit", "", "FILE.xml", G::General, kNoBounds, nullptr, "",
     "with `--test`: also write the results as JUnit XML (one testcase per scene; a difference is a failure "
     "with the numbers, a case that could not be compared an error), atomically",
     setPath<&Options::junit>,
     kNeedsTest},
    {"--report", "", "FILE.html", G::General, kNoBounds, nullptr, "",
     "with `--test`: also write one self-contained HTML page: each failing case's reference, render and "
     "amplified difference side by side at their pixel size, with its numbers; the matching cases listed",
     setPath<&Options::report>,
     kNeedsTest},
    {"--update", "", "", G::General, kNoBounds, nullptr, "",
     "with `--test`: after a person has looked, rewrite the references of the cases that differ or have none "
     "(missing or malformed) from this run's renders, atomically, and say which; matching references are "
     "left untouched. Exit status 0 unless a case could not be rendered",
     setTrue<&Options::update>,
     kNeedsTest},
    {"--artifacts", "", "DIR", G::General, kNoBounds, nullptr, "",
     "with `--test`: write each failing case's render (`NAME.actual.png`), difference (`NAME.diff.png`) and "
     "reference (`NAME.reference.png`) into DIR (created if missing), for the CI to keep; the JUnit testcase "
     "links them as `[[ATTACHMENT|DIR/NAME.diff.png]]`",
     setPath<&Options::artifacts>,
     kNeedsTest},
    {"--list", "", "", G::General, kNoBounds, nullptr, "",
     "with `--test`: print the names of the cases it would run (after `--filter` and `--shard`), one a line, "
     "and render nothing",
     setTrue<&Options::list>,
     kNeedsTest},
    {"--filter", "", "GLOB", G::General, kNoBounds, nullptr, "",
     "with `--test`: only the cases whose name (the scene's path in DIR without .json) matches GLOB (`*` any "
     "characters, `?` one); repeat for more. One that matches no case is refused",
     [](Options& o, const OptionSpec& self, const std::string& v) {
         if (v.empty()) throw InputError(std::string(self.name) + ": empty pattern");
         o.filters.push_back(v);
     },
     kNeedsTest},
    {"--shard", "", "K/N", G::General, kNoBounds, nullptr, "",
     "with `--test`: run the K-th of N disjoint parts of the cases (1 <= K <= N <= 1000), for N parallel CI jobs; "
     "a case's part follows from its name alone, so adding a case moves no other",
     [](Options& o, const OptionSpec& self, const std::string& v) {
         const auto kn = pairOf(self.name, v, '/', "K/N, the K-th of N parts, e.g. 2/4");
         const int n = parseInt(self.name, kn.second, 1, 1000);
         o.shard = {parseInt(self.name, kn.first, 1, n), n};
     },
     kNeedsTest},
    {"--shading", "", "MODE", G::General, kNoBounds, [] { return namesList(kShadingModeNames, " | "); }, "shading",
     "shading mode (single layout): {names}",
     [](Options& o, const OptionSpec& self, const std::string& v) {
         o.shading = choice(self.name, v, kShadingModeNames);
     },
     {}, PanelSection::Shading},
    {"--layout", "", "LAYOUT", G::General, kNoBounds, [] { return namesList(kLayoutNames, " | "); }, "layout",
     "{names}: compare is three equal panes flat | gouraud | phong, one camera; diff is A | B | |A - B| x factor "
     "(see *Lecture tools*)",
     [](Options& o, const OptionSpec& self, const std::string& v) { o.layout = choice(self.name, v, kLayoutNames); },
     {}, PanelSection::Shading},
    {"--diff", "", "A,B", G::General, kNoBounds, [] { return namesList(kShadingModeNames, " | "); }, "diff.a, diff.b",
     "the two shading modes of the diff layout (default gouraud,phong), each {names}",
     [](Options& o, const OptionSpec& self, const std::string& v) {
         const auto ab = pairOf(self.name, v, ',', "two shading modes A,B, e.g. gouraud,phong");
         o.diffA = choice(self.name, ab.first, kShadingModeNames);
         o.diffB = choice(self.name, ab.second, kShadingModeNames);
     },
     {}, PanelSection::Shading},
    parameterOption(Param::DiffFactor, "X", "diff.factor",
                    [](Options& o, const OptionSpec& self, const std::string& v) { o.diffFactor = floatIn(self, v); }),
    {"--reflection", "", "MODEL", G::General, kNoBounds, [] { return namesList(kReflectionModelNames, " | "); },
     "reflection", "the specular lobe: {names}",
     [](Options& o, const OptionSpec& self, const std::string& v) {
         o.reflection = choice(self.name, v, kReflectionModelNames);
     },
     {}, PanelSection::Shading},
    {"--specular-normalization", "", "NORM", G::General, kNoBounds,
     [] { return namesList(kSpecularNormalizationNames, " | "); }, "specular_normalization",
     "{names}: energy-normalised lobes ((k_e+2)/2pi, (k_e+8)/8pi; diffuse 1/pi; see *Lecture tools*)",
     [](Options& o, const OptionSpec& self, const std::string& v) {
         o.specularNormalization = choice(self.name, v, kSpecularNormalizationNames);
     },
     {}, PanelSection::Shading},
    {"--fresnel", "", "MODE", G::General, kNoBounds, [] { return namesList(kFresnelModeNames, " | "); }, "fresnel",
     "{names}: the specular term weighted by the Fresnel reflectance at V.H",
     [](Options& o, const OptionSpec& self, const std::string& v) {
         o.fresnel = choice(self.name, v, kFresnelModeNames);
     },
     {}, PanelSection::Shading},
    {"--output-encoding", "", "ENC", G::General, kNoBounds, [] { return namesList(kOutputEncodingNames, " | "); },
     "output_encoding",
     "{names}: how the clamped linear L is written (default: srgb for a scene that draws a glTF model, whose "
     "colours are linear values meant for an sRGB display; else the scene's, linear unless it says; see *What is "
     "drawn*)",
     [](Options& o, const OptionSpec& self, const std::string& v) {
         o.outputEncoding = choice(self.name, v, kOutputEncodingNames);
     },
     {}, PanelSection::Shading},
    parameterOption(Param::Ior, "X", parameter(Param::Ior).name,
                    [](Options& o, const OptionSpec& self, const std::string& v) { o.ior = floatIn(self, v); }),
    {"--show", "", "TERM", G::General, kNoBounds, [] { return namesList(kShowTermNames, " | "); },
     "show", "draw one addend of the formula alone: {names}",
     [](Options& o, const OptionSpec& self, const std::string& v) { o.show = parseTermView(v, self.name); },
     {}, PanelSection::Shading},
    materialOption<&Options::ka>(Param::Ka),
    materialOption<&Options::kd>(Param::Kd),
    materialOption<&Options::ks>(Param::Ks),
    materialOption<&Options::ke>(Param::Ke),
    parameterOption(Param::Anisotropy, "KT,KB", materialField(Param::Anisotropy),
                    [](Options& o, const OptionSpec& self, const std::string& v) {
                        const auto kb = pairOf(self.name, v, ',', "KT,KB, two exponents, e.g. 8,256");
                        o.anisotropy = glm::vec2(floatIn(self, kb.first), floatIn(self, kb.second));
                    }),
    materialOption<&Options::mirror>(Param::Mirror),
    materialOption<&Options::transmission>(Param::Transmission),
    {"--environment", "", "ENV", G::General, kNoBounds, [] { return namesList(kEnvironmentNames, " | "); },
     "environment",
     "what mirrors and glass reflect and refract, drawn as the background: {names} (room: coloured walls and a "
     "checker floor; sky: a gradient with a sun), or an equirectangular FILE.png or FILE.hdr (see *What is drawn*)",
     [](Options& o, const OptionSpec& self, const std::string& v) {
         o.environment = parseEnvironment(v, "", self.name);
     },
     {}, PanelSection::Background},
    colorOption<&Options::color>(Param::Color, materialField(Param::Color)),
    colorOption<&Options::specularColor>(Param::SpecularColor, materialField(Param::SpecularColor)),
    colorOption<&Options::ambient>(Param::Ambient, parameter(Param::Ambient).name),
    colorOption<&Options::background>(Param::Background, parameter(Param::Background).name),
    {"--size", "", "WxH", G::General, bounds(kImageSideRange), nullptr, "size",
     "image size in pixels, {range} per side, e.g. 1280x720",
     [](Options& o, const OptionSpec& self, const std::string& v) {
         const auto wh = pairOf(self.name, v, 'x', "WIDTHxHEIGHT, e.g. 1280x720");
         const int w = parseInt(self.name, wh.first, -1000000000, 1000000000);
         const int h = parseInt(self.name, wh.second, -1000000000, 1000000000);
         checkImageSize(w, h, self.name);
         o.width = w;
         o.height = h;
     },
     {}, PanelSection::Camera},
    {"--mesh", "", "SPEC", G::General, kNoBounds, nullptr, "objects[0].mesh",
     "replace the first object's mesh: `uvsphere[:slices[:stacks]]`, `icosphere[:n]`, `torus[:major[:minor]]`, "
     "`cube`, `plane[:n]`, or a `.gltf`/`.glb` file",
     [](Options& o, const OptionSpec& self, const std::string& v) { o.mesh = parseMeshShorthand(v, self.name); }},
    {"--light", "", "SPEC", G::General, bounds(kLightCountRange), nullptr, "lights",
     "replace the scene's lights; repeat for more (at most {max}). `TYPE:X,Y,Z[:KEY=VALUE]...` with `point:X,Y,Z` "
     "(position), `directional:X,Y,Z` (travel direction), `area:X,Y,Z` (centre), `spot:X,Y,Z` (position); keys "
     "`color=R,G,B`, `intensity=I`, `attenuation=none|inverse-square`, `range=R` (point, spot, area), "
     "`normal=X,Y,Z`, `size=W,H`, `samples=NXxNY`, `two-sided` (area), `direction=X,Y,Z`, `outer=DEG`, "
     "`inner=DEG` (spot: its axis and cone half-angles in degrees; outer 30, inner half the outer unless given). "
     "E.g. `--light area:0,3,0:size=1.6,1.6:samples=8x8:intensity=9:attenuation=inverse-square`, "
     "`--light spot:0,4,2:direction=0,-2,-1:outer=25:inner=15`",
     [](Options& o, const OptionSpec& self, const std::string& v) {
         const std::string tooMany = std::string(self.name) + ": at most " + formatNumber(self.bounds.hi) + " lights";
         addAtMost(o.lights, parseLightShorthand(v, self.name), std::size_t(self.bounds.hi), tooMany);
     }},
    {"--shadows", "", "", G::General, kNoBounds, nullptr, "shadows", "shadows (occlusion toward every light) on",
     [](Options& o, const OptionSpec&, const std::string&) { o.shadows = true; }, {}, PanelSection::Shadows},
    {"--no-shadows", "", "", G::General, kNoBounds, nullptr, "shadows", "shadows off",
     [](Options& o, const OptionSpec&, const std::string&) { o.shadows = false; }},
    {"--no-textures", "", "", G::General, kNoBounds, nullptr, "textures",
     "glTF models without their base colour textures and vertex colours: C is each material's base colour factor "
     "(see *What is drawn*)",
     setTrue<&Options::noTextures>, {}, PanelSection::Material},
    {"--sweep", "", "PARAM=V1,V2,...", G::General, kNoBounds, nullptr, "",
     "with `--output`: a contact sheet, one labelled tile (of `--size`) per value; a second `--sweep` gives rows. "
     "PARAM: `ke`, `ks`, `kd`, `ka`, `intensity` (every light), `tessellation` (first mesh), `ior`, `shading`, "
     "`reflection`, `specular_normalization`, `fresnel`. E.g. `--sweep ke=1,8,32,128,512 --sweep "
     "shading=gouraud,phong`",
     [](Options& o, const OptionSpec& self, const std::string& v) {
         addAtMost(o.sweeps, parseSweep(v, self.name), std::size_t(kMaxSweeps),
                   std::string(self.name) + ": at most two sweeps (columns and rows)");
         if (o.sweeps.size() == 2 && o.sweeps[0].parameter == o.sweeps[1].parameter)
             throw InputError(std::string(self.name) + ": " + o.sweeps[1].parameter + " is swept twice");
     },
     {nullptr,
      {{"--benchmark", nullptr, "--sweep: renders a sheet to a PNG: give --output FILE.png (and no --benchmark)"}},
      {{{"--output"}, "renders a sheet to a PNG: give --output FILE.png (and no --benchmark)"}},
      RunMode::SweepSheet, RunMode::SweepSheet}},
    // Animations and videos (core/scene/animation.hpp, video/video_encoder.hpp; checked in options.cpp).
    {"--animate", "", "SPEC", G::General, kNoBounds, nullptr, "",
     "with `--output FILE.gif|.mp4|.webm`: render an animation to a video; without, the viewer plays it (Space "
     "pauses; with `--playlist` on every preset, from its start at each slide, capped at the display's refresh). "
     "Repeatable (at most {max-animations}, "
     "all at once). SPEC: `light-orbit[:SECONDS]` (the first light circles the camera's target at its height), "
     "`camera-orbit[:SECONDS]` (a turntable about the target and the up axis), or a ramp `PARAM=A..B[:log][:SECONDS]` "
     "of any `--sweep` parameter from A to B (`:log`: equal ratios, e.g. `ke=1..1000:log`; names switch half way). "
     "SECONDS: one turn or the ramp's length, default {animation-seconds}",
     [](Options& o, const OptionSpec& self, const std::string& v) {
         addAtMost(o.animations, parseAnimation(v, self.name), kMaxAnimations,
                   std::string(self.name) + ": at most " + std::to_string(kMaxAnimations) + " animations");
     },
     {"renders a video of one scene",
      {{"--sweep"}, {"--probe"}, {"--benchmark"}, {"--info"}, {"--plot"}, {"--reference"}, {"--captions"}},
      {}, RunMode::Viewer, RunMode::Video}},
    {"--fps", "", "N", G::General, bounds(kVideoFpsRange), nullptr, "",
     "the video's frames per second ({range}, default {fps})",
     [](Options& o, const OptionSpec& self, const std::string& v) { o.fps = intIn(self, v); },
     kVideoSetting},
    {"--duration", "", "SECONDS", G::General, Bounds{0, kMaxAnimationSeconds, true}, nullptr, "",
     "the video's length (more than 0, at most {max}; default the longest animation's): frame i shows time "
     "i / fps, and a ramp's video ends on a frame of its end value B",
     [](Options& o, const OptionSpec& self, const std::string& v) {
         const float x = parseFloat(self.name, v);
         if (!(x > 0.0f && x <= kMaxAnimationSeconds))
             throw InputError(std::string(self.name) + ": must be more than 0 and at most " +
                              formatNumber(kMaxAnimationSeconds) + " seconds (got " + v + ")");
         o.duration = x;
     },
     kVideoSetting},
    {"--dither", "", "", G::General, kNoBounds, nullptr, "",
     "a GIF's colours Floyd-Steinberg dithered onto each frame's palette (default off: each pixel takes its colour's "
     "palette entry; a frame of at most 256 colours is exact either way)",
     setTrue<&Options::dither>,
     kVideoSetting},
    {"--plot", "", "KIND", G::General, kNoBounds, [] { return namesList(kPlotKindNames, " | "); }, "",
     "{names}, with `--output`: the lecture's plot for the scene's parameters, drawn on the CPU (no GL), {plot-size} "
     "unless `--size` ({plot-sizes}): lobe = Phong and Blinn-Phong spec in the plane of incidence for "
     "k_e; fresnel = R_par, R_perp, their average and Schlick over the angle of incidence; lobe3d = the BRDF "
     "f_r(omega_i -> omega_o) for the light at `--incidence` as a 3-D polar surface over the hemisphere; brdf-slice = "
     "heat maps of f_r over (theta_i, theta_o) in the plane of incidence and over (delta_phi, theta_o) at "
     "`--incidence` "
     "(with `--anisotropy`, at phi_i = 0 and 90 deg) (see *Plots*)",
     [](Options& o, const OptionSpec& self, const std::string& v) { o.plot = choice(self.name, v, kPlotKindNames); },
     {nullptr,
      {{"--sweep", nullptr, "--plot: draws one plot: not with --sweep or --benchmark"},
       {"--benchmark", nullptr, "--plot: draws one plot: not with --sweep or --benchmark"}},
      {{{"--output"}, "writes a PNG: give --output FILE.png"}},
      RunMode::Plot, RunMode::Plot}},
    parameterOption(Param::Incidence, "DEG", "",
                    [](Options& o, const OptionSpec& self, const std::string& v) {
                        o.incidenceDeg = floatIn(self, v, " degrees");
                    },
                    plotSetting("--incidence: sets up the plots: use it with --plot, or in the viewer")),
    {"--from-inside", "", "", G::General, kNoBounds, nullptr, "",
     "the Fresnel plot from inside the material (eta1 = `--ior`, eta2 = 1): total internal reflection past the "
     "critical angle",
     setTrue<&Options::fromInside>,
     plotSetting("--from-inside: sets up the plots: use it with --plot, or in the viewer"), PanelSection::Plots},
    {"--probe", "", "X,Y", G::General, Bounds{0, kImageSideRange.hi - 1, true}, nullptr, "",
     "with `--output`: also print on stdout, as JSON, every term of the formula at pixel X,Y (top-left origin, "
     "any layout) the way that pixel's mode evaluates it (see *Pixel probe*); without `--output`: open the "
     "viewer with the probe set there",
     [](Options& o, const OptionSpec& self, const std::string& v) {
         const auto xy = pairOf(self.name, v, ',', "the pixel as X,Y, e.g. 640,360");
         const int x = intIn(self, xy.first);  // x first: it is named first
         o.probe = glm::ivec2(x, intIn(self, xy.second));
     },
     {"probes one pixel of one frame (with --output, or in the viewer)", {{"--sweep"}, {"--benchmark"}, {"--info"}},
      {}, RunMode::Viewer, RunMode::ProbeImage}},
    {"--benchmark", "", "N", G::General, bounds(kBenchmarkFramesRange), nullptr, "",
     "render N frames ({range}) offscreen per shading mode, print one JSON line per mode (frames, triangles, "
     "size, shading, median and p95 ms)",
     [](Options& o, const OptionSpec& self, const std::string& v) { o.benchmarkFrames = intIn(self, v); },
     {nullptr,
      {{kViewerOptions, nullptr,
        "--benchmark: {viewer} are for the viewer, which --output/--benchmark do not open"}},
      {}, RunMode::Benchmark, RunMode::Benchmark}},
    {"--progressive", "", "S", G::General, bounds(kProgressiveStrideRange), nullptr, "",
     "area lights in the viewer: every S-th sample per axis a frame, S x S frames to the full image ({range}; "
     "default: the viewer adapts S to its frame time); with `--benchmark`, times one such frame while the camera "
     "orbits",
     [](Options& o, const OptionSpec& self, const std::string& v) { o.progressiveStride = intIn(self, v); },
     {nullptr,
      {{"--output", nullptr,
        "--progressive: --output always renders every area-light sample; it is for the viewer and --benchmark"}}}},
    {"--backend", "", "NAME", G::General, kNoBounds, [] { return namesList(kBackendNames, " | "); }, "",
     "the headless OpenGL context for `--output`/`--benchmark`: {names}: OSMesa, EGL (surfaceless or a GPU's "
     "EGL device, drawing into an FBO), or the first that works, OSMesa first (default)",
     [](Options& o, const OptionSpec& self, const std::string& v) {
         choice(self.name, v, kBackendNames);
         o.backend = v;
     }},
    {"--msaa", "", "N", G::General, kNoBounds, [] { return namesList(kMsaaNames, ", ", " or "); }, "",
     "multisample anti-aliasing, N = {names} samples per pixel (0, 1: off; the driver may round up and caps it "
     "at its maximum): the frame is drawn into a multisampled framebuffer and resolved. `--output` and "
     "`--benchmark` default to 1, pixel-exact with the golden images; the viewer to 4 (on a software renderer "
     "such as llvmpipe only the still view is anti-aliased: moving frames are drawn without, see "
     "bench/README.md), a scripted `--frames` run to 1",
     [](Options& o, const OptionSpec& self, const std::string& v) { o.msaa = choice(self.name, v, kMsaaNames); },
     {}, PanelSection::Shading},
    {"--camera", "", "N", G::General, Bounds{0, 100000, true}, nullptr, "",
     "look through the glTF model's camera N (`--info` lists them, in the order the drawn scene reaches them) "
     "instead of shadelab's framing; orthographic cameras are refused (the views are perspective)",
     [](Options& o, const OptionSpec& self, const std::string& v) { o.camera = intIn(self, v); }},
    {"--max-memory", "", "SIZE", G::General, kNoBounds, nullptr, "",
     "the memory budget for `--output`, `--sweep`, `--playlist` and `--benchmark` (`2G`, `512M`, at least `64M`; "
     "default half of the machine's memory, or of the container's cgroup limit where smaller): a request "
     "estimated to need more is refused with one line saying how much",
     [](Options& o, const OptionSpec& self, const std::string& v) {
         const auto bytes = parseByteSize(v);
         if (!bytes)
             throw InputError(std::string(self.name) + ": \"" + quoteInput(v) + "\" is not a size (e.g. 2G, 512M)");
         if (*bytes < (std::uint64_t(64) << 20)) throw InputError(std::string(self.name) + ": at least 64M");
         o.maxMemory = *bytes;
     }},
    {"--shader-dir", "", "DIR", G::General, kNoBounds, nullptr, "",
     "read GLSL files from DIR where present (default: the folder beside the program, an installed "
     "`share/shadelab/shaders`, a checkout's `shaders/` for a build inside it or a build folder's "
     "`share/shadelab/shaders`; else the copies built in)",
     [](Options& o, const OptionSpec&, const std::string& v) { o.shaderDir = v; }},
    {"--info", "", "", G::General, kNoBounds, nullptr, "",
     "print what was loaded (meshes, triangles, bounds, normals, the model's cameras) and exit",
     setTrue<&Options::info>,
     {nullptr, {}, {}, RunMode::Info, RunMode::Info}},
    {"--verbose", "-v", "", G::General, kNoBounds, nullptr, "", "say what was loaded and written",
     setTrue<&Options::verbose>},
    {"--help", "-h", "", G::General, kNoBounds, nullptr, "", "print this help and exit",
     setTrue<&Options::help>,
     {nullptr, {}, {}, RunMode::Help, RunMode::Help}},
    {"--version", "", "", G::General, kNoBounds, nullptr, "", "print the version and exit",
     setTrue<&Options::version>,
     {nullptr, {}, {}, RunMode::Version, RunMode::Version}},
    // The viewer's window (options.cpp refuses them with --output and --benchmark).
    {"--frames", "", "N", G::Viewer, bounds(kViewerFramesRange), nullptr, "", "quit after N frames ({range})",
     [](Options& o, const OptionSpec& self, const std::string& v) { o.frames = intIn(self, v); }},
    {"--screenshot", "", "FILE.png", G::Viewer, kNoBounds, nullptr, "",
     "on the last frame (N-th, or when you quit), save the whole window, panel included",
     setPath<&Options::screenshot>},
    {"--screenshot-view", "", "FILE.png", G::Viewer, kNoBounds, nullptr, "",
     "on the last frame, save the 3D view alone (what F12 saves)",
     setPath<&Options::screenshotView>},
    {"--save-scene", "", "FILE.json", G::Viewer, kNoBounds, nullptr, "",
     "on the last frame, save the scene as the panel's \"save scene\" does",
     setPath<&Options::saveScene>},
    {"--hide-panel", "", "", G::Viewer, kNoBounds, nullptr, "", "start with the panel hidden (Tab shows it)",
     setTrue<&Options::hidePanel>},
    {"--overlays", "", "LIST", G::Viewer, kNoBounds,
     [] { return namesList(kOverlayNames, ","); }, "",
     "start with these overlays on: {names}",
     [](Options& o, const OptionSpec& self, const std::string& v) {
         for (const std::string& name : listOf(self.name, v, kOverlayNames, "value", "one of"))
             o.overlays.push_back(*valueNamed(kOverlayNames, name));
     }},
    {"--panel-sections", "", "LIST", G::Viewer, kNoBounds,
     [] { return namesList(kPanelSections, ", "); }, "",
     "start with exactly these panel sections open, e.g. plots or shading,material ({names}); `--incidence` and "
     "`--from-inside` set the Plots section's controls",
     [](Options& o, const OptionSpec& self, const std::string& v) {
         o.panelSections = listOf(self.name, v, kPanelSections, "section", "some of");
     }},
    {"--select-light", "", "N", G::Viewer, Bounds{0, kLightCountRange.hi - 1, true}, nullptr, "",
     "start with light N selected in the panel (an area light shows its samples)",
     [](Options& o, const OptionSpec& self, const std::string& v) { o.selectLight = intIn(self, v); }},
    {"--ui-scale", "", "S", G::Viewer, bounds(kUiScaleRange), nullptr, "",
     "panel and HUD S times larger ({range}, on top of the monitor's content scale; the text over the view, "
     "captions and labels, is at least 2.4% of the window's height whatever S is); Ctrl+= / Ctrl+- / Ctrl+0 in the "
     "viewer",
     [](Options& o, const OptionSpec& self, const std::string& v) { o.uiScale = floatIn(self, v); }},
    {"--fullscreen", "", "", G::Viewer, kNoBounds, nullptr, "", "cover the whole monitor (F11 toggles)",
     setTrue<&Options::fullscreen>},
    {"--no-labels", "", "", G::Viewer, kNoBounds, nullptr, "",
     "start without the pane labels and light labels (a clean view for slides)",
     setTrue<&Options::noLabels>},
    {"--reset-layout", "", "", G::Viewer, kNoBounds, nullptr, "",
     "forget the remembered window size and position, fullscreen, panel sections, UI scale and anti-aliasing "
     "(`$XDG_CONFIG_HOME/shadelab/viewer.json`)",
     setTrue<&Options::resetLayout>},
};
// clang-format on

}  // namespace

const OptionSpec* optionsBegin() { return std::begin(kOptions); }
const OptionSpec* optionsEnd() { return std::end(kOptions); }

const OptionSpec* findOption(const std::string& name) {
    for (const OptionSpec& spec : kOptions)
        if (name == spec.name || (*spec.alias && name == spec.alias)) return &spec;
    return nullptr;
}

std::string optionHelp(const OptionSpec& spec) {
    std::string text = spec.help;
    auto fill = [&text](const std::string& key, const std::string& value) {
        for (std::size_t at; (at = text.find(key)) != std::string::npos;) text.replace(at, key.size(), value);
    };
    if (spec.bounds.given) {
        fill("{range}", rangeText(Range<double>{spec.bounds.lo, spec.bounds.hi}));
        fill("{max}", formatNumber(spec.bounds.hi));
    }
    if (spec.names) fill("{names}", spec.names());
    fill("{plot-size}", std::to_string(kPlotDefaultWidth) + "x" + std::to_string(kPlotDefaultHeight));
    fill("{plot-sizes}", plotSizesText());
    fill("{max-diff}", formatNumber(ImageTolerance{}.maxDiff));
    fill("{mean-diff}", formatNumber(ImageTolerance{}.meanDiff));
    fill("{diff-factor}", formatNumber(DiffSettings{}.factor));
    if (const Parameter* p = parameterOfOption(spec.name)) fill("{default}", defaultText(*p));
    fill("{max-animations}", std::to_string(kMaxAnimations));
    fill("{animation-seconds}", formatNumber(kDefaultAnimationSeconds));
    fill("{fps}", std::to_string(kDefaultVideoFps));
    return text;
}

std::optional<PanelSection> optionSection(const OptionSpec& spec) {
    if (spec.section) return spec.section;
    if (const Parameter* p = parameterOfOption(spec.name)) return p->section;
    return std::nullopt;
}

std::string optionSynopsis(const OptionSpec& spec) {
    std::string s = *spec.alias ? std::string(spec.alias) + ", " + spec.name : std::string(spec.name);
    return *spec.argument ? s + " " + spec.argument : s;
}

}  // namespace shadelab
