// Animations without GL: parsing --animate's specs, the frame count, and the scene at a time t.
#include "core/base/error.hpp"
#include "core/scene/animation.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>

using namespace shadelab;

namespace {

std::string errorOf(const std::string& spec) {
    try {
        parseAnimation(spec, "--animate");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

Scene twoObjects() {
    Scene s;
    s.objects.resize(2);
    s.lights.resize(1);
    s.camera.eye = {0.0f, 1.0f, 5.0f};
    s.camera.target = {0.0f, 1.0f, 0.0f};
    return s;
}

}  // namespace

TEST(Animation, ParsesEachForm) {
    const Animation light = parseAnimation("light-orbit", "--animate");
    EXPECT_EQ(light.kind, Animation::Kind::LightOrbit);
    EXPECT_EQ(light.seconds, kDefaultAnimationSeconds);
    EXPECT_EQ(parseAnimation("camera-orbit:8", "--animate").seconds, 8.0);
    const Animation ke = parseAnimation("ke=1..1000:log:2.5", "--animate");
    EXPECT_EQ(ke.kind, Animation::Kind::Ramp);
    EXPECT_EQ(ke.parameter, "ke");
    EXPECT_EQ(ke.from, "1");
    EXPECT_EQ(ke.to, "1000");
    EXPECT_TRUE(ke.logarithmic);
    EXPECT_EQ(ke.seconds, 2.5);
    const Animation ks = parseAnimation("ks=0.9..0.1:3", "--animate");  // downwards, linear
    EXPECT_FALSE(ks.logarithmic);
    EXPECT_EQ(ks.seconds, 3.0);
    EXPECT_EQ(parseAnimation("shading=flat..phong", "--animate").to, "phong");
}

TEST(Animation, BadSpecsNameThePartThatIsWrong) {
    EXPECT_NE(errorOf("spin").find("--animate: spin: \"spin\" is not an animation (expected light-orbit"),
              std::string::npos)
        << errorOf("spin");
    EXPECT_NE(errorOf("light-orbit:fast").find("\"fast\" is not a number of seconds"), std::string::npos);
    EXPECT_NE(errorOf("light-orbit:0").find("0 seconds is out of range"), std::string::npos);
    EXPECT_NE(errorOf("camera-orbit:-1").find("out of range"), std::string::npos);
    EXPECT_NE(errorOf("camera-orbit:4:log").find("an orbit takes only :SECONDS"), std::string::npos);
    EXPECT_NE(errorOf("ke=0..1000").find("ke: 0 is out of range"), std::string::npos) << errorOf("ke=0..1000");
    EXPECT_NE(errorOf("shininess=1..8").find("unknown parameter \"shininess\""), std::string::npos);
    EXPECT_NE(errorOf("ke=1,8").find("is not an animation"), std::string::npos);
    EXPECT_NE(errorOf("ke=1..").find("a ramp needs both ends"), std::string::npos);
    EXPECT_NE(errorOf("ks=0..1:log").find(":log needs both ends above 0"), std::string::npos);
    EXPECT_NE(errorOf("shading=flat..phong:log").find(":log ramps numbers"), std::string::npos);
    EXPECT_NE(errorOf("shading=flat..toon").find("unknown value \"toon\""), std::string::npos);
    EXPECT_NE(errorOf("ke=1..8:2:3").find("\"3\" after the seconds"), std::string::npos);
    EXPECT_NE(errorOf("ke=1..8:lin").find("\"lin\" is not a number of seconds"), std::string::npos);
    EXPECT_NE(errorOf("ke=1..8:1:2:3").find("not an animation"), std::string::npos);
}

TEST(Animation, FrameCountEndsARampOnItsEndValueAndAnOrbitBeforeItRepeats) {
    const std::vector<Animation> ramp{parseAnimation("ke=1..1000:log:4", "f")};
    const std::vector<Animation> orbit{parseAnimation("light-orbit:4", "f")};
    EXPECT_EQ(animationFrameCount(ramp, 4.0, 30), 121);  // t = 0, 1/30, ..., 4
    EXPECT_EQ(animationFrameCount(orbit, 4.0, 30), 120);  // t = 4 would be t = 0 again
    EXPECT_EQ(animationFrameCount(ramp, 0.5, 20), 11);
    EXPECT_EQ(animationFrameCount(ramp, 0.52, 20), 12);  // the last frame just past the end
    EXPECT_EQ(animationsDuration({ramp[0], parseAnimation("camera-orbit:6", "f")}), 6.0);
}

TEST(Animation, RampGoesFromAToBAndStays) {
    const Scene base = twoObjects();
    const std::vector<Animation> log{parseAnimation("ke=1..1000:log:4", "f")};
    for (const SceneObject& o : sceneAtTime(base, log, 0.0, "f").objects) EXPECT_EQ(o.material.ke, 1.0f);
    EXPECT_NEAR(sceneAtTime(base, log, 2.0, "f").objects[1].material.ke, std::sqrt(1000.0), 1e-3);  // equal ratios
    EXPECT_EQ(sceneAtTime(base, log, 4.0, "f").objects[0].material.ke, 1000.0f);
    EXPECT_EQ(sceneAtTime(base, log, 9.0, "f").objects[0].material.ke, 1000.0f);
    const std::vector<Animation> linear{parseAnimation("ks=0.9..0.1:2", "f")};
    EXPECT_NEAR(sceneAtTime(base, linear, 0.5, "f").objects[0].material.ks, 0.7f, 1e-6);
    const std::vector<Animation> tess{parseAnimation("tessellation=8..64", "f")};
    EXPECT_EQ(sceneAtTime(base, tess, 1.01, "f").objects[0].mesh.slices, 22);  // 8 + 56 * 0.2525, rounded
    const std::vector<Animation> names{parseAnimation("reflection=phong..blinn-phong:2", "f")};
    EXPECT_EQ(sceneAtTime(base, names, 0.9, "f").reflection, ReflectionModel::Phong);
    EXPECT_EQ(sceneAtTime(base, names, 1.1, "f").reflection, ReflectionModel::BlinnPhong);
}

TEST(Animation, LightOrbitKeepsTheLightsHeightAndDistance) {
    Scene base = twoObjects();
    base.lights[0].position = {3.0f, 4.0f, 0.0f};
    base.lights[0].direction = {-1.0f, -1.0f, 0.0f};
    const std::vector<Animation> orbit{parseAnimation("light-orbit:4", "f")};
    const Light quarter = sceneAtTime(base, orbit, 1.0, "f").lights[0];
    // A quarter turn about +y through the target (0, 1, 0): +x goes to -z; the height stays 4.
    EXPECT_NEAR(quarter.position.x, 0.0f, 1e-5);
    EXPECT_NEAR(quarter.position.y, 4.0f, 1e-5);
    EXPECT_NEAR(quarter.position.z, -3.0f, 1e-5);
    EXPECT_NEAR(quarter.direction.z, 1.0f, 1e-5);  // a directional light's direction turns with it
    EXPECT_NEAR(quarter.direction.y, -1.0f, 1e-5);
    EXPECT_EQ(sceneAtTime(base, orbit, 0.0, "f").lights[0].position, base.lights[0].position);
    EXPECT_EQ(sceneAtTime(base, orbit, 1.0, "f").camera.eye, base.camera.eye);  // only the light moves
    Scene dark = base;
    dark.lights.clear();
    EXPECT_THROW(sceneAtTime(dark, orbit, 0.0, "--animate"), InputError);
}

TEST(Animation, CameraOrbitTurnsTheEyeAboutTheTarget) {
    const Scene base = twoObjects();
    const std::vector<Animation> orbit{parseAnimation("camera-orbit:8", "f")};
    const Scene half = sceneAtTime(base, orbit, 4.0, "f");
    EXPECT_NEAR(half.camera.eye.x, 0.0f, 1e-5);
    EXPECT_NEAR(half.camera.eye.y, 1.0f, 1e-5);
    EXPECT_NEAR(half.camera.eye.z, -5.0f, 1e-5);
    EXPECT_EQ(half.camera.target, base.camera.target);
    EXPECT_EQ(half.lights[0].position, base.lights[0].position);
}

TEST(Animation, SeveralAtOnceAndTheirErrorsNameTheSpec) {
    Scene base = twoObjects();
    const std::vector<Animation> both{parseAnimation("ke=1..100:2", "f"), parseAnimation("camera-orbit", "f")};
    const Scene s = sceneAtTime(base, both, 2.0, "f");
    EXPECT_EQ(s.objects[0].material.ke, 100.0f);
    EXPECT_NEAR(s.camera.eye.z, -5.0f, 1e-5);
    base.objects[0].mesh.type = MeshSpec::Type::Cube;
    try {
        sceneAtTime(base, {parseAnimation("tessellation=8..16", "f")}, 0.0, "--animate");
        ADD_FAILURE() << "a tessellation ramp on a cube was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("--animate: tessellation=8..16: tessellation: the first object is a cube"),
                  std::string::npos)
            << e.what();
    }
}
