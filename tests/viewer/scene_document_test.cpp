// SceneDocument (app/viewer/scene_document.hpp): the viewer's load, save and rebuild, which must leave
// the scene untouched whenever they fail.
#include "core/base/error.hpp"
#include "core/scene/scene_json.hpp"
#include "core/geometry/camera.hpp"
#include "viewer/orbit.hpp"
#include "viewer/scene_document.hpp"

#include "test_files.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace shadelab {
namespace {

namespace fs = std::filesystem;

using test::outDir;
using test::writeText;

SceneDocument defaultDocument() {
    Scene s = defaultScene();
    auto g = std::make_shared<const SceneGeometry>(buildSceneGeometry(s));
    return SceneDocument(std::move(s), std::move(g));
}

TEST(SceneDocument, BadFilesLeaveTheSceneAsItWas) {
    const std::string dir = outDir("bad_files");
    SceneDocument doc = defaultDocument();
    doc.edit().objects[0].material.ke = 123.0f;  // an edit that must survive
    const std::string before = sceneToJson(doc.scene(), dir);
    const SceneGeometry* geometry = doc.geometry().get();

    writeText(dir + "/malformed.json", "{\"mesh\": ");
    writeText(dir + "/wrong.json", "{\"material\": {\"ke\": -4}}");
    writeText(dir + "/missing-model.json", "{\"mesh\": {\"type\": \"gltf\", \"path\": \"nowhere.glb\"}}");
    for (const char* name : {"malformed.json", "wrong.json", "missing-model.json", "absent.json", "absent.glb"}) {
        EXPECT_THROW(doc.load(dir + "/" + name), std::exception) << name;
        EXPECT_EQ(sceneToJson(doc.scene(), dir), before) << name;
        EXPECT_EQ(doc.geometry().get(), geometry) << name;
    }
    try {
        doc.load(dir + "/wrong.json");
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("ke"), std::string::npos) << e.what();
    }
}

TEST(SceneDocument, LoadReplacesSceneGeometryAndHomeCamera) {
    const std::string dir = outDir("load");
    writeText(dir + "/cube.json",
              "{\"mesh\": {\"type\": \"cube\"}, \"camera\": {\"eye\": [4, 4, 4]}, \"size\": [64, 64]}");
    SceneDocument doc = defaultDocument();
    doc.edit().width = 800;  // the view's size
    doc.edit().height = 600;
    doc.load(dir + "/cube.json");
    EXPECT_EQ(doc.scene().objects[0].mesh.type, MeshSpec::Type::Cube);
    EXPECT_EQ(doc.geometry()->meshes[0].triangleCount(), 12u);
    EXPECT_EQ(doc.homeCamera().eye, glm::vec3(4, 4, 4));
    EXPECT_EQ(doc.scene().width, 800);  // the window keeps its size
}

TEST(SceneDocument, SyncRebuildsOnlyWhenAMeshSpecChanges) {
    SceneDocument doc = defaultDocument();
    const auto first = doc.geometry();
    EXPECT_FALSE(doc.syncGeometry());
    doc.edit().objects[0].material.kd = 0.2f;  // not a mesh edit
    EXPECT_FALSE(doc.syncGeometry());
    EXPECT_EQ(doc.geometry(), first);

    doc.edit().objects[0].mesh.slices = 8;
    doc.edit().objects[0].mesh.stacks = 4;
    EXPECT_TRUE(doc.syncGeometry());
    EXPECT_EQ(doc.geometry()->triangleCount(), 2u * 8u * 3u);
    EXPECT_FALSE(doc.syncGeometry());
}

TEST(SceneDocument, FailedRebuildPutsTheOldSpecBack) {
    SceneDocument doc = defaultDocument();
    const MeshSpec good = doc.scene().objects[0].mesh;
    doc.edit().objects[0].mesh.type = MeshSpec::Type::Gltf;
    doc.edit().objects[0].mesh.path = doc.edit().objects[0].mesh.resolvedPath = "/nonexistent/model.glb";
    EXPECT_THROW(doc.syncGeometry(), std::exception);
    EXPECT_EQ(doc.scene().objects[0].mesh, good);
    EXPECT_FALSE(doc.syncGeometry());
}

