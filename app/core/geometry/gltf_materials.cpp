// glTF materials: a part's base colour, alpha, emission (KHR_materials_emissive_strength) and
// sidedness; its base colour and emissive textures (KHR_texture_transform), each image decoded once per
// sampler within the texture limits, with the sampler's wrap modes and filters.
#include "core/geometry/gltf_import_parts.hpp"

#include <stb/stb_image.h>

#include <glm/common.hpp>

#include <algorithm>
#include <limits>

namespace shadelab::gltf_import_parts {

namespace {

// The texture coordinate transform of KHR_texture_transform: translation * rotation * scale, with the
// rotation [[cos, sin], [-sin, cos]] by rows: counter-clockwise in uv with v pointing down, so the
// picture turns clockwise. That is the spec's example, three.js, Babylon.js and Blender; its GLSL
// listing read by columns is the transpose (KhronosGroup/glTF#1563; tests/unit/gltf_import_test.cpp).
glm::mat3 textureTransform(const tinygltf::Value& ext) {
    const auto number = [&](const char* key, int i, double fallback) {
        if (!ext.Has(key)) return fallback;
        const tinygltf::Value& v = ext.Get(key);
        if (i < 0) return v.IsNumber() ? v.GetNumberAsDouble() : fallback;
        return v.IsArray() && v.ArrayLen() > std::size_t(i) && v.Get(i).IsNumber() ? v.Get(i).GetNumberAsDouble()
                                                                                   : fallback;
    };
    const float ox = float(number("offset", 0, 0.0)), oy = float(number("offset", 1, 0.0));
    const float r = float(number("rotation", -1, 0.0));
    const float sx = float(number("scale", 0, 1.0)), sy = float(number("scale", 1, 1.0));
    const glm::mat3 translation(1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, ox, oy, 1.0f);  // column-major
    const glm::mat3 rotation(std::cos(r), -std::sin(r), 0.0f, std::sin(r), std::cos(r), 0.0f, 0.0f, 0.0f, 1.0f);
    const glm::mat3 scale(sx, 0.0f, 0.0f, 0.0f, sy, 0.0f, 0.0f, 0.0f, 1.0f);
    return translation * rotation * scale;
}

// A sampler's GL enum, or glTF's default where the file gives none or one GL does not have.
int wrapMode(int mode) {
    return mode == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE || mode == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT
               ? mode
               : TINYGLTF_TEXTURE_WRAP_REPEAT;
}

// A sampler's wrap modes and filters on a texture; glTF's defaults (repeat, trilinear) where it gives none.
void useSampler(const tinygltf::Sampler& s, TextureImage& out) {
    out.wrapS = wrapMode(s.wrapS);
    out.wrapT = wrapMode(s.wrapT);
    if (s.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST) out.magFilter = s.magFilter;
    switch (s.minFilter) {
    case TINYGLTF_TEXTURE_FILTER_NEAREST:
    case TINYGLTF_TEXTURE_FILTER_LINEAR:
    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST:
    case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST:
    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR:
    case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR: out.minFilter = s.minFilter; break;
    default: break;  // none given: trilinear
    }
}

// Images larger than this on a side, or with more pixels, are not decoded (a 16k texture is 1 GiB),
// nor past kMaxModelTexturePixels in one model (a small PNG can decode to 256 MiB).
constexpr int kMaxTextureSide = 16384;
constexpr std::size_t kMaxTexturePixels = std::size_t(1) << 26;
constexpr std::size_t kMaxModelTexturePixels = std::size_t(1) << 28;

// Parts that look the same: consecutive primitives like these share one draw.
bool sameLook(const MeshPart& a, const MeshPart& b) {
    return a.baseColor == b.baseColor && a.texture == b.texture && a.baseAlpha == b.baseAlpha &&
           a.alphaMode == b.alphaMode && a.alphaCutoff == b.alphaCutoff && a.emissive == b.emissive &&
           a.emissiveTexture == b.emissiveTexture && a.doubleSided == b.doubleSided;
}

// KHR_materials_emissive_strength's factor (1 without it; a negative or non-finite one is ignored).
float emissiveStrength(const tinygltf::Material& m) {
    const auto e = m.extensions.find("KHR_materials_emissive_strength");
    if (e == m.extensions.end() || !e->second.Has("emissiveStrength")) return 1.0f;
    const tinygltf::Value& v = e->second.Get("emissiveStrength");
    const double s = v.IsNumber() ? v.GetNumberAsDouble() : 1.0;
    return std::isfinite(s) && s >= 0.0 ? float(std::min(s, 1e6)) : 1.0f;
}

}  // namespace

GltfReader::MaterialTexture GltfReader::materialTexture(const tinygltf::TextureInfo& info, const char* role) {
    MaterialTexture t;
    t.role = role;
    if (info.index < 0) return t;
    t.texCoord = info.texCoord;
    if (const auto e = info.extensions.find("KHR_texture_transform"); e != info.extensions.end()) {
        t.transform = textureTransform(e->second);
        if (e->second.Has("texCoord") && e->second.Get("texCoord").IsInt())
            t.texCoord = e->second.Get("texCoord").GetNumberAsInt();
    }
    t.slot = textureSlot(info.index);
    return t;
}

GltfReader::MaterialTexture GltfReader::baseColorTexture(int mi) {
    if (mi < 0 || std::size_t(mi) >= model_.materials.size()) return {};
    return materialTexture(model_.materials[std::size_t(mi)].pbrMetallicRoughness.baseColorTexture, "base colour");
}

GltfReader::MaterialTexture GltfReader::emissiveTexture(int mi) {
    if (mi < 0 || std::size_t(mi) >= model_.materials.size()) return {};
    const tinygltf::Material& m = model_.materials[std::size_t(mi)];
    // No light given off (a zero factor): the texture would multiply nothing, and is not read.
    if (m.emissiveFactor.size() < 3 ||
        (m.emissiveFactor[0] <= 0.0 && m.emissiveFactor[1] <= 0.0 && m.emissiveFactor[2] <= 0.0))
        return {};
    return materialTexture(m.emissiveTexture, "emissive");
}

int GltfReader::textureSlot(int ti) {
    const std::string where = "texture " + std::to_string(ti);
    if (std::size_t(ti) >= model_.textures.size()) fail(where, "does not exist");
    const tinygltf::Texture& texture = model_.textures[std::size_t(ti)];
    const auto key = std::make_pair(texture.source, texture.sampler);
    if (const auto known = textureSlots_.find(key); known != textureSlots_.end()) return known->second;
    int& slot = textureSlots_[key];
    slot = -1;
    const auto skip = [&](const std::string& why) {
        info_.warnings.push_back(where + ": " + why + "; drawn in its base colour");
        return -1;
    };
    if (texture.source < 0) return skip("no PNG or JPEG image (only an extension's)");
    if (std::size_t(texture.source) >= model_.images.size())
        fail(where, "image " + std::to_string(texture.source) + " does not exist");
    const tinygltf::Image& image = model_.images[std::size_t(texture.source)];
    auto out = std::make_shared<TextureImage>();
    out->name =
        image.uri.empty() || image.uri.rfind("data:", 0) == 0 ? "image " + std::to_string(texture.source) : image.uri;
    if (const std::string why = decodeImage(image, *out); !why.empty()) return skip(why);
    if (texture.sampler >= 0 && std::size_t(texture.sampler) < model_.samplers.size())
        useSampler(model_.samplers[std::size_t(texture.sampler)], *out);
    slot = int(mesh_.textures.size());
    mesh_.textures.push_back(std::move(out));
    return slot;
}

std::string GltfReader::decodeImage(const tinygltf::Image& image, TextureImage& out) const {
    const unsigned char* bytes = image.image.data();
    std::size_t size = image.image.size();
    if (image.bufferView >= 0) {
        if (std::size_t(image.bufferView) >= model_.bufferViews.size())
            fail(out.name, "bufferView " + std::to_string(image.bufferView) + " does not exist");
        const std::size_t length = model_.bufferViews[std::size_t(image.bufferView)].byteLength;
        if (length == 0) return out.name + "'s bufferView is empty";
        std::size_t stride = 0;  // the view's bytes one by one: its byteStride does not apply to an image
        checkRange(image.bufferView, 0, 1, 1, length, out.name, &stride, &bytes);
        size = length;
    }
    if (size == 0) return out.name + " could not be read";
    if (size > std::size_t(std::numeric_limits<int>::max())) return out.name + " is too large";
    int w = 0, h = 0, channels = 0;
    if (!stbi_info_from_memory(bytes, int(size), &w, &h, &channels))
        return out.name + " is not an image shadelab decodes (PNG or JPEG)";
    if (w <= 0 || h <= 0 || w > kMaxTextureSide || h > kMaxTextureSide ||
        std::size_t(w) * std::size_t(h) > kMaxTexturePixels)
        return out.name + " is " + std::to_string(w) + "x" + std::to_string(h) + " pixels, more than shadelab reads (" +
               std::to_string(kMaxTextureSide) + " on a side, 64 Mpixels)";
    std::size_t decoded = 0;
    for (const auto& t : mesh_.textures) decoded += std::size_t(t->width) * std::size_t(t->height);
    if (decoded + std::size_t(w) * std::size_t(h) > kMaxModelTexturePixels)
        return out.name + " would take the model's textures past 256 Mpixels";
    std::unique_ptr<unsigned char, void (*)(void*)> pixels(
        stbi_load_from_memory(bytes, int(size), &w, &h, &channels, 4), &stbi_image_free);
    if (!pixels) return out.name + " does not decode (" + std::string(stbi_failure_reason()) + ")";
    out.width = w;
    out.height = h;
    out.rgba.assign(pixels.get(), pixels.get() + std::size_t(w) * std::size_t(h) * 4);
    return "";
}

// The part of the indices from `firstIndex` on, with the material's base colour (glTF's default is
// white), alpha, emission and sidedness; consecutive primitives that look the same share a part, so a
// many-primitive model does not cost a draw call per primitive.
void GltfReader::addPart(int materialIndex, std::uint32_t firstIndex, int textureSlot, int emissiveSlot,
                         const std::vector<glm::mat4>& instances) {
    MeshPart part;
    part.firstIndex = firstIndex;
    part.indexCount = std::uint32_t(out_->indices.size()) - firstIndex;
    part.hasBaseColor = true;
    if (materialIndex >= 0 && std::size_t(materialIndex) < model_.materials.size()) {
        const tinygltf::Material& m = model_.materials[std::size_t(materialIndex)];
        const auto& f = m.pbrMetallicRoughness.baseColorFactor;
        if (f.size() >= 3) part.baseColor = glm::clamp(glm::vec3(float(f[0]), float(f[1]), float(f[2])), 0.0f, 1.0f);
        if (f.size() >= 4 && std::isfinite(f[3])) part.baseAlpha = glm::clamp(float(f[3]), 0.0f, 1.0f);
        if (m.alphaMode == "MASK") part.alphaMode = AlphaMode::Mask;
        if (m.alphaMode == "BLEND") part.alphaMode = AlphaMode::Blend;
        if (std::isfinite(m.alphaCutoff)) part.alphaCutoff = glm::clamp(float(m.alphaCutoff), 0.0f, 1.0f);
        const auto& e = m.emissiveFactor;
        if (e.size() >= 3 && std::isfinite(e[0]) && std::isfinite(e[1]) && std::isfinite(e[2]))
            part.emissive =
                glm::clamp(glm::vec3(float(e[0]), float(e[1]), float(e[2])), 0.0f, 1.0f) * emissiveStrength(m);
        part.doubleSided = m.doubleSided;
    }
    part.texture = textureSlot;
    part.emissiveTexture = emissiveSlot;
    part.instances = instances;
    MeshPart* last = out_->parts.empty() ? nullptr : &out_->parts.back();
    if (last && sameLook(*last, part) && last->instances.empty() && part.instances.empty() &&
        last->firstIndex + last->indexCount == part.firstIndex)
        last->indexCount += part.indexCount;
    else if (part.indexCount > 0) out_->parts.push_back(part);
}

}  // namespace shadelab::gltf_import_parts
