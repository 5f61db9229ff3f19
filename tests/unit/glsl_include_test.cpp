// The GLSL include step, and the one source of truth for constants shared by C++ and GLSL.
#include "../../shaders/shared_defs.glsl"
#include "render/cpu/glsl_include.hpp"
#include "core/scene/scene.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>

using namespace shadelab;

TEST(GlslInclude, ResolvesIncludesOnceAndEmitsLineDirectives) {
    const std::map<std::string, std::string> files = {
        {"main.frag", "#include \"a.glsl\"\n#include \"b.glsl\"\nvoid main() {}\n"},
        {"a.glsl", "#include \"b.glsl\"\nfloat a;\n"},
        {"b.glsl", "float b;\n"}};
    const ExpandedGlsl out = expandGlsl("main.frag", [&](const std::string& n) { return files.at(n); });
    EXPECT_EQ(out.files, (std::vector<std::string>{"main.frag", "a.glsl", "b.glsl"}));
    EXPECT_EQ(out.text,
              "#version 330 core\n"
              "#line 1 0\n"
              "#line 100001 1\n"
              "#line 200001 2\n"
              "float b;\n"
              "#line 100002 1\n"
              "float a;\n"
              "#line 2 0\n"   // b.glsl again: already included, skipped
              "#line 3 0\n"
              "void main() {}\n");
}

TEST(GlslInclude, MalformedIncludesAndVersionLinesAreErrors) {
    auto load = [](const std::string& n) -> std::string {
        if (n == "bad.frag") return "#include <x.glsl>\n";
        if (n == "version.frag") return "#version 450\n";
        if (n == "loop.glsl") return "#include \"loop2.glsl\"\n";
        return "#include \"loop.glsl\"\n";
    };
    EXPECT_THROW(expandGlsl("bad.frag", load), std::runtime_error);
    EXPECT_THROW(expandGlsl("version.frag", load), std::runtime_error);
    EXPECT_NO_THROW(expandGlsl("loop.glsl", load));  // include-once also ends cycles
}

TEST(GlslInclude, DriverLogsPointAtFilesAndLines) {
    const std::string log = "0:12(5): error: syntax error\n2:3(1): warning: unused\nlink failed\n";
    EXPECT_EQ(locateGlslLog(log, {"phong.frag", "uniforms.glsl", "lighting.glsl"}),
              "phong.frag:12(5): error: syntax error\nlighting.glsl:3(1): warning: unused\nlink failed\n");
    // Mesa loses the source number inside function bodies; the line number still names the file.
    EXPECT_EQ(locateGlslLog("0:200111(60): error: `oops' undeclared\n", {"phong.frag", "uniforms.glsl", "lighting.glsl"}),
              "lighting.glsl:111(60): error: `oops' undeclared\n");
}

TEST(SharedDefs, CppAndGlslAgreeOnLimits) {
    EXPECT_EQ(SL_MAX_LIGHTS, kMaxLights);
}

// Every shader in shaders/ expands (its includes exist), so no program can miss a file at run time.
TEST(SharedDefs, ShippedShadersExpand) {
    auto load = [](const std::string& n) {
        std::ifstream in(std::string(SHADELAB_SOURCE_DIR) + "/shaders/" + n);
        if (!in) throw std::runtime_error("missing " + n);
        std::ostringstream s;
        s << in.rdbuf();
        return s.str();
    };
    for (const char* program : {"flat", "gouraud", "phong"})
        for (const char* stage : {".vert", ".frag"}) {
            const ExpandedGlsl e = expandGlsl(std::string(program) + stage, load);
            EXPECT_NE(e.text.find("uniform FrameBlock"), std::string::npos) << program << stage;
        }
}
