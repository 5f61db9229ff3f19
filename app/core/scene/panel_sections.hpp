#pragma once
// The panel's collapsing sections and their names, as --panel-sections takes them (in the panel's order).
// Header-only constants in core: cli/ checks the flag against them without depending on the viewer.
#include "core/scene/scene_names.hpp"

namespace shadelab {

enum class PanelSection {
    Shading,
    Material,
    Plots,
    Shader,
    Mesh,
    Lights,
    Shadows,
    Overlays,
    Camera,
    Background,
    File,
    Keys
};

inline constexpr EnumName<PanelSection> kPanelSections[] = {
    {"shading", PanelSection::Shading},       {"material", PanelSection::Material}, {"plots", PanelSection::Plots},
    {"shader", PanelSection::Shader},         {"mesh", PanelSection::Mesh},         {"lights", PanelSection::Lights},
    {"shadows", PanelSection::Shadows},       {"overlays", PanelSection::Overlays}, {"camera", PanelSection::Camera},
    {"background", PanelSection::Background}, {"file", PanelSection::File},         {"keys", PanelSection::Keys}};

// The plots of the "plots" section, top to bottom, by their --plot names (a scene's "viewer": "plot"
// scrolls the panel to one; viewer/panel.cpp checks them against core/figures/plot.hpp's names).
inline constexpr const char* kPanelPlots[] = {"lobe", "fresnel", "lobe3d", "brdf-slice"};

}  // namespace shadelab
