#include "render/shader_library.hpp"

#include "core/base/embedded.hpp"
#include "core/base/file_io.hpp"
#include "platform/platform.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace shadelab {

ShaderLibrary::ShaderLibrary(std::string diskFolder) : diskFolder_(std::move(diskFolder)) {
    if (diskFolder_.empty()) return;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(diskFolder_, ec)) {
        const std::string ext = entry.path().extension().string();
        if (!entry.is_regular_file(ec) || (ext != ".glsl" && ext != ".vert" && ext != ".frag")) continue;
        std::ifstream in(entry.path(), std::ios::binary);
        std::ostringstream s;
        s << in.rdbuf();
        if (in) diskFiles_[entry.path().filename().string()] = s.str();
    }
}

std::string ShaderLibrary::load(const std::string& name) const {
    const auto it = diskFiles_.find(name);
    if (it != diskFiles_.end()) return it->second;
    if (const char* text = findEmbedded(kEmbeddedShaders, name)) return text;
    throw std::runtime_error("shader file " + name + " not found");
}

std::string defaultShaderFolder() {
    // Beside the program (core/base/file_io.hpp): an installed one's share/shadelab/shaders, a build
    // folder's checkout (build/shadelab -> shaders/), or a build folder's own share/shadelab/shaders.
    // Nothing of the build machine is compiled in.
    std::error_code ec;
    for (const std::filesystem::path& dir :
         dataFoldersBesideProgram(platform::executablePath(), "shaders", "shaders")) {
        if (std::filesystem::is_regular_file(dir / "lighting.glsl", ec))
            return std::filesystem::weakly_canonical(dir, ec).string();
    }
    return {};
}

std::string shaderFolder(const std::string& asked) { return asked.empty() ? defaultShaderFolder() : asked; }

}  // namespace shadelab
