#pragma once
// The lecture's parameters, each declared once: its scene-file name, its command-line option, its symbol
// in the lecture (k_e), the panel's label, the range every reader accepts, the range and scale of the
// sliders, its default, the panel section it sits in and one line of help. Everything that names,
// checks, shows or edits one of them reads this table:
//   - the scene reader and writer (scene_reader.cpp, scene_writer.cpp) and checkCoefficients
//     (scene_checks.cpp): names and ranges;
//   - the sweep's and --animate's parameters and labels (sweep.cpp): names, ranges and symbols;
//   - the command line (options/option_table.cpp): the rows of --ka, --ke, --ior, ... from these;
//   - the viewer's panel (viewer/panel.cpp, parameterSlider) and the web page (web_app.cpp's
//     sl_describe() "parameters", read by the page's controls): labels, slider ranges, scales, sections;
//   - the ramp readout over the view ("k_e = 37.2") and the Python module's documentation.
// Adding a parameter is one row here plus its use in the shading (docs/architecture.md, "Adding a
// parameter"). GL-free, no I/O.
#include "core/scene/panel_sections.hpp"
#include "core/scene/scene.hpp"
#include "core/scene/scene_limits.hpp"

#include <cstddef>
#include <string>

namespace shadelab {

// How a slider maps its travel to the value: logarithmic gives 1..10 as much travel as 100..1000 (k_e).
enum class SliderScale { Linear, Log };

// Every parameter of the table, in its order (kParameters[int(p)] is p's row).
// (grouped by kind, one group a line: clang-format leaves it as written)
// clang-format off
enum class Param {
    // Material (each object's; the command line's sets every object's).
    Ka, Kd, Ks, Ke, Anisotropy, Mirror, Transmission, Color, SpecularColor,
    // The scene's.
    Ior, DiffFactor, Ambient, Background, FovY,
    // The plots' angle of incidence (the viewer's and --plot's; not in scene files).
    Incidence,
    // Each light's.
    Intensity, OuterCone, InnerCone,
    // The first object's procedural mesh (by mesh type).
    UvSphereSlices, UvSphereStacks, IcoSphereSubdivisions, TorusMajorSegments, TorusMinorSegments, PlaneSubdivisions,
    // Shadows.
    NormalBias, DepthBias, Pcf,
};
// clang-format on

// Where the value lives: one accessor is set, by the parameter's kind (none for Incidence, which is the
// plots' setting, and for the mesh's, whose field depends on the mesh type: MeshSpec's by name).
struct ParameterField {
    float* (*material)(Material&) = nullptr;  // the first of `components` floats
    float* (*scene)(Scene&) = nullptr;
    int* (*sceneInteger)(Scene&) = nullptr;
    float* (*light)(Light&) = nullptr;
    int* (*mesh)(MeshSpec&) = nullptr;  // a mesh of type `meshType` only
    MeshSpec::Type meshType = MeshSpec::Type::Cube;
};

struct Parameter {
    Param id;
    const char* name;      // the scene file's key in its object ("ke"); also the sweep's and --animate's name
    const char* option;    // "--ke"; "" where no option sets it
    const char* symbol;    // as the lecture writes it, in ASCII ("k_e"): sweep labels, the ramp readout
    const char* label;     // the panel's label, as the lecture names it ("k_e exponent")
    PanelSection section;  // where the panel and the page show it
    Range<double> range;   // what scene files, the option and the sweep accept (each component)
    Range<double> slider;  // what the sliders span; typed values take the whole range
    SliderScale scale;
    int decimals;         // the slider shows this many decimals (0: an integer)
    int components;       // 1; 2 (k_t, k_b); 3 (a colour)
    double defaultValue;  // a scene's default (each component's where they are equal; NaN where not)
    const char* help;     // one line: what it is (the option's help adds how it applies)
    ParameterField field = {};
    const char* parts[2] = {};  // two components shown as two sliders: each one's label (k_t, k_b)
};

// The table, in Param's order.
const Parameter* parametersBegin();
const Parameter* parametersEnd();
const Parameter& parameter(Param p);
// The row named `name` that is not a mesh's (mesh rows share names across mesh types); null if none.
const Parameter* parameterNamed(const std::string& name);
// A mesh type's row named `name` ("slices" of a uvsphere); null if none.
const Parameter* meshParameter(MeshSpec::Type type, const std::string& name);
// The row for an option ("--ke"); null when the option sets no parameter.
const Parameter* parameterOfOption(const std::string& option);
// A parameter's (first) value in a material, a scene or a light. The accessors only point at the
// field: reading a const object through them writes nothing.
inline float materialValue(const Parameter& p, const Material& m) {
    return *p.field.material(const_cast<Material&>(m));
}
inline float sceneValue(const Parameter& p, const Scene& s) { return *p.field.scene(const_cast<Scene&>(s)); }
inline float lightValue(const Parameter& p, const Light& l) { return *p.field.light(const_cast<Light&>(l)); }

// "{default}" in a help text: the default as messages print numbers.
std::string defaultText(const Parameter& p);
// The help with "{range}" ("1..10000") and "{default}" filled in.
std::string parameterHelp(const Parameter& p);

}  // namespace shadelab
