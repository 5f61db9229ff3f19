// Reading a glTF file: .gltf (JSON) or .glb (chunks), from a file or from memory, within the file's
// limits; URIs resolved inside the model's folder and refused outside it, data: URIs decoded here;
// then the extensions' steps (gltf_extensions.hpp) and GltfReader (gltf_import_parts.hpp).
#include "core/geometry/gltf_import_parts.hpp"

#include "core/base/error.hpp"
#include "core/base/file_io.hpp"
#include "core/base/json_depth.hpp"
#include "core/geometry/gltf_extensions.hpp"
#include "platform/platform.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string_view>

namespace shadelab {
namespace {
namespace fs = std::filesystem;
using gltf_import_parts::GltfReader;

// External files are read only from inside the model's folder: a URI with a scheme (http:, file:),
// an absolute path elsewhere, or one that climbs out with ".." is refused before anything is opened.
bool insideFolder(const std::string& p, const fs::path& root) {
    if (p.find("://") != std::string::npos) return false;
    // tinygltf joins every URI onto the folder: an absolute URI arrives as "<folder>//etc/passwd".
    const std::string prefix = root.string() + "/";
    if (p.size() > prefix.size() && p.compare(0, prefix.size(), prefix) == 0 && p[prefix.size()] == '/') return false;
    std::error_code ec;
    const fs::path full = fs::absolute(fs::path(p), ec).lexically_normal();
    if (ec) return false;
    const fs::path rel = full.lexically_relative(root);
    return !rel.empty() && *rel.begin() != "..";
}

// The same with symbolic links followed, in the URI and in the folder: a link inside the folder (or a
// linked subfolder) that leads outside it is outside. A path that cannot be resolved (missing, a loop,
// a name too long) is refused too.
bool insideFolderResolved(const std::string& p, const fs::path& root) {
    std::error_code ec;
    const fs::path real = fs::canonical(fs::path(p), ec);
    if (ec) return false;
    const fs::path realRoot = fs::canonical(root, ec);
    if (ec) return false;
    const fs::path rel = real.lexically_relative(realRoot);
    return !rel.empty() && *rel.begin() != "..";
}

// A .glb: a 12-byte header, a JSON chunk and an optional BIN chunk that holds buffer 0. tinygltf's own
// .glb loader copies the BIN chunk out of the file's bytes, so a large model was in memory twice; here
// the chunks are found first, tinygltf parses the JSON, and buffer 0 is read from its range of the file
// (or of the bytes in memory) straight into tinygltf's buffer, once.
struct GlbLayout {
    std::string json;
    bool hasBin = false;
    std::uint64_t binOffset = 0, binLength = 0;
};

using ByteReader = std::function<void(std::uint64_t offset, std::size_t length, unsigned char* out)>;

std::uint32_t readU32(const unsigned char* b) {
    return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[3]) << 24;
}

GlbLayout splitGlb(std::uint64_t available, const ByteReader& read, const std::string& label) {
    auto bad = [&](const std::string& why) { return InputError(label + ": not a valid .glb: " + why); };
    if (available < 20) throw bad("shorter than its 12-byte header and first chunk header");
    unsigned char head[20];
    read(0, sizeof head, head);
    const std::uint32_t version = readU32(head + 4), total = readU32(head + 8);
    const std::uint32_t jsonLength = readU32(head + 12), jsonType = readU32(head + 16);
    if (version != 2) throw bad("version " + std::to_string(version) + " (only glTF 2.0 is read)");
    if (total > available)
        throw bad("the header says " + std::to_string(total) + " bytes, the file has " + std::to_string(available));
    // Before any length is taken from it: `total - 20` must not wrap.
    if (total < 20) throw bad("the header says " + std::to_string(total) + " bytes, less than its own headers");
    if (jsonType != 0x4E4F534Au) throw bad("the first chunk is not JSON");
    if (std::uint64_t(jsonLength) > std::uint64_t(total) - 20)
        throw bad("the JSON chunk's length " + std::to_string(jsonLength) + " runs past the end");
    GlbLayout g;
    g.json.resize(jsonLength);
    read(20, jsonLength, reinterpret_cast<unsigned char*>(g.json.data()));
    const std::uint64_t next = 20 + std::uint64_t(jsonLength);
    if (next + 8 <= total) {
        unsigned char chunk[8];
        read(next, sizeof chunk, chunk);
        const std::uint32_t binLength = readU32(chunk), binType = readU32(chunk + 4);
        if (binType == 0x004E4942u) {
            if (std::uint64_t(binLength) > total - next - 8)
                throw bad("the BIN chunk's length " + std::to_string(binLength) + " runs past the end");
            g.hasBin = true;
            g.binOffset = next + 8;
            g.binLength = binLength;
        }
    }
    return g;
}

// What the file-system callbacks need: the folder URIs are confined to and, for a .glb, where buffer 0
// is (tinygltf asks for it by a URI that names no file: kGlbBinUri joined onto the folder).
constexpr const char* kGlbBinUri = "<GLB BIN chunk>";
struct LoadContext {
    fs::path folder;
    // The path tinygltf asks the callbacks for when it looks for `uri`: joined onto the folder with
    // '/' as its JoinPath does, whatever the platform's separator ('\\' in the folder on Windows).
    std::string pathOf(const std::string& uri) const {
        std::string out = folder.string();
        if (out.empty()) return uri;
        if (out.back() != '/') out += '/';
        return out + uri;
    }
    std::string binPath;  // pathOf(kGlbBinUri); empty unless a .glb's buffer 0 is its BIN chunk
    std::uint64_t binOffset = 0, binLength = 0;
    const ByteReader* read = nullptr;
    std::string* release = nullptr;  // bytes to free once tinygltf has parsed (it keeps what it needs)
    // A .gltf's base64 buffers, decoded by decodeDataUris(), by the path tinygltf asks for them by
    // (pathOf("<data URI i>")).
    std::map<std::string, std::vector<unsigned char>> decoded;
    GltfPrepass extensions;  // what the JSON step found (core/geometry/gltf_extensions)
};

// Standard base64 (RFC 4648, '=' padding); false on any other character.
bool decodeBase64(std::string_view in, std::vector<unsigned char>& out) {
    static const std::array<std::int8_t, 256> kValue = [] {
        std::array<std::int8_t, 256> t{};
        t.fill(-1);
        for (int i = 0; i < 26; ++i) {
            t[std::size_t('A' + i)] = std::int8_t(i);
            t[std::size_t('a' + i)] = std::int8_t(26 + i);
        }
        for (int i = 0; i < 10; ++i) t[std::size_t('0' + i)] = std::int8_t(52 + i);
        t[std::size_t('+')] = 62;
        t[std::size_t('/')] = 63;
        return t;
    }();
    std::size_t n = in.size();
    while (n > 0 && in.size() - n < 2 && in[n - 1] == '=') --n;
    if (n % 4 == 1) return false;
    out.resize(n / 4 * 3 + (n % 4 == 0 ? 0 : n % 4 - 1));
    std::uint32_t bits = 0;
    int count = 0;
    std::size_t o = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const std::int8_t v = kValue[static_cast<unsigned char>(in[i])];
        if (v < 0) return false;
        bits = (bits << 6) | std::uint32_t(v);
        if (++count == 4) {
            out[o++] = static_cast<unsigned char>(bits >> 16);
            out[o++] = static_cast<unsigned char>(bits >> 8);
            out[o++] = static_cast<unsigned char>(bits);
            bits = 0;
            count = 0;
        }
    }
    if (count == 2) out[o++] = static_cast<unsigned char>(bits >> 4);
    if (count == 3) {
        out[o++] = static_cast<unsigned char>(bits >> 10);
        out[o++] = static_cast<unsigned char>(bits >> 2);
    }
    return o == out.size();
}

