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
#include "cli/options.hpp"
#include "core/scene/scene_limits.hpp"

#include <string>

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

struct OptionSpec {
    const char* name;         // "--ior"
    const char* alias;        // "-o", or ""
    const char* argument;     // "X", "FILE.png"; "" for a switch (which takes no value)
    OptionGroup group;
    Bounds bounds;            // the range its number (or numbers) must be in, when it has one
    std::string (*names)();   // the values it takes when they are names ("flat | gouraud | phong"), else null
    const char* sets;         // the scene-file field it overrides ("ior", "objects[].material.ka"); "" for none
    const char* help;         // one paragraph; "{range}" and "{names}" stand for the two above
    // Reads the value (empty for a switch) into the options; throws InputError "--name: ...".
    void (*apply)(Options& options, const OptionSpec& self, const std::string& value);
};

// Every option, in the order --help and the README list them.
const OptionSpec* optionsBegin();
const OptionSpec* optionsEnd();
// The option called `name` ("--output") or with that alias ("-o"); null when there is none.
const OptionSpec* findOption(const std::string& name);

// The help text with {range} ("1..10") and {names} filled in.
std::string optionHelp(const OptionSpec& spec);
// "-o, --output FILE.png": how --help and the README name the option.
std::string optionSynopsis(const OptionSpec& spec);

}  // namespace shadelab
