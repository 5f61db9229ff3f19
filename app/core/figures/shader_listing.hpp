#pragma once
// The shader view (viewer key S, the panel's Shader section): the GLSL that a shading mode runs, as
// the readable files in shaders/ (not the expanded text the driver compiles), split into coloured
// tokens, each line that computes a term of the formula marked in that term's colour from the formula
// overlay (core/figures/formula.hpp), and a compile error's line found in the driver's log. GL-free.
#include "core/figures/formula.hpp"
#include "core/image/text.hpp"
#include "core/scene/scene.hpp"

#include <string>
#include <vector>

namespace shadelab {

// The files a mode runs: its vertex stage, its fragment stage (and, for flat and Gouraud, the include
// that hands the vertex stage's colour to the fragments) and the shared lighting include.
std::vector<std::string> shaderFilesOf(ShadingMode mode);

enum class GlslToken { Plain, Keyword, Type, Builtin, Number, Comment, Preprocessor };
Rgba8 glslTokenColor(GlslToken token);

struct GlslSpan {
    std::string text;
    GlslToken token = GlslToken::Plain;
};

// The term of the formula a line of code computes (None for the rest, and for lines that are only a
// comment): the first of the term's names it mentions, in code or in its trailing comment:
// ambient k_a; diffuse k_d; specular k_s, k_e, spec_l, cosLobe, the vectors R and H, lobeFactor and
// the Fresnel weights; emission objectEmission (shaders/lecture.glsl and lighting.glsl name them so).
FormulaTerm glslLineTerm(const std::string& line);

// A compile or link error's place, from a log that names files as locateGlslLog writes them
// ("phong.frag:12(5): error: ...").
struct GlslError {
    std::string file;
    int line = 0;
    std::string message;  // that line of the log
};
std::vector<GlslError> glslErrors(const std::string& log);

struct GlslLine {
    int number = 0;  // from 1
    std::vector<GlslSpan> spans;
    FormulaTerm term = FormulaTerm::None;
    std::string error;  // the log's message for this line; empty when none
};

// `text` (the file `file`) as numbered, coloured lines with their terms and `errors` in this file.
std::vector<GlslLine> listGlsl(const std::string& file, const std::string& text, const std::vector<GlslError>& errors);

}  // namespace shadelab
