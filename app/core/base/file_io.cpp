#include "core/base/file_io.hpp"

#include "core/base/error.hpp"
#include "platform/platform.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace shadelab {
namespace fs = std::filesystem;

std::string readTextFile(const std::string& path, std::uint64_t maxBytes) {
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    if (ec || !fs::exists(st)) throw InputError(path + ": cannot read: no such file");
    if (fs::is_directory(st)) throw InputError(path + ": cannot read: is a directory");
    const std::uintmax_t size = fs::file_size(path, ec);
    if (!ec && size > maxBytes)
        throw InputError(path + ": cannot read: larger than " + std::to_string(maxBytes >> 20) + " MiB");
    std::ifstream in(fs::path(path), std::ios::binary);
    if (!in) throw InputError(path + ": cannot read: " + std::strerror(errno));
    // One read into a buffer of the file's size: models can be hundreds of MB.
    std::string data(ec ? 0 : std::size_t(size), '\0');
    in.read(data.data(), std::streamsize(data.size()));
    if (std::size_t(in.gcount()) != data.size()) throw InputError(path + ": cannot read: I/O error");
    if (ec) {  // size unknown (a pipe, a device): read in pieces, never more than maxBytes
        char piece[1 << 16];
        while (in.read(piece, sizeof piece) || in.gcount() > 0) {
            data.append(piece, std::size_t(in.gcount()));
            if (data.size() > maxBytes)
                throw InputError(path + ": cannot read: larger than " + std::to_string(maxBytes >> 20) + " MiB");
        }
    }
    return data;
}

bool hasExtension(const std::string& path, const std::string& ext) {
    if (path.size() < ext.size()) return false;
    std::string tail = path.substr(path.size() - ext.size());
    std::transform(tail.begin(), tail.end(), tail.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return tail == ext;
}

bool hasModelExtension(const std::string& path) { return hasExtension(path, ".gltf") || hasExtension(path, ".glb"); }

std::vector<fs::path> dataFoldersBesideProgram(const fs::path& program, const std::string& kind,
                                               const std::string& inCheckout) {
    if (program.empty()) return {};
    const fs::path bin = program.parent_path();
    return {bin / ".." / "share" / "shadelab" / kind, bin / ".." / inCheckout, bin / "share" / "shadelab" / kind};
}

void checkOutputPath(const std::string& path, const std::string& option) {
    if (path.empty()) throw InputError(option + ": empty path");
    std::error_code ec;
    if (fs::is_directory(path, ec)) throw InputError(option + ": " + path + " is a directory");
    const fs::path parent = fs::path(path).parent_path();
    if (!parent.empty() && !fs::is_directory(parent, ec))
        throw InputError(option + ": " + path + ": the folder " + parent.string() + " does not exist");
}

void checkOutputFolder(const std::string& path, const std::string& option) {
    if (path.empty()) throw InputError(option + ": empty path");
    std::error_code ec;
    if (fs::is_directory(path, ec)) return;
    if (fs::exists(path, ec)) throw InputError(option + ": " + path + " is a file, not a folder");
    if (path.back() != '/' && path.back() != char(fs::path::preferred_separator))
        throw InputError(option + ": " + path +
                         ": names a folder here: an existing one, or end the name with / to have "
                         "it created");
    const fs::path parent = fs::path(path).parent_path().parent_path();  // "a/b/" -> "a/b" -> "a"
    if (!parent.empty() && !fs::is_directory(parent, ec))
        throw InputError(option + ": " + path + ": the folder " + parent.string() + " does not exist");
}

void createOutputFolder(const std::string& path, const std::string& option) {
    checkOutputFolder(path, option);
    std::error_code ec;
    fs::create_directory(path, ec);
    if (ec) throw InputError(option + ": " + path + ": cannot create the folder: " + ec.message());
}

void writeFileAtomic(const std::string& path, const std::function<bool(std::FILE*)>& write) {
    const std::string failure = platform::writeFileAtomic(fs::path(path), write);
    if (!failure.empty()) throw InputError(path + ": cannot write: " + failure);
}

void writeFileAtomicByName(const std::string& path, const std::function<bool(const std::string&)>& write) {
    const std::string failure = platform::writeFileAtomicByName(
        fs::path(path), [&write](const fs::path& temporary) { return write(temporary.string()); });
    if (!failure.empty()) throw InputError(path + ": cannot write: " + failure);
}

}  // namespace shadelab
