#pragma once
// Every key and mouse action of the viewer, in one table: the panel's Keys section, the help overlay
// (F1 or ?) and `shadelab --help` are all printed from it, so they cannot disagree. GL-free; in core
// so the command line prints it without depending on the viewer.
#include "core/scene/scene_limits.hpp"

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <string>

namespace shadelab {

// --ui-scale and Ctrl+= / Ctrl+-: kUiScaleRange (core/scene/scene_limits.hpp).

struct Control {
    const char* input;   // "Page Down / Page Up", "left drag"
    const char* action;  // what it does, in a few words
};

inline constexpr Control kControls[] = {
    {"left drag", "orbit around the target"},
    {"right or middle drag", "pan"},
    {"wheel", "zoom (a fixed step in and out, at any distance)"},
    {"left click", "probe the pixel: N, V, I, R, H and every term"},
    {"drag a light marker", "move the light (Shift: along the view axis)"},
    {"drop a file", "open a .json scene or a .gltf / .glb model"},
    {"1  2  3", "flat / Gouraud / Phong in a single pane"},
    {"C", "compare: flat | Gouraud | Phong"},
    {"D", "difference: A | B | |A - B| x factor"},
    {"W", "wireframe"},
    {"N   Shift+N", "vertex normals / face normals"},
    {"L", "light markers"},
    {"E", "the formula over the view (the term --show isolates highlighted)"},
    {"S", "the shader's GLSL in the panel (Shader section), terms marked"},
    {"R   F", "reset the camera to the scene's / frame the model"},
    {"Page Down  Page Up  (Right  Left)", "playlist: next / previous preset"},
    {"Home  End", "playlist: first / last preset"},
    {"Backspace", "playlist: reset the preset (reload its file)"},
    {"Ctrl+=  Ctrl+-  Ctrl+0", "UI scale larger / smaller / as the monitor's"},
    {"Tab", "hide / show the panel (projector view)"},
    {"F11", "fullscreen on / off"},
    {"F1  or  ?", "this help on / off"},
    {"F5", "reload the shaders (errors show, the picture stays)"},
    {"F12", "screenshot of the 3D view (timestamped PNG)"},
    {"Space", "play / pause the --animate animation"},
    {"Ctrl+R", "record the 3D view to a timestamped MP4 / stop"},
    {"Esc", "close the help, clear the probe, leave a text field"},
    {"Q  or  Ctrl+Q", "quit"},
};

// The table as aligned text lines ("  Tab        hide / show the panel"), for --help.
inline std::string controlsText(const char* indent = "  ") {
    std::size_t width = 0;
    for (const Control& c : kControls) width = std::max(width, std::string(c.input).size());
    std::string text;
    for (const Control& c : kControls) {
        const std::string input = c.input;
        text += indent + input + std::string(width + 2 - input.size(), ' ') + c.action + "\n";
    }
    return text;
}

}  // namespace shadelab