// A .gltf's buffers embedded as base64 data: URIs, decoded here and handed to tinygltf through the
// file callbacks: its own decoder takes ~15 ns a character (the 200k sphere's 6.4 MB: ~100 ms of a
// 0.2 s --output), and its JSON parser then skips a few bytes instead of megabytes. Anything this
// does not recognise is left as it is, for tinygltf to read or to report.
bool decodeDataUris(nlohmann::json& doc, LoadContext& context, const std::string& label) {
    const auto buffers = doc.find("buffers");
    if (buffers == doc.end() || !buffers->is_array()) return false;
    bool changed = false;
    for (std::size_t i = 0; i < buffers->size(); ++i) {
        nlohmann::json& buffer = (*buffers)[i];
        if (!buffer.is_object()) continue;
        const auto uri = buffer.find("uri");
        if (uri == buffer.end() || !uri->is_string()) continue;
        const std::string& text = uri->get_ref<const std::string&>();
        std::string_view data;
        for (const char* prefix : {"data:application/octet-stream;base64,", "data:application/gltf-buffer;base64,"})
            if (text.rfind(prefix, 0) == 0) data = std::string_view(text).substr(std::strlen(prefix));
        if (data.empty()) continue;
        const std::string sentinel = "<data URI " + std::to_string(i) + ">";
        std::vector<unsigned char>& bytes = context.decoded[context.pathOf(sentinel)];
        if (!decodeBase64(data, bytes))
            throw InputError(label + ": buffer " + std::to_string(i) + ": its data: URI is not valid base64");
        buffer["uri"] = sentinel;
        changed = true;
    }
    return changed;
}

