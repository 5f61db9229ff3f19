// libFuzzer target: glTF import from bytes (.glb when they start with "glTF", else .gltf JSON).
// Any input either loads or is an InputError; what loads must be a valid mesh. External URIs resolve
// against an empty folder, so only data: URIs and embedded buffers are exercised.
#include "core/base/error.hpp"
#include "core/geometry/gltf_import.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    shadelab::Mesh mesh;
    try {
        mesh = shadelab::loadGltfFromMemory(bytes, "fuzz.gltf", "/nonexistent-shadelab-fuzz");
    } catch (const shadelab::InputError&) {
        return 0;
    }
    if (mesh.normals.size() != mesh.positions.size() || mesh.indices.size() % 3 != 0) std::abort();
    for (std::uint32_t i : mesh.indices)
        if (i >= mesh.positions.size()) std::abort();
    for (const auto& n : mesh.normals)
        if (!(std::fabs(glm::length(n) - 1.0f) < 1e-3f)) std::abort();
    for (const auto& part : mesh.parts)
        if (std::size_t(part.firstIndex) + part.indexCount > mesh.indices.size()) std::abort();
    return 0;
}
