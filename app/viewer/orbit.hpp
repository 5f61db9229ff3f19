#pragma once
// Mouse camera controls as plain functions on the scene's Camera (no GL, no GLFW), so the viewer's
// orbit, pan, zoom and framing are unit-tested and what the mouse does is exactly what a saved scene
// holds. The target is the centre of the orbit; `up` is kept as the scene gave it.
#include "core/geometry/mesh.hpp"
#include "core/scene/scene.hpp"

#include <glm/vec3.hpp>

#include <vector>

namespace shadelab {

// Turns the eye around the target: `yawRad` about the camera's up vector (positive moves the eye to
// its right), `pitchRad` about its right vector (positive moves the eye up). Pitch stops 1 degree short of the up
// vector, where the look-at frame would flip.
void orbitCamera(Camera& camera, float yawRad, float pitchRad);

// Moves eye and target together in the view plane so the point under the cursor follows it: `dx`, `dy`
// are pixels (right, down) in a view `viewHeight` pixels high.
void panCamera(Camera& camera, float dx, float dy, float viewHeight);

// Moves the eye towards the target by 10% per wheel step (negative steps move away), the same factor at
// every distance; the distance stays within [minDistance, maxDistance] (from the model's size: close to
// its surface, far away). Near and far are not touched: fitClipPlanes() follows the eye every frame.
void zoomCamera(Camera& camera, float wheelSteps, float minDistance, float maxDistance);

// Near and far planes around what can be seen from the eye: the bounding sphere and `points` (the
// lights, whose markers are drawn), with room for the probe's arrows (near at half the nearest depth,
// far at 1.5 times the farthest); near never reaches into the sphere while the eye is outside it, and
// stays above far / 10^4 (24-bit depth) inside it.
void fitClipPlanes(Camera& camera, const BoundingSphere& bounds, const std::vector<glm::vec3>& points);

// The eye's distance from the target, along the current viewing direction, at which the whole sphere
// is inside a pane of this aspect with its half angles shrunk by `margin` (1: touching the borders).
// Near and far are ignored (fitClipPlanes places them).
float fitDistance(const Camera& camera, const BoundingSphere& bounds, float paneAspect, float margin);

// Looks at the bounding sphere from the camera's current direction, from a distance at which it fills
// 90% of the tighter side of a pane with this aspect (width / height); near and far follow.
void frameCamera(Camera& camera, const BoundingSphere& bounds, float paneAspect);

// True when the whole bounding sphere is inside the view frustum of a pane with this aspect.
bool sphereInView(const Camera& camera, const BoundingSphere& bounds, float paneAspect);

}  // namespace shadelab
