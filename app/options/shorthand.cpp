#include "options/shorthand.hpp"

#include "core/base/error.hpp"
#include "core/base/file_io.hpp"
#include "core/base/message.hpp"
#include "core/scene/scene_limits.hpp"
#include "core/scene/scene_names.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <sstream>
#include <vector>

namespace shadelab {

namespace fs = std::filesystem;

MeshSpec parseMeshShorthand(const std::string& text, const std::string& opt) {
    MeshSpec m;
    std::vector<std::string> parts;
    std::stringstream ss(text);
    for (std::string p; std::getline(ss, p, ':');) parts.push_back(p);
    if (parts.empty()) throw InputError(opt + ": empty mesh");
    auto intArg = [&](size_t i, int& out, const Range<int>& range) {
        if (i >= parts.size()) return;
        const std::string& p = parts[i];
        size_t used = 0;
        long v = 0;
        try {
            v = std::stol(p, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != p.size() || p.empty()) throw InputError(opt + ": \"" + quoteInput(p) + "\" is not an integer");
        if (v < range.lo || v > range.hi)
            throw InputError(opt + ": " + p + " is out of range (" + rangeText(range) + ")");
        out = static_cast<int>(v);
    };
    const std::string& kind = parts[0];
    const std::optional<MeshSpec::Type> type = valueNamed(kMeshTypeNames, kind);
    if (!type || *type == MeshSpec::Type::Gltf) {  // a model is given by its file name, not "gltf"
        if (!hasModelExtension(text))
            throw InputError(opt + ": unknown mesh \"" + kind +
                             "\" (expected uvsphere[:slices[:stacks]], icosphere[:n], torus[:major[:minor]], cube, "
                             "plane[:n], or a .gltf/.glb file)");
        m.type = MeshSpec::Type::Gltf;
        m.path = text;
        m.resolvedPath = fs::path(text).lexically_normal().string();
        return m;
    }
    m.type = *type;
    size_t maxParts = 1;
    switch (m.type) {
    case MeshSpec::Type::UvSphere:
        intArg(1, m.slices, kUvSphereSlicesRange);
        intArg(2, m.stacks, kUvSphereStacksRange);
        maxParts = 3;
        break;
    case MeshSpec::Type::IcoSphere:
        intArg(1, m.subdivisions, kIcoSphereSubdivisionsRange);
        maxParts = 2;
        break;
    case MeshSpec::Type::Torus:
        intArg(1, m.majorSegments, kTorusSegmentsRange);
        intArg(2, m.minorSegments, kTorusSegmentsRange);
        maxParts = 3;
        break;
    case MeshSpec::Type::Plane:
        intArg(1, m.planeSubdivisions, kPlaneSubdivisionsRange);
        maxParts = 2;
        break;
    case MeshSpec::Type::Cube:
    case MeshSpec::Type::Gltf: break;
    }
    if (parts.size() > maxParts) throw InputError(opt + ": too many ':' parameters for " + kind);
    return m;
}

namespace {

// The --light shorthand TYPE:X,Y,Z[:KEY=VALUE]... read into a Light; every error names the option and
// quotes the text.
class LightShorthand {
public:
    LightShorthand(const std::string& text, const std::string& opt) : text_(text), opt_(opt) {
        std::stringstream ss(text);
        for (std::string p; std::getline(ss, p, ':');) parts_.push_back(p);
    }

    Light read() {
        if (parts_.size() < 2) fail("expected TYPE:X,Y,Z[:KEY=VALUE...], e.g. point:1,2,3:intensity=2");
        readTypeAndPlace(parts_[0], parts_[1]);
        for (std::size_t i = 2; i < parts_.size(); ++i) readKey(parts_[i]);
        if (rangeGiven_ && l_.attenuation != Attenuation::InverseSquare) fail("range needs attenuation=inverse-square");
        if (l_.type == LightType::Spot) {
            if (!innerGiven_) l_.innerConeDeg = 0.5f * l_.outerConeDeg;
            if (l_.innerConeDeg >= l_.outerConeDeg) fail("inner must be less than outer (degrees from the axis)");
        }
        return l_;
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw InputError(opt_ + ": " + what + " (in \"" + quoteInput(text_) + "\")");
    }

    // `count` numbers in lo..hi separated by `sep`.
    std::vector<float> numbers(const std::string& key, const std::string& v, std::size_t count, char sep, double lo,
                               double hi) const {
        std::vector<float> out;
        std::stringstream vs(v);
        for (std::string item; std::getline(vs, item, sep);) {
            char* end = nullptr;
            const float x = std::strtof(item.c_str(), &end);
            if (item.empty() || end != item.c_str() + item.size() || !std::isfinite(x))
                fail(key + ": \"" + quoteInput(item) + "\" is not a number");
            if (x < lo || x > hi)
                fail(key + ": " + item + " is out of range (" + formatNumber(lo) + ".." + formatNumber(hi) + ")");
            out.push_back(x);
        }
        if (out.size() != count || (!v.empty() && v.back() == sep))
            fail(key + ": expected " + std::to_string(count) + " numbers separated by '" + std::string(1, sep) + "'");
        return out;
    }
    float number(const std::string& key, const std::string& v, double lo, double hi) const {
        return numbers(key, v, 1, ',', lo, hi)[0];
    }
    glm::vec3 vec3Of(const std::string& key, const std::string& v, double lo, double hi) const {
        const std::vector<float> n = numbers(key, v, 3, ',', lo, hi);
        return glm::vec3(n[0], n[1], n[2]);
    }
    // A direction or normal: not (nearly) zero.
    glm::vec3 nonZeroVec3Of(const std::string& key, const std::string& v) const {
        const glm::vec3 d = vec3Of(key, v, kCoordinateRange.lo, kCoordinateRange.hi);
        if (glm::length(d) < 1e-6f) fail(key + ": must not be a zero-length vector");
        return d;
    }

    // TYPE and X,Y,Z: a directional light's travel direction, the others' position (an area light's centre).
    void readTypeAndPlace(const std::string& type, const std::string& xyz) {
        const std::optional<LightType> lightType = valueNamed(kLightTypeNames, type);
        if (!lightType)
            fail("unknown light type \"" + quoteInput(type) + "\" (expected " +
                 namesList(kLightTypeNames, ", ", " or ") + ")");
        l_.type = *lightType;
        const glm::vec3 where = vec3Of(type, xyz, kCoordinateRange.lo, kCoordinateRange.hi);
        if (l_.type == LightType::Directional) {
            if (glm::length(where) < 1e-6f) fail("a direction must not be a zero-length vector");
            l_.direction = where;
        } else {
            l_.position = where;
        }
    }

    // One KEY=VALUE (or "two-sided"); which keys a light takes depends on its type.
    void readKey(const std::string& kv) {
        const std::size_t eq = kv.find('=');
        const std::string key = kv.substr(0, eq), value = eq == std::string::npos ? "" : kv.substr(eq + 1);
        if (key == "two-sided" && l_.type == LightType::Area && eq == std::string::npos) {
            l_.twoSided = true;
            return;
        }
        if (eq == std::string::npos) fail("expected KEY=VALUE, got \"" + quoteInput(kv) + "\"");
        if (key == "color") l_.color = vec3Of(key, value, 0.0, 1.0);
        else if (key == "intensity") l_.intensity = number(key, value, kIntensityRange.lo, kIntensityRange.hi);
        else if (!readAttenuationKey(key, value) && !readAreaKey(key, value) && !readSpotKey(key, value))
            fail("unknown key \"" + quoteInput(key) + "\" for a " + parts_[0] + " light (" + keysOfType() + ")");
    }
    // attenuation, range: point, spot and area lights.
    bool readAttenuationKey(const std::string& key, const std::string& value) {
        if (l_.type == LightType::Directional) return false;
        if (key == "attenuation") {
            const std::optional<Attenuation> a = valueNamed(kAttenuationNames, value);
            if (!a)
                fail("attenuation: unknown value \"" + quoteInput(value) + "\" (expected " +
                     namesList(kAttenuationNames, ", ", " or ") + ")");
            l_.attenuation = *a;
        } else if (key == "range") {
            l_.range = number(key, value, kLightRangeRange.lo, kLightRangeRange.hi);
            rangeGiven_ = true;
        } else {
            return false;
        }
        return true;
    }
    bool readAreaKey(const std::string& key, const std::string& value) {
        if (l_.type != LightType::Area) return false;
        if (key == "normal") {
            l_.normal = nonZeroVec3Of(key, value);
        } else if (key == "size") {
            const std::vector<float> wh = numbers(key, value, 2, ',', kSizeRange.lo, kSizeRange.hi);
            l_.size = {wh[0], wh[1]};
        } else if (key == "samples") {
            const std::vector<float> n = numbers(key, value, 2, 'x', 1, kAreaSamplesPerSideRange.hi);
            if (n[0] != std::floor(n[0]) || n[1] != std::floor(n[1]))
                fail("samples: expected NXxNY integers, e.g. 8x8");
            l_.samples = {int(n[0]), int(n[1])};
        } else {
            return false;
        }
        return true;
    }
    bool readSpotKey(const std::string& key, const std::string& value) {
        if (l_.type != LightType::Spot) return false;
        if (key == "direction") {
            l_.direction = nonZeroVec3Of(key, value);
        } else if (key == "outer") {
            l_.outerConeDeg = number(key, value, kSpotOuterConeDegRange.lo, kSpotOuterConeDegRange.hi);
        } else if (key == "inner") {
            l_.innerConeDeg = number(key, value, kSpotConeDegRange.lo, kSpotConeDegRange.hi);
            innerGiven_ = true;
        } else {
            return false;
        }
        return true;
    }
    const char* keysOfType() const {
        switch (l_.type) {
        case LightType::Area: return "color, intensity, attenuation, range, normal, size, samples, two-sided";
        case LightType::Spot: return "direction, inner, outer, color, intensity, attenuation, range";
        case LightType::Point: return "color, intensity, attenuation, range";
        case LightType::Directional: break;
        }
        return "color, intensity";
    }

    const std::string& text_;
    const std::string& opt_;
    std::vector<std::string> parts_;
    Light l_;
    bool rangeGiven_ = false, innerGiven_ = false;
};

}  // namespace

Light parseLightShorthand(const std::string& text, const std::string& opt) { return LightShorthand(text, opt).read(); }

std::string shortestNumber(float value) {
    char text[32];
    // Whole numbers in full ("40", not "4e+01"); others with the fewest significant digits that read back.
    if (value == std::floor(value) && std::fabs(value) < 1e9f) {
        std::snprintf(text, sizeof text, "%.0f", double(value));
        return text;
    }
    for (int digits = 1; digits <= 9; ++digits) {
        std::snprintf(text, sizeof text, "%.*g", digits, double(value));
        if (std::strtof(text, nullptr) == value) break;
    }
    return text;
}

namespace {

std::string numbers(const float* v, int count, char separator = ',') {
    std::string s;
    for (int i = 0; i < count; ++i) s += (i ? std::string(1, separator) : std::string()) + shortestNumber(v[i]);
    return s;
}

// ":KEY=VALUE" when the value differs from the one the shorthand leaves it at.
template <typename T>
std::string keyUnlessDefault(const char* key, const T& value, const T& unset, const std::string& written) {
    return value == unset ? std::string() : std::string(":") + key + "=" + written;
}

}  // namespace

std::string meshShorthand(const MeshSpec& m) {
    std::string type = toString(m.type);
    switch (m.type) {
    case MeshSpec::Type::UvSphere: return type + ":" + std::to_string(m.slices) + ":" + std::to_string(m.stacks);
    case MeshSpec::Type::IcoSphere: return type + ":" + std::to_string(m.subdivisions);
    case MeshSpec::Type::Torus:
        return type + ":" + std::to_string(m.majorSegments) + ":" + std::to_string(m.minorSegments);
    case MeshSpec::Type::Plane: return type + ":" + std::to_string(m.planeSubdivisions);
    case MeshSpec::Type::Cube: return type;
    case MeshSpec::Type::Gltf: break;
    }
    return m.path;
}

std::string lightShorthand(const Light& l) {
    const Light unset;  // what each key is when the shorthand leaves it out
    std::string s = std::string(toString(l.type)) + ":" +
                    numbers(l.type == LightType::Directional ? &l.direction.x : &l.position.x, 3);
    s += keyUnlessDefault("color", l.color, unset.color, numbers(&l.color.x, 3));
    s += keyUnlessDefault("intensity", l.intensity, unset.intensity, shortestNumber(l.intensity));
    if (l.type == LightType::Directional) return s;
    s += keyUnlessDefault("attenuation", l.attenuation, unset.attenuation, toString(l.attenuation));
    if (l.attenuation == Attenuation::InverseSquare)
        s += keyUnlessDefault("range", l.range, unset.range, shortestNumber(l.range));
    if (l.type == LightType::Area) {
        s += keyUnlessDefault("normal", l.normal, unset.normal, numbers(&l.normal.x, 3));
        s += keyUnlessDefault("size", l.size, unset.size, numbers(&l.size.x, 2));
        s += keyUnlessDefault("samples", l.samples, unset.samples,
                              std::to_string(l.samples.x) + "x" + std::to_string(l.samples.y));
        if (l.twoSided) s += ":two-sided";
    }
    if (l.type == LightType::Spot) {
        s += keyUnlessDefault("direction", l.direction, unset.direction, numbers(&l.direction.x, 3));
        s += keyUnlessDefault("outer", l.outerConeDeg, unset.outerConeDeg, shortestNumber(l.outerConeDeg));
        s += keyUnlessDefault("inner", l.innerConeDeg, 0.5f * l.outerConeDeg, shortestNumber(l.innerConeDeg));
    }
    return s;
}

}  // namespace shadelab
