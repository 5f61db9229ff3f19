// The viewer in a real X server: these tests run the shadelab executable under Xvfb (see xvfb_run.sh)
// with --frames/--screenshot*/--save-scene, and check the files it writes. The "3D view" images
// (--screenshot-view) are read from the window's own default framebuffer, after the renderer and
// before ImGui draws, so they are the pixels the lecturer sees under the panel's labels.
#include "core/image/image.hpp"
#include "core/scene/scene.hpp"
#include "core/scene/scene_json.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace shadelab {
namespace {

namespace fs = std::filesystem;

// A folder of its own per test, emptied first, so a stale file never passes a test.
std::string outDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const fs::path dir = fs::path(VIEWER_TEST_OUT) / (std::string(info->test_suite_name()) + "." + info->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir.string();
}

struct RunResult {
    int status = -1;
    std::string output;  // stdout and stderr together
};

// Runs shadelab with `args` (already shell-quoted where needed); `env` prefixes the command.
RunResult shadelab(const std::string& args, const std::string& dir, const std::string& env = "") {
    const std::string log = dir + "/shadelab.log";
    const std::string cmd = env + " '" SHADELAB_EXE "' " + args + " > '" + log + "' 2>&1";
    const int raw = std::system(cmd.c_str());
    RunResult r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    std::ifstream in(log);
    std::stringstream s;
    s << in.rdbuf();
    r.output = s.str();
    return r;
}

std::string scene(const std::string& name) { return std::string("'") + VIEWER_TEST_SCENES + "/" + name + "'"; }

Image crop(const Image& img, int x0, int y0, int w, int h) {
    Image out(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) std::copy_n(img.pixel(x0 + x, y0 + y), 4, out.pixel(x, y));
    return out;
}

// The status strip above the 3D view (frame time, triangles, renderer): 1.5 x the 16-pixel font at
// content and UI scale 1.
constexpr int kStripPixels = 24;

std::size_t distinctColours(const Image& img) {
    std::set<std::uint32_t> colours;
    for (std::size_t i = 0; i + 3 < img.rgba.size(); i += 4)
        colours.insert(std::uint32_t(img.rgba[i]) << 16 | std::uint32_t(img.rgba[i + 1]) << 8 | img.rgba[i + 2]);
    return colours.size();
}

// toleranceWithShare's defaults (core/image/image.hpp). Window and headless renders both come from
// Mesa's llvmpipe, so they are expected to agree exactly; the tolerance only absorbs a driver that
// rounds differently between its GLX and OSMesa paths.
void expectSameImage(const Image& actual, const Image& expected, const std::string& what) {
    const ImageTolerance tolerance = toleranceWithShare(expected.width, expected.height);
    const CompareResult r = tolerance.compare(actual, expected);
    EXPECT_TRUE(tolerance.matches(r)) << what << ": " << describe(r, tolerance);
}

// The window draws a thin separator between compare panes over the 3D view (not in the view's own
// pixels): window and view are compared pane by pane, leaving out 3 columns either side of each of the
// `panes` - 1 boundaries. Returns whether the window has the separator's grey at every boundary.
bool expectSameImageBesideSeparators(const Image& window, const Image& view, int panes, const std::string& what) {
    bool separators = true;
    for (int i = 0; i < panes; ++i) {
        const int x0 = i == 0 ? 0 : i * view.width / panes + 3, x1 = i + 1 == panes ? view.width : (i + 1) * view.width / panes - 3;
        expectSameImage(crop(window, x0, 0, x1 - x0, window.height), crop(view, x0, 0, x1 - x0, view.height),
                        what + ", pane " + std::to_string(i));
        if (i == 0) continue;
        bool found = false;
        for (int x = x0 - 6; x < x0; ++x) {
            const std::uint8_t* p = window.pixel(x, window.height / 2);
            found = found || (p[0] == 150 && p[1] == 150 && p[2] == 160);
        }
        separators = separators && found;
    }
    return separators;
}

TEST(NoDisplay, SaysSoInOneLineAndExits2) {
    const std::string dir = outDir();
    const RunResult r = shadelab("--frames 1", dir, "env -u DISPLAY -u WAYLAND_DISPLAY");
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("no display"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("--output"), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

// The window opens on the default scene, the panel is in the whole-window screenshot beside a 3D view
// of the requested size, and the 3D view shows a lit sphere in each compare pane.
TEST(Window, Opens) {
    const std::string dir = outDir();
    const RunResult r = shadelab("--layout compare --size 960x540 --no-labels --frames 5 --screenshot " + dir + "/window.png" +
                               " --screenshot-view " + dir + "/view.png",
                           dir);
    ASSERT_EQ(r.status, 0) << r.output;
    const Image window = readPng(dir + "/window.png");
    const Image view = readPng(dir + "/view.png");
    // --size is the 3D view's size; the panel gets its own room to the right, the status strip above.
    EXPECT_EQ(view.width, 960);
    EXPECT_EQ(view.height, 540);
    ASSERT_EQ(window.height, 540 + kStripPixels);
    ASSERT_GT(window.width, view.width + 200) << "no room for the panel";

    // The panel: text and widgets give many colours, where an empty strip of background would give one.
    const Image panel = crop(window, view.width, 0, window.width - view.width, window.height);
    EXPECT_GT(distinctColours(panel), 40u) << "the panel is not in the screenshot";
    // Its top-left corner is not the scene's background colour (0.08, 0.08, 0.1) -> (20, 20, 26).
    const std::uint8_t* corner = panel.pixel(4, 4);
    EXPECT_FALSE(corner[0] == 20 && corner[1] == 20 && corner[2] == 26);

    // Each compare pane's centre is on the sphere: lit, reddish, not background.
    for (int pane = 0; pane < 3; ++pane) {
        const std::uint8_t* p = view.pixel(pane * 320 + 160, 270);
        EXPECT_GT(p[0], 60) << "pane " << pane;
        EXPECT_GT(p[0], p[2]) << "pane " << pane;
    }
    // Below the strip and the pane labels, the window shows exactly the 3D view, but for the panes'
    // separators (drawn over the view, not in its pixels).
    EXPECT_TRUE(expectSameImageBesideSeparators(crop(window, 0, kStripPixels + 100, view.width, 300),
                                                crop(view, 0, 100, view.width, 300), 3, "window vs 3D view"))
        << "no separator between the compare panes in the window";
}

// A scene loaded in the window gives the same 3D pixels as the headless --output render of that scene,
// with the panel shown (the view keeps the scene's size) and with it hidden.
TEST(Window, MatchesHeadless) {
    const std::string dir = outDir();
    const RunResult headless = shadelab(scene("compare_torus.json") + " --output " + dir + "/headless.png", dir);
    ASSERT_EQ(headless.status, 0) << headless.output;
    const Image expected = readPng(dir + "/headless.png");

    // --no-labels: the pane labels would take the top of each pane, and framing keeps the model clear of them.
    const RunResult shown =
        shadelab(scene("compare_torus.json") + " --no-labels --frames 3 --screenshot-view " + dir + "/view.png", dir);
    ASSERT_EQ(shown.status, 0) << shown.output;
    expectSameImage(readPng(dir + "/view.png"), expected, "panel shown");

    const RunResult hidden = shadelab(scene("compare_torus.json") + " --hide-panel --no-labels --frames 3 --screenshot-view " + dir +
                                    "/view-hidden.png --screenshot " + dir + "/window-hidden.png",
                                dir);
    ASSERT_EQ(hidden.status, 0) << hidden.output;
    expectSameImage(readPng(dir + "/view-hidden.png"), expected, "panel hidden");
    // With the panel hidden the window is the frame-time strip over the 3D view; below the pane labels
    // it is pixel for pixel the headless image.
    const Image window = readPng(dir + "/window-hidden.png");
    ASSERT_EQ(window.width, expected.width);
    ASSERT_EQ(window.height, expected.height + kStripPixels);
    const int top = 60, rows = expected.height - top;
    EXPECT_TRUE(expectSameImageBesideSeparators(crop(window, 0, kStripPixels + top, window.width, rows),
                                                crop(expected, 0, top, expected.width, rows), 3, "whole window, panel hidden"))
        << "no separator between the compare panes in the window";
}

// --animate in the viewer: a scripted run steps 1/30 s a frame, so its 16th frame shows t = 0.5 s of the
// ramp k_e 1 -> 1000 (log, 1 s): k_e = 1000^0.5 = 31.6227766, the headless frame at that k_e; and the
// first frame is the ramp's start, k_e 1.
TEST(Window, AnimationPlaysTheRamp) {
    const std::string dir = outDir();
    for (const char* ke : {"31.6227766", "1"}) {
        const RunResult headless = shadelab(scene("compare_torus.json") + " --ke " + ke + " --output " + dir + "/ke" + ke + ".png", dir);
        ASSERT_EQ(headless.status, 0) << headless.output;
    }
    const std::string animate = scene("compare_torus.json") + " --no-labels --animate ke=1..1000:log:1 --screenshot-view ";
    const RunResult half = shadelab(animate + dir + "/half.png --frames 16", dir);
    ASSERT_EQ(half.status, 0) << half.output;
    expectSameImage(readPng(dir + "/half.png"), readPng(dir + "/ke31.6227766.png"), "frame 16 (t = 0.5 s)");
    const RunResult first = shadelab(animate + dir + "/first.png --frames 1", dir);
    ASSERT_EQ(first.status, 0) << first.output;
    expectSameImage(readPng(dir + "/first.png"), readPng(dir + "/ke1.png"), "frame 1 (t = 0)");
    const CompareResult apart = compareImages(readPng(dir + "/half.png"), readPng(dir + "/ke1.png"), 8);
    EXPECT_GT(apart.differingPixels, 100u) << "the two times should differ";
}

// An area light refines over frames in the window (progressive sampling, one pass of 16 per frame
// with --progressive 4); the last frame completes it, so the view equals the headless image.
TEST(Window, ProgressiveAreaLightMatchesHeadless) {
    const std::string dir = outDir();
    const RunResult headless = shadelab(scene("area_progressive.json") + " --output " + dir + "/headless.png", dir);
    ASSERT_EQ(headless.status, 0) << headless.output;
    for (const char* stride : {"4", "2"}) {
        const RunResult shown = shadelab(scene("area_progressive.json") + " --frames 3 --progressive " + stride +
                                             " --screenshot-view " + dir + "/view.png",
                                         dir);
        ASSERT_EQ(shown.status, 0) << shown.output;
        expectSameImage(readPng(dir + "/view.png"), readPng(dir + "/headless.png"), std::string("stride ") + stride);
    }
}

// A scene saved from the viewer holds what was on screen: loaded headless it renders the same image,
// and saved again from the viewer it is the same file.
TEST(Window, SaveRoundTrip) {
    const std::string dir = outDir();
    const std::string edits = " --shading gouraud --layout single --reflection blinn-phong --ke 300 --ks 0.8 "
                              "--mesh icosphere:2 --size 500x300";
    const RunResult viewer = shadelab(scene("compare_torus.json") + edits + " --frames 3 --save-scene " + dir +
                                    "/saved.json --screenshot-view " + dir + "/view.png",
                                dir);
    ASSERT_EQ(viewer.status, 0) << viewer.output;

    const Scene saved = loadSceneFile(dir + "/saved.json");
    EXPECT_EQ(saved.shading, ShadingMode::Gouraud);
    EXPECT_EQ(saved.layout, Layout::Single);
    EXPECT_EQ(saved.reflection, ReflectionModel::BlinnPhong);
    ASSERT_EQ(saved.objects.size(), 1u);
    EXPECT_EQ(saved.objects[0].mesh.type, MeshSpec::Type::IcoSphere);
    EXPECT_EQ(saved.objects[0].mesh.subdivisions, 2);
    EXPECT_FLOAT_EQ(saved.objects[0].material.ke, 300.0f);
    EXPECT_FLOAT_EQ(saved.objects[0].material.ks, 0.8f);
    EXPECT_EQ(saved.lights.size(), 2u);
    EXPECT_EQ(saved.width, 500);
    EXPECT_EQ(saved.height, 300);

    const RunResult headless = shadelab("'" + dir + "/saved.json' --output " + dir + "/headless.png", dir);
    ASSERT_EQ(headless.status, 0) << headless.output;
    expectSameImage(readPng(dir + "/view.png"), readPng(dir + "/headless.png"), "saved scene, headless");

    const RunResult again = shadelab("'" + dir + "/saved.json' --frames 2 --save-scene " + dir + "/saved-again.json", dir);
    ASSERT_EQ(again.status, 0) << again.output;
    std::ifstream a(dir + "/saved.json"), b(dir + "/saved-again.json");
    std::stringstream sa, sb;
    sa << a.rdbuf();
    sb << b.rdbuf();
    EXPECT_EQ(sa.str(), sb.str());
}

// Overlays draw (their program builds, no GL error stops the view) over the surface, and only there.
TEST(Window, Overlays) {
    const std::string dir = outDir();
    const std::string base = "--hide-panel --size 400x300 --frames 3 --screenshot-view ";
    const RunResult plain = shadelab(base + dir + "/plain.png", dir);
    ASSERT_EQ(plain.status, 0) << plain.output;
    const RunResult lines =
        shadelab(base + dir + "/overlays.png --overlays wireframe,vertex-normals,face-normals,lights", dir);
    ASSERT_EQ(lines.status, 0) << lines.output;
    const Image a = readPng(dir + "/plain.png"), b = readPng(dir + "/overlays.png");
    const CompareResult r = compareImages(b, a, 8);
    EXPECT_GT(double(r.differingPixels), 0.02 * double(a.width * a.height))
        << "overlays barely changed the image: " << r.differingPixels << " pixels";
    // The corners are far from the sphere and its normals: untouched background.
    for (const auto& [x, y] : {std::pair{2, 2}, std::pair{397, 2}, std::pair{2, 297}, std::pair{397, 297}})
        EXPECT_TRUE(std::equal(a.pixel(x, y), a.pixel(x, y) + 4, b.pixel(x, y))) << x << "," << y;
}

// The Plots section draws the lecture's plots in the panel, live: opened with --panel-sections plots it
// shows Phong's orange lobe (and nothing in the default panel is that colour), and the lobe follows
// the incidence angle (--incidence sets the section's slider): at 70 degrees it lies further right
// than at 10.
TEST(Window, Plots) {
    const std::string dir = outDir();
    struct Orange {
        int count = 0;
        double meanX = 0.0;
    };
    auto phongOrange = [&](const std::string& args, const std::string& name) {
        const RunResult r = shadelab(args + " --size 640x720 --frames 3 --screenshot " + dir + "/" + name, dir);
        EXPECT_EQ(r.status, 0) << r.output;
        const Image window = readPng(dir + "/" + name);
        Orange o;
        for (int y = 0; y < window.height; ++y)
            for (int x = 640; x < window.width; ++x) {  // the panel, right of the 3D view
                const std::uint8_t* p = window.pixel(x, y);
                if (std::abs(p[0] - 240) <= 20 && std::abs(p[1] - 170) <= 20 && std::abs(p[2] - 40) <= 30)
                    ++o.count, o.meanX += x;
            }
        if (o.count) o.meanX /= o.count;
        return o;
    };
    const Orange closed = phongOrange("", "default.png");
    EXPECT_EQ(closed.count, 0) << "the Plots section is open by default, or something else is orange";
    const Orange steep = phongOrange("--panel-sections plots --incidence 10", "plots-10.png");
    const Orange flat = phongOrange("--panel-sections plots --incidence 70", "plots-70.png");
    EXPECT_GT(steep.count, 150) << "no Phong lobe in the panel";
    EXPECT_GT(flat.count, 150) << "no Phong lobe in the panel";
    EXPECT_GT(flat.meanX, steep.meanX + 20.0) << "the lobe does not follow the incidence angle";
}

// --probe X,Y opens the viewer with the pixel probe set: its arrows are drawn in the probed pane (and
// only there), and the panel lists the terms. The images are kept for a person to look at.
TEST(Window, Probe) {
    const std::string dir = outDir();
    const std::string base = "--layout compare --mesh icosphere:1 --size 600x300 --light point:-3,3,2 --frames 4 ";
    const RunResult plain = shadelab(base + "--screenshot-view " + dir + "/plain.png", dir);
    ASSERT_EQ(plain.status, 0) << plain.output;
    // Pixel 300,150 is the middle of the gouraud pane (x 200..399).
    const RunResult probed =
        shadelab(base + "--probe 300,150 --screenshot-view " + dir + "/probe.png --screenshot " + dir + "/window.png", dir);
    ASSERT_EQ(probed.status, 0) << probed.output;
    const Image a = readPng(dir + "/plain.png"), b = readPng(dir + "/probe.png");
    ASSERT_EQ(a.width, 600);
    // The gouraud pane changes around the probed point; the flat and phong panes are untouched.
    EXPECT_GT(compareImages(crop(b, 200, 50, 200, 200), crop(a, 200, 50, 200, 200), 8).differingPixels, 300u)
        << "no arrows at the probed point";
    EXPECT_EQ(compareImages(crop(b, 0, 0, 200, 300), crop(a, 0, 0, 200, 300)).maxDiff, 0) << "flat pane";
    EXPECT_EQ(compareImages(crop(b, 400, 0, 200, 300), crop(a, 400, 0, 200, 300)).maxDiff, 0) << "phong pane";
    // The panel holds the probe's section: it has text and tables where a bare strip would not.
    const Image window = readPng(dir + "/window.png");
    EXPECT_GT(distinctColours(crop(window, 600, 0, window.width - 600, 300)), 40u);
}

// --select-light 1 selects the area light: its rectangle, its 4 x 3 cells and a marker at each sample
// position are drawn where the light is (upper right of the view), and nothing else changes.
TEST(Window, AreaLightSamples) {
    const std::string dir = outDir();
    const std::string base = "--size 600x300 --light point:-3,3,2 "
                             "--light area:2.2,0.9,1.0:normal=-1,-0.3,0.6:size=1.0,0.7:samples=4x3 --frames 3 ";
    const RunResult plain = shadelab(base + "--screenshot-view " + dir + "/plain.png", dir);
    ASSERT_EQ(plain.status, 0) << plain.output;
    const RunResult selected = shadelab(base + "--select-light 1 --screenshot-view " + dir + "/samples.png", dir);
    ASSERT_EQ(selected.status, 0) << selected.output;
    const Image a = readPng(dir + "/plain.png"), b = readPng(dir + "/samples.png");
    int changed = 0, elsewhere = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            if (std::equal(a.pixel(x, y), a.pixel(x, y) + 3, b.pixel(x, y))) continue;
            ++changed;
            elsewhere += x < 420 || y > 180;  // the light projects to about x 460..570, y 60..140
        }
    EXPECT_GT(changed, 300) << "no sample markers";
    EXPECT_EQ(elsewhere, 0);
}

// --ui-scale 1.5: the window opens with a panel 1.5 times as wide (30 font heights of 16 x 1.5 pixels)
// and a status strip 1.5 times as high.
TEST(Window, UiScaleGrowsThePanel) {
    const std::string dir = outDir();
    const std::string base = "--size 640x360 --frames 3 --screenshot-view " + dir + "/view.png --screenshot ";
    const RunResult normal = shadelab(base + dir + "/normal.png", dir);
    ASSERT_EQ(normal.status, 0) << normal.output;
    const RunResult large = shadelab(base + dir + "/large.png --ui-scale 1.5", dir);
    ASSERT_EQ(large.status, 0) << large.output;
    const Image a = readPng(dir + "/normal.png"), b = readPng(dir + "/large.png");
    // The window opens with room for the panel at its scale; the panel never takes more than half.
    EXPECT_EQ(a.width - 640, 480);
    EXPECT_EQ(b.width - 640, 720);
    EXPECT_GE(readPng(dir + "/view.png").width * 2, b.width);
    EXPECT_EQ(b.height - a.height, 12) << "the status strip is 1.5 font heights: 24 -> 36 pixels";
}

// --msaa 4 in the window: the silhouette's pixels are blends of sphere and background, and nothing
// away from the edges changes (a scripted run without --msaa draws the headless image's pixels).
TEST(Window, MsaaBlendsTheSilhouette) {
    const std::string dir = outDir();
    const std::string base = "--size 400x300 --mesh icosphere:3 --frames 3 --screenshot-view " + dir;
    const RunResult plain = shadelab(base + "/plain.png", dir);
    ASSERT_EQ(plain.status, 0) << plain.output;
    const RunResult smooth = shadelab(base + "/msaa.png --msaa 4", dir);
    ASSERT_EQ(smooth.status, 0) << smooth.output;
    const Image a = readPng(dir + "/plain.png"), b = readPng(dir + "/msaa.png");
    ASSERT_EQ(a.width, b.width);
    const std::uint8_t* background = a.pixel(0, 0);
    auto isBackground = [&](const Image& img, int x, int y) { return std::equal(background, background + 3, img.pixel(x, y)); };
    int blended = 0, farChanges = 0;
    for (int y = 2; y < a.height - 2; ++y)
        for (int x = 2; x < a.width - 2; ++x) {
            if (std::equal(a.pixel(x, y), a.pixel(x, y) + 3, b.pixel(x, y))) continue;
            // Is (x, y) within 2 pixels of the 1-sample silhouette (background next to sphere)?
            bool edge = false;
            for (int dy = -2; dy <= 2 && !edge; ++dy)
                for (int dx = -2; dx <= 2 && !edge; ++dx)
                    edge = isBackground(a, x, y) != isBackground(a, x + dx, y + dy);
            if (edge) ++blended;
            else ++farChanges;
        }
    EXPECT_GT(blended, 200) << "no blended silhouette pixels with --msaa 4";
    // Facet edges inside the sphere may change a little too; the background and the interior do not.
    EXPECT_LT(farChanges, blended / 2);
}

// A preset's title and caption are drawn in a band above the 3D view, with the panel hidden too (a
// projector): the band never covers what the camera frames, and it is not in the 3D view's own pixels
// (F12, --screenshot-view). A scene without them gets no band: the view is the window under the strip.
TEST(Window, TitleAndCaptionAboveTheView) {
    const std::string dir = outDir();
    const std::string base =
        " --hide-panel --no-labels --frames 3 --screenshot " + dir + "/window.png --screenshot-view " + dir + "/view.png";
    const RunResult r = shadelab("--playlist " + scene("playlist") + base, dir);
    ASSERT_EQ(r.status, 0) << r.output;
    const Image window = readPng(dir + "/window.png"), view = readPng(dir + "/view.png");
    ASSERT_EQ(window.width, 400);
    ASSERT_EQ(window.height, 300 + kStripPixels);
    const int band = window.height - kStripPixels - view.height;
    EXPECT_GT(band, 20) << "no caption band";
    EXPECT_LE(band, view.height / 5) << "the caption band is more than a fifth of the view's height";
    // Under the band the window is exactly the 3D view.
    expectSameImage(crop(window, 0, window.height - view.height, 400, view.height), view, "under the caption band");
    // The band: light text on a dark background.
    const Image text = crop(window, 0, kStripPixels, 400, band);
    std::size_t light = 0;
    for (int y = 0; y < text.height; ++y)
        for (int x = 0; x < text.width; ++x)
            light += text.pixel(x, y)[0] > 200 && text.pixel(x, y)[1] > 200 && text.pixel(x, y)[2] > 200;
    EXPECT_GT(light, 150u) << "no caption text in the band";

    const RunResult plain = shadelab(scene("playlist/03-untitled.json") + base, dir);
    ASSERT_EQ(plain.status, 0) << plain.output;
    const Image plainWindow = readPng(dir + "/window.png"), plainView = readPng(dir + "/view.png");
    EXPECT_EQ(plainView.height, plainWindow.height - kStripPixels) << "no title: no band";
}

}  // namespace
}  // namespace shadelab