// The JSON of a .glb with buffer 0 pointed at the BIN chunk (kGlbBinUri) when it is stored there.
bool pointBufferAtBin(nlohmann::json& doc, const GlbLayout& g, const std::string& label, LoadContext& context,
                      const ByteReader& read) {
    const auto buffers = doc.find("buffers");
    if (buffers == doc.end() || !buffers->is_array() || buffers->empty() || !(*buffers)[0].is_object() ||
        (*buffers)[0].contains("uri"))
        return false;  // buffer 0 is external or embedded as a data: URI, or there is none
    nlohmann::json& buffer = (*buffers)[0];
    if (!g.hasBin) throw InputError(label + ": buffer 0 has no uri and the .glb has no BIN chunk");
    const auto length = buffer.find("byteLength");
    if (length == buffer.end() || !length->is_number_unsigned())
        throw InputError(label + ": buffer 0: byteLength is missing or not a non-negative integer");
    if (length->get<std::uint64_t>() > g.binLength)
        throw InputError(label + ": buffer 0: byteLength " + std::to_string(length->get<std::uint64_t>()) +
                         " is more than the BIN chunk's " + std::to_string(g.binLength) + " bytes");
    context.binPath = context.pathOf(kGlbBinUri);
    context.binOffset = g.binOffset;
    context.binLength = length->get<std::uint64_t>();
    context.read = &read;
    buffer["uri"] = kGlbBinUri;
    return true;
}

// The JSON as tinygltf will read it: extensions checked and prepared (core/geometry/gltf_extensions), a .glb's
// buffer 0 pointed at its BIN chunk, base64 buffers decoded here. Parsed once; text that does not
// parse is handed on as it is, for tinygltf to say what is wrong with it.
std::string prepareJson(std::string json, LoadContext& context, const std::string& label, const GlbLayout* glb,
                        const ByteReader* read) {
    nlohmann::json doc = nlohmann::json::parse(json, nullptr, false);
    if (doc.is_discarded() || !doc.is_object()) {
        if (glb) throw InputError(label + ": the .glb's JSON chunk is not a JSON object");
        return json;
    }
    bool changed = prepareGltfExtensions(doc, label, context.extensions);
    for (int i : context.extensions.fallbackBuffers)  // stand-ins: one byte each, never read
        context.decoded[context.pathOf(doc["buffers"][std::size_t(i)]["uri"].get<std::string>())] = {0};
    if (glb) changed = pointBufferAtBin(doc, *glb, label, context, *read) || changed;
    if (json.find(";base64,") != std::string::npos) changed = decodeDataUris(doc, context, label) || changed;
    return changed ? doc.dump() : json;
}

// tinygltf's file callbacks over a LoadContext: the .glb's BIN chunk and decoded data: URIs from
// memory, other files only from inside the model's folder. FileExists answers "yes" for a path outside
// the folder so that tinygltf goes on to read it and ReadWholeFile can refuse it with a message that
// says why (rather than "file not found").
bool modelFileExists(const std::string& p, void* user) {
    const LoadContext& c = *static_cast<const LoadContext*>(user);
    std::error_code ec;  // a symlink loop or an over-long name is "no such file", never an exception
    return p == c.binPath || c.decoded.count(p) || !insideFolder(p, c.folder) || fs::is_regular_file(fs::path(p), ec);
}

bool readModelFile(std::vector<unsigned char>* out, std::string* err, const std::string& p, void* user) {
    LoadContext& c = *static_cast<LoadContext*>(user);
    if (const auto d = c.decoded.find(p); d != c.decoded.end()) {
        out->swap(d->second);  // asked for once, by the buffer that names it
        return true;
    }
    if (!c.binPath.empty() && p == c.binPath) {
        out->resize(std::size_t(c.binLength));
        (*c.read)(c.binOffset, out->size(), out->data());
        return true;
    }
    if (!insideFolder(p, c.folder) || !insideFolderResolved(p, c.folder)) {
        if (err) *err += "refused URI outside the model's folder: " + p;
        return false;
    }
    std::error_code e;
    const fs::path full(p);
    const std::uintmax_t fileSize = fs::file_size(full, e);
    if (e || fileSize > (std::uintmax_t(1) << 31)) {
        if (err) *err += "cannot read " + p;
        return false;
    }
    std::FILE* f = platform::openFile(full, "rb");
    if (!f) {
        if (err) *err += "cannot open " + p;
        return false;
    }
    const std::size_t size = std::size_t(fileSize);  // at most 2 GiB: fits a 32-bit size_t (the web build)
    out->resize(size);
    const bool ok = std::fread(out->data(), 1, size, f) == size;
    std::fclose(f);
    if (!ok && err) *err += "cannot read " + p;
    return ok;
}

