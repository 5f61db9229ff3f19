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

// What a key does in the viewer (Viewer::runCommand carries it out).
// (grouped as the key table groups them: clang-format leaves it as written)
// clang-format off
enum class ViewerCommand {
    None,  // an unused binding slot
    Flat, Gouraud, Phong, Compare, Difference,
    Wireframe, VertexNormals, FaceNormals, LightMarkers, Formula, Intersection, ShaderSection,
    ResetCamera, FrameModel,
    NextPreset, PreviousPreset, FirstPreset, LastPreset, ResetPreset,  // only while a playlist runs
    UiLarger, UiSmaller, UiAsMonitor,
    TogglePanel, Fullscreen, Help, ReloadShaders, Screenshot, PlayPause, Record,
    Escape,  // close the help, else clear the probe
    Quit,
};
// clang-format on

// A key without a character, named here so core needs no window library (the viewer maps GLFW's codes).
// Plus, Minus and Zero are the main keyboard's key or the keypad's.
// (one line, as the keys are listed: clang-format leaves it as written)
// clang-format off
enum class ViewerKey {
    None, Tab, Escape, Backspace, F1, F5, F11, F12, PageDown, PageUp, Right, Left, Home, End, Plus, Minus, Zero, Q, R
};
// clang-format on

enum class KeyMods { None, Ctrl, Any };  // Ctrl not held / held / either (other modifiers are ignored)

// Where a key acts: over the view only (a panel widget holding the keyboard keeps it), or also while
// a widget has focus unless text is typed (a presenter's remote sends Page Down, Page Up and Esc).
enum class KeyFocus { View, UnlessTyping };

// One way to trigger a command: typed characters (letters follow the keyboard layout: Q is Q on AZERTY;
// with Ctrl held there are none) or a key by its code with the modifiers it needs.
struct KeyBinding {
    const char* characters = nullptr;  // any of these typed characters ("cC"), or nullptr
    ViewerKey key = ViewerKey::None;   // else this key
    KeyMods mods = KeyMods::None;
    KeyFocus focus = KeyFocus::View;
    ViewerCommand command = ViewerCommand::None;
};

constexpr KeyBinding typed(const char* characters, ViewerCommand command) {
    return KeyBinding{characters, ViewerKey::None, KeyMods::None, KeyFocus::View, command};
}
constexpr KeyBinding pressed(ViewerKey key, ViewerCommand command, KeyMods mods = KeyMods::None,
                             KeyFocus focus = KeyFocus::View) {
    return KeyBinding{nullptr, key, mods, focus, command};
}

struct Control {
    const char* input;   // "Page Down / Page Up", "left drag"
    const char* action;  // what it does, in a few words
    KeyBinding keys[4];  // the keys that do it (none for the mouse's rows)
};

