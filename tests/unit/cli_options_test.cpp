#include "options/options.hpp"
#include "core/base/error.hpp"
#include "core/scene/scene_json.hpp"
#include "core/ui/controls.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

using namespace shadelab;

namespace {
std::string errorOf(const std::vector<std::string>& args) {
    try {
        parseOptions(args);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}
}  // namespace

TEST(CliOptions, ParsesEveryOption) {
    const Options o = parseOptions({"scene.json", "--output", "x.png", "--shading", "flat", "--layout=compare",
                                    "--reflection", "phong", "--ka", "0.2", "--kd", "0.3", "--ks", "0.4", "--ke",
                                    "128", "--size", "640x480", "--mesh", "icosphere:1", "--shader-dir", "s", "-v"});
    EXPECT_EQ(o.input, "scene.json");
    EXPECT_EQ(*o.output, "x.png");
    EXPECT_EQ(*o.shading, ShadingMode::Flat);
    EXPECT_EQ(*o.layout, Layout::Compare);
    EXPECT_EQ(*o.reflection, ReflectionModel::Phong);
    EXPECT_FLOAT_EQ(*o.ka, 0.2f);
    EXPECT_FLOAT_EQ(*o.ke, 128.0f);
    EXPECT_EQ(*o.width, 640);
    EXPECT_EQ(*o.height, 480);
    EXPECT_EQ(o.mesh->type, MeshSpec::Type::IcoSphere);
    EXPECT_EQ(o.shaderDir, "s");
    EXPECT_TRUE(o.verbose);
    EXPECT_EQ(parseOptions({"--benchmark", "100"}).benchmarkFrames, 100);
    EXPECT_EQ(parseOptions({"--benchmark", "5", "--progressive", "8"}).progressiveStride, 8);
    EXPECT_EQ(parseOptions({"--progressive", "16"}).progressiveStride, 16);
    EXPECT_EQ(parseOptions({}).progressiveStride, 0);  // the viewer adapts
}

TEST(CliOptions, LectureFlags) {
    const Options o = parseOptions({"--layout", "diff", "--diff", "flat,phong", "--diff-factor", "8",
                                    "--specular-normalization", "energy", "--fresnel=schlick", "--ior", "1.33",
                                    "--show", "specular"});
    EXPECT_EQ(*o.layout, Layout::Diff);
    EXPECT_EQ(*o.diffA, ShadingMode::Flat);
    EXPECT_EQ(*o.diffB, ShadingMode::Phong);
    EXPECT_FLOAT_EQ(*o.diffFactor, 8.0f);
    EXPECT_EQ(*o.specularNormalization, SpecularNormalization::Energy);
    EXPECT_EQ(*o.fresnel, FresnelMode::Schlick);
    EXPECT_FLOAT_EQ(*o.ior, 1.33f);
    EXPECT_EQ(o.show->term, ShowTerm::Specular);
    EXPECT_EQ(parseOptions({"--show", "light:3"}).show->light, 3);
    EXPECT_NE(errorOf({"--diff", "flat"}).find("--diff: expected two shading modes"), std::string::npos);
    EXPECT_NE(errorOf({"--diff", "flat,toon"}).find("--diff: unknown value \"toon\""), std::string::npos);
    EXPECT_NE(errorOf({"--diff-factor", "0"}).find("--diff-factor: must be between 1 and 1000"), std::string::npos);
    EXPECT_NE(errorOf({"--ior", "0.1"}).find("--ior: must be between 0.2 and 10"), std::string::npos);
    EXPECT_NE(errorOf({"--fresnel", "fast"}).find("--fresnel: unknown value"), std::string::npos);
    EXPECT_NE(errorOf({"--specular-normalization", "yes"}).find("--specular-normalization: unknown value"),
              std::string::npos);
    EXPECT_NE(errorOf({"--show", "glow"}).find("--show: unknown value \"glow\""), std::string::npos);
    EXPECT_NE(errorOf({"--show", "light:-1"}).find("--show: \"-1\" is not a light index"), std::string::npos);
    // A light that does not exist is found once the scene is known.
    Options missing = parseOptions({"--show", "light:2"});
    try {
        sceneFromOptions(missing);
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("--show: light 2 does not exist"), std::string::npos) << e.what();
    }
}

