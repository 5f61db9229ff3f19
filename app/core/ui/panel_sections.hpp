#pragma once
// The names of the panel's collapsing sections, as --panel-sections takes them (in the panel's order).
// Header-only constants in core: cli/ checks the flag against them without depending on the viewer.
namespace shadelab {

inline constexpr const char* kPanelSections[] = {"shading", "material", "plots", "shader", "mesh", "lights", "shadows",
                                                 "overlays", "camera", "background", "file", "keys"};

// The plots of the "plots" section, top to bottom, by their --plot names (a scene's "viewer": "plot"
// scrolls the panel to one; viewer/panel.cpp checks them against core/figures/plot.hpp's names).
inline constexpr const char* kPanelPlots[] = {"lobe", "fresnel", "lobe3d", "brdf-slice"};

}  // namespace shadelab
