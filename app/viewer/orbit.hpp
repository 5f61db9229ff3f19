#pragma once
// Mouse camera controls as plain functions on the scene's Camera (no GL, no GLFW), so the viewer's
// orbit, pan, zoom and framing are unit-tested and what the mouse does is exactly what a saved scene
// holds. The target is the centre of the orbit; `up` is kept as the scene gave it.
#include "core/mesh.hpp"
#include "core/scene.hpp"

namespace shadelab {

// Turns the eye around the target: `yawRad` about the camera's up vector (positive moves the eye to
// its right), `pitchRad` about its right vector (positive moves the eye up). Pitch stops 1 degree short of the up vector, where the
// look-at frame would flip.
void orbitCamera(Camera& camera, float yawRad, float pitchRad);

// Moves eye and target together in the view plane so the point under the cursor follows it: `dx`, `dy`
// are pixels (right, down) in a view `viewHeight` pixels high.
void panCamera(Camera& camera, float dx, float dy, float viewHeight);

// Moves the eye towards the target by 10% per wheel step (negative steps move away). The distance stays
// between 2 * near and far / 2 so the model is never clipped away.
void zoomCamera(Camera& camera, float wheelSteps);

// Looks at the bounding sphere from the camera's current direction, from a distance at which it fills
// 90% of the tighter side of a pane with this aspect (width / height); near and far follow.
void frameCamera(Camera& camera, const BoundingSphere& bounds, float paneAspect);

// True when the whole bounding sphere is inside the view frustum of a pane with this aspect.
bool sphereInView(const Camera& camera, const BoundingSphere& bounds, float paneAspect);

}  // namespace shadelab
