#include "render/shader_library.hpp"

#include "core/embedded.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace shadelab {

std::string ShaderLibrary::load(const std::string& name) const {
    if (!diskFolder_.empty()) {
        std::ifstream in(diskFolder_ + "/" + name, std::ios::binary);
        if (in) {
            std::ostringstream s;
            s << in.rdbuf();
            return s.str();
        }
    }
    if (const char* text = findEmbedded(kEmbeddedShaders, name)) return text;
    throw std::runtime_error("shader file " + name + " not found");
}

}  // namespace shadelab
