#pragma once
// Files built into the binary at build time (cmake/EmbedFiles.cmake), so an installed shadelab needs
// nothing beside it. Arrays end with {nullptr, nullptr}.
#include <string>

namespace shadelab {

struct EmbeddedFile {
    const char* name;      // path relative to the embedded folder, e.g. "lighting.glsl"
    const char* contents;  // the file's bytes, NUL-terminated
};

extern const EmbeddedFile kEmbeddedShaders[];  // shaders/
extern const EmbeddedFile kEmbeddedScenes[];   // assets/scenes/

// Returns the contents of `name` in `files`, or nullptr if it is not there.
const char* findEmbedded(const EmbeddedFile* files, const std::string& name);

}  // namespace shadelab
