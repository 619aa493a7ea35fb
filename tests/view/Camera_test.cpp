// Camera.cpp: docs/book-reference.md §1.4 defaults, presets, clamps, Update closed form and the view matrix.
#include "Application/View/Camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "tests/support/Approx.h"

namespace {

/// Test access to the protected world matrix setter and limits.
class TestCamera : public OrbitCamera {
public:
    using Camera::SetWorld;
    vec2 ZoomLimits() const { return zoomDistanceLimit; }
    vec2 PitchLimits() const { return yRotationLimit; }
};

vec3 Row(const mat4& m, int i) { return vec3(m[i][0], m[i][1], m[i][2]); }

}  // namespace

TEST(Camera, DefaultsMatchBook) {
    Camera camera;
    EXPECT_FLOAT_EQ(camera.GetAspect(), 1.3f);
    EXPECT_TRUE(camera.IsPerspective());
    EXPECT_TRUE(MatNear(camera.GetProjectionMatrix(), Projection(60.0f, 1.3f, 0.01f, 1000.0f), tol::kExact));
    EXPECT_TRUE(MatNear(camera.GetWorldMatrix(), mat4(), tol::kExact));
}

TEST(Camera, ProjectionEntriesForDemoSettings) {
    // Demos: 60 degrees, 800/600, 0.01, 1000. _22 = cot(30 deg) = sqrt(3), _11 = sqrt(3)/(4/3).
    Camera camera;
    camera.Perspective(60.0f, 800.0f / 600.0f, 0.01f, 1000.0f);
    const mat4 p = camera.GetProjectionMatrix();
    EXPECT_NEAR(p[1][1], std::sqrt(3.0f), tol::kLoose);
    EXPECT_NEAR(p[0][0], std::sqrt(3.0f) * 0.75f, tol::kLoose);
    EXPECT_NEAR(p[2][2], 1000.0f / (1000.0f - 0.01f), tol::kTight);
    EXPECT_FLOAT_EQ(p[2][3], 1.0f);
    EXPECT_NEAR(p[3][2], -0.01f * 1000.0f / (1000.0f - 0.01f), tol::kTight);
    EXPECT_FLOAT_EQ(p[3][3], 0.0f);
}

TEST(Camera, ResizeRebuildsPerspectiveButNotUserProjection) {
    Camera camera;
    camera.Resize(800, 600);
    EXPECT_NEAR(camera.GetAspect(), 4.0f / 3.0f, tol::kExact);
    EXPECT_TRUE(MatNear(camera.GetProjectionMatrix(), Projection(60.0f, 4.0f / 3.0f, 0.01f, 1000.0f), tol::kExact));
    const mat4 user = Scale(2, 3, 4);
    camera.SetProjection(user);
    camera.Resize(100, 100);
    EXPECT_TRUE(MatNear(camera.GetProjectionMatrix(), user, tol::kExact));
    camera.Resize(100, 0);  // zero height does not divide by zero
    EXPECT_TRUE(std::isfinite(camera.GetAspect()));
}

TEST(Camera, ViewMatrixReorthonormalisesSkewedWorld) {
    TestCamera camera;
    // A skewed, scaled world matrix: forward (0,0,2), up (0.3,1,0), right (1,0,0.5), eye (1,2,3).
    mat4 world(1, 0, 0.5f, 0, 0.3f, 1, 0, 0, 0, 0, 2, 0, 1, 2, 3, 1);
    camera.SetWorld(world);
    EXPECT_FALSE(camera.IsOrthoNormal());
    const mat4 view = camera.GetViewMatrix();
    EXPECT_TRUE(camera.IsOrthoNormal());
    // Forward kept (normalised): the view maps the eye to 0 and eye + forward to (0,0,1).
    EXPECT_TRUE(VecNear(MultiplyPoint(vec3(1, 2, 3), view), vec3(0, 0, 0), tol::kTight));
    EXPECT_TRUE(VecNear(MultiplyPoint(vec3(1, 2, 4), view), vec3(0, 0, 1), tol::kTight));
    // right = up x forward = (0.3,1,0) x (0,0,1) = (1,-0.3,0)/|.|.
    const vec3 right = Normalized(vec3(1, -0.3f, 0));
    EXPECT_TRUE(VecNear(Row(camera.GetWorldMatrix(), 0), right, tol::kTight));
}

TEST(OrbitCamera, DefaultsMatchBook) {
    TestCamera camera;
    EXPECT_TRUE(VecNear(camera.GetTarget(), vec3(0, 0, 0), tol::kExact));
    EXPECT_FLOAT_EQ(camera.GetZoom(), 10.0f);
    EXPECT_TRUE(Vec2Near(camera.GetRotation(), vec2(0, 0), tol::kExact));
    EXPECT_TRUE(Vec2Near(camera.ZoomLimits(), vec2(3, 15), tol::kExact));
    EXPECT_TRUE(Vec2Near(camera.PitchLimits(), vec2(-20, 80), tol::kExact));
    // Raycast demo preset = defaults: eye (0,0,-10) looking along +Z, +X on screen right (row 0 = +X).
    camera.Update(0.03f);
    EXPECT_TRUE(VecNear(camera.GetEye(), vec3(0, 0, -10), tol::kExact));
    EXPECT_TRUE(VecNear(GetTranslation(camera.GetWorldMatrix()), vec3(0, 0, -10), tol::kTight));
    EXPECT_TRUE(VecNear(Row(camera.GetWorldMatrix(), 2), vec3(0, 0, 1), tol::kTight));
    EXPECT_TRUE(VecNear(Row(camera.GetWorldMatrix(), 0), vec3(1, 0, 0), tol::kTight));
}

