#pragma once
// The panel's Shader section (key S): the GLSL files the selected pane's mode runs (its vertex and
// fragment stages and shaders/lighting.glsl), read-only, with line numbers, syntax colours and the
// lines that compute each term of the formula marked in the formula overlay's colours; after a failed
// reload (F5) the error's line is marked red with the driver's message (core/figures/shader_listing.hpp).
#include "core/probe/probe.hpp"
#include "core/scene/scene.hpp"
#include "viewer/panel.hpp"

#include <string>
#include <vector>

struct ImFont;

namespace shadelab {

// The Shader section's combo: one item a pane that runs a mode (not the diff layout's difference),
// "pane 2: gouraud", numbered as the probe numbers them (paneName); empty where there is one pane.
std::vector<std::string> shaderPaneChoices(const Scene& scene);

void sectionShader(const Scene& scene, ViewSettings& settings, const PanelStatus& status, const ProbeResult* probe);

// S: the same view, large, over the left of the 3D view (kShaderOverViewShare of its width, its whole
// height) for a lecture hall: `text` (the view text's font) and `mono` (DejaVu Sans Mono at that size;
// null: the panel's), code lines wrapped at the box's width, term lines marked as in the panel.
inline constexpr float kShaderOverViewShare = 0.6f;
void drawShaderOverView(const Scene& scene, ViewSettings& settings, const PanelStatus& status, const ProbeResult* probe,
                        const UiRect& view, ImFont* text, ImFont* mono);

// After a failed reload (F5): points the Shader view at the first error of `log` that names a file,
// in whatever layout: the pane whose mode runs that file is chosen (else the file is shown as one more
// tab beside the pane's), and its tab is selected and the line scrolled to when the view is next drawn.
// Returns whether the log names a file.
bool focusShaderError(const Scene& scene, ViewSettings& settings, const std::string& log);

}  // namespace shadelab
