#include "platform/platform.hpp"

#ifdef _WIN32
#ifndef NOMINMAX
#define NOMINMAX
#endif
#include <windows.h>  // first: the others below rely on its definitions

#include <fcntl.h>
#include <io.h>
#include <process.h>
#include <sys/stat.h>
#else
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#endif

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <mutex>
#include <optional>
#include <random>

namespace shadelab::platform {
namespace fs = std::filesystem;

// ---- Both: temporary names removed on SIGINT and SIGTERM, and the steps every write shares.
namespace {

using Char = fs::path::value_type;  // char on POSIX, wchar_t on Windows

void removeFile(const Char* path) {
#ifdef _WIN32
    ::_wunlink(path);
#else
    ::unlink(path);
#endif
}

// Temporary files that exist under a name while a write is in flight, removed by SIGINT and SIGTERM
// (SIGKILL cannot be caught: that is what O_TMPFILE is for). The handler reads fixed buffers only.
constexpr int kTempSlots = 8;
constexpr std::size_t kTempPathChars = 4096;
enum TempSlot : int { kFree, kClaimed, kNamed };  // a slot is claimed, then its name written, then named
Char gTempPath[kTempSlots][kTempPathChars];
std::atomic<int> gTempState[kTempSlots];

extern "C" void removeTempFilesAndDie(int signal) {
    for (int i = 0; i < kTempSlots; ++i)
        if (gTempState[i].load() == kNamed) removeFile(gTempPath[i]);
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

void installTempCleanup() {
    static std::once_flag once;
    std::call_once(once, [] {
        for (int sig : {SIGINT, SIGTERM}) {
            // A handler someone else installed (the viewer's toolkit) stays.
#ifdef _WIN32
            const auto old = std::signal(sig, removeTempFilesAndDie);
            if (old != SIG_DFL && old != SIG_ERR) std::signal(sig, old);
#else
            struct sigaction old {};
            if (sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_DFL)
                std::signal(sig, removeTempFilesAndDie);
#endif
        }
    });
}

// A temporary name registered for removal on a signal while this object lives.
class TempName {
public:
    explicit TempName(const fs::path& path) {
        installTempCleanup();
        const auto& name = path.native();
        if (name.empty() || name.size() >= kTempPathChars) return;
        for (int i = 0; i < kTempSlots && slot_ < 0; ++i) {
            int expected = kFree;
            if (!gTempState[i].compare_exchange_strong(expected, kClaimed)) continue;
            std::copy(name.c_str(), name.c_str() + name.size() + 1, gTempPath[i]);
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
const char* const kTempTemplate = ".shadelab-XXXXXX";

fs::path randomTempName(const fs::path& dir, std::mt19937& random) {
    std::string name = kTempTemplate;
    for (std::size_t i = name.size() - 6; i < name.size(); ++i)
        name[i] = "abcdefghijklmnopqrstuvwxyz0123456789"[random() % 36];
    return dir / name;
}

std::string reason(int err) { return err ? std::strerror(err) : "write failed"; }

// Runs `write` on `f` and flushes; closes `f` (and removes `tmp`, if any) when `write` throws.
bool writeAndFlush(std::FILE* f, const std::function<bool(std::FILE*)>& write, const Char* tmp) {
    bool ok = false;
    try {
        ok = write(f);
    } catch (...) {
        std::fclose(f);
        if (tmp) removeFile(tmp);
        throw;
    }
    return std::fflush(f) == 0 && ok;
}

fs::path folderOf(const fs::path& path) { return path.parent_path().empty() ? fs::path(".") : path.parent_path(); }

// Runs `write` on the named temporary `tmp`; removes it when `write` returns false or throws.
bool writeNamed(const fs::path& tmp, const std::function<bool(const fs::path&)>& write) {
    bool ok = false;
    try {
        ok = write(tmp);
    } catch (...) {
        removeFile(tmp.c_str());
        throw;
    }
    if (!ok) removeFile(tmp.c_str());
    return ok;
}

}  // namespace

std::tm localTime(std::time_t t) {
    std::tm out{};
#ifdef _WIN32
    localtime_s(&out, &t);
#else
    localtime_r(&t, &out);
#endif
    return out;
}

long processId() {
#ifdef _WIN32
    return long(GetCurrentProcessId());
#else
    return long(::getpid());
#endif
}

std::filesystem::path executablePath() {
    std::error_code ec;
#ifdef _WIN32
    std::wstring name(32768, L'\0');
    const DWORD n = GetModuleFileNameW(nullptr, name.data(), DWORD(name.size()));
    if (n == 0 || n >= name.size()) return {};
    name.resize(n);
    return std::filesystem::path(name);
#else
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
    return ec ? std::filesystem::path() : self;
#endif
}

#ifdef _WIN32
// ---- Windows

namespace {
// The system's wording of a Win32 error code ("Access is denied").
std::string win32Reason(DWORD code) {
    char* text = nullptr;
    const DWORD n =
        FormatMessageA(FORMAT_MESSAGE_ALLOCATE_BUFFER | FORMAT_MESSAGE_FROM_SYSTEM | FORMAT_MESSAGE_IGNORE_INSERTS,
                       nullptr, code, 0, reinterpret_cast<char*>(&text), 0, nullptr);
    std::string out = n && text ? std::string(text, n) : "Windows error " + std::to_string(code);
    if (text) LocalFree(text);
    while (!out.empty() && (out.back() == '\n' || out.back() == '\r' || out.back() == '.' || out.back() == ' '))
        out.pop_back();
    return out;
}

std::wstring wide(const char* text) {
    std::wstring out;
    for (; *text; ++text) out += wchar_t(static_cast<unsigned char>(*text));  // modes are ASCII
    return out;
}
}  // namespace

std::FILE* openFile(const fs::path& path, const char* mode) { return ::_wfopen(path.c_str(), wide(mode).c_str()); }

// A temporary beside the target, written and committed to disk, then moved over the target.
std::string writeFileAtomic(const fs::path& path, const std::function<bool(std::FILE*)>& write) {
    const fs::path dir = folderOf(path);
    std::mt19937 random(std::random_device{}());
    fs::path tmp;
    int fd = -1;
    for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
        tmp = randomTempName(dir, random);
        fd = ::_wopen(tmp.c_str(), _O_CREAT | _O_EXCL | _O_WRONLY | _O_BINARY | _O_NOINHERIT, _S_IREAD | _S_IWRITE);
        if (fd < 0 && errno != EEXIST) return reason(errno);
    }
    if (fd < 0) return reason(EEXIST);
    const TempName named(tmp);
    std::FILE* f = ::_fdopen(fd, "wb");
    if (!f) {
        const int err = errno;
        ::_close(fd);
        removeFile(tmp.c_str());
        return reason(err);
    }
    bool ok = writeAndFlush(f, write, tmp.c_str());
    ok = ok && ::_commit(::_fileno(f)) == 0;
    const int err = errno;
    ok = std::fclose(f) == 0 && ok;
    if (!ok) {
        removeFile(tmp.c_str());
        return reason(err ? err : errno);
    }
    if (!MoveFileExW(tmp.c_str(), path.c_str(), MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH)) {
        const DWORD moveError = GetLastError();
        removeFile(tmp.c_str());
        return win32Reason(moveError);
    }
    return "";
}

std::string writeFileAtomicByName(const fs::path& path, const std::function<bool(const fs::path&)>& write) {
    std::mt19937 random(std::random_device{}());
    fs::path tmp;
    int fd = -1;
    for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
        tmp = randomTempName(folderOf(path), random);
        fd = ::_wopen(tmp.c_str(), _O_CREAT | _O_EXCL | _O_WRONLY | _O_BINARY | _O_NOINHERIT, _S_IREAD | _S_IWRITE);
        if (fd < 0 && errno != EEXIST) return reason(errno);
    }
    if (fd < 0) return reason(EEXIST);
    ::_close(fd);
    const TempName named(tmp);
    if (!writeNamed(tmp, write)) return reason(0);
    if (!MoveFileExW(tmp.c_str(), path.c_str(), MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH)) {
        const DWORD moveError = GetLastError();
        removeFile(tmp.c_str());
        return win32Reason(moveError);
    }
    return "";
}

std::uint64_t physicalMemoryBytes() {
    MEMORYSTATUSEX status{};
    status.dwLength = sizeof status;
    return GlobalMemoryStatusEx(&status) ? std::uint64_t(status.ullTotalPhys) : 0;
}

void restartWithHugePagesIfAsked(char**) {}

#else
// ---- POSIX (Linux's O_TMPFILE where the headers have it)

namespace {
// Linux: the file is written unnamed (O_TMPFILE) and linked in whole, so even SIGKILL leaves nothing.
// nullopt when the folder's file system cannot do that (the caller falls back to a named temporary);
// else "" or why the write failed.
std::optional<std::string> writeUnnamed(const fs::path& path, const fs::path& dir,
                                        const std::function<bool(std::FILE*)>& write) {
#ifdef O_TMPFILE
    char self[64];
    if (::access("/proc/self/fd", X_OK) != 0) return std::nullopt;  // linkat below names the file through /proc
    if (std::getenv("SHADELAB_NO_TMPFILE")) return std::nullopt;    // tests: the named-temporary path, as elsewhere
    const int fd = ::open(dir.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);  // 0666 less the umask
    if (fd < 0) return std::nullopt;
    std::FILE* f = fdopen(fd, "wb");
    if (!f) {
        const int err = errno;
        ::close(fd);
        return reason(err);
    }
    if (!writeAndFlush(f, write, nullptr)) {
        const int err = errno;
        std::fclose(f);
        return reason(err);
    }
    std::snprintf(self, sizeof self, "/proc/self/fd/%d", fd);
    int err = 0;
    if (::linkat(AT_FDCWD, self, AT_FDCWD, path.c_str(), AT_SYMLINK_FOLLOW) != 0) {
        err = errno;
        if (err == EEXIST) {
            // The target exists: link under a short unused name, then rename over it (atomic).
            std::mt19937 random(std::random_device{}());
            for (int attempt = 0; attempt < 100 && err == EEXIST; ++attempt) {
                const fs::path tmp = randomTempName(dir, random);
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
    if (err) return reason(err);
    return std::string();
#else
    (void)path, (void)dir, (void)write;
    return std::nullopt;
#endif
}
}  // namespace

std::FILE* openFile(const fs::path& path, const char* mode) { return std::fopen(path.c_str(), mode); }

std::string writeFileAtomic(const fs::path& path, const std::function<bool(std::FILE*)>& write) {
    const fs::path dir = folderOf(path);
    if (std::optional<std::string> unnamed = writeUnnamed(path, dir, write)) return *unnamed;
    std::string tmp = (dir / kTempTemplate).string();
    const int fd = mkstemp(tmp.data());
    if (fd < 0) return reason(errno);
    const TempName named(tmp);
    std::FILE* f = fdopen(fd, "wb");
    if (!f) {
        const int err = errno;
        ::close(fd);
        ::unlink(tmp.c_str());
        return reason(err);
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
        return reason(err);
    }
    return "";
}

std::string writeFileAtomicByName(const fs::path& path, const std::function<bool(const fs::path&)>& write) {
    std::string tmp = (folderOf(path) / kTempTemplate).string();
    const int fd = mkstemp(tmp.data());
    if (fd < 0) return reason(errno);
    ::close(fd);
    const TempName named(tmp);
    if (!writeNamed(tmp, write)) return reason(0);
    // mkstemp creates files 0600; an output file gets the usual permissions (0666 less the umask).
    const mode_t mask = umask(0);
    umask(mask);
    if (::chmod(tmp.c_str(), 0666 & ~mask) != 0 || std::rename(tmp.c_str(), path.c_str()) != 0) {
        const int err = errno;
        ::unlink(tmp.c_str());
        return reason(err);
    }
    return "";
}

std::uint64_t physicalMemoryBytes() {
    const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
    if (pages <= 0 || pageSize <= 0) return 0;
    return std::uint64_t(pages) * std::uint64_t(pageSize);
}

// glibc reads its tunables only when a process starts: so shadelab starts itself again, once, with
// glibc.malloc.hugetlb=1 set (~4 ms). A 2M-triangle model touches ~250 MiB of fresh memory (the file,
// the mesh, the driver's copies and its binned triangles): ~65k page faults of 4 KiB, fewer on 2 MiB
// pages; but zeroing 2 MiB pages costs system time that a smaller run does not win back.
void restartWithHugePagesIfAsked(char** argv) {
#ifdef __linux__
    const char* asked = std::getenv("SHADELAB_HUGEPAGES");
    if (!asked || std::strcmp(asked, "1") != 0) return;
    // The user's tunables stand; a preloaded tool (valgrind) would not follow the exec.
    if (std::getenv("GLIBC_TUNABLES") || std::getenv("LD_PRELOAD")) return;
    std::ifstream thp("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string mode;
    if (!std::getline(thp, mode) || mode.find("[madvise]") == std::string::npos) return;  // "always", "never"
    setenv("GLIBC_TUNABLES", "glibc.malloc.hugetlb=1", 1);
    execv("/proc/self/exe", argv);
    unsetenv("GLIBC_TUNABLES");  // no /proc: go on as we are
#else
    (void)argv;
#endif
}

#endif

}  // namespace shadelab::platform
