// projectedBoxPixels: the screen area Renderer::interpolatesInputs weighs against an object's
// triangle count. Checked against boxes whose projection is known in closed form.
#include "core/geometry/camera.hpp"

#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include <cmath>

using namespace shadelab;

namespace {

// A camera on +z looking at the origin with a 90 degree vertical field of view: at distance d the
// pane's half height spans d world units.
Camera cameraAt(float distance) {
    Camera c;
    c.eye = {0.0f, 0.0f, distance};
    c.target = {0.0f, 0.0f, 0.0f};
    c.up = {0.0f, 1.0f, 0.0f};
    c.fovYDeg = 90.0f;
    return c;
}

Pane square(int size) {
    Pane p;
    p.width = p.height = size;
    return p;
}

}  // namespace

TEST(ProjectedBoxPixels, AFlatSquareFacingTheCameraCoversItsProjection) {
    // A 1 x 1 square at distance 2 (depth 0) spans 1 / (2 * 2) of the pane per side: 100 of 400 px.
    const float px = projectedBoxPixels(cameraAt(2.0f), square(400), {-0.5f, -0.5f, 0.0f}, {0.5f, 0.5f, 0.0f});
    EXPECT_NEAR(px, 100.0f * 100.0f, 1.0f);
}

TEST(ProjectedBoxPixels, ClippedToThePaneAndZeroOutsideIt) {
    const Pane pane = square(200);
    // Larger than the view: the whole pane.
    EXPECT_NEAR(projectedBoxPixels(cameraAt(1.0f), pane, {-5.0f, -5.0f, 0.0f}, {5.0f, 5.0f, 0.0f}), 200.0f * 200.0f, 1.0f);
    // Entirely to the right of the view: nothing.
    EXPECT_EQ(projectedBoxPixels(cameraAt(1.0f), pane, {10.0f, -0.5f, 0.0f}, {11.0f, 0.5f, 0.0f}), 0.0f);
    // Half of it in view: half of its projection.
    EXPECT_NEAR(projectedBoxPixels(cameraAt(2.0f), square(400), {0.0f, -0.5f, 0.0f}, {4.0f, 0.5f, 0.0f}),
                200.0f * 100.0f, 1.0f);
}

TEST(ProjectedBoxPixels, ABoxAroundTheEyeCountsAsTheWholePane) {
    // A corner at or behind the eye has no projection: the box may cover everything.
    EXPECT_EQ(projectedBoxPixels(cameraAt(1.0f), square(100), {-1.0f, -1.0f, -1.0f}, {1.0f, 1.0f, 3.0f}), 100.0f * 100.0f);
}
