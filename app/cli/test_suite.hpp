#pragma once
// `shadelab --test DIR`: screenshot tests of a folder in one process. Every DIR/*.json (file-name
// order, the command line's overrides applied) is rendered on one GL context that keeps its compiled
// programs (renderScenesHeadless), and compared with DIR/NAME.png (or --references DIR2/NAME.png) as
// --reference compares one image. Reading the references, comparing and encoding PNGs run on other
// threads while the next scene renders. A case that cannot be compared (unreadable scene, missing or
// malformed reference, a shader that does not compile) fails and the run goes on; cli/test_report.hpp
// says how the results are told (stdout, --junit, --report). --update rewrites the references of the
// failing cases that have a render.
#include "cli/options.hpp"
#include "headless/headless_context.hpp"
#include "render/shader_library.hpp"

namespace shadelab {

// Returns the exit status: 0 when every case matches (or, with --update, every failing case got its
// reference rewritten), 1 otherwise. Throws InputError (exit 2) for a DIR that is missing or holds no
// scene file, or a --references folder that does not exist, before anything is rendered.
int runTestSuite(const Options& options, const ShaderLibrary& shaders, HeadlessBackend backend, int msaaSamples);

}  // namespace shadelab
