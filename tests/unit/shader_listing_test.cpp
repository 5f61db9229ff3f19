// The shader view's listing (core/figures/shader_listing.hpp): which files a mode runs, the tokens'
// colours, the lines of the real shaders/ marked with each term, and compile errors found in a log.
#include "core/figures/shader_listing.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <set>
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

TEST(ShaderListing, EachModeRunsItsStagesAndTheLightingInclude) {
    EXPECT_EQ(shaderFilesOf(ShadingMode::Flat), (std::vector<std::string>{"flat.vert", "flat.frag", "lighting.glsl"}));
    EXPECT_EQ(shaderFilesOf(ShadingMode::Gouraud), (std::vector<std::string>{"gouraud.vert", "gouraud.frag", "lighting.glsl"}));
    EXPECT_EQ(shaderFilesOf(ShadingMode::Phong), (std::vector<std::string>{"phong.vert", "phong.frag", "lighting.glsl"}));
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

// The lines of shaders/lighting.glsl that compute each term carry its colour; comments do not.
TEST(ShaderListing, TheLightingIncludesTermLinesAreMarked) {
    const struct {
        const char* code;
        FormulaTerm term;
    } cases[] = {{"L += ambientTerm() * texel;", FormulaTerm::Ambient},
                 {"vec3 diffuse = lightDiffuse(l) * texel * NdotI;", FormulaTerm::Diffuse},
                 {"float NdotI = dot(N, I);", FormulaTerm::Diffuse},
                 {"vec3 specular = lightSpecular(l) * (specularLobe(", FormulaTerm::Specular},
                 {"float spec = pow(max(cosLobe, 0.0), specularExponent());", FormulaTerm::Specular},
                 {"if (SL_FRESNEL == SL_FRESNEL_SCHLICK) spec *= fresnelSchlick(", FormulaTerm::Specular},
                 {"vec3 V = normalize(toEye(posWorld));", FormulaTerm::None},
                 {"L += objectEmission();", FormulaTerm::Emissive},
                 {"// spec_l for a light from direction I (N.I > 0), with the options the scene turned on.", FormulaTerm::None}};
    const std::vector<GlslLine> lines = listGlsl("lighting.glsl", shaderText("lighting.glsl"), {});
    for (const auto& c : cases) {
        bool found = false;
        for (const GlslLine& l : lines)
            if (joined(l.spans).find(c.code) != std::string::npos) {
                found = true;
                EXPECT_EQ(int(l.term), int(c.term)) << l.number << ": " << joined(l.spans);
            }
        EXPECT_TRUE(found) << c.code;
    }
    // Every mode's three files mark all three terms somewhere, and E where lighting.glsl adds it.
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
