#pragma once
// The operating-system calls shadelab makes, behind one small interface: the only file in app/ (with
// platform.cpp) that names POSIX or Windows functions. Core, render and the command line include this
// and compile for any C++17 platform; platform.cpp holds a POSIX and a Windows (_WIN32) implementation.
//
// A layer of its own below core (the target shadelab_platform): it needs nothing of shadelab's, so
// it reports failures as text for the caller to word (core/base/file_io.cpp turns them into InputError).
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <functional>
#include <string>

namespace shadelab::platform {

// std::fopen for a std::filesystem::path: POSIX fopen, Windows _wfopen of the path's wide name (so a
// name std::filesystem can reach opens too). nullptr with errno set when it cannot.
std::FILE* openFile(const std::filesystem::path& path, const char* mode);

// Creates or replaces `path` whole or not at all: `write` gets a FILE* to a file in the same folder
// that has no name yet (Linux O_TMPFILE, linked in when complete) or a short temporary name
// (".shadelab-XXXXXX", removed by SIGINT and SIGTERM), which is then renamed over `path` atomically
// (POSIX rename; Windows MoveFileExW with MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH). The
// file gets the usual permissions of a new file (POSIX: 0666 less the umask).
// Returns "" on success, else why not ("No space left on device"; "write failed" when `write`
// returned false with no system error); then `path` is as it was and no temporary is left. An
// exception from `write` passes through, likewise with nothing left behind.
std::string writeFileAtomic(const std::filesystem::path& path, const std::function<bool(std::FILE*)>& write);

// The same for a writer that needs the file's name rather than a FILE* (a library that opens, seeks
// and reads back what it wrote: libavformat moves an MP4's index to the front so). `write` gets the
// name of an empty temporary file in `path`'s folder (".shadelab-XXXXXX", removed by SIGINT and
// SIGTERM) and writes it; returning true renames it over `path`. Returns "" or why not, as above;
// the temporary is removed on failure and when `write` throws (the exception passes through).
std::string writeFileAtomicByName(const std::filesystem::path& path,
                                  const std::function<bool(const std::filesystem::path& temporary)>& write);

// The local calendar time of `t` (localtime_r / localtime_s).
std::tm localTime(std::time_t t);

// The machine's physical memory in bytes; 0 when it cannot be found out.
std::uint64_t physicalMemoryBytes();

// This process's id (for names that must differ between concurrent processes).
long processId();

// The running program's file (Linux /proc/self/exe, Windows GetModuleFileNameW); empty when it cannot
// be found out. Installed data is found from here, so no build path is compiled in.
std::filesystem::path executablePath();

// Linux: when SHADELAB_HUGEPAGES=1 is set, starts the program again, once, with glibc's tunable
// glibc.malloc.hugetlb=1 (malloc's large blocks on transparent huge pages, for the GL driver's
// allocations as well as shadelab's), where the kernel gives huge pages on request (THP "madvise").
// Off by default: whether it pays depends on the kernel's free huge pages, not on the input
// (bench/README.md, "Huge pages, opt-in"); ./dev run and ./dev bench turn it on.
// Returns when it does not restart (not asked, GLIBC_TUNABLES or LD_PRELOAD already set, another
// THP mode, no /proc). Elsewhere it does nothing.
void restartWithHugePagesIfAsked(char** argv);

}  // namespace shadelab::platform
