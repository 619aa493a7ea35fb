// Picking.cpp: Unproject / GetPickRay against the book's default demo camera and a projection round trip.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "Application/View/Camera.h"
#include "Physics/Geometry/Geometry3D.h"
#include "tests/support/Approx.h"

namespace {

struct DemoCamera {
    mat4 view, proj;
};

/// The Raycast Demo camera: OrbitCamera defaults (eye (0,0,-10) looking +Z), 60 degrees, 800x600, 0.01..1000.
DemoCamera DefaultDemoCamera() {
    OrbitCamera camera;
    camera.Perspective(60.0f, 800.0f / 600.0f, 0.01f, 1000.0f);
    camera.Update(0.03f);
    return {camera.GetViewMatrix(), camera.GetProjectionMatrix()};
}

/// world * view * proj as a row vector, divided by w, then to pixels (y down) and depth in [0,1].
vec3 ProjectToScreen(const vec3& p, const mat4& view, const mat4& proj, const vec2& size) {
    // In double, two steps, so that the test's own rounding does not dominate the comparison.
    double v[4];
    for (int j = 0; j < 4; ++j)
        v[j] = double(p.x) * view[0][j] + double(p.y) * view[1][j] + double(p.z) * view[2][j] + view[3][j];
    double clip[4];
    for (int j = 0; j < 4; ++j) clip[j] = v[0] * proj[0][j] + v[1] * proj[1][j] + v[2] * proj[2][j] + v[3] * proj[3][j];
    const double x = clip[0] / clip[3], y = clip[1] / clip[3], z = clip[2] / clip[3];
    return vec3(float((x + 1.0) * 0.5 * size.x), float((1.0 - y) * 0.5 * size.y), float(z));
}

}  // namespace

TEST(Picking, ScreenCentreOfDefaultCameraLooksAlongPlusZ) {
    const DemoCamera cam = DefaultDemoCamera();
    const Ray ray = GetPickRay(vec2(400, 300), vec2(0, 0), vec2(800, 600), cam.view, cam.proj);
    EXPECT_TRUE(VecNear(ray.direction, vec3(0, 0, 1), tol::kLoose));
    // Origin on the near plane: 0.01 in front of the eye.
    EXPECT_TRUE(VecNear(ray.origin, vec3(0, 0, -9.99f), tol::kLoose));
}

TEST(Picking, CornersSpreadByTheFieldOfView) {
    const DemoCamera cam = DefaultDemoCamera();
    // Top-left pixel: left is -X (left-handed, +X on the right), up is +Y (mouse y points down). In view space
    // the direction is (-tan30 * aspect, tan30, 1).
    const Ray ray = GetPickRay(vec2(0, 0), vec2(0, 0), vec2(800, 600), cam.view, cam.proj);
    const float t30 = std::tan(3.14159265f / 6.0f);
    EXPECT_TRUE(VecNear(ray.direction, Normalized(vec3(-t30 * 4.0f / 3.0f, t30, 1)), tol::kLoose));
    // A viewport offset shifts the same ray: pixel (100,50) of a viewport at (100,50) is its top-left.
    const Ray shifted = GetPickRay(vec2(100, 50), vec2(100, 50), vec2(800, 600), cam.view, cam.proj);
    EXPECT_TRUE(VecNear(shifted.direction, ray.direction, tol::kTight));
}

TEST(Picking, DepthIsClampedToNearAndFar) {
    const DemoCamera cam = DefaultDemoCamera();
    const vec2 o(0, 0), s(800, 600);
    EXPECT_TRUE(VecNear(Unproject(vec3(400, 300, -3), o, s, cam.view, cam.proj),
                        Unproject(vec3(400, 300, 0), o, s, cam.view, cam.proj), tol::kExact));
    // Far plane: on the +Z axis, about 1000 from the eye. The float matrix itself limits this: 1 - _33 is
    // ~1e-5 with an absolute rounding of ~6e-8, so the far distance comes back within ~1% (998 here, not 990).
    const vec3 far = Unproject(vec3(400, 300, 7), o, s, cam.view, cam.proj);
    EXPECT_TRUE(VecNear(vec3(far.x, far.y, 0), vec3(0, 0, 0), tol::kLoose));
    EXPECT_NEAR(far.z, 990.0f, 15.0f);
}

TEST(Picking, TinyNearPlaneStillUnprojects) {
    // erratum 5.2-10: near 0.001 gives det(proj) = fovX * fovY * n f / (f - n) ~ 0.0022 < 0.005, where the
    // book's Inverse returns the identity and the pick ray comes out as garbage. Centre ray must still be +Z.
    OrbitCamera camera;
    camera.Perspective(60.0f, 800.0f / 600.0f, 0.001f, 1000.0f);
    camera.Update(0.03f);
    const Ray ray =
        GetPickRay(vec2(400, 300), vec2(0, 0), vec2(800, 600), camera.GetViewMatrix(), camera.GetProjectionMatrix());
    EXPECT_TRUE(VecNear(ray.direction, vec3(0, 0, 1), tol::kLoose));
    EXPECT_TRUE(VecNear(ray.origin, vec3(0, 0, -9.999f), tol::kLoose));
}

TEST(Picking, ProjectThenUnprojectRoundTrips) {
    // Seeded random points in front of an orbit camera at random states. Tolerance 1e-2: the depth passes
    // through a float NDC z ~ 0.999 whose spacing 6e-8 is worth z_view^2 * 6e-8 / near ~ 2e-3 of view depth
    // at 19 units. The pick ray through the pixel does not depend on depth and is checked to 1e-3.
    std::mt19937 rng(2024);
    std::uniform_real_distribution<float> yaw(-180, 180), pitch(-20, 80), coord(-5, 5);
    const vec2 size(800, 600);
    for (int i = 0; i < 300; ++i) {
        OrbitCamera camera;
        camera.Perspective(60.0f, size.x / size.y, 0.01f, 1000.0f);
        camera.SetRotation(vec2(yaw(rng), pitch(rng)));
        camera.Update(0.03f);
        const mat4 view = camera.GetViewMatrix(), proj = camera.GetProjectionMatrix();
        const vec3 p(coord(rng), coord(rng), coord(rng));  // within 9 units of the target; eye is 10 away
        const vec3 screen = ProjectToScreen(p, view, proj, size);
        const vec3 back = Unproject(screen, vec2(0, 0), size, view, proj);
        ASSERT_TRUE(VecNear(back, p, 1e-2f)) << "case " << i;
        // The pick ray through that pixel passes through p.
        const Ray ray = GetPickRay(vec2(screen.x, screen.y), vec2(0, 0), size, view, proj);
        const vec3 onRay = ray.origin + ray.direction * Dot(p - ray.origin, ray.direction);
        ASSERT_TRUE(VecNear(onRay, p, 1e-3f)) << "case " << i;
    }
}
