// The viewer's command-line flags (app/options/options.*).
#include "options/options.hpp"
#include "core/base/error.hpp"
#include "core/scene/panel_sections.hpp"

#include <gtest/gtest.h>

namespace shadelab {
namespace {

TEST(ViewerOptions, ParseWithEveryOtherOption) {
    const Options o = parseOptions({"scene.json", "--layout", "compare", "--frames", "30", "--screenshot", "w.png",
                                    "--screenshot-view=v.png", "--save-scene", "s.json", "--hide-panel", "--overlays",
                                    "wireframe,lights", "--ke", "100", "--size", "640x360"});
    EXPECT_EQ(o.frames, 30);
    EXPECT_EQ(o.screenshot.value_or(""), "w.png");
    EXPECT_EQ(o.screenshotView.value_or(""), "v.png");
    EXPECT_EQ(o.saveScene.value_or(""), "s.json");
    EXPECT_TRUE(o.hidePanel);
    EXPECT_EQ(o.overlays, (std::vector<Overlay>{Overlay::Wireframe, Overlay::LightMarkers}));
    EXPECT_EQ(o.layout, Layout::Compare);
    EXPECT_EQ(o.width, 640);
}

TEST(ViewerOptions, PanelSections) {
    EXPECT_FALSE(parseOptions({}).panelSections.has_value());
    EXPECT_EQ(*parseOptions({"--panel-sections", "plots,shading"}).panelSections,
              (std::vector<std::string>{"plots", "shading"}));
    for (const auto& section : kPanelSections) EXPECT_NO_THROW(parseOptions({"--panel-sections", section.first})) << section.first;
}

TEST(ViewerOptions, RefusesWhatCannotWork) {
    for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
             {"--frames", "0"},
             {"--frames", "x"},
             {"--screenshot", "w.jpg"},
             {"--save-scene", "s.txt"},
             {"--overlays", "wireframe,glow"},
             {"--hide-panel=yes"},
             {"--output", "x.png", "--frames", "3"},
             {"--benchmark", "5", "--screenshot", "w.png"},
             {"--panel-sections", "plots,charts"},
             {"--output", "x.png", "--panel-sections", "plots"}})
        EXPECT_THROW(parseOptions(args), InputError) << args[0] << " " << args.back();
}

}  // namespace
}  // namespace shadelab
