#pragma once
// Reading input files with size limits and writing output files atomically (temporary file in the same
// folder, then rename), so a failed or killed run never leaves a partial file at the output path.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace shadelab {

// Reads a whole file. InputError "<path>: cannot read: <reason>" if it is missing, a directory,
// unreadable, or larger than maxBytes.
std::string readTextFile(const std::string& path, std::uint64_t maxBytes);

// True for names ending in .gltf or .glb (any case).
bool hasModelExtension(const std::string& path);
// True for names ending in `ext` (with the dot, compared case-insensitively).
bool hasExtension(const std::string& path, const std::string& ext);

// Where shadelab's data of one kind ("shaders", "scenes") may be for the program at `program`, in the
// order a lookup tries them: an installed one's PREFIX/share/shadelab/KIND (the program in PREFIX/bin),
// the checkout's folder `inCheckout` for a program in a build folder inside a checkout (edits there
// need no build), and a build folder's own share/shadelab/KIND beside the program (the build stages
// it, linked to the checkout), so a build folder anywhere finds what an install finds. None for an
// empty `program` (its path unknown).
std::vector<std::filesystem::path> dataFoldersBesideProgram(const std::filesystem::path& program,
                                                            const std::string& kind, const std::string& inCheckout);

// Checks, before any work is done, that `path` can become an output file: its folder exists and it is
// not itself a folder. Throws InputError naming `option` and the path.
void checkOutputPath(const std::string& path, const std::string& option);

// The same for an output folder (--playlist --output DIR/): an existing folder, or a name ending in
// '/' whose parent folder exists, so a typo never creates a tree of folders. Throws InputError.
void checkOutputFolder(const std::string& path, const std::string& option);
// Checks as above and creates the folder when it is missing. Throws InputError.
void createOutputFolder(const std::string& path, const std::string& option);

// Creates `path` atomically: `write` gets a FILE* to a temporary file beside it; on success the
// temporary is renamed over `path`, on any failure (write returns false or throws) it is removed
// (platform::writeFileAtomic). InputError "<path>: cannot write: <reason>".
void writeFileAtomic(const std::string& path, const std::function<bool(std::FILE*)>& write);
// The same for a writer that needs a file name (platform::writeFileAtomicByName): `write` gets the
// name of a temporary file beside `path` to write.
void writeFileAtomicByName(const std::string& path, const std::function<bool(const std::string& temporary)>& write);

}  // namespace shadelab