TEST(CliOptions, BadFlagsNameTheFlag) {
    EXPECT_NE(errorOf({"--frobnicate"}).find("--frobnicate: unknown option"), std::string::npos);
    EXPECT_NE(errorOf({"--ka"}).find("--ka: needs a value"), std::string::npos);
    EXPECT_NE(errorOf({"--ka", "abc"}).find("--ka: \"abc\" is not a number"), std::string::npos);
    EXPECT_NE(errorOf({"--ke", "nan"}).find("--ke"), std::string::npos);
    EXPECT_NE(errorOf({"--shading", "toon"}).find("--shading: unknown value \"toon\""), std::string::npos);
    EXPECT_NE(errorOf({"--size", "640"}).find("--size: expected WIDTHxHEIGHT"), std::string::npos);
    EXPECT_NE(errorOf({"--size", "0x480"}).find("--size"), std::string::npos);
    EXPECT_NE(errorOf({"--size", "100000x100000"}).find("16384"), std::string::npos);
    EXPECT_NE(errorOf({"--benchmark", "0"}).find("--benchmark"), std::string::npos);
    EXPECT_NE(errorOf({"a.json", "b.json"}).find("only one"), std::string::npos);
    EXPECT_NE(errorOf({"--output", "x.jpg"}).find(".png"), std::string::npos);
    EXPECT_NE(errorOf({"--help=yes"}).find("takes no value"), std::string::npos);
}

TEST(CliOptions, Probe) {
    const Options o = parseOptions({"--probe", "12,34", "--output", "x.png", "--layout", "compare"});
    ASSERT_TRUE(o.probe);
    EXPECT_EQ(*o.probe, glm::ivec2(12, 34));
    EXPECT_EQ(parseOptions({"--probe=0,0"}).probe, glm::ivec2(0, 0));  // the viewer's
    EXPECT_NE(errorOf({"--probe", "12"}).find("--probe: expected the pixel as X,Y"), std::string::npos);
    EXPECT_NE(errorOf({"--probe", "1,x"}).find("--probe: \"x\" is not an integer"), std::string::npos);
    EXPECT_NE(errorOf({"--probe", "-1,0"}).find("--probe: -1 is out of range"), std::string::npos);
    EXPECT_NE(errorOf({"--probe", "1,1", "--benchmark", "3"}).find("not with --benchmark"), std::string::npos);
    EXPECT_NE(errorOf({"--probe", "1,1", "--info"}).find("not with --info"), std::string::npos);
    EXPECT_NE(errorOf({"--select-light", "16"}).find("--select-light: 16 is out of range"), std::string::npos);
    // A light that does not exist is found once the scene is known (the default scene has one).
    try {
        sceneFromOptions(parseOptions({"--select-light", "1"}));
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("--select-light: light 1 does not exist"), std::string::npos) << e.what();
    }
}

TEST(CliOptions, OverridesApplyToTheScene) {
    Options o = parseOptions({"--ka", "0.5", "--shading", "gouraud", "--mesh", "cube", "--size", "10x20"});
    const Scene s = sceneFromOptions(o);
    EXPECT_FLOAT_EQ(s.objects[0].material.ka, 0.5f);
    EXPECT_EQ(s.shading, ShadingMode::Gouraud);
    EXPECT_EQ(s.objects[0].mesh.type, MeshSpec::Type::Cube);
    EXPECT_EQ(s.width, 10);
    EXPECT_EQ(s.height, 20);
}

TEST(CliOptions, NegativeCoefficientIsRefused) {
    const Options o = parseOptions({"--kd", "-1"});
    try {
        sceneFromOptions(o);
        ADD_FAILURE();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("--kd"), std::string::npos) << e.what();
    }
    EXPECT_THROW(sceneFromOptions(parseOptions({"--ke", "0"})), InputError);
}

// Issue 5: --light (repeatable) and --shadows.
TEST(CliOptions, LightsAndShadows) {
    const Options o = parseOptions({"--light", "point:1,2,3:intensity=9:attenuation=inverse-square:range=12",
                                    "--light=directional:0,-1,-0.5:color=1,0.9,0.8",
                                    "--light", "area:0,3,0:normal=0,-1,0.1:size=1.6,0.8:samples=8x4:two-sided",
                                    "--shadows"});
    ASSERT_EQ(o.lights.size(), 3u);
    EXPECT_EQ(o.lights[0].type, LightType::Point);
    EXPECT_EQ(o.lights[0].position, glm::vec3(1, 2, 3));
    EXPECT_FLOAT_EQ(o.lights[0].intensity, 9.0f);
    EXPECT_EQ(o.lights[0].attenuation, Attenuation::InverseSquare);
    EXPECT_FLOAT_EQ(o.lights[0].range, 12.0f);
    EXPECT_EQ(o.lights[1].type, LightType::Directional);
    EXPECT_EQ(o.lights[1].direction, glm::vec3(0, -1, -0.5f));
    EXPECT_EQ(o.lights[1].color, glm::vec3(1, 0.9f, 0.8f));
    EXPECT_EQ(o.lights[2].type, LightType::Area);
    EXPECT_EQ(o.lights[2].normal, glm::vec3(0, -1, 0.1f));
    EXPECT_EQ(o.lights[2].size, glm::vec2(1.6f, 0.8f));
    EXPECT_EQ(o.lights[2].samples, glm::ivec2(8, 4));
    EXPECT_TRUE(o.lights[2].twoSided);
    EXPECT_TRUE(*o.shadows);
    EXPECT_FALSE(*parseOptions({"--no-shadows"}).shadows);
    EXPECT_FALSE(parseOptions({}).shadows.has_value());
}

