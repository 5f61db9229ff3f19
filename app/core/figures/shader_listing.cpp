#include "core/figures/shader_listing.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <iterator>
#include <set>
#include <sstream>

namespace shadelab {
namespace {

const std::set<std::string>& keywords() {
    static const std::set<std::string> k = {"if",      "else",     "for",      "while",  "do",        "return",
                                            "break",   "continue", "const",    "in",     "out",       "inout",
                                            "uniform", "layout",   "flat",     "smooth", "struct",    "discard",
                                            "true",    "false",    "location", "std140", "precision", "highp"};
    return k;
}

const std::set<std::string>& types() {
    static const std::set<std::string> t = {"void", "bool", "int", "uint", "float"};
    return t;
}

bool isType(const std::string& word) {
    if (types().count(word)) return true;
    for (const char* prefix : {"vec", "ivec", "uvec", "bvec", "mat", "sampler"})
        if (word.rfind(prefix, 0) == 0) return true;
    return false;
}

const std::set<std::string>& builtins() {
    static const std::set<std::string> b = {
        "dot",          "normalize",      "max",           "min",        "pow",   "clamp",     "mix",     "abs",
        "sqrt",         "inversesqrt",    "texture",       "length",     "cross", "reflect",   "floor",   "fract",
        "step",         "smoothstep",     "exp",           "log",        "sign",  "transpose", "inverse", "gl_Position",
        "gl_FragCoord", "gl_FrontFacing", "gl_InstanceID", "gl_VertexID"};
    return b;
}

bool identifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

void append(std::vector<GlslSpan>& spans, std::string text, GlslToken token) {
    if (text.empty()) return;
    if (!spans.empty() && spans.back().token == token) spans.back().text += text;
    else spans.push_back(GlslSpan{std::move(text), token});
}

// One line's tokens; `inComment`: inside a /* */ comment at the line's start, updated for the next.
std::vector<GlslSpan> highlight(const std::string& line, bool& inComment) {
    std::vector<GlslSpan> spans;
    std::size_t i = 0;
    const std::size_t first = line.find_first_not_of(" \t");
    if (!inComment && first != std::string::npos && line[first] == '#') {
        const std::size_t comment = line.find("//");
        append(spans, line.substr(0, comment), GlslToken::Preprocessor);
        if (comment != std::string::npos) append(spans, line.substr(comment), GlslToken::Comment);
        return spans;
    }
    while (i < line.size()) {
        if (inComment) {
            const std::size_t end = line.find("*/", i);
            const std::size_t stop = end == std::string::npos ? line.size() : end + 2;
            append(spans, line.substr(i, stop - i), GlslToken::Comment);
            inComment = end == std::string::npos;
            i = stop;
        } else if (line.compare(i, 2, "//") == 0) {
            append(spans, line.substr(i), GlslToken::Comment);
            break;
        } else if (line.compare(i, 2, "/*") == 0) {
            inComment = true;
        } else if (std::isdigit(static_cast<unsigned char>(line[i])) ||
                   (line[i] == '.' && i + 1 < line.size() && std::isdigit(static_cast<unsigned char>(line[i + 1])))) {
            std::size_t end = i;
            while (end < line.size() && (identifierChar(line[end]) || line[end] == '.')) ++end;
            append(spans, line.substr(i, end - i), GlslToken::Number);
            i = end;
        } else if (identifierChar(line[i])) {
            std::size_t end = i;
            while (end < line.size() && identifierChar(line[end])) ++end;
            const std::string word = line.substr(i, end - i);
            const GlslToken token = keywords().count(word)   ? GlslToken::Keyword
                                    : isType(word)           ? GlslToken::Type
                                    : builtins().count(word) ? GlslToken::Builtin
                                                             : GlslToken::Plain;
            append(spans, word, token);
            i = end;
        } else {
            append(spans, std::string(1, line[i]), GlslToken::Plain);
            ++i;
        }
    }
    return spans;
}

}  // namespace

std::vector<std::string> shaderFilesOf(ShadingMode mode) {
    // The lecture's formula first (shaders/lecture.glsl: the slide as one function), then the mode's
    // two stages, for flat and Gouraud how their vertex stage hands its shade() to the fragments
    // (shaders/vertex_shading.glsl), then what this program adds around the formula (shaders/lighting.glsl).
    const std::string name = toString(mode);
    if (mode == ShadingMode::Phong) return {"lecture.glsl", name + ".vert", name + ".frag", "lighting.glsl"};
    return {"lecture.glsl", name + ".vert", name + ".frag", "vertex_shading.glsl", "lighting.glsl"};
}

Rgba8 glslTokenColor(GlslToken token) {
    switch (token) {
    case GlslToken::Keyword: return Rgba8{205, 145, 255, 255};
    case GlslToken::Type: return Rgba8{95, 200, 235, 255};
    case GlslToken::Builtin: return Rgba8{225, 225, 150, 255};
    case GlslToken::Number: return Rgba8{240, 165, 115, 255};
    case GlslToken::Comment: return Rgba8{135, 150, 135, 255};
    case GlslToken::Preprocessor: return Rgba8{215, 125, 170, 255};
    case GlslToken::Plain: break;
    }
    return Rgba8{225, 225, 225, 255};
}

FormulaTerm glslLineTerm(const std::string& line) {
    const std::size_t first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line.compare(first, 2, "//") == 0) return FormulaTerm::None;
    static const struct {
        const char* name;
        FormulaTerm term;
    } names[] = {{"k_a", FormulaTerm::Ambient},
                 {"k_d", FormulaTerm::Diffuse},
                 {"k_s", FormulaTerm::Specular},
                 {"k_e", FormulaTerm::Specular},
                 {"spec_l", FormulaTerm::Specular},
                 {"cosLobe", FormulaTerm::Specular},
                 {"vec3 R = ", FormulaTerm::Specular},
                 {"vec3 H = ", FormulaTerm::Specular},
                 {"lobeFactor(", FormulaTerm::Specular},
                 {"fresnelSchlick(", FormulaTerm::Specular},
                 {"fresnelExact(", FormulaTerm::Specular},
                 {"shadeLectureSpecular(", FormulaTerm::Specular},
                 {"objectEmission(", FormulaTerm::Emissive},
                 {"shownEmission(", FormulaTerm::Emissive}};
    std::size_t best = std::string::npos;
    FormulaTerm term = FormulaTerm::None;
    for (const auto& n : names) {
        const std::size_t at = line.find(n.name);
        if (at < best) {
            best = at;
            term = n.term;
        }
    }
    return term;
}

