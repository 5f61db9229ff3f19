#include "viewer/scene_document.hpp"

#include "core/camera.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/scene_json.hpp"
#include "viewer/orbit.hpp"

#include <cstdio>
#include <filesystem>

namespace shadelab {
namespace {

std::string folderOf(const std::string& path) {
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    return parent.empty() ? "." : parent.string();
}

}  // namespace

SceneDocument::SceneDocument(Scene scene, std::shared_ptr<const SceneGeometry> geometry)
    : scene_(std::move(scene)), geometry_(std::move(geometry)), home_(scene_.camera) {}

bool SceneDocument::syncGeometry() {
    bool same = geometry_ && geometry_->specs.size() == scene_.objects.size();
    for (std::size_t i = 0; same && i < scene_.objects.size(); ++i) same = scene_.objects[i].mesh == geometry_->specs[i];
    if (same) return false;
    try {
        geometry_ = std::make_shared<const SceneGeometry>(buildSceneGeometry(scene_));
    } catch (...) {
        // Put back the specs the current geometry was built from; objects added since keep theirs.
        if (geometry_)
            for (std::size_t i = 0; i < scene_.objects.size() && i < geometry_->specs.size(); ++i)
                scene_.objects[i].mesh = geometry_->specs[i];
        throw;
    }
    return true;
}

void SceneDocument::load(const std::string& path) {
    replace(hasModelExtension(path) ? sceneForModel(path) : loadSceneFile(path));
}

void SceneDocument::replace(Scene next) {
    const int fileWidth = next.width, fileHeight = next.height;
    next.width = scene_.width;
    next.height = scene_.height;
    auto geometry = std::make_shared<const SceneGeometry>(buildSceneGeometry(next));
    frameIfNeeded(next, *geometry);
    // Nothing above touched the document: commit.
    scene_ = std::move(next);
    geometry_ = std::move(geometry);
    home_ = scene_.camera;
    fitToView(fileWidth, fileHeight);
}

void SceneDocument::restore(Scene scene, const Camera& home) {
    scene.width = scene_.width;
    scene.height = scene_.height;
    auto geometry = std::make_shared<const SceneGeometry>(buildSceneGeometry(scene));
    scene_ = std::move(scene);
    geometry_ = std::move(geometry);
    home_ = home;
}

void SceneDocument::save(const std::string& path) const {
    checkOutputPath(path, "save");
    const std::string dir = folderOf(path);
    const std::string text = sceneToJson(scene_, dir);
    parseScene(text, path, dir);  // throws if what is on screen is not a loadable scene
    writeFileAtomic(path, [&](std::FILE* f) { return std::fwrite(text.data(), 1, text.size(), f) == text.size(); });
}

BoundingSphere SceneDocument::bounds() const {
    std::vector<const Mesh*> meshes;
    std::vector<glm::mat4> transforms;
    for (std::size_t i = 0; geometry_ && i < geometry_->meshes.size() && i < scene_.objects.size(); ++i) {
        meshes.push_back(&geometry_->meshes[i]);
        transforms.push_back(worldFromObject(scene_.objects[i].transform));
    }
    return worldBounds(meshes, transforms);
}

float SceneDocument::paneAspect(int width, int height) const {
    const Pane pane = layoutPanes(scene_.layout, scene_.shading, width, height, scene_.diff).front();
    return float(std::max(pane.width, 1)) / float(std::max(pane.height, 1));
}

void SceneDocument::frameModel() {
    if (!geometry_) return;
    frameCamera(scene_.camera, bounds(), paneAspect(scene_.width, scene_.height));
}

bool SceneDocument::fitToView(int width, int height) {
    if (!geometry_ || (scene_.width >= width && scene_.height >= height)) return false;
    const BoundingSphere b = bounds();
    if (b.radius <= 0.0f || !sphereInView(scene_.camera, b, paneAspect(width, height)) ||
        sphereInView(scene_.camera, b, paneAspect(scene_.width, scene_.height)))
        return false;
    frameModel();
    home_ = scene_.camera;
    return true;
}

}  // namespace shadelab