TEST(CliOptions, BadLightsNameTheFlagAndTheKey) {
    EXPECT_NE(errorOf({"--light", "torch:1,2,3"}).find("--light: unknown light type \"torch\" (expected point, directional, area or spot)"), std::string::npos);
    EXPECT_NE(errorOf({"--light", "point"}).find("--light: expected TYPE:X,Y,Z"), std::string::npos);
    EXPECT_NE(errorOf({"--light", "point:1,2"}).find("point: expected 3 numbers"), std::string::npos);
    EXPECT_NE(errorOf({"--light", "point:1,2,x"}).find("\"x\" is not a number"), std::string::npos);
    EXPECT_NE(errorOf({"--light", "point:1,2,3:intensity=-1"}).find("intensity: -1 is out of range"), std::string::npos);
    EXPECT_NE(errorOf({"--light", "point:1,2,3:samples=4x4"}).find("unknown key \"samples\" for a point light"),
              std::string::npos);
    EXPECT_NE(errorOf({"--light", "area:0,3,0:samples=0x4"}).find("samples: 0 is out of range"), std::string::npos);
    EXPECT_NE(errorOf({"--light", "area:0,3,0:samples=2.5x4"}).find("samples: expected NXxNY integers"),
              std::string::npos);
    EXPECT_NE(errorOf({"--light", "point:1,2,3:range=5"}).find("range needs attenuation=inverse-square"),
              std::string::npos);
    EXPECT_NE(errorOf({"--light", "directional:0,0,0"}).find("zero-length"), std::string::npos);
    EXPECT_NE(errorOf({"--light", "point:1,2,3:color=2,0,0"}).find("color: 2 is out of range"), std::string::npos);
    EXPECT_NE(errorOf({"--shadows=1"}).find("--shadows: takes no value"), std::string::npos);
    std::vector<std::string> many;
    for (int i = 0; i < 17; ++i) many.insert(many.end(), {"--light", "point:0,1,0"});
    EXPECT_NE(errorOf(many).find("--light: at most 16 lights"), std::string::npos);
}

TEST(CliOptions, Plots) {
    const Options o = parseOptions({"--plot", "fresnel", "--from-inside", "--incidence", "60", "--output", "f.png"});
    EXPECT_EQ(o.plot, PlotKind::Fresnel);
    EXPECT_TRUE(o.fromInside);
    EXPECT_FLOAT_EQ(*o.incidenceDeg, 60.0f);
    EXPECT_FLOAT_EQ(plotSettings(o).incidenceDeg, 60.0f);
    EXPECT_TRUE(plotSettings(o).fromInside);
    EXPECT_FLOAT_EQ(plotSettings(parseOptions({})).incidenceDeg, 45.0f);  // the default
    EXPECT_EQ(parseOptions({"--plot=lobe", "-o", "l.png", "--size", "320x240"}).plot, PlotKind::Lobe);
    EXPECT_EQ(parseOptions({"--plot", "lobe3d", "-o", "l.png"}).plot, PlotKind::Lobe3d);
    EXPECT_EQ(parseOptions({"--plot", "brdf-slice", "-o", "b.png", "--anisotropy", "8,64"}).plot, PlotKind::BrdfSlice);
    EXPECT_NE(errorOf({"--plot", "brdf", "-o", "x.png"}).find("(expected one of lobe, fresnel, lobe3d, brdf-slice)"), std::string::npos);
    // The viewer's Plots section takes them too (no --output there).
    EXPECT_FLOAT_EQ(*parseOptions({"--incidence", "0"}).incidenceDeg, 0.0f);

    EXPECT_NE(errorOf({"--plot", "lobe"}).find("--plot: writes a PNG: give --output FILE.png"), std::string::npos);
    EXPECT_NE(errorOf({"--plot", "polar", "-o", "x.png"}).find("--plot: unknown value \"polar\""), std::string::npos);
    EXPECT_NE(errorOf({"--plot", "lobe", "-o", "x.png", "--benchmark", "3"}).find("not with --sweep or --benchmark"),
              std::string::npos);
    EXPECT_NE(errorOf({"--plot", "lobe", "-o", "x.png", "--size", "319x240"}).find("--size: a plot is 320x240"),
              std::string::npos);
    EXPECT_NE(errorOf({"--plot", "lobe", "-o", "x.png", "--size", "4097x300"}).find("to 4096x4096"), std::string::npos);
    EXPECT_NE(errorOf({"--incidence", "89.5"}).find("--incidence: must be between 0 and 89"), std::string::npos);
    EXPECT_NE(errorOf({"--incidence", "x"}).find("--incidence: \"x\" is not a number"), std::string::npos);
    EXPECT_NE(errorOf({"--from-inside=1"}).find("--from-inside: takes no value"), std::string::npos);
    EXPECT_NE(errorOf({"--incidence", "30", "-o", "x.png"}).find("--incidence: sets up the plots"), std::string::npos);
}