std::vector<GlslError> glslErrors(const std::string& log) {
    // Every "NAME.EXT:LINE" in the log (a viewer's log has one error a line, a one-line message joins
    // them with "; "); the message runs to the next one or the end of the line.
    struct Place {
        std::size_t start, number;
    };
    std::vector<Place> places;
    for (std::size_t at = 0; (at = log.find(':', at)) != std::string::npos; ++at) {
        if (at + 1 >= log.size() || !std::isdigit(static_cast<unsigned char>(log[at + 1]))) continue;
        std::size_t start = at;
        while (start > 0 && (identifierChar(log[start - 1]) || log[start - 1] == '.' || log[start - 1] == '-')) --start;
        const std::string name = log.substr(start, at - start);
        static const std::string kExtensions[] = {".vert", ".frag", ".glsl", ".geom"};
        const bool glsl = std::any_of(std::begin(kExtensions), std::end(kExtensions), [&](const std::string& e) {
            return name.size() > e.size() && name.compare(name.size() - e.size(), e.size(), e) == 0;
        });
        if (glsl) places.push_back(Place{start, at + 1});
    }
    std::vector<GlslError> errors;
    for (std::size_t i = 0; i < places.size(); ++i) {
        std::size_t end =
            std::min(log.find('\n', places[i].start), i + 1 < places.size() ? places[i + 1].start : log.size());
        std::string message = log.substr(places[i].start, std::min(end, log.size()) - places[i].start);
        while (!message.empty() && (message.back() == ' ' || message.back() == ';')) message.pop_back();
        errors.push_back(GlslError{log.substr(places[i].start, places[i].number - 1 - places[i].start),
                                   std::atoi(log.c_str() + places[i].number), message});
    }
    return errors;
}

std::vector<GlslLine> listGlsl(const std::string& file, const std::string& text, const std::vector<GlslError>& errors) {
    std::vector<GlslLine> out;
    std::istringstream lines(text);
    bool inComment = false;
    int number = 0;
    for (std::string line; std::getline(lines, line);) {
        GlslLine l;
        l.number = ++number;
        l.term = inComment ? FormulaTerm::None : glslLineTerm(line);
        l.spans = highlight(line, inComment);
        for (const GlslError& e : errors)
            if (e.file == file && e.line == number) l.error += (l.error.empty() ? "" : "\n") + e.message;
        out.push_back(std::move(l));
    }
    return out;
}

}  // namespace shadelab
