#include "viewer/panel.hpp"

#include "core/figures/formula.hpp"
#include "core/figures/plot.hpp"
#include "core/geometry/camera.hpp"
#include "core/scene/panel_sections.hpp"
#include "core/scene/parameters.hpp"
#include "core/scene/scene_names.hpp"
#include "core/ui/controls.hpp"
#include "core/ui/view_names.hpp"
#include "viewer/plot_view.hpp"
#include "viewer/probe_view.hpp"
#include "viewer/shader_view.hpp"

#include <imgui.h>
#include <imgui_internal.h>
#include <imgui_stdlib.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>

namespace shadelab {
namespace {

// Widgets keep every value inside the ranges the scene-file parser accepts (scene_reader.cpp), so a scene
// saved from the panel always loads again. Sliders show the range a lecture sweeps; Ctrl+click types
// a value, which the clamps below bring back into the parser's range.

bool colorEdit(const char* label, glm::vec3& color) {
    if (!ImGui::ColorEdit3(label, &color.x, ImGuiColorEditFlags_Float)) return false;
    color = glm::clamp(color, glm::vec3(0.0f), glm::vec3(1.0f));
    return true;
}

// While the widget just drawn is dragged (or typed into), its value for the large readout over the
// view ("k_e = 37.2"): the panel's numbers are too small for a hall.
void readoutWhileActive(std::string& readout, const char* name, float value) {
    if (ImGui::IsItemActive()) readout = std::string(name) + " = " + formulaNumber(value);
}

// A slider of a parameter of the table (core/scene/parameters.hpp): its label (or `label`), slider range,
// scale and decimals (or `format`); a typed value is clamped into the parameter's range.
bool parameterSlider(Param id, float& value, const char* label = nullptr, const char* format = nullptr) {
    const Parameter& p = parameter(id);
    const std::string decimals = "%." + std::to_string(p.decimals) + "f";
    const bool changed = ImGui::SliderFloat(label ? label : p.label, &value, float(p.slider.lo), float(p.slider.hi),
                                            format ? format : decimals.c_str(),
                                            p.scale == SliderScale::Log ? ImGuiSliderFlags_Logarithmic : 0);
    if (changed) value = std::clamp(value, float(p.range.lo), float(p.range.hi));
    return changed;
}
bool parameterSlider(Param id, int& value) {
    const Parameter& p = parameter(id);
    const bool changed = ImGui::SliderInt(p.label, &value, int(p.slider.lo), int(p.slider.hi));
    if (changed) value = std::clamp(value, int(p.range.lo), int(p.range.hi));
    return changed;
}
// A material parameter's slider that also shows its value large over the view while dragged.
void materialSlider(Param id, Material& m, std::string& readout) {
    const Parameter& p = parameter(id);
    float& value = *p.field.material(m);
    parameterSlider(id, value);
    readoutWhileActive(readout, p.symbol, value);
}

template <typename E>
bool radio(const char* label, E& value, E choice) {
    if (!ImGui::RadioButton(label, value == choice)) return false;
    value = choice;
    return true;
}

// A row: `label`, then its choices' radio buttons side by side, from 6 font sizes in (rows line up).
template <typename E>
void radioRow(const char* label, E& value, std::initializer_list<std::pair<const char*, E>> choices) {
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted(label);
    float indent = ImGui::GetFontSize() * 6.0f;
    for (const auto& [name, choice] : choices) {
        ImGui::SameLine(indent);
        indent = 0.0f;  // the next button right after this one
        radio(name, value, choice);
    }
}

template <typename E, std::size_t N>
bool combo(const char* label, E& value, const char* const (&names)[N]) {
    int index = int(value);
    if (!ImGui::Combo(label, &index, names, int(N))) return false;
    value = E(index);
    return true;
}

// A combo box of an enum's names as scene files and the command line spell them (core/scene/scene_names.hpp).
template <typename E, std::size_t N>
bool combo(const char* label, E& value, const EnumName<E> (&names)[N]) {
    const char* labels[N];
    int index = 0;
    for (std::size_t i = 0; i < N; ++i) {
        labels[i] = names[i].first;
        if (names[i].second == value) index = int(i);
    }
    if (!ImGui::Combo(label, &index, labels, int(N))) return false;
    value = names[index].second;
    return true;
}

// A position, direction or angle triple, within the range scene files allow.
bool dragCoordinates(const char* label, glm::vec3& v, float speed, const char* format) {
    return ImGui::DragFloat3(label, &v.x, speed, float(kCoordinateRange.lo), float(kCoordinateRange.hi), format);
}

// A vector edit that must not become (nearly) zero: light directions, scales.
bool dragNonZero(const char* label, glm::vec3& v, float speed, bool perComponent) {
    glm::vec3 edited = v;
    if (!dragCoordinates(label, edited, speed, "%.3f")) return false;
    const bool zero =
        perComponent ? glm::any(glm::lessThan(glm::abs(edited), glm::vec3(1e-3f))) : glm::length(edited) < 1e-3f;
    if (zero) return false;
    v = edited;
    return true;
}

bool cameraValid(const Camera& c) {
    const glm::vec3 forward = c.target - c.eye;
    if (glm::length(forward) < 1e-4f || glm::length(c.up) < 1e-4f || c.farPlane <= c.nearPlane) return false;
    return glm::length(glm::cross(glm::normalize(forward), glm::normalize(c.up))) >= 1e-3f;
}

void iorSlider(Scene& scene) { parameterSlider(Param::Ior, scene.ior); }

void sectionShading(Scene& scene) {
    radioRow(
        "Shading", scene.shading,
        {{"flat (1)", ShadingMode::Flat}, {"gouraud (2)", ShadingMode::Gouraud}, {"phong (3)", ShadingMode::Phong}});
    bool compare = scene.layout == Layout::Compare;
    if (ImGui::Checkbox("compare: flat | gouraud | phong  (C)", &compare))
        scene.layout = compare ? Layout::Compare : Layout::Single;
    bool diff = scene.layout == Layout::Diff;
    if (ImGui::Checkbox("difference: A | B | |A - B| x factor  (D)", &diff))
        scene.layout = diff ? Layout::Diff : Layout::Single;
    if (diff) {
        ImGui::PushItemWidth(ImGui::GetFontSize() * 6.0f);
        combo("A", scene.diff.a, kShadingModeNames);
        ImGui::SameLine();
        combo("B", scene.diff.b, kShadingModeNames);
        ImGui::PopItemWidth();
        parameterSlider(Param::DiffFactor, scene.diff.factor);
    }
    radioRow("Reflection", scene.reflection,
             {{"Phong", ReflectionModel::Phong}, {"Blinn-Phong", ReflectionModel::BlinnPhong}});
    static const char* const kEncodings[] = {"linear", "sRGB"};
    combo("output encoding", scene.outputEncoding, kEncodings);
    // Beyond the heuristic model (core/shading/lighting.hpp): each switch recompiles the programs once.
    static const char* const kNormalizations[] = {"none (heuristic)", "energy-normalised"};
    combo("lobe normalisation", scene.specularNormalization, kNormalizations);
    static const char* const kFresnel[] = {"none", "Schlick", "exact"};
    combo("Fresnel", scene.fresnel, kFresnel);
    if (scene.fresnel != FresnelMode::None) iorSlider(scene);
    // Term isolation: each addend of the formula alone.
    static const char* const kTerms[] = {"all",       "ambient", "diffuse",   "specular",
                                         "one light", "unlit C", "emissive E"};  // by ShowTerm
    static_assert(std::size(kTerms) == std::size(kShowTermNames), "a label for every ShowTerm");
    combo("show", scene.show.term, kTerms);
    if (scene.show.term == ShowTerm::Light) {
        const int last = std::max(int(scene.lights.size()) - 1, 0);
        ImGui::SliderInt("light", &scene.show.light, 0, last);
        scene.show.light = std::clamp(scene.show.light, 0, last);
    }
}

// `reflection`: anisotropy is Blinn-Phong's lobe; under Phong its controls are greyed out (and not applied).
void sectionMaterial(Material& m, ReflectionModel reflection, std::string& readout) {
    colorEdit(parameter(Param::Color).label, m.color);
    colorEdit(parameter(Param::SpecularColor).label, m.specularColor);
    for (Param id : {Param::Ka, Param::Kd, Param::Ks, Param::Ke}) materialSlider(id, m, readout);
    // Anisotropic reflection (brushed metal): Ashikhmin and Shirley's k_t along the tangent, k_b along
    // the bitangent, in place of k_e; logarithmic like k_e. Switching it on starts both at k_e.
    ImGui::BeginDisabled(reflection != ReflectionModel::BlinnPhong);
    const bool wasOn = m.anisotropic;
    ImGui::Checkbox("anisotropic (Blinn-Phong)", &m.anisotropic);
    if (m.anisotropic && !wasOn) m.anisotropy = glm::vec2(m.ke);
    ImGui::BeginDisabled(!m.anisotropic);
    const Parameter& anisotropy = parameter(Param::Anisotropy);
    for (int i = 0; i < 2; ++i) {
        parameterSlider(Param::Anisotropy, m.anisotropy[i], anisotropy.parts[i]);
        readoutWhileActive(readout, i == 0 ? "k_t" : "k_b", m.anisotropy[i]);
    }
    ImGui::EndDisabled();
    ImGui::EndDisabled();
    // Mirror and glass, added after the sum with the scene's environment (none: they reflect nothing).
    parameterSlider(Param::Mirror, m.mirror);
    parameterSlider(Param::Transmission, m.transmission);
}

// With a probed pixel, the 3-D lobe is that point's: its N, its I toward the selected light (or the first
// lit one) and its V, in its tangent frame when the lobe is anisotropic, and its material. Gouraud
// evaluates at the triangle's corners: corner a's.
struct ProbedLobe {
    LobeIncidence incidence;
    Material material;
    int light = 0;
};
std::optional<ProbedLobe> probedLobe(const Scene& scene, const ProbeResult* probe, int selectedLight) {
    if (!probe || probe->miss || probe->modes.empty() || probe->modes[0].evaluations.empty()) return std::nullopt;
    const ModeProbe& mode = probe->modes[0];
    const ProbeEvaluation& e = mode.evaluations[0];
    std::vector<int> candidates;
    if (selectedLight >= 0 && selectedLight < int(e.lights.size())) candidates.push_back(selectedLight);
    for (int k = 0; k < int(e.lights.size()); ++k) candidates.push_back(k);
    const TangentFrame* frame =
        e.anisotropic && anisotropicLobe(probe->material, lightingEnvironment(scene)) ? &e.frame : nullptr;
    for (int k : candidates) {
        std::optional<LobeIncidence> li =
            lobeIncidenceAt(e.nrmWorld, e.lights[std::size_t(k)].towardLight, e.viewWorld, frame);
        if (!li) continue;
        li->where = "at pixel " + std::to_string(probe->x) + ", " + std::to_string(probe->y) +
                    (mode.mode == ShadingMode::Gouraud ? " (corner a)" : "") + ", light " + std::to_string(k);
        return ProbedLobe{*li, probe->material, k};
    }
    return std::nullopt;
}

// The lecture's plots for the current parameters (core/figures/plot.hpp): rebuilt every frame, which costs
// about a thousand formula evaluations for the 2-D plots (tens of thousands for the BRDF's), so every
// slider in the panel moves the curves at once.
// A slide's "plot" brings its plot to the panel's top, once (a scene's "viewer" field).
void scrollHereFor(const char* plot, std::string& scrollTo) {
    if (scrollTo != plot) return;
    ImGui::SetScrollHereY(0.0f);
    scrollTo.clear();
}

void sectionPlots(Scene& scene, const Material& material, PlotSettings& plots, const ProbeResult* probe,
                  int selectedLight, std::string& scrollTo) {
    static_assert(
        [] {
            for (std::size_t i = 0; i < std::size(kPanelPlots); ++i)
                if (std::string_view(kPanelPlots[i]) != kPlotKindNames[i].first) return false;
            return std::size(kPanelPlots) == std::size(kPlotKindNames);
        }(),
        "kPanelPlots names the section's plots as --plot does, in the order drawn below");
    parameterSlider(Param::Incidence, plots.incidenceDeg, nullptr, "\u03b8_i = %.1f\u00b0");
    iorSlider(scene);
    ImGui::Checkbox("from inside (\u03b7\u2081 = ior, \u03b7\u2082 = 1)", &plots.fromInside);
    // Heights that leave room for the header and legend rows at the panel's width and the plot below.
    const float width = ImGui::GetContentRegionAvail().x;
    scrollHereFor(kPanelPlots[0], scrollTo);
    plotWidget("##lobe", scenePlot(PlotKind::Lobe, scene, material, plots), width * 0.85f);
    ImGui::Spacing();
    scrollHereFor(kPanelPlots[1], scrollTo);
    plotWidget("##fresnel", scenePlot(PlotKind::Fresnel, scene, material, plots), width * 0.95f);
    // The BRDF as a function: the 3-D lobe from a fixed view, and the heat maps (about 32 000
    // evaluations; two rows of them with anisotropy).
    ImGui::Spacing();
    scrollHereFor(kPanelPlots[2], scrollTo);
    const std::optional<ProbedLobe> probed = probedLobe(scene, probe, selectedLight);
    if (probed) {
        ImGui::TextWrapped("3-D lobe: the probed point's own N, I (light %d) and V; Esc clears the probe.",
                           probed->light);
    } else if (probe && !probe->miss) {
        ImGui::TextWrapped("3-D lobe: every light is behind the probed point; the incidence above is drawn.");
    }
    plots.probed = probed ? std::optional<LobeIncidence>(probed->incidence) : std::nullopt;
    plotWidget("##lobe3d", scenePlot(PlotKind::Lobe3d, scene, probed ? probed->material : material, plots),
               width * 0.9f);
    plots.probed.reset();
    // Dragging the 3-D lobe turns it (the widget holds the mouse, so the scene's camera stays put);
    // a double click goes back to the PNG's view.
    if (ImGui::IsItemActive()) {
        const ImVec2 delta = ImGui::GetIO().MouseDelta;
        plots.lobeView.azimuthDeg = std::fmod(plots.lobeView.azimuthDeg - 0.5f * delta.x, 360.0f);
        plots.lobeView.elevationDeg = std::clamp(plots.lobeView.elevationDeg + 0.5f * delta.y, 0.0f, 89.0f);
    }
    if (ImGui::IsItemHovered() && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) plots.lobeView = LobeView{};
    ImGui::Spacing();
    const bool twoRows = anisotropicLobe(material, lightingEnvironment(scene));
    scrollHereFor(kPanelPlots[3], scrollTo);
    plotWidget("##brdf-slice", scenePlot(PlotKind::BrdfSlice, scene, material, plots),
               width * (twoRows ? 1.0f : 0.65f));
}

void sectionMesh(MeshSpec& m, Transform& t, std::size_t triangles, bool& textures) {
    // Procedural shapes by their scene-file names, plus the glTF model the object was loaded with (its
    // path is kept when the lecturer switches to a sphere, so they can switch back): the last name.
    static_assert(std::end(kMeshTypeNames)[-1].second == MeshSpec::Type::Gltf, "the glTF model comes last");
    const char* names[std::size(kMeshTypeNames)];
    int type = 0;
    for (std::size_t i = 0; i < std::size(kMeshTypeNames); ++i) {
        names[i] = kMeshTypeNames[i].second == MeshSpec::Type::Gltf ? "glTF model" : kMeshTypeNames[i].first;
        if (kMeshTypeNames[i].second == m.type) type = int(i);
    }
    const int count = int(std::size(kMeshTypeNames)) - (m.path.empty() ? 1 : 0);
    if (ImGui::Combo("mesh", &type, names, count)) m.type = kMeshTypeNames[std::size_t(type)].second;
    const float r = 1e-3f, big = 1e3f;
    switch (m.type) {
    case MeshSpec::Type::UvSphere:
        parameterSlider(Param::UvSphereSlices, m.slices);
        parameterSlider(Param::UvSphereStacks, m.stacks);
        ImGui::DragFloat("radius", &m.radius, 0.01f, r, big, "%.3f", ImGuiSliderFlags_AlwaysClamp);
        break;
    case MeshSpec::Type::IcoSphere:
        parameterSlider(Param::IcoSphereSubdivisions, m.subdivisions);
        ImGui::DragFloat("radius", &m.radius, 0.01f, r, big, "%.3f", ImGuiSliderFlags_AlwaysClamp);
        break;
    case MeshSpec::Type::Torus:
        parameterSlider(Param::TorusMajorSegments, m.majorSegments);
        parameterSlider(Param::TorusMinorSegments, m.minorSegments);
        ImGui::DragFloat("major radius", &m.majorRadius, 0.01f, r, big, "%.3f", ImGuiSliderFlags_AlwaysClamp);
        ImGui::DragFloat("minor radius", &m.minorRadius, 0.01f, r, big, "%.3f", ImGuiSliderFlags_AlwaysClamp);
        break;
    case MeshSpec::Type::Cube:
        ImGui::DragFloat("size", &m.size, 0.01f, r, big, "%.3f", ImGuiSliderFlags_AlwaysClamp);
        break;
    case MeshSpec::Type::Plane:
        ImGui::DragFloat("size", &m.size, 0.01f, r, big, "%.3f", ImGuiSliderFlags_AlwaysClamp);
        parameterSlider(Param::PlaneSubdivisions, m.planeSubdivisions);
        break;
    case MeshSpec::Type::Gltf:
        ImGui::TextWrapped("file: %s", m.path.c_str());
        // C = base colour x texture x vertex colour; off: the base colour alone (--no-textures).
        ImGui::Checkbox("textures and vertex colours", &textures);
        break;
    }
    ImGui::Text("%zu triangles", triangles);
    if (ImGui::TreeNode("transform")) {
        dragCoordinates("translation", t.translation, 0.01f, "%.3f");
        dragCoordinates("rotation (deg)", t.rotationDeg, 0.5f, "%.1f");
        dragNonZero("scale", t.scale, 0.01f, true);
        ImGui::TreePop();
    }
}

void areaLightFields(Light& l) {
    dragNonZero("normal", l.normal, 0.02f, false);
    ImGui::DragFloat2("size (w, h)", &l.size.x, 0.01f, 1e-3f, 1e6f, "%.2f", ImGuiSliderFlags_AlwaysClamp);
    l.size = glm::max(l.size, glm::vec2(float(kSizeRange.lo)));
    // Sample counts are a specialisation constant: changing them recompiles (once per count).
    ImGui::SliderInt2("samples (nx, ny)", &l.samples.x, 1, kAreaSamplesPerSideRange.hi);
    l.samples = glm::clamp(l.samples, glm::ivec2(1), glm::ivec2(kAreaSamplesPerSideRange.hi));
    ImGui::Checkbox("two-sided", &l.twoSided);
}

void spotLightFields(Light& l) {
    dragNonZero("direction", l.direction, 0.02f, false);
    // Half-angles from the axis: full light inside the inner cone, none outside the outer.
    parameterSlider(Param::OuterCone, l.outerConeDeg);
    // The inner cone stays inside the outer one: its slider ends just short of it.
    const Parameter& inner = parameter(Param::InnerCone);
    ImGui::SliderFloat(inner.label, &l.innerConeDeg, float(inner.slider.lo), l.outerConeDeg - 0.1f, "%.1f",
                       ImGuiSliderFlags_AlwaysClamp);
    l.innerConeDeg = std::clamp(l.innerConeDeg, float(inner.range.lo), l.outerConeDeg - 0.1f);
}

// One light's fields in its open tree node: type, where it is, what its type adds, colour, intensity, falloff.
void lightFields(Light& l, std::string& readout) {
    combo("type", l.type, kLightTypeNames);
    if (l.type == LightType::Directional) dragNonZero("direction", l.direction, 0.02f, false);
    else dragCoordinates(l.type == LightType::Area ? "centre" : "position", l.position, 0.05f, "%.2f");
    if (l.type == LightType::Area) areaLightFields(l);
    if (l.type == LightType::Spot) spotLightFields(l);
    colorEdit("colour", l.color);
    // A drag, not a slider: intensities span many orders of magnitude (the slider range is its limits).
    const Parameter& intensity = parameter(Param::Intensity);
    ImGui::DragFloat(intensity.label, &l.intensity, 0.01f, float(intensity.slider.lo), float(intensity.slider.hi),
                     "%.3f", ImGuiSliderFlags_AlwaysClamp);
    readoutWhileActive(readout, intensity.symbol, l.intensity);
    if (l.type != LightType::Directional) {
        combo("attenuation", l.attenuation, kAttenuationNames);
        if (l.attenuation == Attenuation::InverseSquare) {
            // 0 = no window; otherwise the light fades smoothly to zero at this distance.
            ImGui::DragFloat("range (0: none)", &l.range, 0.05f, 0.0f, 1e6f, "%.2f", ImGuiSliderFlags_AlwaysClamp);
            if (l.range > 0.0f && l.range < float(kLightRangeRange.lo)) l.range = float(kLightRangeRange.lo);
        }
    }
}

void sectionLights(Scene& scene, int& selected, std::string& readout) {
    colorEdit(parameter(Param::Ambient).label, scene.ambient);
    ImGui::TextDisabled("click a light's name to select it (again: none)");
    int remove = -1;
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        Light& l = scene.lights[i];
        ImGui::PushID(int(i));
        // The arrow folds the node; a click on the name selects the light (an area light then shows
        // its samples, and the probe draws only this light's vectors).
        const bool isSelected = selected == int(i);
        const ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_DefaultOpen | ImGuiTreeNodeFlags_OpenOnArrow |
                                         (isSelected ? ImGuiTreeNodeFlags_Selected : 0);
        const bool open = ImGui::TreeNodeEx("light", flags, "light %zu (%s)%s", i, toString(l.type),
                                            isSelected && l.type == LightType::Area ? ": samples shown" : "");
        if (ImGui::IsItemClicked() && !ImGui::IsItemToggledOpen()) selected = isSelected ? -1 : int(i);
        if (open) {
            lightFields(l, readout);
            if (ImGui::Button("remove light")) remove = int(i);
            ImGui::TreePop();
        }
        ImGui::PopID();
    }
    if (remove >= 0) {
        scene.lights.erase(scene.lights.begin() + remove);
        if (selected == remove) selected = -1;
        else if (selected > remove) --selected;
    }
    ImGui::BeginDisabled(scene.lights.size() >= std::size_t(kMaxLights));
    if (ImGui::Button("add light")) scene.lights.emplace_back();
    ImGui::EndDisabled();
}

void sectionShadows(ShadowSettings& s) {
    ImGui::Checkbox("shadows (occlusion toward every light)", &s.enabled);
    ImGui::BeginDisabled(!s.enabled);
    parameterSlider(Param::NormalBias, s.normalBias);
    parameterSlider(Param::DepthBias, s.depthBias);
    parameterSlider(Param::Pcf, s.pcf);
    // Powers of two over kShadowMapSizeRange (64 to 4096), as an exponent slider.
    auto sizeSlider = [](const char* label, int& size) {
        const auto log2 = [](int v) { return int(std::lround(std::log2(double(v)))); };
        const int lo = log2(kShadowMapSizeRange.lo), hi = log2(kShadowMapSizeRange.hi);
        int exponent = log2(std::max(size, kShadowMapSizeRange.lo));
        if (ImGui::SliderInt(label, &exponent, lo, hi, "")) size = 1 << std::clamp(exponent, lo, hi);
        ImGui::SameLine();
        ImGui::Text("%d", size);
    };
    sizeSlider("map size", s.mapSize);
    sizeSlider("area map size", s.areaMapSize);
    ImGui::EndDisabled();
}

void sectionOverlays(ViewSettings& s) {
    const auto overlay = [&s](Overlay o) { ImGui::Checkbox(nameOf(kOverlayLabels, o), &s.overlays.shown(o)); };
    overlay(Overlay::Wireframe);
    overlay(Overlay::VertexNormals);
    ImGui::SameLine();
    overlay(Overlay::FaceNormals);
    overlay(Overlay::Tangents);
    ImGui::SliderFloat("normal length", &s.overlays.normalScale, 0.02f, 0.5f, "%.2f x radius");
    ImGui::Checkbox("light labels (L)", &s.lightLabels);
    ImGui::SameLine();
    overlay(Overlay::LightMarkers);
    ImGui::Checkbox("formula above the view (E)", &s.showFormula);
    ImGui::Checkbox("pane labels", &s.paneLabels);
    ImGui::SameLine();
    ImGui::Checkbox("frame time", &s.showHud);
    ImGui::Checkbox("frame time also when Tab hides the panel", &s.readoutWhenHidden);
    ImGui::Checkbox("view text for a hall (sized from the window's height)", &s.presentationText);
}

void sectionDisplay(const PanelStatus& status, PanelRequests& requests) {
    float scale = status.uiScale;
    if (ImGui::SliderFloat("UI scale", &scale, kUiScaleRange.lo, kUiScaleRange.hi, "%.2f x  (Ctrl+= / Ctrl+-)"))
        requests.uiScale = std::clamp(scale, kUiScaleRange.lo, kUiScaleRange.hi);
    // Anti-aliasing of the 3D view (on a software renderer only the still view is drawn with it): --msaa's
    // sample counts from 1 on, the largest not above what the driver gave shown as chosen.
    std::vector<int> samples;
    std::vector<std::string> labels;
    for (const auto& n : kMsaaNames)
        if (n.second >= 1) {
            samples.push_back(n.second);
            labels.push_back(msaaLabel(n.second));
        }
    std::vector<const char*> items;
    int choice = 0;
    for (std::size_t i = 0; i < samples.size(); ++i) {
        items.push_back(labels[i].c_str());
        if (status.msaa >= samples[i]) choice = int(i);
    }
    if (ImGui::Combo("anti-aliasing", &choice, items.data(), int(items.size())))
        requests.msaa = samples[std::size_t(choice)];
    requests.toggleFullscreen |= ImGui::Button("fullscreen (F11)");
    if (!status.trueTypeFont) ImGui::TextWrapped("DejaVu Sans not found (Debian: fonts-dejavu-core): bitmap font");
}

void sectionCamera(Camera& c, int modelCamera, const PanelStatus& status, PanelRequests& requests) {
    if (!status.modelCameras.empty()) {  // the glTF model's own cameras (--camera N)
        const std::string current = modelCamera >= 0 && std::size_t(modelCamera) < status.modelCameras.size()
                                        ? status.modelCameras[std::size_t(modelCamera)]
                                        : std::string("shadelab's framing");
        if (ImGui::BeginCombo("camera", current.c_str())) {
            if (ImGui::Selectable("shadelab's framing", modelCamera < 0)) requests.modelCamera = -1;
            for (std::size_t i = 0; i < status.modelCameras.size(); ++i)
                if (ImGui::Selectable((status.modelCameras[i] + "##" + std::to_string(i)).c_str(),
                                      int(i) == modelCamera))
                    requests.modelCamera = int(i);
            ImGui::EndCombo();
        }
    }
    requests.resetCamera |= ImGui::Button("reset (R)");
    ImGui::SameLine();
    requests.frameModel |= ImGui::Button("frame model (F)");
    Camera edited = c;
    bool changed = dragCoordinates("eye", edited.eye, 0.02f, "%.2f");
    changed |= dragCoordinates("target", edited.target, 0.02f, "%.2f");
    changed |= parameterSlider(Param::FovY, edited.fovYDeg);
    if (changed && cameraValid(edited)) c = edited;
    // The viewer places them every frame around the model and the lights (zoom never slices it).
    ImGui::TextDisabled("near %.4g, far %.4g: follow the eye", double(c.nearPlane), double(c.farPlane));
}

// The widest label a widget in the panel has (measured in the current font, so it holds at any scale).
float longestLabelWidth() {
    static const char* const kLongLabels[] = {"lobe normalisation", "normal bias (texels)",
                                              "depth bias (slope)", "samples (nx, ny)",
                                              "range (0: none)",    "output encoding",
                                              "major segments",     "rotation (deg)",
                                              "anti-aliasing",      "ior \u03b7\u2082/\u03b7\u2081",
                                              "k_e exponent"};
    float width = 0.0f;
    for (const char* label : kLongLabels) width = std::max(width, ImGui::CalcTextSize(label).x);
    return width;
}

void sectionFile(ViewSettings& s, const PanelStatus& status, PanelRequests& requests) {
    ImGui::SetNextItemWidth(-1.0f);
    ImGui::InputTextWithHint("##path", "scene.json, model.gltf or model.glb", &s.scenePath);
    requests.save |= ImGui::Button("save scene");
    ImGui::SameLine();
    requests.load |= ImGui::Button("load");
    ImGui::SameLine();
    requests.screenshot |= ImGui::Button("screenshot (F12)");
    if (!status.animation.empty()) {  // --animate
        requests.togglePlay |= ImGui::Button(status.playing ? "pause (Space)" : "play (Space)");
        ImGui::SameLine();
        ImGui::Text("animation: %s", status.animation.c_str());
    }
    if (!status.lastScreenshot.empty()) ImGui::TextWrapped("screenshot: %s", status.lastScreenshot.c_str());
    requests.toggleRecording |=
        ImGui::Button(status.recording ? "stop recording (Ctrl+R)" : "record the view (Ctrl+R)");
    if (!status.lastRecording.empty()) ImGui::TextWrapped("recording: %s", status.lastRecording.c_str());
    requests.reloadShaders |= ImGui::Button("reload shaders (F5)");
    ImGui::TextDisabled("Drop a .json, .gltf or .glb on the window to open it.");
    // The last result, also shown over the view for a while; here at the end, so nothing moves.
    if (!status.message.empty()) {
        if (status.isError) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        ImGui::TextWrapped("%s", status.message.c_str());
        if (status.isError) ImGui::PopStyleColor();
    }
}

void sectionPlaylist(ViewSettings& settings, const PanelStatus& status, PanelRequests& requests) {
    const int count = int(status.presetTitles.size());
    const int current = status.currentPreset;
    ImGui::BeginDisabled(current <= 0);
    if (ImGui::Button("< previous (PgUp)")) requests.gotoPreset = current - 1;
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(current + 1 >= count);
    if (ImGui::Button("next (PgDn) >")) requests.gotoPreset = current + 1;
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::Text("%d / %d", current + 1, count);
    requests.resetPreset |= ImGui::Button("reset preset (Backspace)");
    ImGui::SameLine();
    ImGui::Checkbox("title on view", &settings.showCaption);
    // At most eight rows: the lecture's list without pushing the scene's sections off the panel.
    const float rows = float(std::min(count, 8)) + 0.25f;
    if (ImGui::BeginListBox("##presets", ImVec2(-1.0f, ImGui::GetTextLineHeightWithSpacing() * rows))) {
        for (int i = 0; i < count; ++i) {
            ImGui::PushID(i);
            const bool selected = i == current;
            if (ImGui::Selectable(status.presetTitles[std::size_t(i)].c_str(), selected) && !selected)
                requests.gotoPreset = i;
            if (selected && status.scrollToPreset) ImGui::SetScrollHereY();
            ImGui::PopID();
        }
        ImGui::EndListBox();
    }
}

void sectionKeys() {
    // Columns share the panel's width (the actions wrap), so the table never needs more than the panel.
    if (!ImGui::BeginTable("##keys", 2, ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_RowBg)) return;
    for (const Control& c : kControls) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(c.input);
        ImGui::TableNextColumn();
        ImGui::TextWrapped("%s", c.action);
    }
    ImGui::EndTable();
}

