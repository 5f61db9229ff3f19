// PlaylistNavigator (app/viewer/playlist_navigator.hpp): stepping the viewer's document through a
// playlist, keeping each preset's edits, resetting from the file, and never half-switching.
#include "core/base/error.hpp"
#include "core/scene/playlist.hpp"
#include "viewer/playlist_navigator.hpp"

#include "test_files.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace shadelab {
namespace {

namespace fs = std::filesystem;

using test::outDir;
using test::writeText;

// Three presets that differ in title, shading and mesh, and a document showing the first, as the
// viewer starts.
struct Fixture {
    std::string dir;
    std::unique_ptr<SceneDocument> document;
    std::unique_ptr<PlaylistNavigator> navigator;
    explicit Fixture(const std::string& name, const SceneAdjust& adjust = {}) : dir(outDir(name)) {
        writeText(dir + "/01-one.json", R"({"title": "one", "shading": "flat", "mesh": {"type": "cube"}})");
        writeText(dir + "/02-two.json", R"({"title": "two", "shading": "gouraud", "mesh": {"type": "torus"},
                                          "camera": {"eye": [0, 0, 7]}})");
        writeText(dir + "/03-three.json", R"({"title": "three", "shading": "phong", "mesh": {"type": "icosphere"}})");
        std::vector<Preset> presets = loadPlaylist(dir, adjust);
        Scene first = presets[0].scene;
        auto geometry = std::make_shared<const SceneGeometry>(buildSceneGeometry(first));
        document = std::make_unique<SceneDocument>(std::move(first), std::move(geometry));
        navigator = std::make_unique<PlaylistNavigator>(std::move(presets), adjust);
    }
};

TEST(PlaylistNavigator, StepsInOrderAndStopsAtTheEnds) {
    Fixture f("steps");
    SceneDocument& doc = *f.document;
    PlaylistNavigator& nav = *f.navigator;
    ASSERT_TRUE(nav.active());
    EXPECT_EQ(nav.size(), 3u);
    EXPECT_FALSE(nav.previous(doc));  // already at the first
    EXPECT_EQ(doc.scene().title, "one");
    ASSERT_TRUE(nav.next(doc));
    EXPECT_EQ(nav.current(), 1u);
    EXPECT_EQ(doc.scene().title, "two");
    EXPECT_EQ(doc.scene().shading, ShadingMode::Gouraud);
    EXPECT_EQ(doc.scene().objects[0].mesh.type, MeshSpec::Type::Torus);
    EXPECT_EQ(doc.geometry()->specs[0].type, MeshSpec::Type::Torus);  // geometry rebuilt for it
    EXPECT_EQ(doc.homeCamera().eye, glm::vec3(0, 0, 7));              // R goes to the preset's camera
    ASSERT_TRUE(nav.next(doc));
    EXPECT_FALSE(nav.next(doc));  // the last: stays
    EXPECT_EQ(doc.scene().title, "three");
    EXPECT_TRUE(nav.goTo(0, doc));
    EXPECT_EQ(doc.scene().title, "one");
    EXPECT_TRUE(nav.goTo(99, doc));  // clamped to the last
    EXPECT_EQ(nav.current(), 2u);
}

TEST(PlaylistNavigator, KeepsEditsWhileSteppingAndResetReloadsTheFile) {
    Fixture f("edits");
    SceneDocument& doc = *f.document;
    PlaylistNavigator& nav = *f.navigator;
    nav.next(doc);
    doc.edit().shading = ShadingMode::Flat;                  // the lecturer's live edits ...
    doc.edit().objects[0].material.ke = 300.0f;
    doc.edit().camera.eye = glm::vec3(1, 2, 3);
    nav.next(doc);
    EXPECT_EQ(doc.scene().shading, ShadingMode::Phong);       // ... stay with their preset
    nav.previous(doc);
    EXPECT_EQ(doc.scene().shading, ShadingMode::Flat);        // ... and are there on coming back
    EXPECT_FLOAT_EQ(doc.scene().objects[0].material.ke, 300.0f);
    EXPECT_EQ(doc.scene().camera.eye, glm::vec3(1, 2, 3));
    EXPECT_EQ(doc.homeCamera().eye, glm::vec3(0, 0, 7));      // R still goes to the preset's camera

    // Reset reads the file again: an edit made to it meanwhile shows, the live edits are gone.
    writeText(f.dir + "/02-two.json", R"({"title": "two, edited", "shading": "phong", "mesh": {"type": "torus"}})");
    nav.reset(doc);
    EXPECT_EQ(nav.current(), 1u);
    EXPECT_EQ(doc.scene().title, "two, edited");
    EXPECT_EQ(nav.preset(1).scene.title, "two, edited");     // the list shows the new title
    EXPECT_EQ(doc.scene().shading, ShadingMode::Phong);
    EXPECT_FLOAT_EQ(doc.scene().objects[0].material.ke, Material{}.ke);
    nav.next(doc);
    nav.previous(doc);
    EXPECT_EQ(doc.scene().shading, ShadingMode::Phong);       // nothing of the old edits came back

    // A file broken meanwhile: reset refuses, the preset stays as it is on screen.
    doc.edit().shading = ShadingMode::Gouraud;
    writeText(f.dir + "/02-two.json", R"({"shading": "toon"})");
    EXPECT_THROW(nav.reset(doc), InputError);
    EXPECT_EQ(doc.scene().shading, ShadingMode::Gouraud);
    EXPECT_EQ(doc.scene().title, "two, edited");
}

