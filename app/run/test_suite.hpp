#pragma once
// `shadelab --test DIR`: screenshot tests of a folder in one process. Every scene file of DIR and its
// subfolders (DIR/NAME.json, NAME "sub/scene" for one in a subfolder; in name order, the command line's
// overrides applied; --filter and --shard pick some) is rendered on one GL context that keeps its
// compiled programs (renderScenesHeadless), and compared with DIR/NAME.png (or --references
// DIR2/NAME.png) as --reference compares one image, with the scene's own "test" settings (thresholds,
// masks) over the command line's. Reading the references, comparing and encoding PNGs run on other
// threads while the next scene renders. A case that cannot be compared (unreadable scene, missing or
// malformed reference, a shader that does not compile, a scene over the memory budget) fails and the run
// goes on; run/test_report.hpp says how the results are told (stdout, --junit, --report, --artifacts).
// --update rewrites the references of the failing cases that have a render.
#include "headless/headless_context.hpp"
#include "options/options.hpp"
#include "render/shader_library.hpp"

namespace shadelab {

// Returns the exit status: 0 when every case matches (or, with --update, every failing case got its
// reference rewritten), 1 otherwise. Throws InputError (exit 2) for a DIR that is missing or holds no
// scene file, a --references folder that does not exist (without --update, which creates it), or a
// --filter that matches no case, before anything is rendered; and when OpenGL cannot start, after
// --junit and --report are written with that one error.
int runTestSuite(const Options& options, const ShaderLibrary& shaders, HeadlessBackend backend, int msaaSamples);

}  // namespace shadelab
