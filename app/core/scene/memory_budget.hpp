#pragma once
// What a headless request will need in memory, estimated before anything is allocated, against a
// budget: a sensible share of the machine's memory by default, --max-memory to change it. A request
// over budget is refused with one line that says what it would need (exit status 2), instead of
// running the machine out of memory part-way (README, "Bad input").
//
// The figures are whole-process peaks measured on Mesa's llvmpipe, where framebuffers, textures and
// vertex buffers live in system memory (bench/README.md, "Memory"); a GPU keeps most of it in its
// own memory, so there the estimate errs on the safe side.
#include "core/scene/scene.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace shadelab {

struct MemoryUse {
    std::uint64_t program = 0;       // shadelab and the GL driver themselves, before any request
    std::uint64_t framebuffers = 0;  // colour, depth, multisampled copies, the read-back image
    std::uint64_t shadowMaps = 0;
    std::uint64_t meshes = 0;    // CPU arrays, the driver's vertex buffers and its binned triangles
    std::uint64_t images = 0;    // frames kept for a contact sheet or a playlist
    std::uint64_t textures = 0;  // glTF base colour images: decoded, and as GL textures with their mip levels
    std::uint64_t total() const { return program + framebuffers + shadowMaps + meshes + images + textures; }
};

// Half of the memory this process may use: physical memory (sysconf), or the container's limit where
// its cgroup sets a smaller one (cgroupMemoryLimit); 4 GiB where neither can be read.
std::uint64_t defaultMemoryBudget();
// The memory limit of this process's cgroup (Linux; a container's `docker run --memory`, a CI job's
// limit): cgroup v2's `memory.max` of the process's own group or, where the container's namespace
// shows the group as the root, of `root`; cgroup v1's `memory/.../memory.limit_in_bytes` likewise.
// 0 when there is none ("max", v1's near-2^63 "unlimited") or it cannot be read (not Linux).
// `root` and `selfCgroup` are parameters for the tests (a folder laid out as /sys/fs/cgroup is).
std::uint64_t cgroupMemoryLimit(const std::string& root = "/sys/fs/cgroup",
                                const std::string& selfCgroup = "/proc/self/cgroup");
// The budget in force: --max-memory's, else the default.
std::uint64_t memoryBudget();
void setMemoryBudget(std::optional<std::uint64_t> bytes);

// Triangles a procedural mesh will have (0 for a glTF model: known once it is read).
std::uint64_t proceduralTriangles(const MeshSpec& spec);

// One frame of `scene` at its size. `triangles`: the loaded meshes' total; without it, the
// procedural meshes' (a model's are checked again after it is read). `textureBytes`: the loaded
// models' decoded base colour images (SceneGeometry::textureBytes).
MemoryUse estimateFrame(const Scene& scene, int msaaSamples, std::optional<std::uint64_t> triangles = std::nullopt,
                        std::uint64_t textureBytes = 0);

// Throws InputError "<what> needs about 5.2 GiB (...), more than the memory budget of 4.0 GiB
// (--max-memory)" when `use` is over the budget.
void checkMemory(const MemoryUse& use, const std::string& what);

// "1.5 GiB", "640 MiB".
std::string formatBytes(std::uint64_t bytes);

// "--max-memory" values: a number of bytes with an optional K, M, G or T (powers of 1024).
// std::nullopt when `text` is not one.
std::optional<std::uint64_t> parseByteSize(const std::string& text);

}  // namespace shadelab
