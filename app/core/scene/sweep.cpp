#include "core/scene/sweep.hpp"

#include "core/base/error.hpp"
#include "core/base/message.hpp"
#include "core/image/text.hpp"
#include "core/scene/parameters.hpp"
#include "core/scene/scene_names.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace shadelab {
namespace {

// A number swept: a parameter of the table (core/scene/parameters.hpp), or the first object's
// tessellation, which sets whichever of its mesh's parameters tessellate it (applySweep).
struct NumericParameter {
    const char* name;
    double lo, hi;
    bool integer;
    const Parameter* row;  // null for "tessellation"
};
NumericParameter swept(Param id) {
    const Parameter& p = parameter(id);
    return {p.name, p.range.lo, p.range.hi, p.decimals == 0, &p};
}
const NumericParameter kNumeric[] = {
    swept(Param::Ke), swept(Param::Ks),        swept(Param::Kd),
    swept(Param::Ka), swept(Param::Intensity), {"tessellation", 1.0, double(kUvSphereSlicesRange.hi), true, nullptr},
    swept(Param::Ior)};

const NumericParameter* numericNamed(const std::string& name) {
    for (const NumericParameter& p : kNumeric)
        if (name == p.name) return &p;
    return nullptr;
}

// Sets `field` to the value `v` names in `names`; false when it names none.
template <typename E, std::size_t N>
bool setNamed(E& field, const EnumName<E> (&names)[N], const std::string& v) {
    const std::optional<E> e = valueNamed(names, v);
    if (e) field = *e;
    return e.has_value();
}

// A parameter whose values are names (core/scene/scene_names.hpp): `apply` sets it, false for an unknown name.
struct NamedParameter {
    const char* name;
    std::string allowed;  // "flat, gouraud, phong"
    bool (*apply)(Scene& scene, const std::string& v);
};
const NamedParameter kNamed[] = {
    {"shading", namesList(kShadingModeNames),
     [](Scene& s, const std::string& v) {
         if (!setNamed(s.shading, kShadingModeNames, v)) return false;
         if (s.layout == Layout::Compare) s.layout = Layout::Single;  // one pane per tile
         return true;
     }},
    {"reflection", namesList(kReflectionModelNames),
     [](Scene& s, const std::string& v) { return setNamed(s.reflection, kReflectionModelNames, v); }},
    {"specular_normalization", namesList(kSpecularNormalizationNames),
     [](Scene& s, const std::string& v) { return setNamed(s.specularNormalization, kSpecularNormalizationNames, v); }},
    {"fresnel", namesList(kFresnelModeNames),
     [](Scene& s, const std::string& v) { return setNamed(s.fresnel, kFresnelModeNames, v); }}};

double number(const std::string& v) { return std::strtod(v.c_str(), nullptr); }

}  // namespace

Sweep parseSweep(const std::string& text, const std::string& flag) {
    const std::size_t eq = text.find('=');
    std::string names;
    for (const auto& p : kNumeric) names += std::string(names.empty() ? "" : ", ") + p.name;
    for (const auto& p : kNamed) names += std::string(", ") + p.name;
    if (eq == std::string::npos)
        throw InputError(flag + ": expected PARAMETER=V1,V2,..., e.g. ke=1,8,32,128,512 (got \"" + quoteInput(text) +
                         "\")");
    Sweep s;
    s.parameter = text.substr(0, eq);
    std::stringstream list(text.substr(eq + 1));
    for (std::string v; std::getline(list, v, ',');) s.values.push_back(v);
    if (s.values.empty() || text.back() == ',')
        throw InputError(flag + ": " + s.parameter + ": empty value in the list");
    if (s.values.size() > kMaxSweepValues)
        throw InputError(flag + ": at most " + std::to_string(kMaxSweepValues) + " values (got " +
                         std::to_string(s.values.size()) + ")");
    for (const auto& p : kNumeric) {
        if (s.parameter != p.name) continue;
        for (const std::string& v : s.values) {
            char* end = nullptr;
            const double x = std::strtod(v.c_str(), &end);
            if (v.empty() || end != v.c_str() + v.size() || !std::isfinite(x))
                throw InputError(flag + ": " + s.parameter + ": \"" + quoteInput(v) + "\" is not a number");
            if (p.integer && x != std::floor(x))
                throw InputError(flag + ": " + s.parameter + ": \"" + quoteInput(v) + "\" is not an integer");
            // A number is applied as a float: compared as one with the range (0.2 is kIorRange's 0.2f).
            const double applied = p.integer ? x : double(float(x));
            if (applied < p.lo || applied > p.hi) {
                std::ostringstream range;
                range << p.lo << ".." << p.hi;
                throw InputError(flag + ": " + s.parameter + ": " + v + " is out of range (" + range.str() + ")");
            }
        }
        return s;
    }
    for (const auto& p : kNamed) {
        if (s.parameter != p.name) continue;
        for (const std::string& v : s.values) {
            Scene scratch;
            if (!p.apply(scratch, v))
                throw InputError(flag + ": " + s.parameter + ": unknown value \"" + quoteInput(v) + "\" (expected " +
                                 p.allowed + ")");
        }
        return s;
    }
    throw InputError(flag + ": unknown parameter \"" + quoteInput(s.parameter) + "\" (expected one of " + names + ")");
}