// Framing follows the view: whatever size and layout the view takes, the model is whole in every pane,
// until the user zooms or pans; F and R follow again.
TEST(SceneDocument, FramingFollowsTheViewUntilZoomed) {
    SceneDocument doc = defaultDocument();  // 1280x720, the sphere fits
    const Camera scene = doc.scene().camera;
    const BoundingSphere sphere{{0, 0, 0}, 1.0f};
    auto paneAspect = [&] {
        const Pane p = layoutPanes(doc.scene().layout, doc.scene().shading, doc.scene().width, doc.scene().height).front();
        return float(p.width) / float(p.height);
    };
    doc.followView();
    EXPECT_EQ(doc.scene().camera.eye, scene.eye);  // the scene's own size: its own camera
    doc.edit().width = 1920;                      // wider: never moved
    doc.followView();
    EXPECT_EQ(doc.scene().camera.eye, scene.eye);
    for (Layout layout : {Layout::Compare, Layout::Diff, Layout::Single})
        for (auto [w, h] : {std::pair{1440, 1056}, std::pair{900, 700}, std::pair{400, 900}, std::pair{1280, 200}}) {
            doc.edit().layout = layout;
            doc.edit().width = w, doc.edit().height = h;
            doc.followView();
            EXPECT_TRUE(sphereInView(doc.scene().camera, sphere, paneAspect())) << w << "x" << h << " layout " << int(layout);
            EXPECT_EQ(doc.scene().camera.target, scene.target);
            // The same view again: the very same camera (no creep from frame to frame).
            const Camera placed = doc.scene().camera;
            for (int frame = 0; frame < 10; ++frame) doc.followView();
            EXPECT_EQ(doc.scene().camera.eye, placed.eye);
        }
    // Zoomed: the camera stays where the user put it.
    doc.edit().width = 1280, doc.edit().height = 720, doc.edit().layout = Layout::Single;
    doc.followView();
    doc.stopFollowing();
    doc.edit().camera.eye *= 0.5f;
    const glm::vec3 zoomed = doc.scene().camera.eye;
    doc.edit().layout = Layout::Compare;
    doc.followView();
    EXPECT_EQ(doc.scene().camera.eye, zoomed);
    EXPECT_FALSE(doc.following());
    // F frames the whole model for this pane, and keeps doing so.
    doc.frameModel();
    EXPECT_TRUE(sphereInView(doc.scene().camera, sphere, paneAspect()));
    doc.edit().width = 600;
    doc.followView();
    EXPECT_TRUE(sphereInView(doc.scene().camera, sphere, paneAspect()));
    // R: the scene's camera again.
    doc.edit().width = 1280, doc.edit().layout = Layout::Single;
    doc.resetCamera();
    EXPECT_EQ(doc.scene().camera.eye, scene.eye);
    EXPECT_TRUE(doc.following());
}

TEST(SceneDocument, SaveWritesALoadableSceneOrNothing) {
    const std::string dir = outDir("save");
    SceneDocument doc = defaultDocument();
    doc.edit().objects[0].material.ke = 250.0f;
    doc.save(dir + "/ok.json");
    EXPECT_FLOAT_EQ(loadSceneFile(dir + "/ok.json").objects[0].material.ke, 250.0f);

    EXPECT_THROW(doc.save(dir + "/no/such/folder/x.json"), InputError);
    doc.edit().camera.target = doc.scene().camera.eye;  // a camera the parser refuses
    EXPECT_THROW(doc.save(dir + "/bad.json"), InputError);
    EXPECT_FALSE(fs::exists(dir + "/bad.json"));
    for (const auto& entry : fs::directory_iterator(dir))  // no temporary left behind
        EXPECT_EQ(entry.path().filename(), "ok.json");
}

}  // namespace
// The viewer restarts a progressive image and re-uploads meshes by comparing revisions: every change
// counts, and what changes nothing (a frame's framing, clip planes and view size, all recomputed every
// frame) does not, or a still view would never finish sampling.
TEST(SceneDocument, RevisionsCountChangesAndOnlyChanges) {
    SceneDocument doc = defaultDocument();
    doc.setViewSize(800, 600);
    doc.followView();
    doc.fitClipPlanes();
    const std::uint64_t settled = doc.revision(), geometry = doc.geometryRevision();
    for (int frame = 0; frame < 3; ++frame) {  // still frames
        doc.setViewSize(800, 600);
        doc.followView();
        doc.fitClipPlanes();
        EXPECT_EQ(doc.scene().objects.size(), 1u);  // reading is not editing
    }
    EXPECT_EQ(doc.revision(), settled);
    EXPECT_FALSE(doc.syncGeometry());
    EXPECT_EQ(doc.geometryRevision(), geometry);

    doc.setViewSize(1024, 600);  // a resize: a new size, and the camera follows it
    EXPECT_GT(doc.revision(), settled);
    std::uint64_t r = doc.revision();
    doc.edit().objects[0].material.ke = 64.0f;
    EXPECT_EQ(doc.revision(), r + 1);
    r = doc.revision();
    doc.sceneForWidgets().objects[0].material.kd = 0.5f;  // a widget's edit, counted when the panel says so
    doc.markEdited();
    EXPECT_EQ(doc.revision(), r + 1);
    r = doc.revision();
    doc.resetCamera();
    EXPECT_GT(doc.revision(), r);

    r = doc.revision();
    doc.edit().objects[0].mesh.type = MeshSpec::Type::Torus;  // a mesh edit: new geometry
    EXPECT_TRUE(doc.syncGeometry());
    EXPECT_EQ(doc.geometryRevision(), geometry + 1);
    EXPECT_GT(doc.revision(), r);
    doc.replace(defaultScene());  // a preset or a file
    EXPECT_EQ(doc.geometryRevision(), geometry + 2);
}

}  // namespace shadelab