// The panel's window at `area`; false (and ended) when ImGui skips it.
bool beginPanelWindow(const UiRect& area) {
    ImGui::SetNextWindowPos(ImVec2(area.x, area.y));
    ImGui::SetNextWindowSize(ImVec2(area.width, area.height));
    // NoNavInputs: Tab belongs to the viewer (hide the panel), not to ImGui's widget tabbing.
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoNavInputs |
                                   // At a UI scale the window has no room for (the panel is at most half
                                   // of it), a row wider than the panel scrolls instead of being cut.
                                   ImGuiWindowFlags_HorizontalScrollbar;
    if (ImGui::Begin("shadelab  (Tab hides this panel)", nullptr, flags)) return true;
    ImGui::End();
    return false;
}

// A collapsing header; on the first frame of a --panel-sections run, open exactly as listed.
bool section(ViewSettings& settings, const char* title, PanelSection id, bool defaultOpen) {
    const char* name = nameOf(kPanelSections, id);
    if (settings.startSections) {
        const auto& open = *settings.startSections;
        ImGui::SetNextItemOpen(std::find(open.begin(), open.end(), name) != open.end(), ImGuiCond_Always);
    }
    const bool open =
        ImGui::CollapsingHeader(title, defaultOpen ? ImGuiTreeNodeFlags_DefaultOpen : ImGuiTreeNodeFlags_None);
    if (open) settings.openSections.push_back(name);
    return open;
}

