// The checks the scene reader shares with the command line (scene_json.hpp, "Validation shared with the
// command line"): a term to show, material coefficients, an environment, anisotropy under the reflection
// model, an image size. Each throws InputError "<where>: <what>".
#include "core/scene/scene_json.hpp"

#include "core/base/error.hpp"
#include "core/base/message.hpp"
#include "core/scene/parameters.hpp"
#include "core/scene/scene_names.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>

namespace shadelab {

namespace fs = std::filesystem;

TermView parseTermView(const std::string& text, const std::string& where) {
    const std::string prefix = where.empty() ? std::string() : where + ": ";
    TermView t;
    for (const auto& k : kShowTermNames)
        if (k.second != ShowTerm::Light && text == k.first) {  // light:N below
            t.term = k.second;
            return t;
        }
    if (text.rfind("light:", 0) == 0) {
        const std::string n = text.substr(6);
        char* end = nullptr;
        const long v = std::strtol(n.c_str(), &end, 10);
        if (n.empty() || end != n.c_str() + n.size() || n[0] == '-' || n[0] == '+')
            throw InputError(prefix + "\"" + quoteInput(n) + "\" is not a light index (light:N, N = 0.." +
                             std::to_string(kMaxLights - 1) + ")");
        if (v >= kMaxLights)
            throw InputError(prefix + "light index " + n + " is out of range (0.." + std::to_string(kMaxLights - 1) +
                             ")");
        t.term = ShowTerm::Light;
        t.light = int(v);
        return t;
    }
    throw InputError(prefix + "unknown value \"" + text + "\" (expected one of " + namesList(kShowTermNames) + ")");
}

void checkCoefficients(const Material& m, const std::string& where) {
    auto check = [&](const char* name, float v, float lo, float hi) {
        if (!std::isfinite(v) || v < lo || v > hi)
            throw InputError(where + name + ": must be between " + formatNumber(lo) + " and " + formatNumber(hi) +
                             " (got " + formatNumber(v) + ")");
    };
    for (Param id : {Param::Ka, Param::Kd, Param::Ks, Param::Ke, Param::Mirror, Param::Transmission}) {
        const Parameter& p = parameter(id);
        check(p.name, materialValue(p, m), float(p.range.lo), float(p.range.hi));
    }
}

EnvironmentSpec parseEnvironment(const std::string& text, const std::string& baseDir, const std::string& where) {
    EnvironmentSpec e;
    if (const std::optional<EnvironmentKind> kind = valueNamed(kEnvironmentNames, text)) {
        e.kind = *kind;
        return e;
    }
    if (text.empty()) throw InputError(where + ": expected room, sky, none or a .png or .hdr file");
    e.kind = EnvironmentKind::Image;
    e.path = text;
    const fs::path p(text);
    e.resolvedPath = (p.is_absolute() || baseDir.empty() ? p : fs::path(baseDir) / p).lexically_normal().string();
    try {
        e.image = std::make_shared<const EnvironmentImage>(readEnvironmentImage(e.resolvedPath));
    } catch (const InputError& error) {
        throw InputError(where + ": " + error.what());
    }
    return e;
}

void checkAnisotropy(const Scene& s, const std::string& where) {
    if (s.reflection != ReflectionModel::Phong) return;
    for (const SceneObject& o : s.objects)
        if (o.material.anisotropic)
            throw InputError(where +
                             "anisotropy: Ashikhmin and Shirley's lobe is Blinn-Phong's (about H); it needs "
                             "reflection blinn-phong, not phong");
}

void checkImageSize(int width, int height, const std::string& where) {
    if (width < 1 || height < 1 || width > kImageSideRange.hi || height > kImageSideRange.hi)
        throw InputError(where + ": width and height must be between 1 and " + std::to_string(kImageSideRange.hi) +
                         " (got " + std::to_string(width) + "x" + std::to_string(height) + ")");
}

}  // namespace shadelab