TEST(CliOptions, PlaylistFlags) {
    const Options o = parseOptions({"--playlist", "lecture", "--output", "handout/", "--captions", "--size", "640x360",
                                    "--shading=gouraud"});
    EXPECT_EQ(o.playlist.value_or(""), "lecture");
    EXPECT_EQ(o.output.value_or(""), "handout/");  // a folder: no .png needed
    EXPECT_TRUE(o.captions);
    EXPECT_TRUE(parseOptions({"--playlist", "lecture", "--frames", "3"}).playlist.has_value());  // the viewer
    EXPECT_NE(errorOf({"scene.json", "--playlist", "lecture"}).find("--playlist: "), std::string::npos);
    EXPECT_NE(errorOf({"--playlist", "lecture", "--sweep", "ke=1,2", "--output", "d/"}).find("--sweep: not with --playlist"),
              std::string::npos);
    EXPECT_NE(errorOf({"--playlist", "lecture", "--benchmark", "3"}).find("--benchmark: not with --playlist"),
              std::string::npos);
    EXPECT_NE(errorOf({"--playlist", "lecture", "--info"}).find("--info: not with --playlist"), std::string::npos);
    // --animate plays on every preset in the viewer (issue 31, item 9); a video is of one preset file.
    EXPECT_EQ(parseOptions({"--playlist", "lecture", "--animate", "ke=1..1000:log"}).animations.size(), 1u);
    EXPECT_NE(errorOf({"--playlist", "lecture", "--animate", "light-orbit", "--output", "d/"})
                  .find("--animate: with --playlist the viewer plays it on every preset"),
              std::string::npos);
    EXPECT_NE(errorOf({"--playlist", "lecture", "--animate", "light-orbit", "--sweep", "ke=1,2"}).find("--sweep"),
              std::string::npos);
    EXPECT_NE(errorOf({"--playlist", ""}).find("--playlist: empty folder name"), std::string::npos);
    EXPECT_NE(errorOf({"--playlist"}).find("--playlist: needs a value"), std::string::npos);
    EXPECT_NE(errorOf({"--captions"}).find("--captions: "), std::string::npos);
    EXPECT_NE(errorOf({"--captions=yes", "--output", "x.png"}).find("--captions: takes no value"), std::string::npos);
    EXPECT_NE(errorOf({"--output", "x.png", "--sweep", "ke=1,2", "--captions"}).find("--captions: "), std::string::npos);
    EXPECT_NO_THROW(parseOptions({"scene.json", "--output", "x.png", "--captions"}));
    EXPECT_NE(errorOf({"--output", "dir/"}).find("only .png output"), std::string::npos);  // a folder only with --playlist
}

