#include "viewer/panel.hpp"

#include "core/camera.hpp"
#include "viewer/panel_sections.hpp"
#include "viewer/plot_view.hpp"
#include "viewer/probe_view.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>

namespace shadelab {
namespace {

// Widgets keep every value inside the ranges the scene-file parser accepts (scene_json.cpp), so a scene
// saved from the panel always loads again. Sliders show the range a lecture sweeps; Ctrl+click types
// a value, which the clamps below bring back into the parser's range.

bool colorEdit(const char* label, glm::vec3& color) {
    if (!ImGui::ColorEdit3(label, &color.x, ImGuiColorEditFlags_Float)) return false;
    color = glm::clamp(color, glm::vec3(0.0f), glm::vec3(1.0f));
    return true;
}

bool coefficient(const char* label, float& value, float sliderMax) {
    if (!ImGui::SliderFloat(label, &value, 0.0f, sliderMax, "%.3f")) return false;
    value = std::clamp(value, 0.0f, 1000.0f);
    return true;
}

template <typename E>
bool radio(const char* label, E& value, E choice) {
    if (!ImGui::RadioButton(label, value == choice)) return false;
    value = choice;
    return true;
}

template <typename E, std::size_t N>
bool combo(const char* label, E& value, const char* const (&names)[N]) {
    int index = int(value);
    if (!ImGui::Combo(label, &index, names, int(N))) return false;
    value = E(index);
    return true;
}

// A vector edit that must not become (nearly) zero: light directions, scales.
bool dragNonZero(const char* label, glm::vec3& v, float speed, bool perComponent) {
    glm::vec3 edited = v;
    if (!ImGui::DragFloat3(label, &edited.x, speed, -1e6f, 1e6f, "%.3f")) return false;
    const bool zero = perComponent ? glm::any(glm::lessThan(glm::abs(edited), glm::vec3(1e-3f)))
                                   : glm::length(edited) < 1e-3f;
    if (zero) return false;
    v = edited;
    return true;
}

bool cameraValid(const Camera& c) {
    const glm::vec3 forward = c.target - c.eye;
    if (glm::length(forward) < 1e-4f || glm::length(c.up) < 1e-4f || c.farPlane <= c.nearPlane) return false;
    return glm::length(glm::cross(glm::normalize(forward), glm::normalize(c.up))) >= 1e-3f;
}

void iorSlider(Scene& scene) {
    ImGui::SliderFloat("ior eta2/eta1", &scene.ior, kMinIor, 4.0f, "%.3f");
    scene.ior = std::clamp(scene.ior, kMinIor, kMaxIor);
}

void sectionShading(Scene& scene) {
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("Shading");
    ImGui::SameLine(ImGui::GetFontSize() * 6.0f);
    radio("flat (1)", scene.shading, ShadingMode::Flat);
    ImGui::SameLine();
    radio("gouraud (2)", scene.shading, ShadingMode::Gouraud);
    ImGui::SameLine();
    radio("phong (3)", scene.shading, ShadingMode::Phong);
    bool compare = scene.layout == Layout::Compare;
    if (ImGui::Checkbox("compare: flat | gouraud | phong  (C)", &compare))
        scene.layout = compare ? Layout::Compare : Layout::Single;
    bool diff = scene.layout == Layout::Diff;
    if (ImGui::Checkbox("difference: A | B | |A - B| x factor  (D)", &diff))
        scene.layout = diff ? Layout::Diff : Layout::Single;
    if (diff) {
        static const char* const kModes[] = {"flat", "gouraud", "phong"};
        ImGui::PushItemWidth(ImGui::GetFontSize() * 6.0f);
        combo("A", scene.diff.a, kModes);
        ImGui::SameLine();
        combo("B", scene.diff.b, kModes);
        ImGui::PopItemWidth();
        ImGui::SliderFloat("factor", &scene.diff.factor, 1.0f, kMaxDiffFactor, "%.1f", ImGuiSliderFlags_Logarithmic);
        scene.diff.factor = std::clamp(scene.diff.factor, 1.0f, kMaxDiffFactor);
    }
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("Reflection");
    ImGui::SameLine(ImGui::GetFontSize() * 6.0f);
    radio("Phong", scene.reflection, ReflectionModel::Phong);
    ImGui::SameLine();
    radio("Blinn-Phong", scene.reflection, ReflectionModel::BlinnPhong);
    static const char* const kEncodings[] = {"linear", "sRGB"};
    combo("output encoding", scene.outputEncoding, kEncodings);
    // Beyond the heuristic model (core/lighting.hpp): each switch recompiles the programs once.
    static const char* const kNormalizations[] = {"none (heuristic)", "energy-normalised"};
    combo("lobe normalisation", scene.specularNormalization, kNormalizations);
    static const char* const kFresnel[] = {"none", "Schlick", "exact"};
    combo("Fresnel", scene.fresnel, kFresnel);
    if (scene.fresnel != FresnelMode::None) iorSlider(scene);
    // Term isolation: each addend of the formula alone.
    static const char* const kTerms[] = {"all", "ambient", "diffuse", "specular", "one light", "unlit C"};
    combo("show", scene.show.term, kTerms);
    if (scene.show.term == ShowTerm::Light) {
        const int last = std::max(int(scene.lights.size()) - 1, 0);
        ImGui::SliderInt("light", &scene.show.light, 0, last);
        scene.show.light = std::clamp(scene.show.light, 0, last);
    }
}

void sectionMaterial(Material& m) {
    colorEdit("colour C", m.color);
    colorEdit("specular S", m.specularColor);
    coefficient("k_a ambient", m.ka, 1.0f);
    coefficient("k_d diffuse", m.kd, 1.0f);
    coefficient("k_s specular", m.ks, 1.0f);
    // The exponent is what the lecture sweeps: a logarithmic slider gives 1..10 as much travel as 100..1000.
    if (ImGui::SliderFloat("k_e exponent", &m.ke, 1.0f, 1000.0f, "%.1f", ImGuiSliderFlags_Logarithmic))
        m.ke = std::clamp(m.ke, kMinExponent, kMaxExponent);
}

// The lecture's plots for the current parameters (core/plot.hpp): rebuilt every frame, which costs
// about a thousand formula evaluations, so every slider in the panel moves the curves at once.
void sectionPlots(Scene& scene, const Material& material, PlotSettings& plots) {
    ImGui::SliderFloat("incidence", &plots.incidenceDeg, 0.0f, kMaxIncidenceDeg, "theta_i = %.1f deg");
    plots.incidenceDeg = std::clamp(plots.incidenceDeg, 0.0f, kMaxIncidenceDeg);
    iorSlider(scene);
    ImGui::Checkbox("from inside (eta_1 = ior, eta_2 = 1)", &plots.fromInside);
    // Heights that leave room for the header and legend rows at the panel's width and the plot below.
    const float width = ImGui::GetContentRegionAvail().x;
    plotWidget("##lobe", scenePlot(PlotKind::Lobe, scene, material, plots), width * 0.85f);
    ImGui::Spacing();
    plotWidget("##fresnel", scenePlot(PlotKind::Fresnel, scene, material, plots), width * 0.95f);
}

void sectionMesh(MeshSpec& m, Transform& t, std::size_t triangles) {
    // Procedural shapes, plus the glTF model the object was loaded with (its path is kept when the
    // lecturer switches to a sphere, so they can switch back).
    const char* names[] = {"uvsphere", "icosphere", "torus", "cube", "plane", "glTF model"};
    const int count = m.path.empty() ? 5 : 6;
    int type = int(m.type);
    if (ImGui::Combo("mesh", &type, names, count)) m.type = MeshSpec::Type(type);
    const float r = 1e-3f, big = 1e3f;
    switch (m.type) {
    case MeshSpec::Type::UvSphere:
        ImGui::SliderInt("slices", &m.slices, 3, 256);
        ImGui::SliderInt("stacks", &m.stacks, 2, 128);
        ImGui::DragFloat("radius", &m.radius, 0.01f, r, big, "%.3f", ImGuiSliderFlags_AlwaysClamp);
        break;
    case MeshSpec::Type::IcoSphere:
        // 20 * 4^7 = 327,680 triangles is still interactive on llvmpipe; the file format allows 8.
        ImGui::SliderInt("subdivisions", &m.subdivisions, 0, 7);
        ImGui::DragFloat("radius", &m.radius, 0.01f, r, big, "%.3f", ImGuiSliderFlags_AlwaysClamp);
        break;
    case MeshSpec::Type::Torus:
        ImGui::SliderInt("major segments", &m.majorSegments, 3, 256);
        ImGui::SliderInt("minor segments", &m.minorSegments, 3, 128);
        ImGui::DragFloat("major radius", &m.majorRadius, 0.01f, r, big, "%.3f", ImGuiSliderFlags_AlwaysClamp);
        ImGui::DragFloat("minor radius", &m.minorRadius, 0.01f, r, big, "%.3f", ImGuiSliderFlags_AlwaysClamp);
        break;
    case MeshSpec::Type::Cube:
        ImGui::DragFloat("size", &m.size, 0.01f, r, big, "%.3f", ImGuiSliderFlags_AlwaysClamp);
        break;
    case MeshSpec::Type::Plane:
        ImGui::DragFloat("size", &m.size, 0.01f, r, big, "%.3f", ImGuiSliderFlags_AlwaysClamp);
        ImGui::SliderInt("subdivisions", &m.planeSubdivisions, 1, 128);
        break;
    case MeshSpec::Type::Gltf:
        ImGui::TextWrapped("file: %s", m.path.c_str());
        break;
    }
    ImGui::Text("%zu triangles", triangles);
    if (ImGui::TreeNode("transform")) {
        ImGui::DragFloat3("translation", &t.translation.x, 0.01f, -1e6f, 1e6f, "%.3f");
        ImGui::DragFloat3("rotation (deg)", &t.rotationDeg.x, 0.5f, -1e6f, 1e6f, "%.1f");
        dragNonZero("scale", t.scale, 0.01f, true);
        ImGui::TreePop();
    }
}

void sectionLights(Scene& scene, int& selected) {
    colorEdit("ambient A", scene.ambient);
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
            static const char* const kTypes[] = {"point", "directional", "area"};
            combo("type", l.type, kTypes);
            if (l.type == LightType::Directional)
                dragNonZero("direction", l.direction, 0.02f, false);
            else
                ImGui::DragFloat3(l.type == LightType::Area ? "centre" : "position", &l.position.x, 0.05f, -1e6f,
                                  1e6f, "%.2f");
            if (l.type == LightType::Area) {
                dragNonZero("normal", l.normal, 0.02f, false);
                ImGui::DragFloat2("size (w, h)", &l.size.x, 0.01f, 1e-3f, 1e6f, "%.2f", ImGuiSliderFlags_AlwaysClamp);
                l.size = glm::max(l.size, glm::vec2(1e-4f));
                // Sample counts are a specialisation constant: changing them recompiles (once per count).
                ImGui::SliderInt2("samples (nx, ny)", &l.samples.x, 1, kMaxAreaSamplesPerSide);
                l.samples = glm::clamp(l.samples, glm::ivec2(1), glm::ivec2(kMaxAreaSamplesPerSide));
                ImGui::Checkbox("two-sided", &l.twoSided);
            }
            colorEdit("colour", l.color);
            ImGui::DragFloat("intensity", &l.intensity, 0.01f, 0.0f, 1e6f, "%.3f", ImGuiSliderFlags_AlwaysClamp);
            if (l.type != LightType::Directional) {
                static const char* const kAttenuation[] = {"none", "inverse-square"};
                combo("attenuation", l.attenuation, kAttenuation);
                if (l.attenuation == Attenuation::InverseSquare) {
                    // 0 = no window; otherwise the light fades smoothly to zero at this distance.
                    ImGui::DragFloat("range (0: none)", &l.range, 0.05f, 0.0f, 1e6f, "%.2f",
                                     ImGuiSliderFlags_AlwaysClamp);
                    if (l.range > 0.0f && l.range < 1e-4f) l.range = 1e-4f;
                }
            }
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
    ImGui::SliderFloat("normal bias (texels)", &s.normalBias, 0.0f, 8.0f, "%.2f");
    ImGui::SliderFloat("depth bias (slope)", &s.depthBias, 0.0f, 8.0f, "%.2f");
    s.normalBias = std::clamp(s.normalBias, 0.0f, 100.0f);
    s.depthBias = std::clamp(s.depthBias, 0.0f, 100.0f);
    ImGui::SliderInt("PCF radius", &s.pcf, 0, kMaxPcfRadius);
    s.pcf = std::clamp(s.pcf, 0, kMaxPcfRadius);
    // Powers of two from 64 to 4096, as an exponent slider.
    auto sizeSlider = [](const char* label, int& size) {
        int exponent = int(std::lround(std::log2(double(std::max(size, kMinShadowMapSize)))));
        if (ImGui::SliderInt(label, &exponent, 6, 12, "")) size = 1 << std::clamp(exponent, 6, 12);
        ImGui::SameLine();
        ImGui::Text("%d", size);
    };
    sizeSlider("map size", s.mapSize);
    sizeSlider("area map size", s.areaMapSize);
    ImGui::EndDisabled();
}

void sectionOverlays(ViewSettings& s) {
    ImGui::Checkbox("wireframe (W)", &s.overlays.wireframe);
    ImGui::Checkbox("vertex normals (N)", &s.overlays.vertexNormals);
    ImGui::SameLine();
    ImGui::Checkbox("face normals (Shift+N)", &s.overlays.faceNormals);
    ImGui::SliderFloat("normal length", &s.overlays.normalScale, 0.02f, 0.5f, "%.2f x radius");
    ImGui::Checkbox("light markers (L)", &s.overlays.lightMarkers);
    ImGui::Checkbox("pane labels", &s.paneLabels);
    ImGui::SameLine();
    ImGui::Checkbox("HUD", &s.showHud);
}

void sectionCamera(Camera& c, PanelRequests& requests) {
    requests.resetCamera |= ImGui::Button("reset (R)");
    ImGui::SameLine();
    requests.frameModel |= ImGui::Button("frame model (F)");
    Camera edited = c;
    bool changed = ImGui::DragFloat3("eye", &edited.eye.x, 0.02f, -1e6f, 1e6f, "%.2f");
    changed |= ImGui::DragFloat3("target", &edited.target.x, 0.02f, -1e6f, 1e6f, "%.2f");
    changed |= ImGui::SliderFloat("fov y (deg)", &edited.fovYDeg, 5.0f, 120.0f, "%.1f");
    changed |= ImGui::DragFloat("near", &edited.nearPlane, 0.001f, 1e-4f, 1e5f, "%.4f", ImGuiSliderFlags_AlwaysClamp);
    changed |= ImGui::DragFloat("far", &edited.farPlane, 0.5f, 1e-3f, 1e6f, "%.1f", ImGuiSliderFlags_AlwaysClamp);
    edited.fovYDeg = std::clamp(edited.fovYDeg, 1.0f, 179.0f);
    if (changed && cameraValid(edited)) c = edited;
    ImGui::TextDisabled("left drag: orbit   right/middle drag: pan   wheel: zoom");
}

void sectionFile(ViewSettings& s, const PanelStatus& status, PanelRequests& requests) {
    ImGui::SetNextItemWidth(-1.0f);
    ImGui::InputTextWithHint("##path", "scene.json, model.gltf or model.glb", &s.scenePath);
    requests.save |= ImGui::Button("save scene");
    ImGui::SameLine();
    requests.load |= ImGui::Button("load");
    ImGui::SameLine();
    requests.screenshot |= ImGui::Button("screenshot (F12)");
    if (!status.lastScreenshot.empty()) ImGui::TextWrapped("screenshot: %s", status.lastScreenshot.c_str());
    requests.reloadShaders |= ImGui::Button("reload shaders (F5)");
    ImGui::TextDisabled("Drop a .json, .gltf or .glb on the window to open it.");
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
    ImGui::TextUnformatted(
        "PgDn PgUp   next / previous preset (or Right / Left)\n"
        "Home End    first / last preset\n"
        "Backspace   reset the preset (reload its file)\n"
        "1 2 3       flat / gouraud / phong (single pane)\n"
        "C           compare flat | gouraud | phong\n"
        "W           wireframe\n"
        "N           vertex normals   Shift+N face normals\n"
        "L           light markers\n"
        "click       probe the pixel: N, I, V, R, H and every term\n"
        "R           reset camera     F  frame model\n"
        "F12         screenshot of the 3D view\n"
        "Tab         hide / show the panel\n"
        "Esc         clear the probe (with none: quit)\n"
        "Q           quit");
}

}  // namespace

PanelRequests drawPanel(Scene& scene, ViewSettings& settings, const PanelStatus& status, const UiRect& area,
                        const ProbeResult* probe) {
    PanelRequests requests;
    ImGui::SetNextWindowPos(ImVec2(area.x, area.y));
    ImGui::SetNextWindowSize(ImVec2(area.width, area.height));
    // NoNavInputs: Tab belongs to the viewer (hide the panel), not to ImGui's widget tabbing.
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoNavInputs;
    if (!ImGui::Begin("shadelab  (Tab hides this panel)", nullptr, flags)) {
        ImGui::End();
        return requests;
    }
    ImGui::PushItemWidth(-ImGui::GetFontSize() * 9.0f);  // room for the labels on the right
    if (!status.message.empty()) {
        if (status.isError) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        ImGui::TextWrapped("%s", status.message.c_str());
        if (status.isError) ImGui::PopStyleColor();
        ImGui::Separator();
    }
    if (!status.presetTitles.empty() && ImGui::CollapsingHeader("Playlist", ImGuiTreeNodeFlags_DefaultOpen))
        sectionPlaylist(settings, status, requests);
    // The probe's terms come first: a click on the view is a question the panel answers at once.
    if (probe && ImGui::CollapsingHeader("Probe", ImGuiTreeNodeFlags_DefaultOpen))
        requests.clearProbe |= probeSection(scene, *probe);
    // A collapsing header; on the first frame of a --panel-sections run, open exactly as listed.
    auto section = [&](const char* title, const char* name, bool defaultOpen) {
        if (settings.startSections) {
            const auto& open = *settings.startSections;
            ImGui::SetNextItemOpen(std::find(open.begin(), open.end(), name) != open.end(), ImGuiCond_Always);
        }
        return ImGui::CollapsingHeader(title, defaultOpen ? ImGuiTreeNodeFlags_DefaultOpen : ImGuiTreeNodeFlags_None);
    };
    if (section("Shading", kPanelSections[0], true)) sectionShading(scene);
    settings.selectedObject = std::clamp(settings.selectedObject, 0, std::max(int(scene.objects.size()) - 1, 0));
    SceneObject* object = scene.objects.empty() ? nullptr : &scene.objects[std::size_t(settings.selectedObject)];
    if (object && section("Material", kPanelSections[1], true)) {
        if (scene.objects.size() > 1)
            ImGui::SliderInt("object", &settings.selectedObject, 0, int(scene.objects.size()) - 1);
        sectionMaterial(object->material);
    }
    if (section("Plots: specular lobe, Fresnel", kPanelSections[2], false))
        sectionPlots(scene, object ? object->material : Material{}, settings.plots);
    if (object && section("Mesh", kPanelSections[3], true))
        sectionMesh(object->mesh, object->transform, status.objectTriangles);
    if (section("Lights", kPanelSections[4], true)) sectionLights(scene, settings.selectedLight);
    if (section("Shadows", kPanelSections[5], true)) sectionShadows(scene.shadows);
    if (section("Overlays", kPanelSections[6], true)) sectionOverlays(settings);
    if (section("Camera", kPanelSections[7], false)) sectionCamera(scene.camera, requests);
    if (section("Background", kPanelSections[8], false)) colorEdit("background", scene.background);
    if (section("File", kPanelSections[9], true)) sectionFile(settings, status, requests);
    if (section("Keys", kPanelSections[10], false)) sectionKeys();
    static_assert(std::size(kPanelSections) == 11, "every section above has its name");
    settings.startSections.reset();
    ImGui::PopItemWidth();
    ImGui::End();
    return requests;
}

void drawPaneLabels(const Scene& scene, const UiRect& view, float framebufferScale) {
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    const float fontSize = ImGui::GetFontSize() * 2.0f;  // read from the back of a lecture hall
    const float pad = fontSize * 0.3f;
    const std::string diffLabel = "|" + std::string(toString(scene.diff.a)) + " - " + toString(scene.diff.b) + "| x " +
                                  std::to_string(int(std::lround(scene.diff.factor)));
    for (const Pane& pane : layoutPanes(scene.layout, scene.shading, scene.width, scene.height, scene.diff)) {
        const char* text = pane.difference ? diffLabel.c_str() : toString(pane.mode);
        const ImVec2 size = ImGui::GetFont()->CalcTextSizeA(fontSize, 1e9f, 0.0f, text);
        const float cx = view.x + (float(pane.x) + float(pane.width) * 0.5f) / framebufferScale;
        const ImVec2 pos(std::round(cx - size.x * 0.5f), std::round(view.y + float(pane.y) / framebufferScale + pad * 2));
        draw->AddRectFilled(ImVec2(pos.x - pad, pos.y - pad), ImVec2(pos.x + size.x + pad, pos.y + size.y + pad),
                            IM_COL32(0, 0, 0, 150), pad);
        draw->AddText(ImGui::GetFont(), fontSize, pos, IM_COL32(255, 255, 255, 235), text);
    }
}

float drawCaption(const Scene& scene, const std::string& counter, const UiRect& view) {
    if (scene.title.empty() && scene.caption.empty()) return 0.0f;
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    ImFont* font = ImGui::GetFont();
    // Sizes follow the view's width (a 1000-unit view gets 1.75 times the panel's font for the title,
    // 1.35 for the caption), so the band reads from the back of the room yet covers only the bottom
    // ~15% of a 16:9 view, and a small window's view is not all caption.
    const float zoom = std::clamp(view.width / 1000.0f, 0.6f, 1.25f);
    const float titleSize = ImGui::GetFontSize() * 1.75f * zoom;
    const float captionSize = ImGui::GetFontSize() * 1.35f * zoom;
    const float pad = captionSize * 0.5f;
    const float counterWidth = counter.empty() ? 0.0f : font->CalcTextSizeA(captionSize, 1e9f, 0.0f, counter.c_str()).x + pad;
    const float wrap = std::max(view.width - 2.0f * pad - counterWidth, 1.0f);
    const char* title = scene.title.c_str();
    const char* caption = scene.caption.c_str();
    const float titleHeight = scene.title.empty() ? 0.0f : font->CalcTextSizeA(titleSize, 1e9f, wrap, title).y;
    const float captionHeight = scene.caption.empty() ? 0.0f : font->CalcTextSizeA(captionSize, 1e9f, wrap, caption).y;
    const float gap = titleHeight > 0.0f && captionHeight > 0.0f ? pad * 0.5f : 0.0f;
    const float band = titleHeight + gap + captionHeight + 2.0f * pad;
    const float top = view.y + view.height - band;
    draw->AddRectFilled(ImVec2(view.x, top), ImVec2(view.x + view.width, view.y + view.height), IM_COL32(0, 0, 0, 150));
    const ImVec2 titlePos(std::round(view.x + pad), std::round(top + pad));
    draw->AddText(font, titleSize, titlePos, IM_COL32(255, 255, 255, 255), title, nullptr, wrap);
    draw->AddText(font, captionSize, ImVec2(titlePos.x, std::round(titlePos.y + titleHeight + gap)),
                  IM_COL32(225, 225, 225, 255), caption, nullptr, wrap);
    if (!counter.empty())
        draw->AddText(font, captionSize, ImVec2(std::round(view.x + view.width - counterWidth), titlePos.y),
                      IM_COL32(200, 200, 200, 255), counter.c_str());
    return band;
}

void drawHud(const PanelStatus& status, const UiRect& view) {
    const ImGuiIO& io = ImGui::GetIO();
    const float margin = ImGui::GetFontSize() * 0.6f;
    ImGui::SetNextWindowPos(ImVec2(view.x + margin, view.y + view.height - margin), ImGuiCond_Always, ImVec2(0.0f, 1.0f));
    ImGui::SetNextWindowBgAlpha(0.55f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                   ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs;
    if (ImGui::Begin("##hud", nullptr, flags)) {
        // ImGui's Framerate is a running average over the last 120 frames.
        const float fps = io.Framerate > 0.0f ? io.Framerate : 0.0f;
        ImGui::Text("%.2f ms  %.1f FPS  %zu triangles", fps > 0.0f ? 1000.0f / fps : 0.0f, fps, status.frameTriangles);
        ImGui::TextUnformatted(status.glRenderer.c_str());
        if (!status.progress.empty()) ImGui::TextUnformatted(status.progress.c_str());
    }
    ImGui::End();
}

}  // namespace shadelab
