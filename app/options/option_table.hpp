#pragma once
// The command line's one table: every option's name, argument, range or names, the scene-file field
// it overrides, its help text and how it is read into Options. Parsing (options.cpp), its messages,
// `--help` and the README's option table (tests/unit/cli_options_test.cpp compares them) are all
// made from it.
//
// Why a small table of our own rather than CLI11 (libcli11-dev 2.1) or cxxopts (libcxxopts-dev 3.1):
// their refusals are theirs, and not shadelab's contract (one line that names the flag and what is
// wrong with the value). Tried on Debian 12's packages: `--ka abc` gives CLI11's "Could not convert:
// --ka = abc" and cxxopts' "Argument 'abc' failed to parse" (shadelab: --ka: "abc" is not a number);
// `--ior 0.9` with CLI11::Range "--ior: Value 0.9 not in range 1.000000 to 10.000000"; a second
// file "The following argument was not expected: b.json"; CLI11 takes `--info=yes` as true where
// shadelab says "--info: takes no value"; cxxopts has no value checks and keeps extra positionals
// silently. Keeping every message would mean catching each exception type and rewriting its text,
// more code around either library than the ~60 lines of parsing this table needs, plus a build
// dependency (for the libFuzzer build too). The table keeps what a library would give: one
// declaration per option, --help and the README's table generated from it.
#include "core/scene/panel_sections.hpp"
#include "core/scene/scene_limits.hpp"
#include "options/options.hpp"

#include <optional>

#include <string>
#include <vector>

namespace shadelab {

// Where --help lists an option: the run and the scene, or the viewer's window (which --output and
// --benchmark refuse: see options.cpp).
enum class OptionGroup { General, Viewer };

// A number's range, when the option has one; from core/scene/scene_limits.hpp.
struct Bounds {
    double lo = 0, hi = 0;
    bool given = false;
};
template <typename T>
constexpr Bounds bounds(const Range<T>& r) {
    return {double(r.lo), double(r.hi), true};
}

// Which options go together, declared on each option's row and checked for every option given in one
// loop (options.cpp, checkRules): what it refuses, what it needs, and the run it asks for.
//
// An option another cannot go with. The refusal names the row's option: "--test: " + the row's
// OptionRules::does + "; not with " + (shownAs or other), or `message` as it stands when given.
struct Conflict {
    const char* other;              // "--sweep"; kViewerOptions: any option of the viewer's group
    const char* shownAs = nullptr;  // how the refusal names it, when not by `other`
    const char* message = nullptr;  // the whole refusal ("{viewer}": the viewer's options, listed)
    const char* unless = nullptr;   // no conflict when this option is given too
};
inline constexpr const char* kViewerOptions = "the viewer's options";
// Options one of which must be given too: refused with "NAME: " + text.
struct Need {
    std::vector<const char*> anyOf;
    const char* text;
};
struct OptionRules {
    const char* does = nullptr;            // what the option does, before "; not with OTHER"
    std::vector<Conflict> conflicts = {};  // checked in this order, every option's before any `needs`
    std::vector<Need> needs = {};
    // The run it asks for, alone and with --output; the run is the first in RunMode's order of the
    // options given (none: the viewer).
    RunMode mode = RunMode::Viewer;
    RunMode modeWithOutput = RunMode::Viewer;
};

struct OptionSpec {
    const char* name;      // "--ior"
    const char* alias;     // "-o", or ""
    const char* argument;  // "X", "FILE.png"; "" for a switch (which takes no value)
    OptionGroup group;
    Bounds bounds;           // the range its number (or numbers) must be in, when it has one
    std::string (*names)();  // the values it takes when they are names ("flat | gouraud | phong"), else null
    std::string sets;        // the scene-file field it overrides ("ior", "objects[].material.ka"); "" for none
    const char* help;        // one paragraph; "{range}" and "{names}" stand for the two above
    // Reads the value (empty for a switch) into the options; throws InputError "--name: ...".
    void (*apply)(Options& options, const OptionSpec& self, const std::string& value);
    OptionRules rules = {};  // which options it goes with, and the run it asks for
    // The panel section where the viewer and the web page show its control; a parameter's option takes
    // its parameter's (core/scene/parameters.hpp). None: no control (or one the panel places itself).
    std::optional<PanelSection> section = std::nullopt;
};

// Every option, in the order --help and the README list them.
const OptionSpec* optionsBegin();
const OptionSpec* optionsEnd();
// The option called `name` ("--output") or with that alias ("-o"); null when there is none.
const OptionSpec* findOption(const std::string& name);

// Where the option's control sits: its row's section, else its parameter's; none for the others.
std::optional<PanelSection> optionSection(const OptionSpec& spec);

// The help text with {range} ("1..10") and {names} filled in.
std::string optionHelp(const OptionSpec& spec);
// "-o, --output FILE.png": how --help and the README name the option.
std::string optionSynopsis(const OptionSpec& spec);

}  // namespace shadelab
