// The viewer's mouse camera controls (app/viewer/orbit.hpp): plain maths on the scene's Camera.
#include "core/geometry/camera.hpp"
#include "viewer/orbit.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace shadelab {
namespace {

// Float tolerance for positions of order 1..10 after a few rotations.
constexpr float kEps = 1e-4f;

void expectNear(const glm::vec3& a, const glm::vec3& b, float eps = kEps) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

TEST(Orbit, KeepsDistanceAndTarget) {
    Camera c;
    const float dist = glm::length(c.eye - c.target);
    orbitCamera(c, 0.7f, 0.3f);
    orbitCamera(c, -2.0f, -0.5f);
    EXPECT_NEAR(glm::length(c.eye - c.target), dist, kEps);
    expectNear(c.target, Camera{}.target);
}

TEST(Orbit, YawMovesTheEyeToItsRight) {
    Camera c;
    c.eye = {0, 0, 5};
    orbitCamera(c, glm::half_pi<float>(), 0.0f);
    expectNear(c.eye, {5, 0, 0});
    orbitCamera(c, 3.0f * glm::half_pi<float>(), 0.0f);  // full turn
    expectNear(c.eye, {0, 0, 5});
}

TEST(Orbit, PitchMovesTheEyeUpAndStopsShortOfThePole) {
    Camera c;
    c.eye = {0, 0, 5};
    orbitCamera(c, 0.0f, 0.5f);
    EXPECT_GT(c.eye.y, 0.0f);
    orbitCamera(c, 0.0f, 10.0f);  // far past straight above
    const glm::vec3 dir = glm::normalize(c.eye - c.target);
    EXPECT_LT(glm::dot(dir, glm::vec3(0, 1, 0)), std::cos(glm::radians(0.9f)));
    EXPECT_GT(glm::dot(dir, glm::vec3(0, 1, 0)), std::cos(glm::radians(1.1f)));
    // The look-at frame is still well defined: viewFromWorld has no NaN.
    const glm::mat4 m = viewFromWorld(c);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) EXPECT_FALSE(std::isnan(m[i][j]));
}

TEST(Pan, MovesEyeAndTargetTogetherInTheViewPlane) {
    Camera c;
    const glm::vec3 before = c.eye - c.target;
    panCamera(c, 100.0f, -50.0f, 720.0f);
    expectNear(c.eye - c.target, before);
    // Dragging right moves the camera left, so the model follows the cursor.
    EXPECT_LT(c.target.x, 0.0f);
    EXPECT_LT(c.target.y, 0.0f);  // and dragging up moves it down
    // One view height of drag moves the target by the visible height at its depth.
    Camera d;
    d.eye = {0, 0, 5};
    panCamera(d, 0.0f, 720.0f, 720.0f);
    EXPECT_NEAR(d.target.y, 2.0f * 5.0f * std::tan(glm::radians(45.0f) / 2.0f), kEps);
}

TEST(Zoom, SameFactorAtEveryDistanceWithinItsRange) {
    Camera c;
    c.eye = {0, 0, 5};
    zoomCamera(c, 1.0f, 0.001f, 1000.0f);
    EXPECT_NEAR(c.eye.z, 4.5f, kEps);
    // Near and far do not limit it (they follow the eye): no dead range after framing.
    c.nearPlane = 4.0f, c.farPlane = 5.0f;
    float previous = c.eye.z;
    for (int step = 0; step < 40; ++step) {
        zoomCamera(c, 1.0f, 0.001f, 1000.0f);
        EXPECT_NEAR(c.eye.z, 0.9f * previous, 1e-4f) << "step " << step;
        previous = c.eye.z;
    }
    for (int step = 0; step < 40; ++step) {
        zoomCamera(c, -1.0f, 0.001f, 1000.0f);
        EXPECT_NEAR(c.eye.z, previous / 0.9f, 1e-3f) << "step " << step;
        previous = c.eye.z;
    }
    zoomCamera(c, 1000.0f, 0.001f, 1000.0f);
    EXPECT_NEAR(c.eye.z, 0.001f, 1e-6f);
    zoomCamera(c, -1000.0f, 0.001f, 1000.0f);
    EXPECT_NEAR(c.eye.z, 1000.0f, 1e-1f);
}