// Issue 19: --test DIR and its settings; the thresholds and the scene overrides go with it, the one-image
// options do not, and its own settings need it (the whole refusals: tests/bad-inputs/cases.txt).
TEST(CliOptions, TestSuite) {
    const Options o = parseOptions({"--test", "cases", "--references", "refs", "--junit", "j.xml", "--report",
                                    "r.html", "--update", "--max-diff", "3", "--mean-diff", "0.01", "--size", "64x48",
                                    "--shader-dir", "student", "--backend", "egl"});
    EXPECT_EQ(o.mode, RunMode::TestSuite);
    EXPECT_EQ(o.testDir.value_or(""), "cases");
    EXPECT_EQ(o.referencesDir.value_or(""), "refs");
    EXPECT_EQ(o.junit.value_or(""), "j.xml");
    EXPECT_EQ(o.report.value_or(""), "r.html");
    EXPECT_TRUE(o.update);
    EXPECT_EQ(o.maxDiff.value_or(-1), 3);
    EXPECT_EQ(parseOptions({"--test", "cases"}).mode, RunMode::TestSuite);
    EXPECT_FALSE(parseOptions({"--test", "cases"}).update);
    EXPECT_NE(errorOf({"--test", ""}).find("--test: empty folder name"), std::string::npos);
    EXPECT_NE(errorOf({"--max-diff", "3"}).find("--max-diff: sets up the comparison with a reference: give --reference "
                                                "REF.png (or --test DIR)"),
              std::string::npos);
    for (const char* flag : {"--references", "--junit", "--report"})
        EXPECT_NE(errorOf({flag, "x"}).find(std::string(flag) + ": belongs to a folder of screenshot tests: give --test DIR"),
                  std::string::npos)
            << flag;
    for (const char* other : {"--output", "--reference", "--diff-output", "--probe", "--sweep", "--benchmark", "--plot"}) {
        const std::string value = std::string(other) == "--probe" ? "1,2" : std::string(other) == "--sweep" ? "ke=1,2"
                                  : std::string(other) == "--benchmark" ? "3" : std::string(other) == "--plot" ? "lobe"
                                                                                                   : "x.png";
        EXPECT_NE(errorOf({"--test", "cases", other, value}).find("--test: compares its folder's scenes with their "
                                                                  "references; not with " + std::string(other)),
                  std::string::npos)
            << other << ": " << errorOf({"--test", "cases", other, value});
    }
}

// Issue 19: --reference and its settings, with one --output image (a frame or a plot) and nothing else.
TEST(CliOptions, Reference) {
    const Options o = parseOptions({"--output", "x.png", "--reference", "r.png", "--max-diff", "3", "--mean-diff",
                                    "0.5", "--diff-output", "d.png", "--reference-missing=write"});
    EXPECT_EQ(o.mode, RunMode::Image);
    EXPECT_EQ(o.reference.value_or(""), "r.png");
    EXPECT_EQ(o.maxDiff.value_or(-1), 3);
    EXPECT_FLOAT_EQ(o.meanDiff.value_or(-1), 0.5f);
    EXPECT_EQ(o.diffOutput.value_or(""), "d.png");
    EXPECT_EQ(o.referenceMissing, MissingReference::Write);
    EXPECT_EQ(parseOptions({"--plot", "lobe", "-o", "x.png", "--reference", "r.png"}).mode, RunMode::Plot);
    EXPECT_FALSE(parseOptions({"-o", "x.png", "--reference", "r.png"}).referenceMissing.has_value());  // fail
    EXPECT_NO_THROW(parseOptions({"-o", "x.png", "--reference", "r.png", "--captions", "--layout", "diff"}));

    // Each of its settings needs it; it needs one --output image.
    for (const char* flag : {"--max-diff", "--mean-diff", "--diff-output", "--reference-missing"}) {
        const std::string value = std::string(flag) == "--diff-output" ? "d.png" : std::string(flag) == "--reference-missing" ? "write" : "1";
        EXPECT_NE(errorOf({"-o", "x.png", flag, value}).find(std::string(flag) + ": sets up the comparison with a "
                                                             "reference: give --reference REF.png"),
                  std::string::npos)
            << flag;
    }
    EXPECT_NE(errorOf({"--reference", "r.png"}).find("--reference: compares the --output image with it: give --output"),
              std::string::npos);
    const std::vector<std::vector<std::string>> others = {
        {"--sweep", "ke=1,2", "-o", "x.png"}, {"--probe", "1,2", "-o", "x.png"}, {"--benchmark", "3"},
        {"--info", "-o", "x.png"}, {"--playlist", "lecture", "-o", "out/"}};
    for (std::vector<std::string> args : others) {
        const std::string flag = args[0];
        args.insert(args.end(), {"--reference", "r.png"});
        EXPECT_NE(errorOf(args).find("--reference: compares one --output image (a frame or a --plot); not with " + flag),
                  std::string::npos)
            << flag << ": " << errorOf(args);
    }
    EXPECT_NE(errorOf({"-o", "x.png", "--reference", "r.jpg"}).find("--reference: r.jpg: only .png references"),
              std::string::npos);
    EXPECT_NE(errorOf({"-o", "x.png", "--reference", "r.png", "--diff-output", "d"}).find("--diff-output: d: only .png"),
              std::string::npos);
    EXPECT_NE(errorOf({"-o", "x.png", "--reference", "r.png", "--max-diff", "256"}).find("--max-diff: 256 is out of range (0..255)"),
              std::string::npos);
    EXPECT_NE(errorOf({"-o", "x.png", "--reference", "r.png", "--max-diff", "1.5"}).find("--max-diff: \"1.5\" is not an integer"),
              std::string::npos);
    EXPECT_NE(errorOf({"-o", "x.png", "--reference", "r.png", "--mean-diff", "-1"}).find("--mean-diff: must be between 0 and 255 (got -1)"),
              std::string::npos);
    EXPECT_NE(errorOf({"-o", "x.png", "--reference", "r.png", "--reference-missing", "create"})
                  .find("--reference-missing: unknown value \"create\" (expected one of fail, write)"),
              std::string::npos);
    // --help gives the defaults, from core/image/image.hpp (ImageTolerance).
    const std::string help = usage();
    EXPECT_NE(help.find("(0..255, default " + std::to_string(ImageTolerance{}.maxDiff) + ")"), std::string::npos) << help;
    EXPECT_NE(help.find("default 0.002)"), std::string::npos) << help;
}

