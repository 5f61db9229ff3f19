#pragma once
// Camera and transform maths (GLM conventions: right-handed look-at, OpenGL clip space), and the
// pane layout of a frame. Names say the spaces: clipFromView * viewFromWorld * worldFromObject.
#include "core/geometry/mesh.hpp"
#include "core/scene/scene.hpp"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include <string>
#include <vector>

namespace shadelab {

glm::mat4 viewFromWorld(const Camera& camera);
glm::mat4 clipFromView(const Camera& camera, float aspect);
glm::mat4 worldFromObject(const Transform& t);
// Inverse transpose of the upper 3x3: takes object-space normals to world space.
glm::mat3 normalWorldFromObject(const glm::mat4& worldFromObject);

// One viewport of a frame. Coordinates are image pixels with (0, 0) at the top-left corner.
struct Pane {
    int x = 0, y = 0, width = 0, height = 0;
    ShadingMode mode = ShadingMode::Phong;
    bool difference = false;  // layout diff's third pane: |pane 0 - pane 1| * factor (mode = diff.b)
};
// single: one pane with the scene's mode; compare: three equal panes flat | gouraud | phong;
// diff: three panes of exactly the same size diff.a | diff.b | difference (the last width % 3
// columns stay background, so the difference pane's pixels line up with both sources).
std::vector<Pane> layoutPanes(Layout layout, ShadingMode mode, int width, int height,
                              const DiffSettings& diff = DiffSettings{});
// How many of a layout's panes draw the scene (layoutPanes' panes but the difference pane): single 1,
// compare 3, diff 2. A frame draws the scene's triangles this many times.
std::size_t scenePaneCount(Layout layout);

// The unit direction (world space) from the eye through image point (px, py) of a pane; pixel
// centres are at +0.5, y runs down. The inverse of the renderer's projection for that pane.
glm::vec3 pixelDirectionWorld(const Camera& camera, const Pane& pane, float px, float py);
// Where a world point lands in the image: continuous pixel coordinates (y down) in x, y, and the
// clip-space w in z (positive in front of the eye).
glm::vec3 projectToImage(const Camera& camera, const Pane& pane, const glm::vec3& posWorld);
// How many of a pane's pixels a world-space box [lo, hi] can cover: the rectangle around its eight
// projected corners, clipped to the pane; the whole pane when a corner is at or behind the eye.
float projectedBoxPixels(const Camera& camera, const Pane& pane, const glm::vec3& lo, const glm::vec3& hi);

// Places the camera so a bounding sphere fills most of a pane of the given aspect, looking from the
// default camera's direction; when the scene gave no lights, moves the default light with it.
void frameBounds(Scene& scene, const BoundingSphere& bounds, float paneAspect);

}  // namespace shadelab
