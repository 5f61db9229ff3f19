// probeToJson (core/probe/probe.hpp): the probe's result as the JSON `shadelab --probe X,Y` prints. Kept
// apart from probe.cpp so only this unit compiles nlohmann::json.
#include "core/probe/probe.hpp"

#include <nlohmann/json.hpp>

#include <cmath>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace shadelab {
namespace {

// ordered_json: the fields in the order a reader wants them (pixel, mode, point, terms, total), not sorted.
using json = nlohmann::ordered_json;

// Seven significant digits: what a float holds, without the binary tail a double print would add
// (0.1f is 0.100000001490116...).
double number(float v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.7g", double(v));
    return std::strtod(text, nullptr);
}

json vec(const glm::vec3& v) { return json::array({number(v.x), number(v.y), number(v.z)}); }
json ivec(const glm::ivec3& v) { return json::array({v.x, v.y, v.z}); }

const char* siteName(ProbeEvaluation::Site s) {
    switch (s) {
    case ProbeEvaluation::Site::Point: return "point";
    case ProbeEvaluation::Site::Centroid: return "centroid";
    case ProbeEvaluation::Site::Vertex: return "vertex";
    }
    return "point";
}

// Mirror and glass at the point: R, T (null past the critical angle), the angles, the indices, F (null
// without Fresnel: both weights 1) and the two terms k_r F env(R), k_t (1 - F) env(T).
json environmentJson(const EnvironmentTerm& t) {
    const double toDeg = 180.0 / 3.14159265358979323846;
    json j;
    j["R"] = vec(t.reflectedDirection);
    j["T"] = t.totalInternal ? json(nullptr) : vec(t.transmittedDirection);
    j["theta_i_deg"] = number(float(std::acos(double(t.cosThetaI)) * toDeg));
    j["theta_t_deg"] = t.totalInternal ? json(nullptr) : json(number(float(std::acos(double(t.cosThetaT)) * toDeg)));
    j["eta_i"] = number(t.eta.etaI);
    j["eta_t"] = number(t.eta.etaT);
    j["F"] = t.weighted || t.totalInternal ? json(number(t.fresnel)) : json(nullptr);
    j["reflected"] = vec(t.reflected);
    j["transmitted"] = vec(t.transmitted);
    return j;
}

json evaluationJson(const Scene& scene, const ProbeEvaluation& e) {
    json j;
    j["at"] = siteName(e.site);
    if (e.site == ProbeEvaluation::Site::Vertex) j["vertex"] = e.vertex;
    j["position"] = vec(e.posWorld);
    j["N"] = vec(e.nrmWorld);
    j["V"] = vec(e.viewWorld);
    json lights = json::array();
    for (std::size_t l = 0; l < e.lights.size(); ++l) {
        const ProbeLight& p = e.lights[l];
        json light = {{"light", l},
                      {"type", toString(scene.lights[l].type)},
                      {"I", vec(p.towardLight)},
                      {"N.I", number(p.nDotI)},
                      {"R", vec(p.reflected)},
                      {"R.V", number(p.rDotV)},
                      {"H", vec(p.halfway)},
                      {"H.N", number(p.hDotN)},
                      {"diffuse", vec(p.diffuse)},
                      {"specular", vec(p.specular)}};
        light["exponent"] = number(p.exponent);
        if (e.anisotropic) {
            light["tangent"] = vec(e.frame.tangent);
            light["bitangent"] = vec(e.frame.bitangent);
        }
        if (scene.lights[l].type == LightType::Area)
            light["samples"] = json::array({scene.lights[l].samples.x, scene.lights[l].samples.y});
        if (scene.shadows.enabled) {
            light["visibility"] = number(p.visibility);
            light["samples_tested"] = p.samplesTested;
            light["samples_visible"] = p.samplesVisible;
        }
        lights.push_back(std::move(light));
    }
    j["lights"] = std::move(lights);
    if (scene.emissiveModel || e.terms.emissive != glm::vec3(0.0f)) j["emissive"] = vec(e.terms.emissive);
    j["ambient"] = vec(e.terms.ambient);
    j["diffuse"] = vec(e.terms.diffuse);
    j["specular"] = vec(e.terms.specular);
    if (e.mirrorGlass) j["environment"] = environmentJson(e.environment);
    j["sum"] = vec(e.terms.shown);
    j["total"] = vec(e.terms.total);
    return j;
}

// The fields of one mode's answer, written into `j`.
void writeMode(const Scene& scene, const ProbeResult& r, const ModeProbe& m, json& j) {
    j["mode"] = toString(m.mode);
    json evaluations = json::array();
    for (std::size_t k = 0; k < m.evaluations.size(); ++k) {
        json e = evaluationJson(scene, m.evaluations[k]);
        if (m.mode == ShadingMode::Gouraud) e["weight"] = number(r.anchor.barycentric[int(k)]);
        evaluations.push_back(std::move(e));
    }
    j["evaluations"] = std::move(evaluations);
    j["color"] = vec(m.color);
    j["output"] = vec(m.output);
    j["output_8bit"] = ivec(m.output8);
}

// Pretty-printed like json::dump(2), except that an array of numbers stays on one line: a vector reads
// as [0.29, 0.54, 0.79], not as five lines.
void writeReadable(std::string& out, const json& j, int depth) {
    const bool numbers = j.is_array() && std::all_of(j.begin(), j.end(), [](const json& e) { return e.is_number(); });
    if (numbers) {
        out += '[';
        for (std::size_t i = 0; i < j.size(); ++i) out += (i ? ", " : "") + j[i].dump();
        out += ']';
        return;
    }
    if (!j.is_structured() || j.empty()) {
        out += j.dump();
        return;
    }
    const std::string indent(2 * std::size_t(depth + 1), ' ');
    out += j.is_object() ? "{\n" : "[\n";
    bool first = true;
    for (auto it = j.begin(); it != j.end(); ++it) {
        out += (first ? "" : ",\n") + indent;
        first = false;
        if (j.is_object()) out += json(it.key()).dump() + ": ";
        writeReadable(out, it.value(), depth + 1);
    }
    out += "\n" + std::string(2 * std::size_t(depth), ' ') + (j.is_object() ? "}" : "]");
}

std::string readable(const json& j) {
    std::string out;
    writeReadable(out, j, 0);
    return out;
}

// The material as drawn at the point (the glTF part's C, its texel, E and coverage where it has them).
void writeMaterial(const Scene& scene, const ProbeResult& r, json& j) {
    const Material& m = r.material;
    j["material"] = {{"C", vec(m.color)},  {"S", vec(m.specularColor)}, {"ka", number(m.ka)},
                     {"kd", number(m.kd)}, {"ks", number(m.ks)},        {"ke", number(m.ke)}};
    if (m.mirror > 0.0f) j["material"]["mirror"] = number(m.mirror);
    if (m.transmission > 0.0f) j["material"]["transmission"] = number(m.transmission);
    if (m.anisotropic) j["material"]["anisotropy"] = json::array({number(m.anisotropy.x), number(m.anisotropy.y)});
    if (r.textured) {
        // C = base colour x texel: flat and Gouraud evaluate their terms with the base colour and
        // multiply the ambient and diffuse parts by the texel per fragment; Phong evaluates with C.
        j["material"]["C_base"] = vec(r.baseColor);
        j["texture"] = {{"texcoord", {number(r.texcoord.x), number(r.texcoord.y)}}, {"texel", vec(r.texel)}};
    }
    // What a glTF material adds: E (the emission at the point; flat and Gouraud add it per fragment
    // where it varies) and the coverage.
    if (m.emissive != glm::vec3(0.0f) || scene.emissiveModel) j["material"]["E"] = vec(m.emissive);
    if (r.alphaMode != AlphaMode::Opaque) {
        j["alpha"] = {{"mode", r.alphaMode == AlphaMode::Mask ? "mask" : "blend"}, {"alpha", number(r.alpha)}};
        if (r.alphaMode == AlphaMode::Mask) j["alpha"]["cutoff"] = number(r.alphaCutoff);
    }
}

}  // namespace

