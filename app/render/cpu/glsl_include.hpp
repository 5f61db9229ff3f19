#pragma once
// The small include step for GLSL files: resolves `#include "file"` (each file once per program, like
// #pragma once), puts `#version 330 core` (kGlslPrologue) first and emits `#line N S` so a driver's log points at the
// right file and line: source-string number S is the index of the file in `files`. The line numbers
// carry it too, N = S * kGlslLinesPerFile + the line: Mesa reports source 0 for errors inside a
// function body (its parser does not pass the source number on), but keeps their line numbers.
#include <functional>
#include <string>
#include <vector>

namespace shadelab {

inline constexpr int kGlslLinesPerFile = 100000;

// What comes before every program: GLSL 330 so the programs run on OpenGL 3.3 core (and macOS's 4.1);
// in the web build (WebGL2) GLSL ES 3.00 and its precisions, the only change the files get there. ES
// has no default precision for floats in fragment shaders nor for shadow and array samplers; highp
// everywhere is what desktop GLSL computes in.
#if SHADELAB_GLES
inline constexpr const char* kGlslPrologue =
    "#version 300 es\n"
    "precision highp float;\nprecision highp int;\nprecision highp sampler2D;\n"
    "precision highp sampler2DArray;\nprecision highp sampler2DShadow;\nprecision highp sampler2DArrayShadow;\n";
inline constexpr const char* kGlslVersionName = "GLSL ES 3.00";
#else
inline constexpr const char* kGlslPrologue = "#version 330 core\n";
inline constexpr const char* kGlslVersionName = "GLSL 330 core";
#endif

struct ExpandedGlsl {
    std::string text;                // ready for glShaderSource
    std::vector<std::string> files;  // files[S] is the file that #line's source number S means
};

// `load(name)` returns a file's text or throws. `defines` ("NAME VALUE" each) become #define lines
// right after #version. Throws std::runtime_error "<file>:<line>: ..." on a malformed or missing include.
ExpandedGlsl expandGlsl(const std::string& name, const std::function<std::string(const std::string&)>& load,
                        const std::vector<std::string>& defines = {});

// Rewrites a driver log so that source numbers become file names: Mesa's "0:12(5): error: ..."
// becomes "phong.frag:12(5): error: ..."; a line number past kGlslLinesPerFile names its file itself
// ("0:200012(5)" is line 12 of files[2]).
std::string locateGlslLog(const std::string& log, const std::vector<std::string>& files);

}  // namespace shadelab
