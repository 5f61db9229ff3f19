#include "cli/options.hpp"
#include "core/error.hpp"

#include <gtest/gtest.h>

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
