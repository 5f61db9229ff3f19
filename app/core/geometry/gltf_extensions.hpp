#pragma once
// glTF extensions as the tools people use write them (gltfpack, glTF Transform, Blender): which ones
// shadelab decodes, which it names and refuses, and what the others would have changed.
//
// Two steps around tinygltf, which does not decode compressed data: before it parses, the JSON is
// checked and rewritten where tinygltf would refuse a valid file (a meshopt fallback buffer has no
// URI, a Draco primitive's accessors have no buffer view); after, the compressed buffer views and
// primitives are decoded into plain buffers, so the importer reads them like any other.
#include <nlohmann/json_fwd.hpp>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace tinygltf {
class Model;
}

namespace shadelab {

// Extensions whose data shadelab reads (a file may require them).
extern const std::vector<std::string> kDecodedGltfExtensions;

// What the JSON step found.
struct GltfPrepass {
    std::vector<std::string> warnings;  // one line for the extensions used but not read
    std::vector<int> fallbackBuffers;   // EXT_meshopt_compression fallback buffers (no data of their own)
    // Draco primitives' index accessors, by (mesh, primitive): taken out of the JSON for tinygltf
    // (which insists on their buffer view) and put back before decoding.
    std::map<std::pair<int, int>, int> dracoIndices;
};

// Checks `extensionsRequired` (InputError "<label>: requires KHR_texture_basisu, which shadelab does
// not read" for the first that is not decoded), words a warning for each extension only used, and
// prepares `doc` for tinygltf. True when `doc` was changed.
bool prepareGltfExtensions(nlohmann::json& doc, const std::string& label, GltfPrepass& out);

// Decodes EXT_meshopt_compression buffer views and KHR_draco_mesh_compression primitives of a parsed
// model in place. InputError naming the buffer view or primitive for data that does not decode.
void decodeCompressedGltf(tinygltf::Model& model, const GltfPrepass& prepass, const std::string& label);

}  // namespace shadelab