// The scene's sections, Shading to Keys, in the panel's order.
void sceneSections(Scene& scene, ViewSettings& settings, const PanelStatus& status, PanelRequests& requests,
                   const ProbeResult* probe) {
    if (section(settings, "Shading", PanelSection::Shading, true)) sectionShading(scene);
    settings.selectedObject = std::clamp(settings.selectedObject, 0, std::max(int(scene.objects.size()) - 1, 0));
    SceneObject* object = scene.objects.empty() ? nullptr : &scene.objects[std::size_t(settings.selectedObject)];
    if (object && section(settings, "Material", PanelSection::Material, true)) {
        if (scene.objects.size() > 1)
            ImGui::SliderInt("object", &settings.selectedObject, 0, int(scene.objects.size()) - 1);
        sectionMaterial(object->material, scene.reflection, settings.readout);
    }
    if (section(settings, "Plots: specular lobe, Fresnel", PanelSection::Plots, false))
        sectionPlots(scene, object ? object->material : Material{}, settings.plots, probe, settings.selectedLight,
                     settings.scrollToPlot);
    // S opens or closes it, and brings it into view.
    if (settings.openShader) ImGui::SetNextItemOpen(*settings.openShader, ImGuiCond_Always);
    if (section(settings, "Shader: the GLSL of the pane's mode (S: large over the view)", PanelSection::Shader,
                false)) {
        if (settings.openShader) ImGui::SetScrollHereY(0.0f);
        sectionShader(scene, settings, status, probe);
    }
    settings.openShader.reset();
    if (object && section(settings, "Mesh", PanelSection::Mesh, true))
        sectionMesh(object->mesh, object->transform, status.objectTriangles, scene.textures);
    if (section(settings, "Lights", PanelSection::Lights, true))
        sectionLights(scene, settings.selectedLight, settings.readout);
    if (section(settings, "Shadows", PanelSection::Shadows, true)) sectionShadows(scene.shadows);
    if (section(settings, "Overlays", PanelSection::Overlays, true)) {
        sectionOverlays(settings);
        sectionDisplay(status, requests);
    }
    if (section(settings, "Camera", PanelSection::Camera, false))
        sectionCamera(scene.camera, scene.modelCamera, status, requests);
    if (section(settings, "Background", PanelSection::Background, false))
        colorEdit(parameter(Param::Background).label, scene.background);
    if (section(settings, "File", PanelSection::File, true)) sectionFile(settings, status, requests);
    if (section(settings, "Keys", PanelSection::Keys, false)) sectionKeys();
}

}  // namespace

