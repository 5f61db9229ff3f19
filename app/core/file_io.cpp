#include "core/file_io.hpp"

#include "core/error.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <mutex>
#include <random>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

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
    std::ifstream in(path, std::ios::binary);
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
    if (path.back() != '/')
        throw InputError(option + ": " + path + ": names a folder here: an existing one, or end the name with / to have "
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

namespace {

// Temporary files that exist under a name while a write is in flight, removed by SIGINT and SIGTERM
// (SIGKILL cannot be caught: that is what O_TMPFILE is for). The handler reads fixed buffers only.
constexpr int kTempSlots = 8;
enum TempSlot : int { kFree, kClaimed, kNamed };  // a slot is claimed, then its name written, then named
char gTempPath[kTempSlots][4096];
std::atomic<int> gTempState[kTempSlots];

extern "C" void removeTempFilesAndDie(int signal) {
    for (int i = 0; i < kTempSlots; ++i)
        if (gTempState[i].load() == kNamed) ::unlink(gTempPath[i]);
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

void installTempCleanup() {
    static std::once_flag once;
    std::call_once(once, [] {
        for (int sig : {SIGINT, SIGTERM}) {
            struct sigaction old {};
            // A handler someone else installed (the viewer's toolkit) stays.
            if (sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_DFL) std::signal(sig, removeTempFilesAndDie);
        }
    });
}

// A temporary name registered for removal on a signal while this object lives.
class TempName {
public:
    explicit TempName(const std::string& path) {
        installTempCleanup();
        if (path.empty() || path.size() >= sizeof gTempPath[0]) return;
        for (int i = 0; i < kTempSlots && slot_ < 0; ++i) {
            int expected = kFree;
            if (!gTempState[i].compare_exchange_strong(expected, kClaimed)) continue;
            std::memcpy(gTempPath[i], path.c_str(), path.size() + 1);
            gTempState[i].store(kNamed);
            slot_ = i;
        }
    }
    ~TempName() {
        if (slot_ >= 0) gTempState[slot_].store(kFree);
    }
    TempName(const TempName&) = delete;
    TempName& operator=(const TempName&) = delete;

private:
    int slot_ = -1;
};

// Short temporary names, whatever the length of the target's: ".shadelab-XXXXXX" fits where the
// target's name does (a 250-byte name plus ".tmp-XXXXXX" was over the 255-byte limit).
std::string tempTemplate(const fs::path& dir) { return (dir / ".shadelab-XXXXXX").string(); }

[[noreturn]] void cannotWrite(const std::string& path, int err) {
    throw InputError(path + ": cannot write: " + (err ? std::strerror(err) : "write failed"));
}

// Runs `write` on `f` and flushes; closes `f` (and removes `tmp`, if any) when it fails or throws.
bool writeAndFlush(std::FILE* f, const std::function<bool(std::FILE*)>& write, const char* tmp) {
    bool ok = false;
    try {
        ok = write(f);
    } catch (...) {
        std::fclose(f);
        if (tmp) ::unlink(tmp);
        throw;
    }
    return std::fflush(f) == 0 && ok;
}

// Linux: the file is written unnamed (O_TMPFILE) and linked in whole, so even SIGKILL leaves nothing.
// False when the folder's file system cannot do that (the caller falls back to a named temporary).
bool writeUnnamed(const std::string& path, const fs::path& dir, const std::function<bool(std::FILE*)>& write) {
#ifdef O_TMPFILE
    char self[64];
    if (::access("/proc/self/fd", X_OK) != 0) return false;  // linkat below names the file through /proc
    if (std::getenv("SHADELAB_NO_TMPFILE")) return false;     // tests: the named-temporary path, as elsewhere
    const int fd = ::open(dir.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);  // 0666 less the umask
    if (fd < 0) return false;
    std::FILE* f = fdopen(fd, "wb");
    if (!f) {
        const int err = errno;
        ::close(fd);
        cannotWrite(path, err);
    }
    if (!writeAndFlush(f, write, nullptr)) {
        const int err = errno;
        std::fclose(f);
        cannotWrite(path, err);
    }
    std::snprintf(self, sizeof self, "/proc/self/fd/%d", fd);
    int err = 0;
    if (::linkat(AT_FDCWD, self, AT_FDCWD, path.c_str(), AT_SYMLINK_FOLLOW) != 0) {
        err = errno;
        if (err == EEXIST) {
            // The target exists: link under a short unused name, then rename over it (atomic).
            std::mt19937 random(std::random_device{}());
            err = EEXIST;
            for (int attempt = 0; attempt < 100 && err == EEXIST; ++attempt) {
                std::string tmp = tempTemplate(dir);
                for (std::size_t i = tmp.size() - 6; i < tmp.size(); ++i)
                    tmp[i] = "abcdefghijklmnopqrstuvwxyz0123456789"[random() % 36];
                const TempName registered(tmp);
                if (::linkat(AT_FDCWD, self, AT_FDCWD, tmp.c_str(), AT_SYMLINK_FOLLOW) != 0) {
                    err = errno;
                    continue;
                }
                err = std::rename(tmp.c_str(), path.c_str()) == 0 ? 0 : errno;
                if (err) ::unlink(tmp.c_str());
            }
        }
    }
    std::fclose(f);
    if (err) cannotWrite(path, err);
    return true;
#else
    (void)path, (void)dir, (void)write;
    return false;
#endif
}

}  // namespace

void writeFileAtomic(const std::string& path, const std::function<bool(std::FILE*)>& write) {
    const fs::path target(path);
    const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    if (writeUnnamed(path, dir, write)) return;
    std::string tmp = tempTemplate(dir);
    const int fd = mkstemp(tmp.data());
    if (fd < 0) cannotWrite(path, errno);
    const TempName named(tmp);
    std::FILE* f = fdopen(fd, "wb");
    if (!f) {
        const int err = errno;
        ::close(fd);
        ::unlink(tmp.c_str());
        cannotWrite(path, err);
    }
    bool ok = writeAndFlush(f, write, tmp.c_str());
    ok = std::fclose(f) == 0 && ok;
    // mkstemp creates files 0600; an output file gets the usual permissions (0666 less the umask).
    const mode_t mask = umask(0);
    umask(mask);
    if (ok) ok = ::chmod(tmp.c_str(), 0666 & ~mask) == 0;
    if (!ok || std::rename(tmp.c_str(), path.c_str()) != 0) {
        const int err = errno;
        ::unlink(tmp.c_str());
        cannotWrite(path, err);
    }
}

}  // namespace shadelab
