// The shader view's listing (core/figures/shader_listing.hpp): which files a mode runs, the tokens'
// colours, the lines of the real shaders/ marked with each term, and compile errors found in a log.
#include "core/figures/shader_listing.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <string>

using namespace shadelab;

namespace {

std::string shaderText(const std::string& file) {
    std::ifstream in(std::string(SHADELAB_SOURCE_DIR) + "/shaders/" + file);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string joined(const std::vector<GlslSpan>& spans) {
    std::string s;
    for (const GlslSpan& span : spans) s += span.text;
    return s;
}

GlslToken tokenOf(const GlslLine& line, const std::string& text) {
    for (const GlslSpan& s : line.spans)
        if (s.text == text) return s.token;
    return GlslToken::Plain;
}

}  // namespace

// The slide's formula first, then the mode's stages, then what the program adds.
TEST(ShaderListing, EachModeShowsTheLectureFirstThenItsStagesAndTheLightingInclude) {
    EXPECT_EQ(shaderFilesOf(ShadingMode::Flat),
              (std::vector<std::string>{"lecture.glsl", "flat.vert", "flat.frag", "vertex_shading.glsl", "lighting.glsl"}));
    EXPECT_EQ(shaderFilesOf(ShadingMode::Gouraud),
              (std::vector<std::string>{"lecture.glsl", "gouraud.vert", "gouraud.frag", "vertex_shading.glsl",
                                        "lighting.glsl"}));
    EXPECT_EQ(shaderFilesOf(ShadingMode::Phong),
              (std::vector<std::string>{"lecture.glsl", "phong.vert", "phong.frag", "lighting.glsl"}));
    for (ShadingMode m : {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong})
        for (const std::string& f : shaderFilesOf(m)) EXPECT_FALSE(shaderText(f).empty()) << f;
}

TEST(ShaderListing, TokensAreColouredAndKeepTheText) {
    const std::string line = "    vec3 N = normalize(v_nrm) * 2.0;  // the unit normal";
    const std::vector<GlslLine> l = listGlsl("x.frag", line + "\n#include \"lighting.glsl\"\nfor (int i = 0; i < 3; ++i) {}\n", {});
    ASSERT_EQ(l.size(), 3u);
    EXPECT_EQ(l[0].number, 1);
    EXPECT_EQ(joined(l[0].spans), line);
    EXPECT_EQ(tokenOf(l[0], "vec3"), GlslToken::Type);
    EXPECT_EQ(tokenOf(l[0], "normalize"), GlslToken::Builtin);
    EXPECT_EQ(tokenOf(l[0], "2.0"), GlslToken::Number);
    EXPECT_EQ(l[0].spans.back().token, GlslToken::Comment);
    EXPECT_EQ(l[1].spans.size(), 1u);
    EXPECT_EQ(l[1].spans[0].token, GlslToken::Preprocessor);
    EXPECT_EQ(tokenOf(l[2], "for"), GlslToken::Keyword);
    EXPECT_EQ(tokenOf(l[2], "int"), GlslToken::Type);
    // A block comment spans lines.
    const std::vector<GlslLine> block = listGlsl("x.frag", "a /* b\nk_d c */ d\n", {});
    EXPECT_EQ(block[1].spans[0].token, GlslToken::Comment);
    EXPECT_EQ(block[1].term, FormulaTerm::None);
    EXPECT_EQ(tokenOf(block[1], " d"), GlslToken::Plain);
    // Token colours differ from plain text.
    for (GlslToken t : {GlslToken::Keyword, GlslToken::Type, GlslToken::Number, GlslToken::Comment, GlslToken::Preprocessor})
        EXPECT_NE(glslTokenColor(t).b + 256 * glslTokenColor(t).r, glslTokenColor(GlslToken::Plain).b + 256 * glslTokenColor(GlslToken::Plain).r);
}

// The lines of shaders/lecture.glsl and lighting.glsl that compute each term carry its colour;
// comments do not.
TEST(ShaderListing, TheFormulasTermLinesAreMarked) {
    const struct {
        const char* file;
        const char* code;
        FormulaTerm term;
    } cases[] = {{"lecture.glsl", "vec3 L = m.k_a * A * m.C;", FormulaTerm::Ambient},
                 {"lecture.glsl", "vec3 diffuse = m.k_d * m.C * max(dot(N, I), 0.0);", FormulaTerm::Diffuse},
                 {"lecture.glsl", "vec3 R = 2.0 * dot(N, I) * N - I;", FormulaTerm::Specular},
                 {"lecture.glsl", "float spec_l = pow(max(cosLobe, 0.0), lobeExponent(H, m.k_e))", FormulaTerm::Specular},
                 {"lecture.glsl", "vec3 specular = m.k_s * m.S * spec_l;", FormulaTerm::Specular},
                 {"lecture.glsl", "vec3 I = normalize(toLight(l, P));", FormulaTerm::None},
                 {"lighting.glsl", "if (SL_FRESNEL == SL_FRESNEL_SCHLICK) factor *= fresnelSchlick(", FormulaTerm::Specular},
                 {"lighting.glsl", "vec3 V = normalize(toEye(P));", FormulaTerm::None},
                 {"lighting.glsl", "vec3 E = shownEmission();", FormulaTerm::Emissive},
                 {"lighting.glsl", "// spec_l's factor besides the lobe", FormulaTerm::None}};
    for (const auto& c : cases) {
        bool found = false;
        for (const GlslLine& l : listGlsl(c.file, shaderText(c.file), {}))
            if (joined(l.spans).find(c.code) != std::string::npos) {
                found = true;
                EXPECT_EQ(int(l.term), int(c.term)) << c.file << ":" << l.number << ": " << joined(l.spans);
            }
        EXPECT_TRUE(found) << c.file << ": " << c.code;
    }
    // Every mode's files mark all three terms somewhere, and E where lighting.glsl adds it.
    for (ShadingMode m : {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong}) {
        std::set<FormulaTerm> terms;
        for (const std::string& f : shaderFilesOf(m))
            for (const GlslLine& l : listGlsl(f, shaderText(f), {})) terms.insert(l.term);
        EXPECT_EQ(terms.size(), 5u) << toString(m);  // None, the three and E
    }
}

// The driver's log as the renderer words it (locateGlslLog names files): each error's file and line,
// also when a one-line message joins them; listGlsl marks those lines of that file only.
TEST(ShaderListing, CompileErrorsPointAtTheirLines) {
    const std::string log = "program phong, fragment stage (phong.frag, GLSL 330 core) failed to compile: "
                            "phong.frag:2(15): error: `x' undeclared; lighting.glsl:3(1): error: syntax error\n"
                            "phong.frag:1(3): warning: unused";
    const std::vector<GlslError> errors = glslErrors(log);
    ASSERT_EQ(errors.size(), 3u);
    EXPECT_EQ(errors[0].file, "phong.frag");
    EXPECT_EQ(errors[0].line, 2);
    EXPECT_EQ(errors[0].message, "phong.frag:2(15): error: `x' undeclared");
    EXPECT_EQ(errors[1].file, "lighting.glsl");
    EXPECT_EQ(errors[1].line, 3);
    EXPECT_EQ(errors[2].line, 1);
    const std::vector<GlslLine> lines = listGlsl("phong.frag", "a\nb\nc\n", errors);
    EXPECT_NE(lines[0].error.find("warning: unused"), std::string::npos);
    EXPECT_NE(lines[1].error.find("undeclared"), std::string::npos);
    EXPECT_TRUE(lines[2].error.empty());  // line 3 is lighting.glsl's
    EXPECT_TRUE(glslErrors("no file here: 12").empty());
}

// Issue 28: the file the Shader view shows first is the slide. Its two functions, one light's term and
// the sum, fit a slide (at most 40 lines together) and name the lecture's symbols; no preprocessor
// switch sits in them; phong.frag is a page a student reads at a glance.
TEST(ShaderListing, TheLectureFileIsTheSlide) {
    const std::string lecture = shaderText("lecture.glsl");
    const std::size_t start = lecture.find("vec3 oneLight(");
    ASSERT_NE(start, std::string::npos);
    const std::string functions = lecture.substr(start);
    EXPECT_LE(std::count(functions.begin(), functions.end(), '\n'), 40);
    EXPECT_EQ(functions.find("#if"), std::string::npos);
    EXPECT_NE(functions.find("vec3 lecture(Material m, vec3 A, vec3 P, vec3 N, vec3 V)"), std::string::npos);
    for (const char* name : {"m.k_a", "m.k_d", "m.k_s", "m.k_e", "m.C", "m.S", " A ", "L_l", "vec3 I", "vec3 R", "vec3 H",
                             "max(", "dot(", "pow(", "for (int l = 0; l < SL_LIGHT_COUNT; ++l)"})
        EXPECT_NE(functions.find(name), std::string::npos) << name;
    const std::string phong = shaderText("phong.frag");
    EXPECT_LE(std::count(phong.begin(), phong.end(), '\n'), 20);
    EXPECT_EQ(phong.find("#if"), std::string::npos);
    EXPECT_NE(phong.find("shade("), std::string::npos);
}

// Issue 40: every mode's files read like phong.frag, where the lecture's sum is evaluated and nothing
// else. A variant's differences (textured, double-sided, anisotropic, packed, instanced) are decided in
// named helpers (vertex_shading.glsl, object_color.glsl, tangent.glsl, ...), so no preprocessor
// conditional sits in a mode's file, and each still fits a slide.
TEST(ShaderListing, EveryModeFileIsASlide) {
    for (const char* file : {"flat.vert", "flat.frag", "gouraud.vert", "gouraud.frag", "phong.vert", "phong.frag"}) {
        const std::string text = shaderText(file);
        EXPECT_LE(std::count(text.begin(), text.end(), '\n'), 20) << file;
        std::istringstream lines(text);
        int number = 0;
        for (std::string line; std::getline(lines, line);) {
            ++number;
            std::size_t at = line.find_first_not_of(" \t");
            if (at == std::string::npos || line[at] != '#') continue;
            at = line.find_first_not_of(" \t", at + 1);
            const std::string directive = line.substr(at, line.find_first_of(" \t(", at) - at);
            for (const char* conditional : {"if", "ifdef", "ifndef", "elif", "else", "endif"})
                EXPECT_NE(directive, conditional) << file << ":" << number << ": " << line;
        }
    }
    EXPECT_NE(shaderText("flat.vert").find("shadeAndPass("), std::string::npos);
    EXPECT_NE(shaderText("gouraud.vert").find("shadeAndPass("), std::string::npos);
}