TEST(OrbitCamera, BookPresetsGiveBookEyes) {
    // docs/book-reference.md §1.4 table: target (3.75622, 2.98255, 0), rotation (-67.9312, 19.8).
    struct Case {
        float zoom;
        vec3 eye;
    };
    for (const Case& c :
         {Case{9.0f, vec3(11.6037f, 6.0312f, -3.1816f)}, Case{12.0f, vec3(14.2196f, 7.0474f, -4.2421f)}}) {
        TestCamera camera;
        camera.SetTarget(vec3(3.75622f, 2.98255f, 0));
        camera.SetZoom(c.zoom);
        camera.SetRotation(vec2(-67.9312f, 19.8f));
        camera.Update(0.03f);
        EXPECT_TRUE(VecNear(camera.GetEye(), c.eye, 2e-4f)) << "zoom " << c.zoom;  // book prints 4 decimals
        EXPECT_TRUE(VecNear(GetTranslation(camera.GetWorldMatrix()), c.eye, 2e-4f));
        // The camera looks at the target: target in view space is (0, 0, zoom).
        EXPECT_TRUE(VecNear(MultiplyPoint(camera.GetTarget(), camera.GetViewMatrix()), vec3(0, 0, c.zoom), 1e-3f));
    }
}

TEST(OrbitCamera, UpdateMatchesClosedFormForRandomStates) {
    std::mt19937 rng(1414);
    std::uniform_real_distribution<float> yaw(-360, 360), pitch(-20, 80), zoom(3, 15), pos(-10, 10);
    for (int i = 0; i < 500; ++i) {
        TestCamera camera;
        const vec3 target(pos(rng), pos(rng), pos(rng));
        const float y = yaw(rng), p = pitch(rng), z = zoom(rng);
        camera.SetTarget(target);
        camera.SetZoom(z);
        camera.SetRotation(vec2(y, p));
        camera.Update(0.03f);
        const float pr = p * 3.14159265f / 180.0f, yr = y * 3.14159265f / 180.0f;
        const vec3 expected =
            target + vec3(-std::cos(pr) * std::sin(yr), std::sin(pr), -std::cos(pr) * std::cos(yr)) * z;
        ASSERT_TRUE(VecNear(camera.GetEye(), expected, 2e-4f)) << i;
        // The world matrix is orthonormal with forward toward the target.
        const mat4 w = camera.GetWorldMatrix();
        ASSERT_TRUE(camera.IsOrthoNormal());
        ASSERT_TRUE(VecNear(Row(w, 2), Normalized(target - expected), 1e-4f)) << i;
    }
}

TEST(OrbitCamera, ZoomIsScaledAndClamped) {
    TestCamera camera;
    camera.Zoom(0.01f, 0.5f);  // 10 + 0.01 * 200 * 0.5 = 11
    EXPECT_NEAR(camera.GetZoom(), 11.0f, tol::kTight);
    camera.Zoom(1.0f, 1.0f);  // far past 15
    EXPECT_FLOAT_EQ(camera.GetZoom(), 15.0f);
    camera.Zoom(-1.0f, 1.0f);
    EXPECT_FLOAT_EQ(camera.GetZoom(), 3.0f);
}

TEST(OrbitCamera, RotateScalesWithZoomWrapsYawClampsPitch) {
    TestCamera camera;
    // x: 0.01 * 250 * 10 * 0.1 = 2.5 degrees; y: 0.01 * 120 * 10 * 0.1 = 1.2 degrees.
    camera.Rotate(vec2(0.01f, 0.01f), 0.1f);
    EXPECT_TRUE(Vec2Near(camera.GetRotation(), vec2(2.5f, 1.2f), tol::kTight));
    // Pitch clamps at 80 and -20.
    camera.Rotate(vec2(0, 1), 1.0f);
    EXPECT_FLOAT_EQ(camera.GetRotation().y, 80.0f);
    camera.Rotate(vec2(0, -1), 1.0f);
    EXPECT_FLOAT_EQ(camera.GetRotation().y, -20.0f);
    // Yaw wraps by whole turns into [-360, 360]: 2.5 + 0.2 * 250 * 10 * 1 = 502.5 -> 142.5.
    camera.Rotate(vec2(0.2f, 0), 1.0f);
    EXPECT_NEAR(camera.GetRotation().x, 142.5f, tol::kLoose);
    EXPECT_FLOAT_EQ(camera.ClampAngle(-400.0f, -360.0f, 360.0f), -40.0f);
    EXPECT_FLOAT_EQ(camera.ClampAngle(30.0f, -20.0f, 10.0f), 10.0f);
}

TEST(OrbitCamera, PanMovesTargetAndResetsZoomKeepingEye) {
    TestCamera camera;  // eye (0,0,-10), right = +X
    camera.Update(0.03f);
    camera.Pan(vec2(0.01f, 0.02f), 0.5f);  // target -= X * 0.9, target += Y * 1.8
    // Panned target (-0.9, 1.8, 0); eye stays at (-0.9, 1.8, -10); zoom becomes 9 along +Z.
    EXPECT_FLOAT_EQ(camera.GetZoom(), 9.0f);
    EXPECT_TRUE(VecNear(camera.GetTarget(), vec3(-0.9f, 1.8f, -1.0f), tol::kTight));
    EXPECT_TRUE(VecNear(camera.GetEye(), vec3(-0.9f, 1.8f, -10.0f), tol::kTight));
}
