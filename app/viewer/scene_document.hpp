#pragma once
// What the viewer shows, without any GL or window: the scene the panel edits, the geometry built from
// it, and the camera `R` goes back to. Loading, saving and rebuilding are all-or-nothing: when one
// throws, the document is as it was, so a bad file or a failing glTF never costs the room its scene.
#include "core/geometry/scene_geometry.hpp"
#include "core/scene/scene.hpp"

#include <algorithm>
#include <cstdint>
#include <memory>
#include <string>

namespace shadelab {

class SceneDocument {
public:
    // `geometry` must have been built from `scene` (the CLI built it already).
    SceneDocument(Scene scene, std::shared_ptr<const SceneGeometry> geometry);

    // The scene as it is now. Every change goes through edit() (or the document's own operations
    // below), which count it: a reader that remembers revision() knows whether anything changed since
    // it last looked (the viewer restarts a progressive image on that), without comparing scenes.
    const Scene& scene() const { return scene_; }
    Scene& edit() {
        ++revision_;
        return scene_;
    }
    std::uint64_t revision() const { return revision_; }
    // The panel's widgets edit the scene in place every frame and tell afterwards whether they changed
    // anything (PanelRequests::sceneEdited): then markEdited() counts it.
    Scene& sceneForWidgets() { return scene_; }
    void markEdited() { ++revision_; }
    // The 3D view's size in pixels is the scene's (a saved scene renders that image): an edit only
    // when it differs.
    void setViewSize(int width, int height);

    const std::shared_ptr<const SceneGeometry>& geometry() const { return geometry_; }
    // Counts the geometry's rebuilds (syncGeometry, load, replace, restore): the renderer gets new
    // meshes when it differs from the one they were uploaded at.
    std::uint64_t geometryRevision() const { return geometryRevision_; }
    // The camera the scene came with (after auto-framing a model): what `R` restores.
    const Camera& homeCamera() const { return home_; }

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
    // edits): the camera is left as it was, and follows the view again if it did then (`following`; the
    // home camera was made for a `fileWidth` x `fileHeight` image); the view's size kept. Throws and
    // changes nothing on failure.
    void restore(Scene scene, const Camera& home, bool following, int fileWidth, int fileHeight);

    // Writes the scene as JSON, atomically. The text is parsed back before anything is written, so a
    // file that would not load again is never saved (throws InputError naming the field).
    void save(const std::string& path) const;

    // Framing is a property of the view: while it is on, followView() places the camera every frame
    // for the view's current size and layout (scene().width/height), so a resize, a layout switch, the
    // caption or the panel appearing never crops the model. Zooming, panning or editing the camera
    // (stopFollowing) turns it off until F, R or another scene.
    //  - a scene's own camera ("home") that shows the model's whole height: kept where the whole model
    //    fits this pane, else moved back along its viewing direction until it does (5% margin; in
    //    compare and diff, up to 15% as the pane gets narrower than the scene's own, the lecture hall);
    //  - one that crops the model (a close-up): moved back in a pane narrower than the one the scene
    //    was made for until the same width shows;
    //  - F, or a model without a camera: the whole model, centred, filling 90% of the tighter side
    //    (about 80% in compare and diff).
    void followView();
    void frameModel();     // F
    void resetCamera();    // R: the home camera, followed
    void stopFollowing();  // the user zoomed, panned or typed a camera
    // The share of each pane's height the pane labels take at its top (0..0.3): framing keeps the model
    // clear of them.
    void setLabelInset(float fraction) { labelInset_ = std::clamp(fraction, 0.0f, 0.3f); }
    bool following() const { return framing_ != Framing::Off; }

    // Near and far around the model and the lights as seen from the eye (every frame, after the
    // camera moved): zoom never slices the model, and there is no dead range.
    void fitClipPlanes();
    // The wheel's range of eye-to-target distances for this model: close to its surface, far away.
    float minZoomDistance() const;
    float maxZoomDistance() const;

private:
    enum class Framing { Off, Home, Model };
    BoundingSphere bounds() const;
    float paneAspect(int width, int height) const;
    // After a new scene: what the home camera is, and how the view follows it.
    void adopt(Scene next);  // replace's and restore's common step
    void startFraming(int fileWidth, int fileHeight);
    Camera clearOfLabels(const Camera& camera, float& aspect) const;
    void frameInsidePane(Camera& camera, const BoundingSphere& bounds, float aspect) const;
    bool multiPane() const;  // compare or diff: panes side by side

    // A camera placed by framing or by the clip planes: an edit only when it moved.
    void placeCamera(const Camera& placed);

    Scene scene_;
    std::uint64_t revision_ = 0, geometryRevision_ = 0;
    std::shared_ptr<const SceneGeometry> geometry_;
    Camera home_;
    Framing framing_ = Framing::Home;
    float homeAspect_ = 1.0f;  // the pane aspect the home camera was made for (the file's size)
    float labelInset_ = 0.0f;
    // bounds() of this geometry with these transforms. Weak: a rebuilt geometry may reuse a freed one's
    // address, an expired pointer cannot be mistaken for it.
    mutable BoundingSphere boundsCache_;
    mutable std::weak_ptr<const SceneGeometry> boundsGeometry_;
    mutable std::vector<glm::mat4> boundsTransforms_;
    bool homeFits_ = true;  // the home camera shows the model's whole height (framesWholeModel)
};

}  // namespace shadelab