SweepValues sweepValues(const std::string& parameter) {
    for (const auto& p : kNumeric)
        if (parameter == p.name) return p.integer ? SweepValues::Integer : SweepValues::Number;
    for (const auto& p : kNamed)
        if (parameter == p.name) return SweepValues::Name;
    return SweepValues::Unknown;
}

void applySweep(Scene& scene, const Sweep& sweep, std::size_t index, const std::string& flag) {
    const std::string& v = sweep.values.at(index);
    const std::string& p = sweep.parameter;
    const auto x = float(number(v));
    const NumericParameter* numeric = numericNamed(p);
    if (numeric && numeric->row) {
        const ParameterField& field = numeric->row->field;
        if (field.material)
            for (SceneObject& o : scene.objects) *field.material(o.material) = x;
        if (field.light)
            for (Light& l : scene.lights) *field.light(l) = x;
        if (field.scene) *field.scene(scene) = x;
    } else if (p == "tessellation") {
        if (scene.objects.empty()) throw InputError(flag + ": tessellation: the scene has no object");
        MeshSpec& m = scene.objects[0].mesh;
        const int n = int(x);
        auto need = [&](const Range<int>& range) {
            if (!range.contains(n))
                throw InputError(flag + ": tessellation: " + v + " is out of range for a " + toString(m.type) + " (" +
                                 rangeText(range) + ")");
        };
        // A sphere's stacks and a torus's minor segments are half of n: n is at least twice their minimum.
        const Range<int> uvSphere{2 * kUvSphereStacksRange.lo, kUvSphereSlicesRange.hi};
        const Range<int> torus{2 * kTorusSegmentsRange.lo, kTorusSegmentsRange.hi};
        switch (m.type) {
        case MeshSpec::Type::UvSphere:
            need(uvSphere);
            m.slices = n;
            m.stacks = std::max(n / 2, kUvSphereStacksRange.lo);
            break;
        case MeshSpec::Type::IcoSphere:
            need(kIcoSphereSubdivisionsRange);
            m.subdivisions = n;
            break;
        case MeshSpec::Type::Torus:
            need(torus);
            m.majorSegments = n;
            m.minorSegments = std::max(n / 2, kTorusSegmentsRange.lo);
            break;
        case MeshSpec::Type::Plane:
            need(kPlaneSubdivisionsRange);
            m.planeSubdivisions = n;
            break;
        case MeshSpec::Type::Cube:
        case MeshSpec::Type::Gltf:
            throw InputError(flag + ": tessellation: the first object is a " + std::string(toString(m.type)) +
                             ", which has no tessellation");
        }
    } else {
        for (const NamedParameter& named : kNamed)
            if (p == named.name) named.apply(scene, v);
    }
}

std::string sweepLabel(const Sweep& sweep, std::size_t index) {
    const NumericParameter* numeric = numericNamed(sweep.parameter);
    const std::string name = numeric && numeric->row                       ? numeric->row->symbol
                             : sweep.parameter == "specular_normalization" ? "norm"
                             : sweep.parameter == "tessellation"           ? "tess"
                                                                           : sweep.parameter;
    return name + "=" + sweep.values.at(index);
}

Image contactSheet(const std::vector<Image>& tiles, const std::vector<std::string>& labels, int columns) {
    if (tiles.empty() || columns < 1) return Image();
    const int tw = tiles[0].width, th = tiles[0].height;
    const int gap = 4, bar = textHeight("Ag", kSheetLabelScale) + 10;
    const int rows = (int(tiles.size()) + columns - 1) / columns;
    Image sheet(columns * tw + (columns + 1) * gap, rows * (th + bar) + (rows + 1) * gap);
    fillRect(sheet, 0, 0, sheet.width, sheet.height, Rgba8{40, 40, 44, 255});
    // One label size for the whole sheet: twice the font when every label fits its tile, else 1x
    // (and a label still too long is cut at the tile's width).
    int scale = kSheetLabelScale;
    for (const std::string& l : labels)
        if (textWidth(l, kSheetLabelScale) > tw - 4) scale = 1;
    for (std::size_t i = 0; i < tiles.size(); ++i) {
        const int col = int(i) % columns, row = int(i) / columns;
        const int x0 = gap + col * (tw + gap), y0 = gap + row * (th + bar + gap);
        std::string label = i < labels.size() ? labels[i] : std::string();
        while (!label.empty() && textWidth(label, scale) > tw - 4) label.pop_back();
        const int lw = textWidth(label, scale);
        drawText(sheet, x0 + std::max((tw - lw) / 2, 2), y0 + (bar - textHeight("Ag", scale)) / 2, label, scale,
                 Rgba8{235, 235, 235, 255});
        for (int y = 0; y < th && y < tiles[i].height; ++y)
            for (int x = 0; x < tw && x < tiles[i].width; ++x) {
                const std::uint8_t* s = tiles[i].pixel(x, y);
                std::uint8_t* d = sheet.pixel(x0 + x, y0 + bar + y);
                d[0] = s[0];
                d[1] = s[1];
                d[2] = s[2];
                d[3] = 255;
            }
    }
    return sheet;
}

}  // namespace shadelab
