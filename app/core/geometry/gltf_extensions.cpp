#include "core/geometry/gltf_extensions.hpp"

#include "core/base/error.hpp"

// Meshoptimizer and Draco are Debian's Linux libraries: a build without them (SHADELAB_MESHOPT,
// SHADELAB_DRACO off, as the Windows build is) does not list their extensions as read, so a file that
// requires one is refused by name and one that only uses it gets the usual warning.
#if SHADELAB_HAVE_DRACO
#include <draco/compression/decode.h>
#endif
#if SHADELAB_HAVE_MESHOPT
#include <meshoptimizer.h>
#endif
#include <tiny_gltf.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstring>

namespace shadelab {

const std::vector<std::string> kDecodedGltfExtensions = {
    "KHR_mesh_quantization",  // integer positions and normals, dequantized by the node transform
#if SHADELAB_HAVE_MESHOPT
    "EXT_meshopt_compression",  // meshoptimizer's vertex and index codecs and filters
#endif
#if SHADELAB_HAVE_DRACO
    "KHR_draco_mesh_compression",  // Draco-compressed primitives
#endif
    "EXT_mesh_gpu_instancing",          // a node drawn once per TRANSLATION / ROTATION / SCALE
    "KHR_texture_transform",            // the base colour and emissive textures' coordinates offset, rotated, scaled
    "KHR_materials_emissive_strength",  // E's factor multiplied past 1
    "KHR_lights_punctual",              // point, spot and directional lights: a scene's lights when it gives none
};

namespace {

bool decoded(const std::string& name) {
    return std::find(kDecodedGltfExtensions.begin(), kDecodedGltfExtensions.end(), name) !=
           kDecodedGltfExtensions.end();
}

// What extensions that are used but not read would have changed, in the words of the lecture: one
// warning line for all of them. Metadata (KHR_xmp) changes nothing drawn and is not mentioned.
std::string notRead(const std::vector<std::string>& names) {
    std::string list, effects;
    bool textures = false, materials = false, lights = false, other = false;
    for (const std::string& name : names) {
        if (name.rfind("KHR_xmp", 0) == 0) continue;
        list += (list.empty() ? "" : ", ") + name;
        if (name.rfind("KHR_materials_", 0) == 0) materials = true;
        else if (name.rfind("KHR_texture_", 0) == 0 || name.rfind("EXT_texture_", 0) == 0 || name == "MSFT_texture_dds")
            textures = true;
        else if (name == "KHR_lights_punctual") lights = true;
        else other = true;
    }
    if (list.empty()) return "";
    const auto add = [&](bool on, const char* what) {
        if (on) effects += std::string(effects.empty() ? "" : "; ") + what;
    };
    add(textures, "textures stored only in those formats are not drawn (a PNG or JPEG fallback is)");
    add(materials, "the lecture's model and the base colour shade every material");
    add(lights, "the scene's lights light the model, not the file's");
    add(other, "what the others add is not drawn");
    return "uses " + list + ", which shadelab does not read: " + effects;
}

const nlohmann::json* extension(const nlohmann::json& object, const char* name) {
    if (!object.is_object()) return nullptr;
    const auto ext = object.find("extensions");
    if (ext == object.end() || !ext->is_object()) return nullptr;
    const auto e = ext->find(name);
    return e == ext->end() ? nullptr : &*e;
}

}  // namespace

bool prepareGltfExtensions(nlohmann::json& doc, const std::string& label, GltfPrepass& out) {
    const auto names = [&](const char* key) {
        std::vector<std::string> list;
        const auto it = doc.find(key);
        if (it != doc.end() && it->is_array())
            for (const auto& e : *it)
                if (e.is_string()) list.push_back(e.get<std::string>());
        return list;
    };
    for (const std::string& name : names("extensionsRequired"))
        if (!decoded(name)) throw InputError(label + ": requires " + name + ", which shadelab does not read");
    std::vector<std::string> unread;
    for (const std::string& name : names("extensionsUsed"))
        if (!decoded(name)) unread.push_back(name);
    if (const std::string line = notRead(unread); !line.empty()) out.warnings.push_back(line);

    bool changed = false;
    // A meshopt fallback buffer holds nothing shadelab reads (every view into it is compressed
    // elsewhere) and often has no URI at all: it is given an empty stand-in tinygltf can load.
    const auto buffers = doc.find("buffers");
    if (buffers != doc.end() && buffers->is_array())
        for (std::size_t i = 0; i < buffers->size(); ++i) {
            nlohmann::json& b = (*buffers)[i];
            const nlohmann::json* ext = extension(b, "EXT_meshopt_compression");
            if (!ext || !ext->is_object() || !ext->value("fallback", false) || b.contains("uri") ||
                !decoded("EXT_meshopt_compression"))
                continue;
            out.fallbackBuffers.push_back(int(i));
            b["uri"] = "<meshopt fallback buffer " + std::to_string(i) + ">";
            b["byteLength"] = 1;
            changed = true;
        }
    const auto meshes = doc.find("meshes");
    if (meshes != doc.end() && meshes->is_array())
        for (std::size_t m = 0; m < meshes->size(); ++m) {
            nlohmann::json& mesh = (*meshes)[m];
            if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
            for (std::size_t p = 0; p < mesh["primitives"].size(); ++p) {
                nlohmann::json& prim = mesh["primitives"][p];
                if (!extension(prim, "KHR_draco_mesh_compression") || !prim.contains("indices") ||
                    !decoded("KHR_draco_mesh_compression"))
                    continue;
                if (!prim["indices"].is_number_integer()) continue;  // tinygltf names that error
                out.dracoIndices[{int(m), int(p)}] = prim["indices"].get<int>();
                prim.erase("indices");
                changed = true;
            }
        }
    return changed;
}

namespace {

#if SHADELAB_HAVE_MESHOPT
// The meshopt codecs reach at best about 1:64 (a block of 256 vertices costs at least 4 header bytes
// per byte of a vertex); a stream that claims more than 256 times its size is refused unread.
constexpr std::size_t kMaxMeshoptRatio = 256;

// A compressed bufferView as the extension describes it, checked against its buffer and the codec's ratio.
struct MeshoptStream {
    const unsigned char* in = nullptr;  // the compressed bytes
    std::size_t encoded = 0;            // how many
    std::size_t count = 0, stride = 0;  // the decoded elements, and each one's bytes
    std::string mode, filter;
};

MeshoptStream meshoptStream(const tinygltf::Model& model, const tinygltf::Value& e, const std::string& where) {
    const auto number = [&](const char* key, double fallback) {
        return e.Has(key) && e.Get(key).IsNumber() ? e.Get(key).GetNumberAsDouble() : fallback;
    };
    const auto text = [&](const char* key, const char* fallback) {
        return e.Has(key) && e.Get(key).IsString() ? e.Get(key).Get<std::string>() : std::string(fallback);
    };
    const double buffer = number("buffer", -1), offset = number("byteOffset", 0), length = number("byteLength", -1),
                 stride = number("byteStride", -1), count = number("count", -1);
    if (!(buffer >= 0 && buffer < double(model.buffers.size())))
        throw InputError(where + ": buffer " + std::to_string(long(buffer)) + " does not exist");
    const std::vector<unsigned char>& source = model.buffers[std::size_t(buffer)].data;
    if (!(offset >= 0 && length >= 0 && offset + length <= double(source.size())))
        throw InputError(where + ": its range lies outside buffer " + std::to_string(long(buffer)));
    if (!(stride >= 1 && stride <= 256 && count >= 0 && count <= 5e8))
        throw InputError(where + ": byteStride or count out of range");
    const auto n = std::size_t(count), s = std::size_t(stride), encoded = std::size_t(length);
    if (n * s > kMaxMeshoptRatio * encoded + 65536)
        throw InputError(where + ": " + std::to_string(n * s) + " bytes from " + std::to_string(encoded) +
                         ", more than the codec can encode");
    return {source.data() + std::size_t(offset), encoded, n, s, text("mode", ""), text("filter", "NONE")};
}

// ATTRIBUTES: the vertex codec, then its filter (checked once the data has decoded). meshopt's result.
int decodeMeshoptAttributes(unsigned char* out, const MeshoptStream& m, const std::string& where) {
    const std::size_t n = m.count, s = m.stride;
    if (s % 4 != 0) throw InputError(where + ": ATTRIBUTES need a byteStride that is a multiple of 4");
    const int result = meshopt_decodeVertexBuffer(out, n, s, m.in, m.encoded);
    if (result == 0 && m.filter == "OCTAHEDRAL") {
        if (s != 4 && s != 8) throw InputError(where + ": the OCTAHEDRAL filter needs a byteStride of 4 or 8");
        meshopt_decodeFilterOct(out, n, s);
    } else if (result == 0 && m.filter == "QUATERNION") {
        if (s != 8) throw InputError(where + ": the QUATERNION filter needs a byteStride of 8");
        meshopt_decodeFilterQuat(out, n, s);
    } else if (result == 0 && m.filter == "EXPONENTIAL") {
        meshopt_decodeFilterExp(out, n, s);
    } else if (m.filter != "NONE") {
        throw InputError(where + ": unknown filter \"" + m.filter + "\"");
    }
    return result;
}

// TRIANGLES or INDICES: the index codecs. meshopt's result.
int decodeMeshoptIndices(unsigned char* out, const MeshoptStream& m, const std::string& where) {
    const std::size_t n = m.count, s = m.stride;
    if (s != 2 && s != 4) throw InputError(where + ": indices need a byteStride of 2 or 4");
    if (m.mode == "TRIANGLES" && n % 3 != 0)
        throw InputError(where + ": TRIANGLES need a count that is a multiple of 3");
    return m.mode == "TRIANGLES" ? meshopt_decodeIndexBuffer(out, n, s, m.in, m.encoded)
                                 : meshopt_decodeIndexSequence(out, n, s, m.in, m.encoded);
}

void decodeMeshopt(tinygltf::Model& model, const std::string& label) {
    for (std::size_t i = 0; i < model.bufferViews.size(); ++i) {
        tinygltf::BufferView& bv = model.bufferViews[i];
        const auto it = bv.extensions.find("EXT_meshopt_compression");
        if (it == bv.extensions.end()) continue;
        const std::string where = label + ": bufferView " + std::to_string(i) + " (EXT_meshopt_compression)";
        const MeshoptStream stream = meshoptStream(model, it->second, where);
        std::vector<unsigned char> out(stream.count * stream.stride);
        int result = -1;
        if (stream.mode == "ATTRIBUTES") result = decodeMeshoptAttributes(out.data(), stream, where);
        else if (stream.mode == "TRIANGLES" || stream.mode == "INDICES")
            result = decodeMeshoptIndices(out.data(), stream, where);
        else throw InputError(where + ": unknown mode \"" + stream.mode + "\"");
        if (result != 0)
            throw InputError(where + ": the compressed data does not decode (meshopt error " + std::to_string(result) +
                             ")");
        // The view now reads a buffer of its own, holding the decoded bytes.
        tinygltf::Buffer plain;
        plain.data = std::move(out);
        bv.buffer = int(model.buffers.size());
        bv.byteOffset = 0;
        bv.byteLength = plain.data.size();
        bv.byteStride = stream.stride;
        model.buffers.push_back(std::move(plain));
        bv.extensions.erase(it);
    }
}

#endif

#if SHADELAB_HAVE_DRACO
// A decoded attribute or index list as a new buffer, view and accessor contents.
void pointAccessorAt(tinygltf::Model& model, int accessorIndex, std::vector<unsigned char> bytes, int componentType) {
    tinygltf::Buffer buffer;
    buffer.data = std::move(bytes);
    tinygltf::BufferView view;
    view.buffer = int(model.buffers.size());
    view.byteLength = buffer.data.size();
    model.buffers.push_back(std::move(buffer));
    tinygltf::Accessor& a = model.accessors[std::size_t(accessorIndex)];
    a.bufferView = int(model.bufferViews.size());
    a.byteOffset = 0;
    a.componentType = componentType;
    a.normalized = false;
    a.sparse.isSparse = false;
    model.bufferViews.push_back(std::move(view));
}

// The primitive's Draco data (the extension's bufferView), decoded, within the size limits.
std::unique_ptr<draco::Mesh> decodeDracoMesh(const tinygltf::Model& model, const tinygltf::Value& e,
                                             const std::string& where) {
    const int bvIndex =
        e.Has("bufferView") && e.Get("bufferView").IsNumber() ? e.Get("bufferView").GetNumberAsInt() : -1;
    if (bvIndex < 0 || std::size_t(bvIndex) >= model.bufferViews.size())
        throw InputError(where + ": bufferView " + std::to_string(bvIndex) + " does not exist");
    const tinygltf::BufferView& bv = model.bufferViews[std::size_t(bvIndex)];
    if (bv.buffer < 0 || std::size_t(bv.buffer) >= model.buffers.size() ||
        bv.byteOffset > model.buffers[std::size_t(bv.buffer)].data.size() ||
        bv.byteLength > model.buffers[std::size_t(bv.buffer)].data.size() - bv.byteOffset)
        throw InputError(where + ": bufferView " + std::to_string(bvIndex) + " lies outside its buffer");
    draco::DecoderBuffer stream;
    stream.Init(reinterpret_cast<const char*>(model.buffers[std::size_t(bv.buffer)].data.data() + bv.byteOffset),
                bv.byteLength);
    draco::Decoder decoder;
    auto result = decoder.DecodeMeshFromBuffer(&stream);
    if (!result.ok()) throw InputError(where + ": does not decode: " + result.status().error_msg_string());
    std::unique_ptr<draco::Mesh> mesh = std::move(result).value();
    if (mesh->num_points() > 50'000'000 || mesh->num_faces() > 50'000'000)
        throw InputError(where + ": more than 50,000,000 points or triangles");
    return mesh;
}

// Indices: back from where the JSON step kept them (accessor `kept`), filled with the decoded triangles.
void restoreDracoIndices(tinygltf::Model& model, tinygltf::Primitive& prim, int kept, const draco::Mesh& mesh,
                         const std::string& where) {
    const std::uint32_t faces = mesh.num_faces();
    prim.indices = kept;
    if (prim.indices < 0 || std::size_t(prim.indices) >= model.accessors.size())
        throw InputError(where + ": accessor " + std::to_string(prim.indices) + " does not exist");
    if (model.accessors[std::size_t(prim.indices)].count != std::size_t(faces) * 3)
        throw InputError(where + ": its indices accessor counts " +
                         std::to_string(model.accessors[std::size_t(prim.indices)].count) + ", the data " +
                         std::to_string(std::size_t(faces) * 3));
    std::vector<unsigned char> bytes(std::size_t(faces) * 3 * sizeof(std::uint32_t));
    auto* out = reinterpret_cast<std::uint32_t*>(bytes.data());
    for (draco::FaceIndex f(0); f < faces; ++f)
        for (int k = 0; k < 3; ++k) *out++ = mesh.face(f)[k].value();
    pointAccessorAt(model, prim.indices, std::move(bytes), TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
}

// Attributes: each accessor the extension names, filled with the decoded values as floats.
void decodeDracoAttributes(tinygltf::Model& model, const tinygltf::Primitive& prim, const tinygltf::Value& e,
                           const draco::Mesh& mesh, const std::string& where) {
    const std::uint32_t points = mesh.num_points();
    if (!e.Has("attributes") || !e.Get("attributes").IsObject()) throw InputError(where + ": no attributes");
    const tinygltf::Value& attributes = e.Get("attributes");
    for (const std::string& name : attributes.Keys()) {
        const auto accessor = prim.attributes.find(name);
        if (accessor == prim.attributes.end() || accessor->second < 0 ||
            std::size_t(accessor->second) >= model.accessors.size())
            throw InputError(where + ": " + name + " has no accessor in the primitive");
        const draco::PointAttribute* attribute =
            mesh.GetAttributeByUniqueId(std::uint32_t(attributes.Get(name).GetNumberAsInt()));
        if (!attribute) throw InputError(where + ": " + name + ": no such attribute in the data");
        tinygltf::Accessor& a = model.accessors[std::size_t(accessor->second)];
        const int components = tinygltf::GetNumComponentsInType(std::uint32_t(a.type));
        if (components <= 0 || components > 4 || a.count != points)
            throw InputError(where + ": " + name + ": the accessor does not match the decoded data");
        std::vector<unsigned char> bytes(std::size_t(points) * std::size_t(components) * sizeof(float));
        auto* out = reinterpret_cast<float*>(bytes.data());
        for (draco::PointIndex i(0); i < points; ++i, out += components)
            if (!attribute->ConvertValue<float>(attribute->mapped_index(i), std::int8_t(components), out))
                throw InputError(where + ": " + name + ": values do not convert to floats");
        pointAccessorAt(model, accessor->second, std::move(bytes), TINYGLTF_COMPONENT_TYPE_FLOAT);
    }
}

void decodeDraco(tinygltf::Model& model, const GltfPrepass& prepass, const std::string& label) {
    for (std::size_t m = 0; m < model.meshes.size(); ++m)
        for (std::size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
            tinygltf::Primitive& prim = model.meshes[m].primitives[p];
            const auto it = prim.extensions.find("KHR_draco_mesh_compression");
            if (it == prim.extensions.end()) continue;
            const std::string where = label + ": mesh " + std::to_string(m) + " primitive " + std::to_string(p) +
                                      " (KHR_draco_mesh_compression)";
            const std::unique_ptr<draco::Mesh> mesh = decodeDracoMesh(model, it->second, where);
            // No indices kept by the JSON step: the decoded order.
            if (const auto kept = prepass.dracoIndices.find({int(m), int(p)}); kept != prepass.dracoIndices.end())
                restoreDracoIndices(model, prim, kept->second, *mesh, where);
            decodeDracoAttributes(model, prim, it->second, *mesh, where);
            prim.extensions.erase(it);
        }
}
#endif

}  // namespace

void decodeCompressedGltf(tinygltf::Model& model, const GltfPrepass& prepass, const std::string& label) {
#if SHADELAB_HAVE_MESHOPT
    decodeMeshopt(model, label);
#endif
#if SHADELAB_HAVE_DRACO
    decodeDraco(model, prepass, label);
#else
    (void)prepass;
#endif
    (void)model;
    (void)label;
}

}  // namespace shadelab
