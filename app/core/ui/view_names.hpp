#pragma once
// The names of the view's choices that both the command line and the viewer's panel offer, defined
// once: the overlays (--overlays, the panel's Overlays section) and multisample anti-aliasing (--msaa,
// the panel's Display section). GL-free, header-only; in core so the command line needs no viewer
// header (like core/ui/controls.hpp and core/scene/panel_sections.hpp).
#include "core/scene/scene_names.hpp"

#include <string>

namespace shadelab {

// The overlays a session can start with; render/overlay_renderer.hpp's OverlayOptions switches them.
enum class Overlay { Wireframe, VertexNormals, FaceNormals, Tangents, LightMarkers };

// --overlays' names.
inline constexpr EnumName<Overlay> kOverlayNames[] = {{"wireframe", Overlay::Wireframe},
                                                      {"vertex-normals", Overlay::VertexNormals},
                                                      {"face-normals", Overlay::FaceNormals},
                                                      {"tangents", Overlay::Tangents},
                                                      {"lights", Overlay::LightMarkers}};
// The panel's checkboxes, with the key that toggles each (core/ui/controls.hpp).
inline constexpr EnumName<Overlay> kOverlayLabels[] = {{"wireframe (W)", Overlay::Wireframe},
                                                       {"vertex normals (N)", Overlay::VertexNormals},
                                                       {"face normals (Shift+N)", Overlay::FaceNormals},
                                                       {"tangents (anisotropy's T)", Overlay::Tangents},
                                                       {"3D light crosses", Overlay::LightMarkers}};

// Samples per pixel as --msaa takes them (0 and 1: off; the driver may round up). The panel offers
// the same counts from 1 on, labelled by msaaLabel().
inline constexpr EnumName<int> kMsaaNames[] = {{"0", 0}, {"1", 1}, {"2", 2}, {"4", 4}, {"8", 8}};

// How the panel shows a sample count: "off" for 0 and 1, else "4x".
inline std::string msaaLabel(int samples) { return samples <= 1 ? "off" : std::to_string(samples) + "x"; }

// A pane by its index in layoutPanes (core/geometry/camera.hpp): numbered from 1, left to right, the
// same in the probe's line and the Shader section's combo.
inline std::string paneName(int index) { return "pane " + std::to_string(index + 1); }

}  // namespace shadelab