// The overrides a playlist applies to each preset are the ones a scene file gets.
TEST(CliOptions, OverridesApplyToAnyScene) {
    const Options o = parseOptions({"--size", "96x54", "--shading", "flat", "--ke", "7", "--no-shadows"});
    Scene s;
    s.objects.resize(2);
    s.shadows.enabled = true;
    applyOverrides(s, o);
    EXPECT_EQ(s.width, 96);
    EXPECT_EQ(s.height, 54);
    EXPECT_EQ(s.shading, ShadingMode::Flat);
    EXPECT_FLOAT_EQ(s.objects[0].material.ke, 7.0f);
    EXPECT_FLOAT_EQ(s.objects[1].material.ke, 7.0f);
    EXPECT_FALSE(s.shadows.enabled);
    s.lights.clear();
    EXPECT_THROW(applyOverrides(s, parseOptions({"--show", "light:0"})), InputError);
}

// Issue 17: the run mode is decided once, by the parser.
TEST(CliOptions, RunModeIsDecidedOnce) {
    EXPECT_EQ(parseOptions({}).mode, RunMode::Viewer);
    EXPECT_EQ(parseOptions({"--help", "--output", "x.png"}).mode, RunMode::Help);
    EXPECT_EQ(parseOptions({"--version"}).mode, RunMode::Version);
    EXPECT_EQ(parseOptions({"--output", "x.png"}).mode, RunMode::Image);
    EXPECT_EQ(parseOptions({"--output", "x.png", "--info"}).mode, RunMode::Info);
    EXPECT_EQ(parseOptions({"--output", "x.png", "--benchmark", "3"}).mode, RunMode::Benchmark);
    EXPECT_EQ(parseOptions({"--benchmark", "3"}).mode, RunMode::Benchmark);
    EXPECT_EQ(parseOptions({"--output", "x.png", "--sweep", "ke=1,2"}).mode, RunMode::SweepSheet);
    EXPECT_EQ(parseOptions({"--output", "x.png", "--probe", "1,2"}).mode, RunMode::ProbeImage);
    EXPECT_EQ(parseOptions({"--probe", "1,2"}).mode, RunMode::Viewer);
    EXPECT_EQ(parseOptions({"--output", "x.png", "--plot", "lobe"}).mode, RunMode::Plot);
    EXPECT_EQ(parseOptions({"--output", "x.png", "--plot", "lobe", "--info"}).mode, RunMode::Info);
    EXPECT_EQ(parseOptions({"--playlist", "dir"}).mode, RunMode::PlaylistViewer);
    EXPECT_EQ(parseOptions({"--playlist", "dir", "--output", "out/"}).mode, RunMode::PlaylistImages);
}

