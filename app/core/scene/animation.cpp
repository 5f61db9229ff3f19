#include "core/scene/animation.hpp"

#include "core/base/error.hpp"
#include "core/base/message.hpp"
#include "core/scene/scene_limits.hpp"
#include "core/scene/sweep.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace shadelab {
namespace {

const char* const kForms = "light-orbit[:SECONDS], camera-orbit[:SECONDS] or PARAM=A..B[:log][:SECONDS]";

std::vector<std::string> split(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::stringstream in(text);
    for (std::string part; std::getline(in, part, separator);) parts.push_back(part);
    if (!text.empty() && text.back() == separator) parts.emplace_back();
    return parts;
}

double parseSeconds(const std::string& v, const std::string& where) {
    char* end = nullptr;
    const double x = std::strtod(v.c_str(), &end);
    if (v.empty() || end != v.c_str() + v.size() || !std::isfinite(x))
        throw InputError(where + ": \"" + quoteInput(v) + "\" is not a number of seconds");
    if (!(x > 0.0 && x <= kMaxAnimationSeconds))
        throw InputError(where + ": " + v + " seconds is out of range (more than 0, at most " +
                         formatNumber(kMaxAnimationSeconds) + ")");
    return x;
}

// "ke=1..1000" into the ramp's parameter and bounds, each bound checked as --sweep checks a value.
void parseRamp(Animation& a, const std::string& range, const std::string& flag) {
    const std::string where = flag + ": " + quoteInput(a.text);
    const std::size_t eq = range.find('=');
    const std::size_t dots = range.find("..", eq == std::string::npos ? 0 : eq);
    if (eq == std::string::npos || dots == std::string::npos)
        throw InputError(where + ": \"" + quoteInput(range) + "\" is not an animation (expected " + kForms + ")");
    a.parameter = range.substr(0, eq);
    a.from = range.substr(eq + 1, dots - eq - 1);
    a.to = range.substr(dots + 2);
    if (a.from.empty() || a.to.empty()) throw InputError(where + ": a ramp needs both ends, A..B (e.g. ke=1..1000)");
    parseSweep(a.parameter + "=" + a.from + "," + a.to, where);  // the parameter and both ends, or throws
}

// A ramp's value at u in [0, 1]: interpolated (rounded for whole numbers), or A then B for names.
std::string rampValue(const Animation& a, double u) {
    if (u <= 0.0) return a.from;
    if (u >= 1.0) return a.to;
    const SweepValues values = sweepValues(a.parameter);
    if (values == SweepValues::Name) return u < 0.5 ? a.from : a.to;
    const double lo = std::strtod(a.from.c_str(), nullptr), hi = std::strtod(a.to.c_str(), nullptr);
    double x = a.logarithmic ? lo * std::pow(hi / lo, u) : lo + (hi - lo) * u;
    if (values == SweepValues::Integer) x = std::round(x);
    char text[40];
    std::snprintf(text, sizeof text, "%.9g", x);  // 9 digits: a float's value exactly
    return text;
}

// `v` turned by `angle` radians about `axis` (a unit vector).
glm::vec3 turned(const glm::vec3& v, const glm::vec3& axis, float angle) {
    return glm::vec3(glm::rotate(glm::mat4(1.0f), angle, axis) * glm::vec4(v, 0.0f));
}

void orbitLight(Scene& s, float angle, const std::string& where) {
    if (s.lights.empty()) throw InputError(where + ": the scene has no light to orbit");
    const glm::vec3 axis = glm::normalize(s.camera.up), pivot = s.camera.target;
    Light& l = s.lights.front();
    l.position = pivot + turned(l.position - pivot, axis, angle);  // its height along the axis is kept
    l.direction = turned(l.direction, axis, angle);                // directional and spot lights
    l.normal = turned(l.normal, axis, angle);                      // area lights
}

}  // namespace

Animation parseAnimation(const std::string& spec, const std::string& flag) {
    Animation a;
    a.text = spec;
    const std::string where = flag + ": " + quoteInput(spec);
    std::vector<std::string> parts = split(spec, ':');
    if (parts.empty() || parts.size() > 3) throw InputError(where + ": not an animation (expected " + kForms + ")");
    if (parts[0] == "light-orbit" || parts[0] == "camera-orbit") {
        a.kind = parts[0] == "light-orbit" ? Animation::Kind::LightOrbit : Animation::Kind::CameraOrbit;
        if (parts.size() > 2) throw InputError(where + ": an orbit takes only :SECONDS (expected " + kForms + ")");
        if (parts.size() == 2) a.seconds = parseSeconds(parts[1], where);
        return a;
    }
    parseRamp(a, parts[0], flag);
    std::size_t next = 1;
    if (next < parts.size() && parts[next] == "log") {
        a.logarithmic = true;
        ++next;
        if (sweepValues(a.parameter) == SweepValues::Name)
            throw InputError(where + ": :log ramps numbers; " + a.parameter + " takes names");
        if (!(std::strtod(a.from.c_str(), nullptr) > 0.0 && std::strtod(a.to.c_str(), nullptr) > 0.0))
            throw InputError(where + ": :log needs both ends above 0");
    }
    if (next < parts.size()) a.seconds = parseSeconds(parts[next++], where);
    if (next < parts.size())
        throw InputError(where + ": \"" + quoteInput(parts[next]) + "\" after the seconds (expected " + kForms + ")");
    return a;
}

double animationsDuration(const std::vector<Animation>& animations) {
    double longest = 0.0;
    for (const Animation& a : animations) longest = std::max(longest, a.seconds);
    return longest;
}

int animationFrameCount(const std::vector<Animation>& animations, double seconds, int fps) {
    const bool ramp = std::any_of(animations.begin(), animations.end(),
                                  [](const Animation& a) { return a.kind == Animation::Kind::Ramp; });
    const int frames = int(std::ceil(seconds * fps - 1e-6));  // the frame at `seconds`, or the first past it
    return std::max(1, ramp ? frames + 1 : frames);
}

Scene sceneAtTime(const Scene& base, const std::vector<Animation>& animations, double t, const std::string& flag) {
    Scene s = base;
    for (const Animation& a : animations) {
        const std::string where = flag + ": " + quoteInput(a.text);
        const float angle = float(2.0 * glm::pi<double>() * std::fmod(t / a.seconds, 1.0));
        switch (a.kind) {
        case Animation::Kind::LightOrbit: orbitLight(s, angle, where); break;
        case Animation::Kind::CameraOrbit:
            s.camera.eye = s.camera.target + turned(s.camera.eye - s.camera.target, glm::normalize(s.camera.up), angle);
            break;
        case Animation::Kind::Ramp: applySweep(s, Sweep{a.parameter, {rampValue(a, t / a.seconds)}}, 0, where); break;
        }
    }
    return s;
}

}  // namespace shadelab
