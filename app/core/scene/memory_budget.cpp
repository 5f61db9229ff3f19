#include "core/scene/memory_budget.hpp"

#include "core/base/error.hpp"
#include "platform/platform.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace shadelab {
namespace {

std::optional<std::uint64_t> gBudget;

// The process with its GL driver loaded and a small frame drawn: ~85 MB peak (llvmpipe).
constexpr std::uint64_t kProgramBytes = std::uint64_t(96) << 20;
// Per pixel of a frame: colour and depth of the window-system buffer, the read-back RGBA image and
// the PNG's rows (~20 bytes measured); each sample of a multisampled target adds ~10.
constexpr std::uint64_t kBytesPerPixel = 20, kBytesPerSample = 10;
// Per shadow-map texel: a 32-bit depth; area lights' sample maps measured ~1.6 times that.
constexpr std::uint64_t kBytesPerTexel = 4;
// Per triangle: ~60 bytes drawn smooth (the mesh, the driver's buffers and binning), ~85 more when a
// flat pane needs its own vertices (2M-triangle sphere: single 245 MB, compare 607 MB, measured).
constexpr std::uint64_t kBytesPerTriangle = 60, kBytesPerFlatTriangle = 85;

// Per byte of a decoded base colour image: ~3.3 (a 4096 x 4096 texture, 64 MiB decoded, raised the
// peak by 213 MB: the decoded copy, the decoder's buffer while it is copied, the GL texture and its
// mip levels).
constexpr std::uint64_t kTextureBytesNumerator = 10, kTextureBytesDenominator = 3;

bool drawsFlat(const Scene& s) {
    return s.layout == Layout::Compare || s.shading == ShadingMode::Flat ||
           (s.layout == Layout::Diff && (s.diff.a == ShadingMode::Flat || s.diff.b == ShadingMode::Flat));
}

// A limit file's number ("536870912\n"); 0 for "max", v1's "no limit" (2^63 less a page) or anything
// unreadable.
std::uint64_t limitIn(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::string text;
    if (!(in >> text) || text.empty() || text.find_first_not_of("0123456789") != std::string::npos || text.size() > 19)
        return 0;
    const std::uint64_t bytes = std::stoull(text);
    return bytes >= (std::uint64_t(1) << 62) ? 0 : bytes;
}

}  // namespace

std::uint64_t cgroupMemoryLimit(const std::string& root, const std::string& selfCgroup) {
    namespace fs = std::filesystem;
    // /proc/self/cgroup: "0::/PATH" (v2), "N:memory:/PATH" or "N:cpu,memory:/PATH" (v1).
    std::ifstream lines(selfCgroup);
    std::uint64_t smallest = 0;
    const auto take = [&smallest](std::uint64_t bytes) {
        if (bytes && (!smallest || bytes < smallest)) smallest = bytes;
    };
    for (std::string line; std::getline(lines, line);) {
        const std::size_t first = line.find(':'), second = line.find(':', first + 1);
        if (first == std::string::npos || second == std::string::npos) continue;
        const std::string controllers = "," + line.substr(first + 1, second - first - 1) + ",";
        const fs::path group = fs::path(line.substr(second + 1)).relative_path();
        fs::path base;
        std::string file;
        if (line.compare(0, first, "0") == 0 && controllers == ",,") {
            base = root;
            file = "memory.max";
        } else if (controllers.find(",memory,") != std::string::npos) {
            base = fs::path(root) / "memory";
            file = "memory.limit_in_bytes";
        } else {
            continue;
        }
        // The group and each parent up to the root (a limit set on a parent holds for its children), and
        // the root itself: inside a container's namespace the group's path is the host's, its files at the root.
        for (fs::path g = group;; g = g.parent_path()) {
            take(limitIn(base / g / file));
            if (g.empty()) break;
        }
    }
    return smallest;
}

std::uint64_t defaultMemoryBudget() {
    std::uint64_t physical = platform::physicalMemoryBytes();
    const std::uint64_t limit = cgroupMemoryLimit();
    if (limit && (physical == 0 || limit < physical)) physical = limit;
    if (physical == 0) return std::uint64_t(4) << 30;
    return physical / 2;
}

std::uint64_t memoryBudget() { return gBudget ? *gBudget : defaultMemoryBudget(); }

void setMemoryBudget(std::optional<std::uint64_t> bytes) { gBudget = bytes; }

