// Sweep sheets without GL: parsing "PARAM=V1,V2", applying a value to the scene, the labels, and the
// composition of the sheet with its text drawn into the image.
#include "core/base/error.hpp"
#include "core/scene/sweep.hpp"
#include "core/image/text.hpp"

#include <gtest/gtest.h>

using namespace shadelab;

namespace {
std::string errorOf(const std::string& text) {
    try {
        parseSweep(text, "--sweep");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}
}  // namespace

TEST(Sweep, ParsesNumbersAndNames) {
    const Sweep ke = parseSweep("ke=1,8,32,128,512", "--sweep");
    EXPECT_EQ(ke.parameter, "ke");
    EXPECT_EQ(ke.values, (std::vector<std::string>{"1", "8", "32", "128", "512"}));
    EXPECT_EQ(parseSweep("shading=flat,phong", "--sweep").values.size(), 2u);
    EXPECT_EQ(sweepLabel(ke, 2), "k_e=32");
    EXPECT_EQ(sweepLabel(parseSweep("shading=flat,phong", "--sweep"), 1), "shading=phong");
}

TEST(Sweep, BadSpecsNameTheFlagAndTheValue) {
    EXPECT_NE(errorOf("ke").find("--sweep: expected PARAMETER=V1,V2"), std::string::npos);
    EXPECT_NE(errorOf("shininess=1,2").find("--sweep: unknown parameter \"shininess\""), std::string::npos);
    EXPECT_NE(errorOf("ke=1,x").find("--sweep: ke: \"x\" is not a number"), std::string::npos);
    EXPECT_NE(errorOf("ke=0,8").find("--sweep: ke: 0 is out of range"), std::string::npos);
    EXPECT_NE(errorOf("ke=1,").find("--sweep: ke: empty value"), std::string::npos);
    EXPECT_NE(errorOf("ke=").find("--sweep: ke: empty value"), std::string::npos);
    EXPECT_NE(errorOf("ke=inf").find("is not a number"), std::string::npos);
    EXPECT_NE(errorOf("tessellation=8.5").find("is not an integer"), std::string::npos);
    EXPECT_NE(errorOf("shading=toon").find("--sweep: shading: unknown value \"toon\""), std::string::npos);
    std::string many = "ks=0";
    for (int i = 0; i < 40; ++i) many += ",0";
    EXPECT_NE(errorOf(many).find("at most 32 values"), std::string::npos);
}

TEST(Sweep, AppliesEachParameter) {
    Scene s;
    s.objects.resize(2);
    s.lights.resize(2);
    applySweep(s, parseSweep("ke=7", "f"), 0, "f");
    applySweep(s, parseSweep("ks=0.25", "f"), 0, "f");
    applySweep(s, parseSweep("intensity=0.5,3", "f"), 1, "f");
    applySweep(s, parseSweep("tessellation=10", "f"), 0, "f");
    applySweep(s, parseSweep("shading=gouraud", "f"), 0, "f");
    applySweep(s, parseSweep("fresnel=exact", "f"), 0, "f");
    for (const SceneObject& o : s.objects) {
        EXPECT_EQ(o.material.ke, 7.0f);
        EXPECT_EQ(o.material.ks, 0.25f);
    }
    for (const Light& l : s.lights) EXPECT_EQ(l.intensity, 3.0f);
    EXPECT_EQ(s.objects[0].mesh.slices, 10);
    EXPECT_EQ(s.objects[0].mesh.stacks, 5);
    EXPECT_EQ(s.shading, ShadingMode::Gouraud);
    EXPECT_EQ(s.fresnel, FresnelMode::Exact);
    s.objects[0].mesh.type = MeshSpec::Type::Cube;
    EXPECT_THROW(applySweep(s, parseSweep("tessellation=10", "f"), 0, "f"), InputError);
}

TEST(Sweep, ContactSheetPlacesTilesAndDrawsLabels) {
    std::vector<Image> tiles(6, Image(40, 30));
    for (Image& t : tiles)
        for (std::size_t i = 0; i < t.rgba.size(); i += 4) t.rgba[i] = 200;  // red tiles
    const Image sheet = contactSheet(tiles, {"a", "b", "c", "d", "e", "f"}, 3);
    const int bar = textHeight("Ag", kSheetLabelScale) + 10;
    EXPECT_EQ(sheet.width, 3 * 40 + 4 * 4);
    EXPECT_EQ(sheet.height, 2 * (30 + bar) + 3 * 4);
    // The last tile's bottom-right pixel is red; its label bar has white text on grey.
    const std::uint8_t* p = sheet.pixel(4 + 2 * 44 + 39, 4 + (30 + bar + 4) + bar + 29);
    EXPECT_EQ(p[0], 200);
    int white = 0;
    for (int y = 0; y < bar; ++y)
        for (int x = 0; x < 40; ++x) white += sheet.pixel(4 + x, 4 + y)[1] > 200;
    EXPECT_GT(white, 4) << "no label drawn";
}

TEST(Text, DrawsInsideTheImageOnly) {
    Image img(30, 20);
    drawText(img, 2, 2, "k_e=8", 1, Rgba8{255, 255, 255, 255});
    int lit = 0;
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 30; ++x) lit += img.pixel(x, y)[0] == 255;
    EXPECT_GT(lit, 10);
    EXPECT_EQ(textWidth("k_e=8", 2), 2 * textWidth("k_e=8", 1));
    drawText(img, 25, 15, "clipped at the edge", 3, Rgba8{});  // must not write outside
}

// A title in any UTF-8, with DEL and control bytes, draws as '?' for each character the bitmap font
// lacks (it read out of bounds before: UBSan in CI catches a regression).
TEST(Text, AnyUtf8IsDrawnWithReplacementMarks) {
    Image a(120, 20), b(120, 20);
    drawText(a, 1, 1, "\xce\xb8_i \x7f\x01\xe2\x86\x92 \xff", 1, Rgba8{255, 255, 255, 255});
    drawText(b, 1, 1, "?_i ??? ?", 1, Rgba8{255, 255, 255, 255});
    EXPECT_EQ(a.rgba, b.rgba);
    EXPECT_EQ(textWidth("\xce\xb8\x7f", 1), textWidth("??", 1));
}
