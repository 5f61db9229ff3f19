#include "core/base/embedded.hpp"

namespace shadelab {

const char* findEmbedded(const EmbeddedFile* files, const std::string& name) {
    for (const EmbeddedFile* f = files; f && f->name; ++f)
        if (name == f->name) return f->contents;
    return nullptr;
}

}  // namespace shadelab
