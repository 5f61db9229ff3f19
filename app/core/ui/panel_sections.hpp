#pragma once
// The names of the panel's collapsing sections, as --panel-sections takes them (in the panel's order).
// Header-only constants in core: cli/ checks the flag against them without depending on the viewer.
namespace shadelab {

inline constexpr const char* kPanelSections[] = {"shading", "material", "plots", "shader", "mesh", "lights", "shadows",
                                                 "overlays", "camera", "background", "file", "keys"};

}  // namespace shadelab