TEST(ClipPlanes, AroundTheModelAndTheLightsFromAnyDistance) {
    const BoundingSphere unit{{0, 0, 0}, 1.0f};
    for (float d : {1.05f, 2.0f, 5.0f, 50.0f, 5000.0f}) {
        Camera c;
        c.eye = {0, 0, d};
        fitClipPlanes(c, unit, {});
        EXPECT_LE(c.nearPlane, d - 1.0f) << d;  // never into the sphere
        EXPECT_GE(c.farPlane, d + 1.0f) << d;   // never cuts its back
        EXPECT_GT(c.nearPlane, 0.0f);
    }
    Camera inside;
    inside.eye = {0, 0, 0.5f};
    fitClipPlanes(inside, unit, {glm::vec3(0, 0, -10)});
    EXPECT_GE(inside.farPlane, 10.5f);  // the light behind the model is in range for its marker
    EXPECT_GE(inside.nearPlane, inside.farPlane * 1e-5f);  // depth precision
    EXPECT_LT(inside.nearPlane, 0.01f);
    // A very distant light in front of the eye never pushes near into the model.
    Camera outside;
    outside.eye = {0, 0, 5};
    fitClipPlanes(outside, unit, {glm::vec3(0, 0, -5000)});
    EXPECT_LE(outside.nearPlane, 4.0f);
    EXPECT_GE(outside.farPlane, 6.0f);
}

TEST(FitDistance, ClosestDistanceAtWhichTheSphereFits) {
    Camera c;
    c.eye = {0, 0, 5};
    const BoundingSphere unit{{0, 0, 0}, 1.0f};
    for (float aspect : {0.3f, 1.0f, 16.0f / 9.0f}) {
        const float d = fitDistance(c, unit, aspect, 1.0f);
        Camera at = c;
        at.nearPlane = 1e-3f, at.farPlane = 1e6f;
        at.eye = {0, 0, d * 1.001f};
        EXPECT_TRUE(sphereInView(at, unit, aspect)) << aspect;
        at.eye = {0, 0, d * 0.999f};
        EXPECT_FALSE(sphereInView(at, unit, aspect)) << aspect;
    }
    // A narrower pane needs more distance, a margin more still.
    EXPECT_GT(fitDistance(c, unit, 0.3f, 1.0f), fitDistance(c, unit, 1.0f, 1.0f));
    EXPECT_GT(fitDistance(c, unit, 1.0f, 0.9f), fitDistance(c, unit, 1.0f, 1.0f));
}

TEST(Frame, FitsTheSphereAndKeepsTheDirection) {
    Camera c;
    const glm::vec3 dir = glm::normalize(c.eye - c.target);
    frameCamera(c, BoundingSphere{{1, 2, 3}, 2.0f}, 16.0f / 9.0f);
    expectNear(c.target, {1, 2, 3});
    expectNear(glm::normalize(c.eye - c.target), dir);
    // The sphere's silhouette takes 90% of the vertical half-angle (the tighter side at 16:9).
    const float dist = glm::length(c.eye - c.target);
    EXPECT_NEAR(std::asin(2.0f / dist), 0.9f * glm::radians(c.fovYDeg) / 2.0f, 1e-4f);
    EXPECT_LT(c.nearPlane, dist - 2.0f);
    EXPECT_GT(c.farPlane, dist + 2.0f);
}

TEST(SphereInView, FollowsThePaneAspect) {
    Camera c;
    c.eye = {0, 0, 5};
    const BoundingSphere unit{{0, 0, 0}, 1.0f};
    EXPECT_TRUE(sphereInView(c, unit, 16.0f / 9.0f));
    // At d = 5 and a 45 degree vertical field, a pane narrower than ~0.52 of its height crops x.
    EXPECT_FALSE(sphereInView(c, unit, 0.4f));
    EXPECT_FALSE(sphereInView(c, BoundingSphere{{3, 0, 0}, 1.0f}, 16.0f / 9.0f));
    EXPECT_FALSE(sphereInView(c, BoundingSphere{{0, 0, 6}, 0.5f}, 1.0f));  // behind the eye
    frameCamera(c, unit, 0.4f);
    EXPECT_TRUE(sphereInView(c, unit, 0.4f));
}

}  // namespace
}  // namespace shadelab
