// The parameter table (core/scene/parameters.hpp) is the one source of each parameter's name, range,
// default and help: the scene reader accepts each row's range ends and refuses just past them under the
// row's name; the defaults are the scene's; each option that sets a parameter has its name, range and
// help; the sweep takes its names, ranges and symbols; sliders lie inside the ranges.
#include "core/base/error.hpp"
#include "core/scene/parameters.hpp"
#include "core/scene/scene_json.hpp"
#include "core/scene/sweep.hpp"
#include "options/option_table.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

using namespace shadelab;
using nlohmann::json;

namespace {

// A value of the row as the scene file writes it: one number, or as many as its components.
json valueJson(const Parameter& p, double v) {
    if (p.components == 1) return p.decimals == 0 ? json(std::llround(v)) : json(v);
    json list = json::array();
    for (int i = 0; i < p.components; ++i) list.push_back(v);
    return list;
}

// A scene file that gives the row the value `v` where scene files hold it; null for a row no scene file
// holds (the plots' incidence). Where each row lives is said here, independently of the table.
json sceneWith(const Parameter& p, double v) {
    const json value = valueJson(p, v);
    switch (p.id) {
    case Param::Ka: case Param::Kd: case Param::Ks: case Param::Ke: case Param::Mirror: case Param::Transmission:
    case Param::Color: case Param::SpecularColor:
        return {{"material", {{p.name, value}}}};
    case Param::Anisotropy: return {{"reflection", "blinn-phong"}, {"material", {{p.name, value}}}};
    case Param::Ior: case Param::Ambient: case Param::Background: return {{p.name, value}};
    case Param::DiffFactor: return {{"diff", {{p.name, value}}}};
    case Param::FovY: return {{"camera", {{p.name, value}}}};
    case Param::Intensity: return {{"lights", {{{"type", "point"}, {p.name, value}}}}};
    case Param::OuterCone:
        return {{"lights", {{{"type", "spot"}, {p.name, value}, {"inner_cone_deg", 0}}}}};
    case Param::InnerCone:  // below the outer cone, which is at its largest
        return {{"lights", {{{"type", "spot"}, {"outer_cone_deg", 90}, {p.name, std::min(v, 89.0)}}}}};
    case Param::UvSphereSlices: case Param::UvSphereStacks:
        return {{"mesh", {{"type", "uvsphere"}, {p.name, value}}}};
    case Param::IcoSphereSubdivisions: return {{"mesh", {{"type", "icosphere"}, {p.name, value}}}};
    case Param::TorusMajorSegments: case Param::TorusMinorSegments:
        return {{"mesh", {{"type", "torus"}, {p.name, value}}}};
    case Param::PlaneSubdivisions: return {{"mesh", {{"type", "plane"}, {p.name, value}}}};
    case Param::NormalBias: case Param::DepthBias: case Param::Pcf: return {{"shadow_settings", {{p.name, value}}}};
    case Param::Incidence: break;
    }
    return nullptr;
}

std::string readError(const json& scene) {
    try {
        parseScene(scene.dump(), "t.json", ".");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

// Past the range's end by a step the reader sees (an integer's next value, else 1% of the range).
double beyond(const Parameter& p, double end, int direction) {
    const double step = p.decimals == 0 ? 1.0 : std::max(std::fabs(end) * 0.01, (p.range.hi - p.range.lo) * 0.01);
    return end + direction * step;
}

}  // namespace

TEST(Parameters, TheSceneReaderTakesEachRowsNameAndRange) {
    int checked = 0;
    for (const Parameter* p = parametersBegin(); p != parametersEnd(); ++p) {
        if (sceneWith(*p, 0).is_null()) continue;
        // Inner cone: the outer (at most 90) bounds it before its own range does.
        const double hi = p->id == Param::InnerCone ? 89.0 : p->range.hi;
        EXPECT_EQ(readError(sceneWith(*p, p->range.lo)), "") << p->name << " = " << p->range.lo;
        EXPECT_EQ(readError(sceneWith(*p, hi)), "") << p->name << " = " << hi;
        // The message names the field by the row's name ("material.ke: ...", "ambient[0]: ...").
        const std::string field = std::string(p->name) + (p->components > 1 ? "[0]" : "");
        const std::string low = readError(sceneWith(*p, beyond(*p, p->range.lo, -1)));
        EXPECT_NE(low.find(field + ": must be >= "), std::string::npos) << p->name << ": " << low;
        if (p->id != Param::InnerCone) {
            const std::string high = readError(sceneWith(*p, beyond(*p, p->range.hi, +1)));
            EXPECT_NE(high.find(field + ": must be <= "), std::string::npos) << p->name << ": " << high;
        }
        ++checked;
    }
    EXPECT_GE(checked, 25);
}

TEST(Parameters, DefaultsAreTheScenesDefaults) {
    Scene scene;
    Material material;
    Light light;
    for (const Parameter* p = parametersBegin(); p != parametersEnd(); ++p) {
        if (std::isnan(p->defaultValue)) continue;
        const ParameterField& f = p->field;
        double actual = NAN;
        if (f.material) actual = *f.material(material);
        if (f.scene) actual = *f.scene(scene);
        if (f.sceneInteger) actual = *f.sceneInteger(scene);
        if (f.light) actual = *f.light(light);
        if (f.mesh) {
            MeshSpec mesh;
            actual = *f.mesh(mesh);
        }
        if (p->id == Param::Incidence) actual = 45.0;  // PlotSettings' default (viewer) and --plot's
        EXPECT_FLOAT_EQ(float(actual), float(p->defaultValue)) << p->name;
        for (int i = 1; f.material && i < p->components; ++i) {
            EXPECT_FLOAT_EQ(f.material(material)[i], float(p->defaultValue)) << p->name;
        }
    }
}

TEST(Parameters, SlidersLieInsideTheRanges) {
    for (const Parameter* p = parametersBegin(); p != parametersEnd(); ++p) {
        EXPECT_LT(p->slider.lo, p->slider.hi) << p->name;
        EXPECT_GE(p->slider.lo, p->range.lo) << p->name;
        EXPECT_LE(p->slider.hi, p->range.hi) << p->name;
        if (p->scale == SliderScale::Log) {
            EXPECT_GT(p->slider.lo, 0.0) << p->name << ": a logarithmic slider starts above 0";
        }
        if (!std::isnan(p->defaultValue)) {
            EXPECT_GE(p->defaultValue, p->range.lo) << p->name;
            EXPECT_LE(p->defaultValue, p->range.hi) << p->name;
        }
        EXPECT_TRUE(*p->label && *p->symbol && *p->help) << p->name;
        EXPECT_EQ(p, &parameter(p->id)) << p->name << ": the table is in Param's order";
    }
}

TEST(Parameters, EachOptionOfAParameterIsItsRow) {
    int options = 0;
    for (const Parameter* p = parametersBegin(); p != parametersEnd(); ++p) {
        if (!*p->option) continue;
        const OptionSpec* o = findOption(p->option);
        ASSERT_NE(o, nullptr) << p->option;
        EXPECT_EQ(parameterOfOption(p->option), p);
        EXPECT_TRUE(o->bounds.given) << p->option;
        EXPECT_EQ(o->bounds.lo, p->range.lo) << p->option;
        EXPECT_EQ(o->bounds.hi, p->range.hi) << p->option;
        EXPECT_STREQ(o->help, p->help) << p->option;
        EXPECT_EQ(optionSection(*o), p->section) << p->option;
        // The field it overrides ends in the parameter's scene-file name ("objects[].material.ke").
        if (!o->sets.empty()) {
            EXPECT_EQ(o->sets.substr(o->sets.size() - std::string(p->name).size()), p->name) << p->option;
        }
        // "{default}" is filled in from the row.
        const std::string help = optionHelp(*o);
        EXPECT_EQ(help.find('{'), std::string::npos) << p->option << ": " << help;
        ++options;
    }
    EXPECT_GE(options, 14);
}

TEST(Parameters, TheSweepTakesNamesRangesAndSymbols) {
    for (Param id : {Param::Ka, Param::Kd, Param::Ks, Param::Ke, Param::Intensity, Param::Ior}) {
        const Parameter& p = parameter(id);
        const std::string name = p.name;
        EXPECT_NO_THROW(parseSweep(name + "=" + formatNumber(p.range.lo) + "," + formatNumber(p.range.hi), "--sweep"))
            << name;
        EXPECT_THROW(parseSweep(name + "=" + formatNumber(beyond(p, p.range.hi, +1)), "--sweep"), InputError) << name;
        const Sweep sweep = parseSweep(name + "=2", "--sweep");
        EXPECT_EQ(sweepLabel(sweep, 0), std::string(p.symbol) + "=2");
        Scene scene;
        scene.lights.emplace_back();
        applySweep(scene, sweep, 0, "--sweep");
        const ParameterField& f = p.field;
        float value = 0.0f;
        if (f.material) value = *f.material(scene.objects.at(0).material);
        if (f.light) value = *f.light(scene.lights[0]);
        if (f.scene) value = *f.scene(scene);
        EXPECT_FLOAT_EQ(value, 2.0f) << name;
    }
}

TEST(Parameters, MeshRowsAreFoundByTypeAndName) {
    EXPECT_EQ(meshParameter(MeshSpec::Type::IcoSphere, "subdivisions")->id, Param::IcoSphereSubdivisions);
    EXPECT_EQ(meshParameter(MeshSpec::Type::Plane, "subdivisions")->id, Param::PlaneSubdivisions);
    EXPECT_EQ(meshParameter(MeshSpec::Type::Cube, "subdivisions"), nullptr);
    EXPECT_EQ(parameterNamed("subdivisions"), nullptr) << "mesh rows are found by their mesh type";
    EXPECT_EQ(parameterNamed("ke")->id, Param::Ke);
}