// (a table, read row by row: clang-format leaves it as written)
// clang-format off
inline constexpr Control kControls[] = {
    {"left drag", "orbit around the target", {}},
    {"right or middle drag", "pan", {}},
    {"wheel", "zoom (a fixed step in and out, at any distance)", {}},
    {"left click", "probe the pixel: N, V, I, R, H and every term", {}},
    {"drag a light marker", "move the light (Shift: along the view axis)", {}},
    {"drop a file", "open a .json scene or a .gltf / .glb model", {}},
    {"1  2  3", "flat / Gouraud / Phong in a single pane",
     {typed("1", ViewerCommand::Flat), typed("2", ViewerCommand::Gouraud), typed("3", ViewerCommand::Phong)}},
    {"C", "compare: flat | Gouraud | Phong", {typed("cC", ViewerCommand::Compare)}},
    {"D", "difference: A | B | |A - B| x factor", {typed("dD", ViewerCommand::Difference)}},
    {"W", "wireframe", {typed("wW", ViewerCommand::Wireframe)}},
    {"N   Shift+N", "vertex normals / face normals",
     {typed("n", ViewerCommand::VertexNormals), typed("N", ViewerCommand::FaceNormals)}},
    {"L", "light markers", {typed("lL", ViewerCommand::LightMarkers)}},
    {"E", "the lecture's formula (the term --show isolates highlighted)", {typed("eE", ViewerCommand::Formula)}},
    {"I", "the intersection at the probed point: I, N, R, T, theta_i, theta_t, eta and the Fresnel split",
     {typed("iI", ViewerCommand::Intersection)}},
    {"S", "the shader's GLSL, large, terms marked (F5's errors shown in it)",
     {typed("sS", ViewerCommand::ShaderSection)}},
    {"R   F", "reset the camera to the scene's / frame the model",
     {typed("rR", ViewerCommand::ResetCamera), typed("fF", ViewerCommand::FrameModel)}},
    {"Page Down  Page Up  (Right  Left)", "playlist: next / previous preset",
     {pressed(ViewerKey::PageDown, ViewerCommand::NextPreset, KeyMods::Any, KeyFocus::UnlessTyping),
      pressed(ViewerKey::PageUp, ViewerCommand::PreviousPreset, KeyMods::Any, KeyFocus::UnlessTyping),
      pressed(ViewerKey::Right, ViewerCommand::NextPreset), pressed(ViewerKey::Left, ViewerCommand::PreviousPreset)}},
    {"Home  End", "playlist: first / last preset",
     {pressed(ViewerKey::Home, ViewerCommand::FirstPreset), pressed(ViewerKey::End, ViewerCommand::LastPreset)}},
    {"Backspace", "playlist: reset the preset (reload its file)",
     {pressed(ViewerKey::Backspace, ViewerCommand::ResetPreset)}},
    {"Ctrl+=  Ctrl+-  Ctrl+0", "UI scale larger / smaller / as the monitor's",
     {pressed(ViewerKey::Plus, ViewerCommand::UiLarger, KeyMods::Ctrl),
      pressed(ViewerKey::Minus, ViewerCommand::UiSmaller, KeyMods::Ctrl),
      pressed(ViewerKey::Zero, ViewerCommand::UiAsMonitor, KeyMods::Ctrl)}},
    {"Tab", "hide / show the panel (projector view)", {pressed(ViewerKey::Tab, ViewerCommand::TogglePanel)}},
    {"F11", "fullscreen on / off", {pressed(ViewerKey::F11, ViewerCommand::Fullscreen)}},
    {"F1  or  ?", "this help on / off", {pressed(ViewerKey::F1, ViewerCommand::Help), typed("?", ViewerCommand::Help)}},
    {"F5", "reload the shaders (errors show, the picture stays)",
     {pressed(ViewerKey::F5, ViewerCommand::ReloadShaders)}},
    {"F12", "screenshot of the 3D view (timestamped PNG)", {pressed(ViewerKey::F12, ViewerCommand::Screenshot)}},
    {"Space", "play / pause the --animate animation", {typed(" ", ViewerCommand::PlayPause)}},
    {"Ctrl+R", "record the 3D view to a timestamped MP4 / stop",
     {pressed(ViewerKey::R, ViewerCommand::Record, KeyMods::Ctrl)}},
    {"Esc", "close the help, clear the probe, leave a text field",
     {pressed(ViewerKey::Escape, ViewerCommand::Escape, KeyMods::Any, KeyFocus::UnlessTyping)}},
    {"Q  or  Ctrl+Q", "quit",
     {typed("qQ", ViewerCommand::Quit), pressed(ViewerKey::Q, ViewerCommand::Quit, KeyMods::Ctrl)}},
};
// clang-format on

// The binding of a typed character, or nullptr.
inline const KeyBinding* characterBinding(unsigned character) {
    for (const Control& c : kControls)
        for (const KeyBinding& b : c.keys)
            for (const char* ch = b.characters; ch && *ch; ++ch)
                if (static_cast<unsigned char>(*ch) == character) return &b;
    return nullptr;
}

// The binding of a key pressed with Ctrl held or not, or nullptr.
inline const KeyBinding* keyBinding(ViewerKey key, bool ctrl) {
    if (key == ViewerKey::None) return nullptr;
    for (const Control& c : kControls)
        for (const KeyBinding& b : c.keys)
            if (b.key == key && (b.mods == KeyMods::Any || (b.mods == KeyMods::Ctrl) == ctrl)) return &b;
    return nullptr;
}

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
