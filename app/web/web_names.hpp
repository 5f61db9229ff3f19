#pragma once
// The key table's keys and commands (core/ui/controls.hpp) by the names the page uses: a key as the
// browser's KeyboardEvent.key names it, a command as the page (web/src/keys.js) carries it out.
#include "core/ui/controls.hpp"

namespace shadelab {

inline const char* webKeyName(ViewerKey key) {
    switch (key) {
    case ViewerKey::None: return "";
    case ViewerKey::Tab: return "Tab";
    case ViewerKey::Escape: return "Escape";
    case ViewerKey::Backspace: return "Backspace";
    case ViewerKey::F1: return "F1";
    case ViewerKey::F5: return "F5";
    case ViewerKey::F11: return "F11";
    case ViewerKey::F12: return "F12";
    case ViewerKey::PageDown: return "PageDown";
    case ViewerKey::PageUp: return "PageUp";
    case ViewerKey::Right: return "ArrowRight";
    case ViewerKey::Left: return "ArrowLeft";
    case ViewerKey::Home: return "Home";
    case ViewerKey::End: return "End";
    case ViewerKey::Plus: return "=";
    case ViewerKey::Minus: return "-";
    case ViewerKey::Zero: return "0";
    case ViewerKey::Q: return "q";
    case ViewerKey::R: return "r";
    }
    return "";
}

inline const char* commandName(ViewerCommand command) {
    switch (command) {
    case ViewerCommand::None: return "";
    case ViewerCommand::Flat: return "flat";
    case ViewerCommand::Gouraud: return "gouraud";
    case ViewerCommand::Phong: return "phong";
    case ViewerCommand::Compare: return "compare";
    case ViewerCommand::Difference: return "difference";
    case ViewerCommand::Wireframe: return "wireframe";
    case ViewerCommand::VertexNormals: return "vertex-normals";
    case ViewerCommand::FaceNormals: return "face-normals";
    case ViewerCommand::LightMarkers: return "light-markers";
    case ViewerCommand::Formula: return "formula";
    case ViewerCommand::Intersection: return "intersection";
    case ViewerCommand::ShaderSection: return "shader";
    case ViewerCommand::ResetCamera: return "reset-camera";
    case ViewerCommand::FrameModel: return "frame-model";
    case ViewerCommand::NextPreset: return "next-preset";
    case ViewerCommand::PreviousPreset: return "previous-preset";
    case ViewerCommand::FirstPreset: return "first-preset";
    case ViewerCommand::LastPreset: return "last-preset";
    case ViewerCommand::ResetPreset: return "reset-preset";
    case ViewerCommand::UiLarger: return "ui-larger";
    case ViewerCommand::UiSmaller: return "ui-smaller";
    case ViewerCommand::UiAsMonitor: return "ui-as-monitor";
    case ViewerCommand::TogglePanel: return "toggle-panel";
    case ViewerCommand::Fullscreen: return "fullscreen";
    case ViewerCommand::Help: return "help";
    case ViewerCommand::ReloadShaders: return "reload-shaders";
    case ViewerCommand::Screenshot: return "screenshot";
    case ViewerCommand::PlayPause: return "play-pause";
    case ViewerCommand::Record: return "record";
    case ViewerCommand::Escape: return "escape";
    case ViewerCommand::Quit: return "quit";
    }
    return "";
}

}  // namespace shadelab