std::string probeToJson(const Scene& scene, const ProbeResult& r) {
    json j;
    j["pixel"] = json::array({r.x, r.y});
    j["size"] = json::array({scene.width, scene.height});
    j["layout"] = toString(scene.layout);
    if (r.pane >= 0) {
        j["pane"] = {{"index", r.pane},
                     {"rect", json::array({r.paneRect.x, r.paneRect.y, r.paneRect.width, r.paneRect.height})}};
        j["mode"] = r.paneRect.difference ? "difference" : toString(r.paneRect.mode);
    } else {
        j["pane"] = nullptr;  // the diff layout's spare columns: background
        j["mode"] = nullptr;
    }
    j["miss"] = r.miss;
    if (r.miss) {
        j["background"] = vec(scene.background);
        j["output_8bit"] = ivec(r.output8);
        return readable(j);
    }
    j["object"] = r.anchor.object;
    j["triangle"] = r.anchor.triangle;
    j["barycentric"] = vec(r.anchor.barycentric);
    j["position"] = vec(r.posWorld);
    if (r.doubleSided) {  // only for double-sided parts: a single-sided part is seen from the front
        j["double_sided"] = true;
        j["back_face"] = r.backFace;  // true: every N below is the surface's normal flipped
    }
    j["eye"] = vec(scene.camera.eye);
    j["reflection"] = toString(scene.reflection);
    j["specular_normalization"] = toString(scene.specularNormalization);
    j["fresnel"] = toString(scene.fresnel);
    j["show"] = toString(scene.show);
    j["output_encoding"] = toString(scene.outputEncoding);
    writeMaterial(scene, r, j);
    j["ambient_A"] = vec(scene.ambient);
    j["shadows"] = {{"enabled", scene.shadows.enabled}};
    if (scene.shadows.enabled)
        j["shadows"]["test"] =
            "ray cast on the CPU toward each light sample; the renderer uses shadow maps, so "
            "within a few shadow-map texels of a shadow's edge the pixel can differ";
    if (r.paneRect.difference) {
        writeMode(scene, r, r.modes[0], j["a"]);
        writeMode(scene, r, r.modes[1], j["b"]);
        j["factor"] = number(scene.diff.factor);
        j["output_8bit"] = ivec(r.output8);
    } else {
        writeMode(scene, r, r.modes[0], j);
    }
    return readable(j);
}

}  // namespace shadelab