// Issue 17: the messages print the ranges of core/scene/scene_limits.hpp, which --help prints too.
TEST(CliOptions, TableRangesInMessagesAndHelp) {
    EXPECT_NE(errorOf({"--ui-scale", "5"}).find("--ui-scale: must be between 0.75 and 4 (got 5)"), std::string::npos);
    EXPECT_NE(errorOf({"--incidence", "90"}).find("--incidence: must be between 0 and 89 degrees (got 90)"),
              std::string::npos);
    EXPECT_NE(errorOf({"--benchmark", "0"}).find("--benchmark: 0 is out of range (1..1000000)"), std::string::npos);
    EXPECT_NE(errorOf({"--progressive", "17"}).find("--progressive: 17 is out of range (1..16)"), std::string::npos);
    EXPECT_NE(errorOf({"--msaa", "3"}).find("--msaa: unknown value \"3\" (expected one of 0, 1, 2, 4, 8)"),
              std::string::npos);
    EXPECT_NE(errorOf({"--overlays", "grid"}).find("--overlays: unknown value \"grid\" (expected one of wireframe"),
              std::string::npos);
    EXPECT_NE(errorOf({"--panel-sections", "x"}).find("--panel-sections: unknown section \"x\" (expected some of shading"),
              std::string::npos);
    EXPECT_NE(errorOf({"-o", "x.png", "--frames", "3"}).find("--output: --frames, --screenshot"), std::string::npos);
    const std::string help = usage();
    EXPECT_NE(help.find("refraction (0.2..10, default 1.5)"),
              std::string::npos)
        << help;
    EXPECT_NE(help.find("--ui-scale S"), std::string::npos);
    EXPECT_EQ(help.find('`'), std::string::npos);  // the README's code marks stay in the README
}

// Issue 17: the README's option table is the option table (SHADELAB_UPDATE_README=1 rewrites it).
TEST(CliOptions, ReadmeOptionTableIsTheTable) {
    const std::string path = std::string(SHADELAB_SOURCE_DIR) + "/README.md";
    std::ifstream in(path);
    ASSERT_TRUE(in) << path;
    std::stringstream text;
    text << in.rdbuf();
    std::string readme = text.str();
    const std::string begin = "<!-- options: generated from app/options/option_table.cpp (tests/unit/cli_options_test.cpp) -->\n";
    const std::string end = "<!-- end of options -->";
    const std::size_t from = readme.find(begin), to = readme.find(end);
    ASSERT_NE(from, std::string::npos) << "README.md has no line " << begin;
    ASSERT_NE(to, std::string::npos) << "README.md has no line " << end;
    const std::string table = readme.substr(from + begin.size(), to - from - begin.size());
    if (table != optionsMarkdown() && std::getenv("SHADELAB_UPDATE_README")) {
        readme.replace(from + begin.size(), to - from - begin.size(), optionsMarkdown());
        std::ofstream(path) << readme;
        return;
    }
    EXPECT_EQ(table, optionsMarkdown()) << "README.md's option table differs from the option table: run "
                                           "SHADELAB_UPDATE_README=1 build/tests/unit_tests "
                                           "--gtest_filter=CliOptions.ReadmeOptionTableIsTheTable";
}

TEST(CliOptions, AnimateWritesAVideoOfSeveralAnimations) {
    const Options o = parseOptions({"--animate", "ke=1..1000:log", "--animate", "camera-orbit:8", "--output", "a.webm",
                                    "--fps", "24", "--duration", "2.5"});
    EXPECT_EQ(o.mode, RunMode::Video);
    ASSERT_EQ(o.animations.size(), 2u);
    EXPECT_EQ(o.animations[1].kind, Animation::Kind::CameraOrbit);
    EXPECT_EQ(o.fps, 24);
    EXPECT_EQ(o.duration, 2.5);
    EXPECT_EQ(parseOptions({"--animate", "light-orbit", "--output", "A.GIF", "--dither"}).mode, RunMode::Video);
    // Without --output the viewer plays it; a video's settings and a mesh rebuilt every frame are refused.
    EXPECT_EQ(parseOptions({"--animate", "light-orbit"}).mode, RunMode::Viewer);
    EXPECT_NE(errorOf({"--animate", "light-orbit", "--fps", "24"}).find("--fps: sets up the video"), std::string::npos);
    EXPECT_NE(errorOf({"--animate", "tessellation=8..64"}).find("a tessellation ramp is for videos"), std::string::npos);
    EXPECT_NE(errorOf({"--animate", "light-orbit", "--output", "a.png"}).find("--animate: writes a video"),
              std::string::npos);
}

