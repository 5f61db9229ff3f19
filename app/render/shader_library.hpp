#pragma once
// Where GLSL files come from: a folder on disk when one is given and holds the file (so a lecturer
// can edit the shaders), otherwise the copies built into the binary.
#include <string>

namespace shadelab {

class ShaderLibrary {
public:
    explicit ShaderLibrary(std::string diskFolder = {}) : diskFolder_(std::move(diskFolder)) {}
    // The file's text; throws std::runtime_error if it is neither on disk nor embedded.
    std::string load(const std::string& name) const;
    const std::string& diskFolder() const { return diskFolder_; }

private:
    std::string diskFolder_;
};

}  // namespace shadelab
