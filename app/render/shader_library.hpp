#pragma once
// Where GLSL files come from: a folder on disk when one is given and holds the file (so a lecturer
// can edit the shaders and reload them), otherwise the copies built into the binary.
//
// The folder is read once, when the library is made: a renderer compiles its programs lazily (on
// first use of a mode), and it must compile them from the sources it was validated with, not from a
// file someone broke a minute later.
#include <map>
#include <string>

namespace shadelab {

class ShaderLibrary {
public:
    explicit ShaderLibrary(std::string diskFolder = {});
    // The file's text; throws std::runtime_error if it is neither on disk nor embedded.
    std::string load(const std::string& name) const;
    const std::string& diskFolder() const { return diskFolder_; }

private:
    std::string diskFolder_;
    std::map<std::string, std::string> diskFiles_;  // name -> contents, read at construction
};

// The GLSL folder beside the program: an installed shadelab's share/shadelab/shaders; for a program in
// a build folder of a checkout, the checkout's shaders/ (so edits there take effect without a
// rebuild); else a build folder's share/shadelab/shaders (linked to its checkout's shaders/); empty
// when there is none (the built-in copies are used).
std::string defaultShaderFolder();

// The folder a run reads GLSL from: `asked` (--shader-dir), else defaultShaderFolder().
std::string shaderFolder(const std::string& asked);

}  // namespace shadelab
