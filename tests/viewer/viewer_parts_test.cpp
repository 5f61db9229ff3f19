// The viewer's parts that decide without GL (issue 28, part 2): when the view changed (ViewRevision),
// the progressive sum's restarts and stride (ProgressiveSampling), the --animate clock
// (AnimationPlayback), render on demand and the frame cap (FramePacing), anti-aliasing and reduced
// moving frames (ViewQuality), the probe (ProbeState) and the caches keyed on placed geometry.
#include "core/scene/animation.hpp"
#include "core/scene/scene_json.hpp"
#include "viewer/animation_playback.hpp"
#include "viewer/frame_pacing.hpp"
#include "viewer/panel.hpp"
#include "viewer/placed_geometry.hpp"
#include "viewer/probe_state.hpp"
#include "viewer/probe_view.hpp"
#include "viewer/progressive_sampling.hpp"
#include "viewer/recording_session.hpp"
#include "viewer/shader_view.hpp"
#include "viewer/view_overlays.hpp"
#include "viewer/view_quality.hpp"
#include "viewer/view_revision.hpp"

#include "test_files.hpp"

#include "core/scene/scene_limits.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <memory>

namespace shadelab {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;
const Clock::time_point kT0 = Clock::time_point{} + 100s;

TEST(ViewRevision, EveryInputMovesItAndNothingElseDoes) {
    ViewRevision revision;
    const ViewInputs start{3, 1, 0, 7, 640, 480, 0};
    const std::uint64_t r0 = revision.of(start);
    EXPECT_EQ(revision.of(start), r0);  // nothing changed: the same view
    // Each input in turn (the fields in declaration order): the view changed, and stays at its new revision.
    std::uint64_t ViewInputs::*const fields[] = {&ViewInputs::scene,     &ViewInputs::geometry, &ViewInputs::renderer,
                                                 &ViewInputs::animation, &ViewInputs::width,    &ViewInputs::height,
                                                 &ViewInputs::moving};
    static_assert(std::size(fields) * sizeof(std::uint64_t) == sizeof(ViewInputs), "a new input: add it here");
    std::uint64_t last = r0;
    for (auto field : fields) {
        ViewInputs changed = start;
        ++(changed.*field);
        const std::uint64_t r = revision.of(changed);
        EXPECT_GT(r, last);
        EXPECT_EQ(revision.of(changed), r);
        last = revision.of(start);  // and back: a change again
        EXPECT_GT(last, r);
    }
}

TEST(ProgressiveSampling, RestartsWhenTheViewRevisionMoves) {
    ProgressiveSampling p;
    EXPECT_FALSE(p.refining());
    p.frameBegins(kT0);
    EXPECT_TRUE(p.begin(1, 64).restart);  // the first frame of a sum
    p.drawn(false, false);
    EXPECT_TRUE(p.refining());  // not complete: the viewer keeps drawing
    p.frameBegins(kT0 + 50ms);
    EXPECT_FALSE(p.begin(1, 64).restart);  // the same view: the next pass
    p.drawn(true, false);
    EXPECT_FALSE(p.refining());  // complete: the viewer may sleep
    p.frameBegins(kT0 + 100ms);
    EXPECT_TRUE(p.begin(2, 64).restart);  // the view changed
    p.drawn(false, false);
    p.abandon();  // a failing program, a minimised window: nothing refines
    EXPECT_FALSE(p.refining());
    p.off();  // a scene without sampled lights: no sum; the next one restarts whatever the revision
    p.frameBegins(kT0 + 150ms);
    EXPECT_TRUE(p.begin(2, 64).restart);
}

// A moving frame (ViewQuality) draws one sample of each area light and leaves the still view's stride
// alone; the still frame after it restarts the sum at that stride.
TEST(ProgressiveSampling, MovingFramesTakeOneSampleAndKeepTheStillStride) {
    ProgressiveSampling p;
    p.frameBegins(kT0);
    const int still = p.begin(1, 64).stride;
    p.drawn(false, false);
    p.frameBegins(kT0 + 50ms);
    const ProgressiveSampling::Pass moving = p.begin(2, 64, true);
    EXPECT_TRUE(moving.restart);
    EXPECT_EQ(moving.stride, kAreaSamplesPerSideRange.hi);
    p.drawn(false, false);
    p.frameBegins(kT0 + 900ms);  // a slow moving frame is not taken for a pass's time
    const ProgressiveSampling::Pass after = p.begin(3, 64);
    EXPECT_TRUE(after.restart);
    EXPECT_EQ(after.stride, still);
}

TEST(ProgressiveSampling, StrideStartsNearFourSamplesAPassThenFollowsThePassTime) {
    // First: about 4 samples per pass (8x8 = 64 samples: stride 4, 16 passes of 4).
    EXPECT_EQ(ProgressiveSampling::adaptStride(0, 64, 0.0), 4);
    EXPECT_EQ(ProgressiveSampling::adaptStride(0, 4, 0.0), 1);
    EXPECT_EQ(ProgressiveSampling::adaptStride(0, 256, 0.0), 8);
    // Then doubled over the budget, halved under a quarter of it, else kept.
    const double budget = ProgressiveSampling::kPassBudgetMs;
    EXPECT_EQ(ProgressiveSampling::adaptStride(4, 64, budget + 1), 8);
    EXPECT_EQ(ProgressiveSampling::adaptStride(4, 64, budget / 4 - 1), 2);
    EXPECT_EQ(ProgressiveSampling::adaptStride(4, 64, budget / 2), 4);
    EXPECT_EQ(ProgressiveSampling::adaptStride(1, 64, 1.0), 1);  // never below 1
}

TEST(ProgressiveSampling, APassIsTimedOnlyWhenAFrameDrewExactlyOne) {
    ProgressiveSampling p;
    p.frameBegins(kT0);
    EXPECT_EQ(p.begin(1, 64).stride, 4);
    p.drawn(false, false);
    p.frameBegins(kT0 + 200ms);  // that frame's one pass took 200 ms, over the budget
    EXPECT_DOUBLE_EQ(p.lastPassMs(), 200.0);
    p.begin(1, 64);
    p.drawn(true, true);  // a screenshot finished every pass at once: not one pass's time
    p.frameBegins(kT0 + 900ms);
    EXPECT_DOUBLE_EQ(p.lastPassMs(), 200.0);
    EXPECT_EQ(p.begin(2, 64).stride, 8);  // the restart adapts to the last timed pass
    // --progressive S fixes the stride.
    ProgressiveSampling fixed(2);
    fixed.frameBegins(kT0);
    EXPECT_EQ(fixed.begin(1, 64).stride, 2);
}

std::vector<Animation> ramp(const std::string& spec) { return {parseAnimation(spec, "--animate")}; }

TEST(AnimationPlayback, AScriptedRunStepsAThirtiethOfASecondAFrameAndLoops) {
    AnimationPlayback a(ramp("ke=1..100:0.1"), true, kT0);  // a 0.1 s ramp: three frames a loop
    ASSERT_TRUE(a.playing());
    const Scene base = defaultScene();
    for (int frame = 0; frame < 5; ++frame) {
        ASSERT_FALSE(a.advance(base, kT0).has_value());
        EXPECT_NEAR(a.shownSeconds(), std::fmod(frame / 30.0, 0.1), 1e-9) << frame;
        EXPECT_EQ(a.step(), std::uint64_t(frame + 1));
        ASSERT_NE(a.scene(), nullptr);
    }
    EXPECT_FLOAT_EQ(a.scene()->objects[0].material.ke,
                    sceneAtTime(base, a.animations(), a.shownSeconds(), "").objects[0].material.ke);
    EXPECT_FLOAT_EQ(base.objects[0].material.ke, defaultScene().objects[0].material.ke);  // the document's is untouched
}

TEST(AnimationPlayback, APersonsSessionFollowsTheClockAndPausing) {
    AnimationPlayback a(ramp("ke=1..100:4"), false, kT0);
    const Scene base = defaultScene();
    a.advance(base, kT0 + 250ms);  // shown at 0; the clock moves by the 250 ms since the start
    a.advance(base, kT0 + 500ms);
    EXPECT_NEAR(a.shownSeconds(), 0.25, 1e-9);
    a.togglePlay();
    EXPECT_FALSE(a.playing());
    const std::uint64_t step = a.step();
    a.advance(base, kT0 + 2s);
    a.advance(base, kT0 + 3s);
    EXPECT_NEAR(a.shownSeconds(), 0.5, 1e-9);  // paused: the time and the step stay
    EXPECT_EQ(a.step(), step);
    a.restart();  // a new preset plays from the start
    EXPECT_TRUE(a.playing());
    a.advance(base, kT0 + 4s);
    EXPECT_NEAR(a.shownSeconds(), 0.0, 1e-9);
}

TEST(AnimationPlayback, AnAnimationThatDoesNotFitStopsWithItsError) {
    AnimationPlayback a({parseAnimation("light-orbit", "--animate")}, true, kT0);
    Scene dark = defaultScene();
    dark.lights.clear();  // removed in the panel: nothing to orbit
    const auto error = a.advance(dark, kT0);
    ASSERT_TRUE(error.has_value());
    EXPECT_NE(error->find("--animate"), std::string::npos) << *error;
    EXPECT_FALSE(a.playing());
    EXPECT_EQ(a.scene(), nullptr);  // the document's scene is drawn
    AnimationPlayback none({}, true, kT0);
    EXPECT_FALSE(none.playing());
    none.togglePlay();  // Space without --animate: nothing plays
    EXPECT_FALSE(none.playing());
}

TEST(FramePacing, AnEventDrawsAFewFramesThenTheViewerMaySleep) {
    FramePacing f;
    EXPECT_TRUE(f.pending(0));  // the first frames are drawn
    EXPECT_TRUE(f.countEvents(0));
    EXPECT_TRUE(f.countEvents(0));
    EXPECT_FALSE(f.pending(0));
    EXPECT_TRUE(f.pending(1));  // an event came
    EXPECT_FALSE(f.countEvents(1));
    for (int i = 1; i < FramePacing::kFramesAfterEvent; ++i) {
        EXPECT_TRUE(f.pending(1)) << i;
        EXPECT_TRUE(f.countEvents(1));
    }
    EXPECT_FALSE(f.pending(1));
    f.drawAnother();  // a message to show
    EXPECT_TRUE(f.pending(1));
    f.countEvents(1);
    EXPECT_FALSE(f.pending(1));
}

TEST(FramePacing, TheCapIsTheDisplaysRefreshElseSixtyHertz) {
    EXPECT_EQ(FramePacing::capHz(144), 144);
    EXPECT_EQ(FramePacing::capHz(0), 60);     // the monitor does not say
    EXPECT_EQ(FramePacing::capHz(1000), 60);  // implausible
    FramePacing f;
    f.frameBegins(kT0);
    EXPECT_EQ(std::chrono::duration_cast<std::chrono::microseconds>(f.nextDue(50) - kT0).count(), 20000);
}

ViewQuality::Frame moving(double lastFrameMs) {
    ViewQuality::Frame f;
    f.mouseDown = true;
    f.lastFrameMs = lastFrameMs;
    return f;
}

TEST(ViewQuality, AGpuAntiAliasesEveryFrame) {
    ViewQuality q(4, false);
    for (int i = 0; i < 3; ++i) {
        q.plan(moving(100.0));
        EXPECT_TRUE(q.antiAliasThisFrame());
        EXPECT_FALSE(q.reducedThisFrame());  // only a software rasterizer reduces
        q.drawn();
        EXPECT_FALSE(q.wantsStillFrame());
    }
}

TEST(ViewQuality, ASoftwareRasterizerReducesWhileMovingAndDrawsTheStillViewInFull) {
    ViewQuality q(4, true);
    q.plan(moving(100.0));  // the first moving frame: full size, the scale is measured from here on
    EXPECT_FALSE(q.antiAliasThisFrame());
    EXPECT_FALSE(q.reducedThisFrame());
    q.drawn();
    EXPECT_TRUE(q.wantsStillFrame());
    float scale = 1.0f;
    for (int i = 0; i < 20; ++i) {  // frames of 100 ms: smaller, down to the smallest scale
        q.plan(moving(100.0));
        EXPECT_TRUE(q.reducedThisFrame());
        EXPECT_LE(q.movingScale(), scale);
        scale = q.movingScale();
        q.drawn();
    }
    EXPECT_FLOAT_EQ(scale, ViewQuality::kMinMovingScale);
    for (int i = 0; i < 20; ++i) q.plan(moving(5.0)), q.drawn();  // fast frames: back to full size
    EXPECT_FLOAT_EQ(q.movingScale(), 1.0f);
    EXPECT_FALSE(q.reducedThisFrame());
    ViewQuality::Frame still;
    still.still = true;
    q.plan(still);  // the mouse let go: anti-aliased, full size, then nothing more to draw
    EXPECT_TRUE(q.antiAliasThisFrame());
    q.drawn();
    EXPECT_FALSE(q.wantsStillFrame());
}

TEST(ViewQuality, ACaptureOrAScriptedRunIsNeverReduced) {
    ViewQuality q(4, true);
    for (int i = 0; i < 5; ++i) q.plan(moving(100.0)), q.drawn();
    ASSERT_TRUE(q.reducedThisFrame());
    ViewQuality::Frame capture = moving(100.0);
    capture.capture = true;
    q.plan(capture);
    EXPECT_FALSE(q.reducedThisFrame());
    EXPECT_TRUE(q.antiAliasThisFrame());
    ViewQuality::Frame scripted = moving(100.0);
    scripted.scripted = true;
    q.plan(scripted);
    EXPECT_FALSE(q.reducedThisFrame());
}

std::shared_ptr<const SceneGeometry> geometryOf(const Scene& scene) {
    return std::make_shared<const SceneGeometry>(buildSceneGeometry(scene));
}

TEST(ProbeState, SetAtASurfaceFollowsTheSceneAndNewMeshesDropIt) {
    Scene scene = defaultScene();
    auto geometry = geometryOf(scene);
    ProbeState probe(glm::ivec2(scene.width / 2, scene.height / 2));
    const auto pending = probe.takePending();
    ASSERT_TRUE(pending.has_value());
    EXPECT_FALSE(probe.takePending().has_value());  // once
    const ProbeState::Outcome at = probe.set(scene, geometry, pending->x, pending->y);
    EXPECT_TRUE(at.set) << at.message;
    EXPECT_FALSE(at.isError);
    probe.evaluate(scene, geometry);
    ASSERT_NE(probe.result(), nullptr);
    const glm::ivec3 before = probe.result()->output8;
    scene.objects[0].material.kd *= 0.5f;  // a slider: the probe's numbers follow
    probe.evaluate(scene, geometry);
    ASSERT_NE(probe.result(), nullptr);
    EXPECT_NE(probe.result()->output8, before);
    probe.evaluate(scene, geometryOf(scene));  // rebuilt meshes: the anchor's triangle is gone
    EXPECT_EQ(probe.result(), nullptr);
    EXPECT_FALSE(probe.anchored());
}

TEST(ProbeState, OutsideTheViewAndOnTheBackgroundSayWhy) {
    const Scene scene = defaultScene();
    auto geometry = geometryOf(scene);
    ProbeState probe;
    const ProbeState::Outcome outside = probe.set(scene, geometry, scene.width, 0);
    EXPECT_FALSE(outside.set);
    EXPECT_TRUE(outside.isError);
    EXPECT_NE(outside.message.find("outside"), std::string::npos) << outside.message;
    const ProbeState::Outcome background = probe.set(scene, geometry, 0, 0);  // the default scene's corner
    EXPECT_FALSE(background.set);
    EXPECT_FALSE(background.isError);
    EXPECT_NE(background.message.find("background"), std::string::npos) << background.message;
    EXPECT_FALSE(probe.anchored());
}

// Issue 31, item 11: the probe's line and the Shader section's combo number the panes alike, so
// "pane 2" in the Probe section is the combo's "pane 2: gouraud", in compare and in diff.
TEST(ProbeState, NumbersPanesAsTheShaderSectionDoes) {
    for (const Layout layout : {Layout::Compare, Layout::Diff}) {
        Scene scene = defaultScene();
        scene.layout = layout;
        auto geometry = geometryOf(scene);
        const std::vector<std::string> choices = shaderPaneChoices(scene);
        const std::vector<Pane> panes = layoutPanes(scene.layout, scene.shading, scene.width, scene.height, scene.diff);
        ASSERT_EQ(panes.size(), 3u);
        EXPECT_EQ(choices.size(), layout == Layout::Compare ? 3u : 2u);
        for (std::size_t p = 0; p < panes.size(); ++p) {
            ProbeState probe;
            const ProbeState::Outcome at =
                probe.set(scene, geometry, panes[p].x + panes[p].width / 2, panes[p].y + panes[p].height / 2);
            ASSERT_TRUE(at.set) << at.message;
            probe.evaluate(scene, geometry);
            ASSERT_NE(probe.result(), nullptr);
            const ProbeResult& r = *probe.result();
            EXPECT_EQ(r.pane, int(p));
            const std::string number = "pane " + std::to_string(p + 1);
            EXPECT_NE(probeWhere(r).find(", " + number + ":"), std::string::npos) << probeWhere(r);
            if (panes[p].difference) continue;  // the difference pane runs no program of its own
            ASSERT_LT(p, choices.size());
            EXPECT_EQ(choices[p], number + ": " + toString(r.modes.at(0).mode));
        }
    }
}

// Issue 31, item 11: on a 2x screen the status strip beside the panel is narrow; what does not fit
// is left out whole, the renderer's name first, never the frame time or the animation's clock.
TEST(StatusStrip, LeavesOutTheRendererThenTheTrianglesWhereTheStripIsNarrow) {
    PanelStatus status;
    status.frameMs = 20.0;
    status.frameTriangles = 8588;
    status.glRenderer = "llvmpipe (LLVM 15.0.6, 256 bits)";
    status.progress = "pass 3 of 16";
    status.animation = "1.25 s of 4.00 s";
    status.playing = true;
    const auto chars = [](const std::string& t) { return float(t.size()); };  // a byte a unit
    const std::string all = statusStripText(status, 1000.0f, chars);
    for (const char* part :
         {"20.0 ms (50 FPS)", "8588 triangles", "llvmpipe", "pass 3 of 16", "playing 1.25 s of 4.00 s"})
        EXPECT_NE(all.find(part), std::string::npos) << part << " in " << all;
    const std::string noRenderer = statusStripText(status, chars(all) - 1.0f, chars);
    EXPECT_EQ(noRenderer.find("llvmpipe"), std::string::npos) << noRenderer;
    EXPECT_NE(noRenderer.find("8588 triangles"), std::string::npos) << noRenderer;
    EXPECT_LE(chars(noRenderer), chars(all) - 1.0f);
    const std::string least = statusStripText(status, 10.0f, chars);
    EXPECT_EQ(least.find("triangles"), std::string::npos) << least;
    for (const char* part : {"20.0 ms (50 FPS)", "pass 3 of 16", "playing 1.25 s of 4.00 s"})
        EXPECT_NE(least.find(part), std::string::npos) << part << " in " << least;
    status.idle = true;
    EXPECT_EQ(statusStripText(status, 1000.0f, chars).rfind("idle", 0), 0u);
}

TEST(PlacedGeometry, ATransformOrNewMeshesChangeItAndALightDoesNot) {
    Scene scene = defaultScene();
    auto geometry = geometryOf(scene);
    PlacedGeometry placed;
    EXPECT_FALSE(placed.same(scene, geometry));  // nothing remembered yet
    placed.remember(scene, geometry);
    EXPECT_TRUE(placed.same(scene, geometry));
    scene.lights[0].intensity *= 2.0f;
    EXPECT_TRUE(placed.same(scene, geometry));
    EXPECT_FALSE(placed.same(scene, geometryOf(scene)));
    scene.objects[0].transform.translation.x += 1.0f;
    EXPECT_FALSE(placed.same(scene, geometry));
    ModelSpheres spheres;
    const BoundingSphere moved = spheres.of(scene, geometry).at(0);
    scene.objects[0].transform.translation.x -= 1.0f;
    EXPECT_NEAR(spheres.of(scene, geometry).at(0).center.x, moved.center.x - 1.0f, 1e-5f);
}

Image gray(int width, int height) {
    Image image;
    image.width = width, image.height = height;
    image.rgba.assign(std::size_t(width) * std::size_t(height) * 4, 128);
    return image;
}

TEST(RecordingSession, ToggledAtTheFrameItsEndAndAResizeStopsAndSaves) {
    const std::string path = test::outDir("recording") + "/view.mp4";
    std::vector<std::pair<std::string, bool>> said;
    RecordingSession r([&] { return path; },
                       [&](const std::string& m, bool isError) { said.emplace_back(m, isError); });
    r.toggle();
    EXPECT_TRUE(r.capturing());  // the frame the key was pressed in is read back
    r.frame(Image{}, kT0);       // but the view was empty
    EXPECT_FALSE(r.active());
    ASSERT_EQ(said.size(), 1u);
    EXPECT_EQ(said.back(), std::make_pair(std::string("nothing to record: the view is empty"), true));
    r.toggle();
    r.frame(gray(64, 48), kT0);
    if (!r.active()) GTEST_SKIP() << "no video encoding in this build: " << said.back().first;
    EXPECT_EQ(said.back().first, "recording " + path + " (Ctrl+R stops)");
    r.frame(gray(64, 48), kT0 + 100ms);
    r.frame(gray(80, 48), kT0 + 200ms);  // the window was resized
    EXPECT_FALSE(r.active());
    EXPECT_EQ(said.back(),
              std::make_pair("saved recording " + path + " (recording stopped: the view changed size)", false));
    EXPECT_EQ(r.lastSaved(), path);
    EXPECT_GT(std::filesystem::file_size(path), 0u);
}

}  // namespace
}  // namespace shadelab