TEST(PlaylistNavigator, ResetAppliesTheCommandLineOverridesAgain) {
    Fixture f("overrides", [](Scene& s) { s.shading = ShadingMode::Gouraud; });
    SceneDocument& doc = *f.document;
    EXPECT_EQ(doc.scene().shading, ShadingMode::Gouraud);  // 01-one.json says flat
    doc.edit().shading = ShadingMode::Phong;
    f.navigator->reset(doc);
    EXPECT_EQ(doc.scene().shading, ShadingMode::Gouraud);
}

TEST(PlaylistNavigator, AFailingStepChangesNothing) {
    const std::string dir = outDir("failing");
    fs::copy_file(fs::path(SHADELAB_SOURCE_DIR) / "assets/models/lowpoly_gem.gltf", dir + "/gem.gltf");
    writeText(dir + "/01-sphere.json", R"({"title": "sphere"})");
    writeText(dir + "/02-gem.json", R"({"title": "gem", "mesh": {"type": "gltf", "path": "gem.gltf"}})");
    std::vector<Preset> presets = loadPlaylist(dir);
    fs::remove(dir + "/gem.gltf");  // the model goes away after the playlist was loaded
    Scene first = presets[0].scene;
    auto geometry = std::make_shared<const SceneGeometry>(buildSceneGeometry(first));
    SceneDocument doc(std::move(first), geometry);
    PlaylistNavigator nav(std::move(presets), {});
    doc.edit().objects[0].material.ke = 77.0f;
    EXPECT_THROW(nav.next(doc), std::exception);
    EXPECT_EQ(nav.current(), 0u);
    EXPECT_EQ(doc.scene().title, "sphere");
    EXPECT_FLOAT_EQ(doc.scene().objects[0].material.ke, 77.0f);
    EXPECT_EQ(doc.geometry(), geometry);
}

TEST(PlaylistNavigator, AFileLoadedInBetweenIsNotTakenForThePresetsEdits) {
    Fixture f("detach");
    SceneDocument& doc = *f.document;
    PlaylistNavigator& nav = *f.navigator;
    const std::string other = outDir("detach-other") + "/other.json";
    writeText(other, R"({"title": "other", "shading": "gouraud"})");
    doc.load(other);
    nav.detach();
    nav.next(doc);
    nav.previous(doc);
    EXPECT_EQ(doc.scene().title, "one");  // not "other"
    EXPECT_EQ(doc.scene().shading, ShadingMode::Flat);
    // Detached, stepping to the preset the navigator is on shows it again.
    doc.load(other);
    nav.detach();
    EXPECT_TRUE(nav.goTo(0, doc));
    EXPECT_EQ(doc.scene().title, "one");
}

TEST(PlaylistNavigator, AnEmptyPlaylistIsInactive) {
    Scene s;
    auto g = std::make_shared<const SceneGeometry>(buildSceneGeometry(s));
    SceneDocument doc(s, g);
    PlaylistNavigator nav({}, {});
    EXPECT_FALSE(nav.active());
    EXPECT_FALSE(nav.next(doc));
    EXPECT_NO_THROW(nav.reset(doc));
    EXPECT_EQ(doc.geometry(), g);
}

}  // namespace
}  // namespace shadelab
