#include "viewer/scene_document.hpp"

#include "core/base/error.hpp"
#include "core/base/file_io.hpp"
#include "core/geometry/camera.hpp"
#include "core/scene/scene_json.hpp"
#include "viewer/orbit.hpp"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

namespace shadelab {
namespace {

// The share of each half of the pane a fitted model may take: 5% margin; in side by side panes
// (compare, diff) 15%, the lecture-hall rule.
constexpr float kFitMargin = 0.95f, kPaneFitMargin = 0.85f;

// Whether a camera was meant to show the whole model: it fits the view's height (a narrower image
// than the one the camera was made for, or a --size override, cuts only the sides). A camera that
// crops the model top and bottom too (a close-up, a floor that fills the view) was meant to crop it.
bool framesWholeModel(Camera camera, const BoundingSphere& bounds) {
    camera.nearPlane = 0.0f;
    camera.farPlane = std::numeric_limits<float>::max();
    return sphereInView(camera, bounds, 1e6f);
}

std::string folderOf(const std::string& path) {
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    return parent.empty() ? "." : parent.string();
}

}  // namespace

SceneDocument::SceneDocument(Scene scene, std::shared_ptr<const SceneGeometry> geometry)
    : scene_(std::move(scene)), geometry_(std::move(geometry)), home_(scene_.camera) {
    startFraming(scene_.width, scene_.height);
}

bool SceneDocument::syncGeometry() {
    bool same = geometry_ && geometry_->specs.size() == scene_.objects.size();
    for (std::size_t i = 0; same && i < scene_.objects.size(); ++i)
        same = scene_.objects[i].mesh == geometry_->specs[i];
    if (same) return false;
    try {
        geometry_ = std::make_shared<const SceneGeometry>(buildSceneGeometry(scene_));
    } catch (...) {
        // Put back the specs the current geometry was built from; objects added since keep theirs.
        if (geometry_)
            for (std::size_t i = 0; i < scene_.objects.size() && i < geometry_->specs.size(); ++i)
                scene_.objects[i].mesh = geometry_->specs[i];
        ++revision_;
        throw;
    }
    ++revision_;
    ++geometryRevision_;
    return true;
}

void SceneDocument::load(const std::string& path) {
    replace(hasModelExtension(path) ? sceneForModel(path) : loadSceneFile(path));
}

// The document becomes `next` at the window's size, with its geometry. The geometry is built before
// anything of the document changes: when that throws, the document is as it was.
void SceneDocument::adopt(Scene next) {
    next.width = scene_.width;
    next.height = scene_.height;
    auto geometry = std::make_shared<const SceneGeometry>(buildSceneGeometry(next));
    scene_ = std::move(next);
    geometry_ = std::move(geometry);
    ++revision_;
    ++geometryRevision_;
}

void SceneDocument::replace(Scene next) {
    const int fileWidth = next.width, fileHeight = next.height;
    adopt(std::move(next));
    home_ = scene_.camera;
    startFraming(fileWidth, fileHeight);
}

void SceneDocument::restore(Scene scene, const Camera& home, bool following, int fileWidth, int fileHeight) {
    adopt(std::move(scene));
    home_ = home;
    // A camera that followed the view follows it again (the view may have changed size since).
    bool model = false;
    for (const SceneObject& o : scene_.objects) model = model || o.mesh.type == MeshSpec::Type::Gltf;
    framing_ = !following ? Framing::Off : scene_.cameraGiven || !model ? Framing::Home : Framing::Model;
    homeAspect_ = paneAspect(fileWidth, fileHeight);
    homeFits_ = framesWholeModel(home_, bounds());
}

void SceneDocument::save(const std::string& path) const {
    checkOutputPath(path, "save");
    const std::string dir = folderOf(path);
    const std::string text = sceneToJson(scene_, dir);
    parseScene(text, path, dir);  // throws if what is on screen is not a loadable scene
    writeFileAtomic(path, [&](std::FILE* f) { return std::fwrite(text.data(), 1, text.size(), f) == text.size(); });
}

// Framing and the clip planes ask for it every frame; walking every vertex of a large model each time
// is kept for when the geometry or an object's transform changed.
BoundingSphere SceneDocument::bounds() const {
    std::vector<glm::mat4> transforms;
    for (std::size_t i = 0; geometry_ && i < geometry_->meshes.size() && i < scene_.objects.size(); ++i)
        transforms.push_back(worldFromObject(scene_.objects[i].transform));
    if (geometry_ && boundsGeometry_.lock() == geometry_ && boundsTransforms_ == transforms) return boundsCache_;
    std::vector<const Mesh*> meshes;
    for (std::size_t i = 0; i < transforms.size(); ++i) meshes.push_back(&geometry_->meshes[i]);
    boundsCache_ = worldBounds(meshes, transforms);
    boundsGeometry_ = geometry_;
    boundsTransforms_ = std::move(transforms);
    return boundsCache_;
}

float SceneDocument::paneAspect(int width, int height) const {
    const Pane pane = layoutPanes(scene_.layout, scene_.shading, width, height, scene_.diff).front();
    return float(std::max(pane.width, 1)) / float(std::max(pane.height, 1));
}

void SceneDocument::startFraming(int fileWidth, int fileHeight) {
    homeAspect_ = paneAspect(fileWidth, fileHeight);
    // A model without a camera of its own (what frameIfNeeded frames) is framed for whatever view shows it.
    bool model = false;
    for (const SceneObject& o : scene_.objects) model = model || o.mesh.type == MeshSpec::Type::Gltf;
    framing_ = scene_.cameraGiven || !geometry_ || !model ? Framing::Home : Framing::Model;
    if (framing_ == Framing::Model) {
        frameCamera(scene_.camera, bounds(), paneAspect(scene_.width, scene_.height));
        home_ = scene_.camera;
    }
    homeFits_ = geometry_ && framesWholeModel(home_, bounds());
}

void SceneDocument::followView() {
    if (!geometry_ || framing_ == Framing::Off) return;
    const BoundingSphere b = bounds();
    const float aspect = paneAspect(scene_.width, scene_.height);
    // A new placement only when it differs by more than rounding: recomputing the same one every frame
    // must not creep (a progressive area-light sum restarts on any camera change).
    const auto settle = [this](const Camera& placed) {
        const Camera& c = scene_.camera;
        const float scale = std::max(glm::length(c.eye - c.target), 1e-6f);
        if (glm::length(placed.eye - c.eye) > 1e-4f * scale || glm::length(placed.target - c.target) > 1e-4f * scale)
            placeCamera(placed);
    };
    if (framing_ == Framing::Model) {
        Camera placed = scene_.camera;
        frameInsidePane(placed, b, aspect);
        settle(placed);
        return;
    }
    // The home camera's target and the current viewing direction (an orbit keeps following).
    const Camera& c = scene_.camera;
    glm::vec3 dir = c.eye - c.target;
    const float homeDistance = glm::length(home_.eye - home_.target);
    if (glm::length(dir) <= 0.0f || homeDistance <= 0.0f) return;
    dir = glm::normalize(dir);
    // A camera that shows the whole model: back only as far as it takes to keep it whole in this pane.
    // One that crops it (a close-up): the same width at the target's depth as the scene's own pane
    // showed, further back in a narrower pane.
    // The lecture-hall rule: side by side panes (compare, diff) are narrow, and a model 5% from their
    // edges looks cramped next to its neighbour; the narrower the pane than the scene's own, the more
    // margin, up to 15% on each side once it is 15% narrower. At the scene's own size the margin is the
    // plain 5% (the view is then the headless image).
    float margin = kFitMargin;
    if (multiPane()) {
        const float narrower = std::clamp((homeAspect_ / aspect - 1.0f) / 0.15f, 0.0f, 1.0f);
        margin -= (kFitMargin - kPaneFitMargin) * narrower;
    }
    float fitAspect = aspect;
    const Camera clear = clearOfLabels(c, fitAspect);
    const float distance = homeFits_ ? std::max(homeDistance, fitDistance(clear, b, fitAspect, margin))
                                     : homeDistance * std::max(1.0f, homeAspect_ / aspect);
    Camera placed = c;
    placed.eye = c.target + distance * dir;
    settle(placed);
}

void SceneDocument::frameModel() {
    if (!geometry_) return;
    scene_.modelCamera = -1;  // framed by shadelab, not through the model's camera
    frameInsidePane(scene_.camera, bounds(), paneAspect(scene_.width, scene_.height));
    framing_ = Framing::Model;
    ++revision_;
}

// The pane labels take the top `labelInset_` of each pane; a model centred in the pane keeps clear of
// them when it fits the middle 1 - 2 * inset of the height: the same camera with a field of view that
// much narrower vertically, and the aspect that keeps its horizontal field.
Camera SceneDocument::clearOfLabels(const Camera& c, float& aspect) const {
    const float keep = 1.0f - 2.0f * labelInset_;
    Camera narrower = c;
    narrower.fovYDeg = glm::degrees(2.0f * std::atan(std::tan(glm::radians(c.fovYDeg) / 2.0f) * keep));
    aspect /= keep;
    return narrower;
}

bool SceneDocument::multiPane() const {
    return layoutPanes(scene_.layout, scene_.shading, scene_.width, scene_.height, scene_.diff).size() > 1;
}

void SceneDocument::frameInsidePane(Camera& c, const BoundingSphere& b, float aspect) const {
    Camera narrower = clearOfLabels(c, aspect);
    // Side by side panes: the lecture-hall margin (the model in 85% of the pane rather than 95%).
    if (multiPane())
        narrower.fovYDeg = glm::degrees(
            2.0f * std::atan(std::tan(glm::radians(narrower.fovYDeg) / 2.0f) * kPaneFitMargin / kFitMargin));
    frameCamera(narrower, b, aspect);
    narrower.fovYDeg = c.fovYDeg;
    c = narrower;
}

void SceneDocument::resetCamera() {
    scene_.camera = home_;
    scene_.modelCamera = -1;
    framing_ = Framing::Home;
    ++revision_;
    followView();
}

void SceneDocument::stopFollowing() { framing_ = Framing::Off; }

void SceneDocument::fitClipPlanes() {
    if (!geometry_) return;
    std::vector<glm::vec3> lights;
    for (const Light& l : scene_.lights)
        if (l.type != LightType::Directional) lights.push_back(l.position);
    Camera fitted = scene_.camera;
    shadelab::fitClipPlanes(fitted, bounds(), lights);
    if (fitted.nearPlane != scene_.camera.nearPlane || fitted.farPlane != scene_.camera.farPlane) placeCamera(fitted);
}

void SceneDocument::placeCamera(const Camera& placed) {
    scene_.camera = placed;
    ++revision_;
}

void SceneDocument::setViewSize(int width, int height) {
    if (scene_.width == width && scene_.height == height) return;
    scene_.width = width;
    scene_.height = height;
    ++revision_;
}

float SceneDocument::minZoomDistance() const {
    const BoundingSphere b = bounds();
    return 1e-3f * (b.radius > 0.0f ? b.radius : 1.0f);
}

float SceneDocument::maxZoomDistance() const {
    const BoundingSphere b = bounds();
    return 1e3f * (b.radius > 0.0f ? b.radius : 1.0f) + glm::length(scene_.camera.target - b.center);
}

}  // namespace shadelab