std::uint64_t proceduralTriangles(const MeshSpec& m) {
    const auto n = [](int v) { return std::uint64_t(std::max(v, 0)); };
    switch (m.type) {
    case MeshSpec::Type::UvSphere: return 2 * n(m.slices) * (n(m.stacks) > 0 ? n(m.stacks) - 1 : 0);
    case MeshSpec::Type::IcoSphere:
        return 20 * (std::uint64_t(1) << (2 * std::min(n(m.subdivisions), std::uint64_t(20))));
    case MeshSpec::Type::Torus: return 2 * n(m.majorSegments) * n(m.minorSegments);
    case MeshSpec::Type::Cube: return 12;
    case MeshSpec::Type::Plane: return 2 * n(m.planeSubdivisions) * n(m.planeSubdivisions);
    case MeshSpec::Type::Gltf: return 0;
    }
    return 0;
}

MemoryUse estimateFrame(const Scene& s, int msaaSamples, std::optional<std::uint64_t> triangles,
                        std::uint64_t textureBytes) {
    MemoryUse use;
    use.program = kProgramBytes;
    const std::uint64_t pixels = std::uint64_t(std::max(s.width, 0)) * std::uint64_t(std::max(s.height, 0));
    use.framebuffers = pixels * (kBytesPerPixel + (msaaSamples > 1 ? kBytesPerSample * std::uint64_t(msaaSamples) : 0));
    if (s.shadows.enabled) {
        const std::uint64_t map = std::uint64_t(s.shadows.mapSize) * std::uint64_t(s.shadows.mapSize);
        const std::uint64_t areaMap = std::uint64_t(s.shadows.areaMapSize) * std::uint64_t(s.shadows.areaMapSize);
        for (const Light& l : s.lights) {
            if (l.type == LightType::Point) use.shadowMaps += 6 * map * kBytesPerTexel;
            else if (l.type == LightType::Directional || l.type == LightType::Spot)
                use.shadowMaps += map * kBytesPerTexel;
            else
                use.shadowMaps +=
                    std::uint64_t(l.samples.x) * std::uint64_t(l.samples.y) * areaMap * kBytesPerTexel * 8 / 5;
        }
    }
    std::uint64_t tris = 0;
    if (triangles) tris = *triangles;
    else
        for (const SceneObject& o : s.objects) tris += proceduralTriangles(o.mesh);
    use.meshes = tris * (kBytesPerTriangle + (drawsFlat(s) ? kBytesPerFlatTriangle : 0));
    use.textures = textureBytes * kTextureBytesNumerator / kTextureBytesDenominator;
    return use;
}

std::string formatBytes(std::uint64_t bytes) {
    char text[32];
    if (bytes >= (std::uint64_t(1) << 30))
        std::snprintf(text, sizeof text, "%.1f GiB", double(bytes) / double(1u << 30));
    else std::snprintf(text, sizeof text, "%.0f MiB", double(bytes) / double(1u << 20));
    return text;
}

void checkMemory(const MemoryUse& use, const std::string& what) {
    const std::uint64_t budget = memoryBudget();
    if (use.total() <= budget) return;
    std::string parts;
    const auto part = [&](const char* name, std::uint64_t b) {
        if (b >= (std::uint64_t(1) << 20))
            parts += std::string(parts.empty() ? "" : ", ") + name + " " + formatBytes(b);
    };
    part("framebuffers", use.framebuffers);
    part("shadow maps", use.shadowMaps);
    part("meshes", use.meshes);
    part("images", use.images);
    part("textures", use.textures);
    throw InputError(what + " needs about " + formatBytes(use.total()) + " (" + parts +
                     "), more than the memory budget of " + formatBytes(budget) + " (--max-memory)");
}

std::optional<std::uint64_t> parseByteSize(const std::string& text) {
    if (text.empty() || !std::isdigit(static_cast<unsigned char>(text[0]))) return std::nullopt;
    std::size_t used = 0;
    double value = 0;
    try {
        value = std::stod(text, &used);
    } catch (...) {
        return std::nullopt;
    }
    std::string unit = text.substr(used);
    if (!unit.empty() && (unit.back() == 'B' || unit.back() == 'b') && unit.size() > 1)
        unit.pop_back();  // "2GB", "2GiB"
    if (unit.size() == 2 && (unit[1] == 'i' || unit[1] == 'I')) unit.pop_back();
    int shift = 0;
    if (unit.empty()) shift = 0;
    else if (unit == "K" || unit == "k") shift = 10;
    else if (unit == "M" || unit == "m") shift = 20;
    else if (unit == "G" || unit == "g") shift = 30;
    else if (unit == "T" || unit == "t") shift = 40;
    else return std::nullopt;
    const double bytes = value * double(std::uint64_t(1) << shift);
    if (!std::isfinite(bytes) || bytes < 0 || bytes > 9.0e18) return std::nullopt;
    return std::uint64_t(bytes);
}

}  // namespace shadelab
