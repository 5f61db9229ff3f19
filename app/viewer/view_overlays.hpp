#pragma once
// What the viewer draws over and around the 3D view with Dear ImGui, outside the panel: the compare
// panes' labels and separators, a preset's caption band, the status strip, the last message, the help
// overlay and each light's marker; and picking a light's marker under the mouse (to drag it). Immediate
// mode, like panel.hpp: called every frame, no state of their own.
#include "core/geometry/camera.hpp"
#include "core/geometry/scene_geometry.hpp"
#include "core/scene/scene.hpp"
#include "viewer/panel.hpp"

#include <functional>
#include <string>
#include <vector>

namespace shadelab {

// Labels each pane of the 3D view with what differs between panes: the shading mode and the reflection
// model ("Phong shading · Blinn-Phong lobe"), two lines where the pane is narrow. `view` is the 3D view;
// `framebufferScale` converts the renderer's pixel panes to ImGui units.
// Returns the bottom of the lowest label (ImGui units; view.y when there are none).
// `fontSize`: the labels' text size (0: 1.4 times the current font's).
float drawPaneLabels(const Scene& scene, const UiRect& view, float framebufferScale, float fontSize = 0.0f);
// A thin line between side by side panes (compare, diff) over the view, so the class sees where one
// pane ends; 2 px at content scale 1. Not part of the 3D view's pixels (F12, --output).
void drawPaneSeparators(const Scene& scene, const UiRect& view, float framebufferScale);

// A preset's title and caption, sized for a projector and fitted into at most `maxHeight`: the band's
// text sizes and height (0: no title or caption).
struct CaptionLayout {
    float titleSize = 0, captionSize = 0, pad = 0, height = 0;
    int step = 0;  // how far it was made smaller to fit (0: not)
};
// Where the band has no room, the title gets smaller first (down to 1.3 times the caption's base, in
// kCaptionTitleSteps), then the caption by 10% with the title back at 1.6 times it, and so on: the
// caption keeps the view text's size wherever a smaller title makes room.
inline constexpr int kCaptionTitleSteps = 3;
// `minStep` is where the steps start (a playlist's captions share the largest step any of them needs).
// `viewText`: the view text's size (ImGui units; the caption is 1.25 times it, the title 1.6 times),
// where that is larger than the size the view's width gives the panel's font.
CaptionLayout layoutCaption(const Scene& scene, const std::string& counter, float width, float maxHeight,
                            int minStep = 0, float viewText = 0.0f);
// Draws it into `band` (above the 3D view), with `counter` ("3 / 20") at the right.
void drawCaption(const Scene& scene, const std::string& counter, const CaptionLayout& layout, const UiRect& band);

// The status strip above the view: frame time (the mean of the last second's frames) and the FPS it
// allows, or "idle" while nothing is drawn; triangles, GL renderer, progressive passes, animation.
void drawStatusStrip(const PanelStatus& status, const UiRect& strip);
// Its text, in at most `width` as `measure` gives a text's width: where all does not fit (a 2x screen
// beside the panel), the GL renderer's name goes first, then the triangle count; the frame time, the
// progressive passes and the animation's clock stay. Never cut mid-word at the strip's edge.
std::string statusStripText(const PanelStatus& status, float width,
                            const std::function<float(const std::string&)>& measure);

// The last message over the bottom of the 3D view (where the lecturer looks), red for an error.
void drawMessage(const PanelStatus& status, const UiRect& view);

// Every key and mouse action (core/ui/controls.hpp) in a box over the view: F1 or ?.
void drawHelpOverlay(const UiRect& view);

// Each light's marker over the view: a ring with its number and kind, an arrow along a directional
// light's travel, or an arrow at the pane's border toward a light outside it. Lines thicken with the
// UI scale. `selected`: the panel's selected light, drawn highlighted. Labels and border arrows stay
// below `top` (the pane labels' bottom) and off the `models` (world-space bounding spheres of the
// objects: a label that would cover one moves out, tied to its marker by a line). Returns the labels'
// boxes, for the probe's labels to avoid.
std::vector<UiRect> drawLightLabels(const Scene& scene, const UiRect& view, float framebufferScale, int selected,
                                    float top, const std::vector<BoundingSphere>& models = {});

// Where light `light`'s marker is grabbed (world space): core/scene's lightHandle, for a directional
// light the tail of its arrow.
glm::vec3 lightHandleWorld(const Scene& scene, std::size_t light);
// The light whose handle is nearest to `pixel` (image pixels of the view, in `pane`) within
// `radiusPixels`; -1 for none.
int lightAtPixel(const Scene& scene, const Pane& pane, glm::vec2 pixel, float radiusPixels);

}  // namespace shadelab
