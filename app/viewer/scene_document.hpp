#pragma once
// What the viewer shows, without any GL or window: the scene the panel edits, the geometry built from
// it, and the camera `R` goes back to. Loading, saving and rebuilding are all-or-nothing: when one
// throws, the document is as it was, so a bad file or a failing glTF never costs the room its scene.
#include "core/scene.hpp"
#include "core/scene_geometry.hpp"

#include <memory>
#include <string>

namespace shadelab {

class SceneDocument {
public:
    // `geometry` must have been built from `scene` (the CLI built it already).
    SceneDocument(Scene scene, std::shared_ptr<const SceneGeometry> geometry);

    Scene& scene() { return scene_; }
    const Scene& scene() const { return scene_; }
    const std::shared_ptr<const SceneGeometry>& geometry() const { return geometry_; }
    // The camera the scene came with (after auto-framing a model): what `R` restores.
    const Camera& homeCamera() const { return home_; }
    void setHomeCamera(const Camera& camera) { home_ = camera; }

    // Rebuilds the geometry if an object's mesh spec (or the number of objects) differs from what it
    // was built from; returns true when it did, so the renderer gets the new meshes. Cheap otherwise:
    // it only compares specs. If building throws, the specs that were built come back, and it rethrows.
    bool syncGeometry();

    // Replaces the scene with a scene file (.json) or a model (.gltf/.glb). The document's view size
    // (scene().width/height, the viewer keeps them at the 3D view's size) is kept and used to frame a
    // model. Throws InputError (or another exception) and changes nothing on failure.
    void load(const std::string& path);
    // The same for a scene already read (a playlist preset): geometry built, a model without a camera
    // framed, the home camera set, the view's size kept. Throws and changes nothing on failure.
    void replace(Scene next);
    // Puts back a scene and home camera this document showed before (a preset the lecturer left with
    // edits): the camera is left as it was, the view's size kept. Throws and changes nothing on failure.
    void restore(Scene scene, const Camera& home);

    // Writes the scene as JSON, atomically. The text is parsed back before anything is written, so a
    // file that would not load again is never saved (throws InputError naming the field).
    void save(const std::string& path) const;

    // Places the camera to fit every object in the first pane, keeping the viewing direction.
    void frameModel();

    // For a view smaller than the scene was made for (a 1280x720 projector, the panel beside the
    // view): when the model fits its pane at the scene's own `width` x `height` but the view's panes
    // crop it, frames it (as F) and makes that the home camera. Returns true when it did. A view that
    // gives the scene its size never moves the camera, so it shows what --output renders.
    bool fitToView(int width, int height);

private:
    BoundingSphere bounds() const;
    float paneAspect(int width, int height) const;

    Scene scene_;
    std::shared_ptr<const SceneGeometry> geometry_;
    Camera home_;
};

}  // namespace shadelab
