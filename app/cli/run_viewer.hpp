#pragma once
// The interactive viewer, for one scene or a playlist (run_viewer.cpp; built with SHADELAB_VIEWER).
#include "options/options.hpp"

namespace shadelab {

int runViewerMode(const Options& options);

}  // namespace shadelab