// The viewer's key table (core/ui/controls.hpp): the viewer acts on its bindings, and --help, F1 and
// the panel's Keys section print its rows. Each key does one thing and every command has a key.
TEST(Controls, EveryCommandHasAKeyAndNoKeyTwoCommands) {
    std::set<int> commands;
    std::set<std::pair<int, bool>> keys;  // (key, Ctrl held)
    std::set<char> characters;
    for (const Control& c : kControls)
        for (const KeyBinding& b : c.keys) {
            if (b.command == ViewerCommand::None) {
                EXPECT_TRUE(b.characters == nullptr && b.key == ViewerKey::None) << c.input;
                continue;
            }
            commands.insert(int(b.command));
            EXPECT_TRUE((b.characters != nullptr) != (b.key != ViewerKey::None)) << c.input << ": a character or a key";
            for (const char* ch = b.characters; ch && *ch; ++ch) EXPECT_TRUE(characters.insert(*ch).second) << c.input << ": " << *ch;
            for (const bool ctrl : {false, true}) {
                if (b.key == ViewerKey::None || (b.mods != KeyMods::Any && (b.mods == KeyMods::Ctrl) != ctrl)) continue;
                EXPECT_TRUE(keys.insert({int(b.key), ctrl}).second) << c.input;
            }
        }
    for (int command = int(ViewerCommand::None) + 1; command <= int(ViewerCommand::Quit); ++command)
        EXPECT_EQ(commands.count(command), 1u) << "command " << command << " has no key";
    // The lookups: letters as typed, Ctrl only where a key asks for it, Page Down with or without it.
    EXPECT_EQ(characterBinding('N')->command, ViewerCommand::FaceNormals);
    EXPECT_EQ(characterBinding('n')->command, ViewerCommand::VertexNormals);
    EXPECT_EQ(characterBinding('x'), nullptr);
    EXPECT_EQ(keyBinding(ViewerKey::Q, true)->command, ViewerCommand::Quit);
    EXPECT_EQ(keyBinding(ViewerKey::Q, false), nullptr);
    EXPECT_EQ(keyBinding(ViewerKey::F5, true), nullptr);
    EXPECT_EQ(keyBinding(ViewerKey::PageDown, true)->command, ViewerCommand::NextPreset);
    EXPECT_EQ(keyBinding(ViewerKey::PageDown, false)->focus, KeyFocus::UnlessTyping);
}

// --output-encoding sets the scene's output_encoding as the field does, so a glTF scene keeps it
// (frameIfNeeded's sRGB default applies only where neither says).
TEST(CliOptions, OutputEncodingIsTheScenesField) {
    Scene s;
    applyOverrides(s, parseOptions({"--output-encoding", "linear"}));
    EXPECT_EQ(s.outputEncoding, OutputEncoding::Linear);
    EXPECT_TRUE(s.outputEncodingGiven);
    applyOverrides(s, parseOptions({"--output-encoding=srgb"}));
    EXPECT_EQ(s.outputEncoding, OutputEncoding::Srgb);
    Scene untouched;
    applyOverrides(untouched, parseOptions({}));
    EXPECT_FALSE(untouched.outputEncodingGiven);
    EXPECT_NE(errorOf({"--output-encoding", "gamma"}).find("--output-encoding: unknown value \"gamma\""), std::string::npos);
}

// The colours a scene file sets (C, S, A, background) as options too: the web page's panel is a
// command line, and a sweep or a CI scene can set them without a file.
TEST(CliOptions, ColoursAreTheScenesFields) {
    Scene s = defaultScene();
    s.objects.push_back(s.objects.front());
    applyOverrides(s, parseOptions({"--color", "1,0.5,0", "--specular-color", "0,0,1", "--ambient", "0.2,0.3,0.4",
                                    "--background", "1,1,1"}));
    for (const SceneObject& o : s.objects) {
        EXPECT_EQ(o.material.color, glm::vec3(1.0f, 0.5f, 0.0f));
        EXPECT_TRUE(o.material.colorSet);  // so it also replaces a glTF model's base colours
        EXPECT_EQ(o.material.specularColor, glm::vec3(0.0f, 0.0f, 1.0f));
    }
    EXPECT_EQ(s.ambient, glm::vec3(0.2f, 0.3f, 0.4f));
    EXPECT_EQ(s.background, glm::vec3(1.0f));
    Scene untouched = defaultScene();
    const Scene before = untouched;
    applyOverrides(untouched, parseOptions({}));
    EXPECT_EQ(untouched.objects.front().material.color, before.objects.front().material.color);
    EXPECT_EQ(untouched.background, before.background);
    EXPECT_EQ(errorOf({"--color", "1,2,0"}), "--color: must be between 0 and 1 (got 2)");
    EXPECT_EQ(errorOf({"--ambient", "1,0"}), "--ambient: expected R,G,B, three numbers between 0 and 1 (got \"1,0\")");
    EXPECT_EQ(errorOf({"--background", "1,0,0,"}),
              "--background: expected R,G,B, three numbers between 0 and 1 (got \"1,0,0,\")");
    EXPECT_EQ(errorOf({"--specular-color", "red"}), "--specular-color: \"red\" is not a number");
}