Mesh parseGltf(std::string json, LoadContext& context, const std::string& path, GltfInfo* infoOut) {
    GltfInfo info;
    tinygltf::TinyGLTF loader;
    tinygltf::FsCallbacks fsc{};
    fsc.FileExists = modelFileExists;
    fsc.ExpandFilePath = [](const std::string& p, void*) { return p; };
    fsc.ReadWholeFile = readModelFile;
    fsc.WriteWholeFile = nullptr;
    fsc.user_data = &context;
    loader.SetFsCallbacks(fsc);
    // Images are decoded later, and only those a base colour texture uses (GltfReader::textureSlot):
    // here a URI's bytes are kept as they are. An image in a buffer view is read from the view then,
    // with its range checked (tinygltf hands it over unchecked).
    loader.SetImageLoader(
        [](tinygltf::Image* image, const int, std::string*, std::string*, int, int, const unsigned char* bytes,
           int size, void*) {
            if (image->bufferView < 0 && bytes && size > 0) image->image.assign(bytes, bytes + size);
            return true;
        },
        nullptr);

    tinygltf::Model model;
    std::string err, warn;
    const bool ok = loader.LoadASCIIFromString(&model, &err, &warn, json.data(), static_cast<unsigned int>(json.size()),
                                               context.folder.string());
    // tinygltf copied what it needs: a large file's bytes (a .gltf's data: URIs) need not stay.
    std::string().swap(json);
    if (context.release) std::string().swap(*context.release);
    if (!ok || !err.empty()) {
        std::string msg = err.empty() ? "not a valid glTF file" : err;
        while (!msg.empty() && (msg.back() == '\n' || msg.back() == ' ')) msg.pop_back();
        for (char& c : msg)
            if (c == '\n') c = ';';
        throw InputError(path + ": " + msg);
    }
    decodeCompressedGltf(model, context.extensions, path);
    info.warnings = context.extensions.warnings;
    Mesh mesh = GltfReader(path, model, info).read();
    if (infoOut) *infoOut = std::move(info);
    return mesh;
}

// A .glb through a reader of its bytes (a file or memory).
Mesh parseGlb(std::uint64_t size, const ByteReader& read, const std::string& path, const fs::path& folder,
              GltfInfo* infoOut, std::string* release = nullptr) {
    const GlbLayout layout = splitGlb(size, read, path);
    checkJsonDepth(layout.json, path);
    LoadContext context;
    context.folder = folder;
    std::string json = prepareJson(layout.json, context, path, &layout, &read);
    if (json.size() > std::uint64_t(~0u)) throw InputError(path + ": the JSON chunk is too large");
    context.release = release;
    return parseGltf(std::move(json), context, path, infoOut);
}

}  // namespace

Mesh loadGltf(const std::string& path, GltfInfo* infoOut) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) throw InputError(path + ": cannot read: no such file");
    const fs::path folder = fs::absolute(fs::path(path), ec).parent_path().lexically_normal();
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec) throw InputError(path + ": cannot read: " + ec.message());
    if (size > (std::uintmax_t(1) << 31)) throw InputError(path + ": cannot read: larger than 2048 MiB");
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(platform::openFile(path, "rb"), &std::fclose);
    if (!file) throw InputError(path + ": cannot read: " + std::strerror(errno));
    char magic[4] = {};
    const bool glb = std::fread(magic, 1, 4, file.get()) == 4 && std::memcmp(magic, "glTF", 4) == 0;
    if (!glb) {
        file.reset();
        return loadGltfFromMemory(readTextFile(path, std::uint64_t(1) << 31), path, folder.string(), infoOut);
    }
    // A .glb is read a chunk at a time: the JSON, then buffer 0 straight into tinygltf's buffer.
    const ByteReader read = [&](std::uint64_t offset, std::size_t length, unsigned char* out) {
        if (std::fseek(file.get(), long(offset), SEEK_SET) != 0 || std::fread(out, 1, length, file.get()) != length)
            throw InputError(path + ": cannot read: I/O error");
    };
    return parseGlb(size, read, path, folder, infoOut);
}

Mesh loadGltfFromMemory(std::string bytes, const std::string& label, const std::string& folderName, GltfInfo* infoOut) {
    const fs::path folder(folderName);
    // A .glb starts with the magic "glTF"; anything else is read as JSON.
    if (bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0) {
        const ByteReader read = [&](std::uint64_t offset, std::size_t length, unsigned char* out) {
            std::memcpy(out, bytes.data() + offset, length);  // splitGlb checked every range against the size
        };
        return parseGlb(bytes.size(), read, label, folder, infoOut, &bytes);
    }
    if (bytes.size() > std::uint64_t(~0u)) throw InputError(label + ": larger than 4 GiB");
    checkJsonDepth(bytes, label);
    LoadContext context;
    context.folder = folder;
    std::string json = prepareJson(std::move(bytes), context, label, nullptr, nullptr);
    return parseGltf(std::move(json), context, label, infoOut);
}

}  // namespace shadelab
