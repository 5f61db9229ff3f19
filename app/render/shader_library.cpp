#include "render/shader_library.hpp"

#include "core/embedded.hpp"

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
#ifdef SHADELAB_SOURCE_SHADER_DIR
    std::error_code ec;
    if (std::filesystem::is_regular_file(std::filesystem::path(SHADELAB_SOURCE_SHADER_DIR) / "lighting.glsl", ec))
        return SHADELAB_SOURCE_SHADER_DIR;
#endif
    return {};
}

}  // namespace shadelab