PanelRequests drawPanel(Scene& scene, ViewSettings& settings, const PanelStatus& status, const UiRect& area,
                        const ProbeResult* probe) {
    PanelRequests requests;
    const std::size_t lightsBefore = scene.lights.size();
    if (!beginPanelWindow(area)) return requests;
    // Widgets leave room for the longest label on their right, so no label is clipped at any scale.
    ImGui::PushItemWidth(-(longestLabelWidth() + ImGui::GetStyle().ItemInnerSpacing.x * 2.0f + ImGui::GetFontSize()));
    if (!status.presetTitles.empty() && ImGui::CollapsingHeader("Playlist", ImGuiTreeNodeFlags_DefaultOpen))
        sectionPlaylist(settings, status, requests);
    // The probe's terms come first: a click on the view is a question the panel answers at once.
    if (probe && settings.scrollToProbe) {
        ImGui::SetScrollHereY(0.0f);
        settings.scrollToProbe = false;
    }
    if (probe && ImGui::CollapsingHeader("Probe", ImGuiTreeNodeFlags_DefaultOpen))
        requests.clearProbe |= probeSection(scene, *probe);
    settings.openSections.clear();
    settings.readout.clear();
    sceneSections(scene, settings, status, requests, probe);
    settings.startSections.reset();
    // ImGui marks every edit a widget makes (MarkItemEdited, this frame's flag); the light buttons
    // change the list.
    requests.sceneEdited =
        ImGui::GetCurrentContext()->ActiveIdHasBeenEditedThisFrame || scene.lights.size() != lightsBefore;
    ImGui::PopItemWidth();
    ImGui::End();
    return requests;
}

}  // namespace shadelab
