// RaycastScene: the book's five primitives, closest-hit selection and the scripted cursor path.
#include "Demos/Scenes/RaycastScene.h"

#include <gtest/gtest.h>

#include <string>

#include "Application/View/Camera.h"
#include "tests/support/Approx.h"

namespace {

/// The demo's default camera (docs/book-reference.md §1.4): eye (0,0,-10) looking along +Z, 60 degrees, 800 x 600.
struct DefaultView {
    OrbitCamera camera;
    DefaultView() {
        camera.Perspective(60.0f, 800.0f / 600.0f, 0.01f, 1000.0f);
        camera.Update(0.0f);
    }
    Ray Pick(const vec2& cursor) {
        return GetPickRay(cursor, vec2(0, 0), vec2(800, 600), camera.GetViewMatrix(), camera.GetProjectionMatrix());
    }
};

}  // namespace

TEST(RaycastScene, BookPrimitives) {
    const RaycastScene s;
    EXPECT_TRUE(VecNear(s.obb.position, vec3(-4, -2, 0), tol::kExact));
    EXPECT_TRUE(VecNear(GetRow(s.obb.orientation, 0), vec3(0.93969f, 0.0f, -0.34202f), tol::kBook));
    EXPECT_TRUE(VecNear(s.plane.normal, vec3(-0.89443f, 0.44721f, 0.0f), tol::kBook));
    EXPECT_NEAR(s.plane.distance, -4.02492f, 1e-4f);
    EXPECT_FALSE(s.HasModel());
}

TEST(RaycastScene, ClosestHitWins) {
    const RaycastScene s;
    RaycastScene::Shape shape;
    // Straight along +Z through the sphere centre: the sphere's near side at z = -1.
    RaycastResult r = s.CastAll(Ray(vec3(-4, 2, -10), vec3(0, 0, 1)), &shape);
    ASSERT_TRUE(r.hit);
    EXPECT_EQ(shape, RaycastScene::Shape::Sphere);
    EXPECT_NEAR(r.t, 9.0f, tol::kLoose);
    // Through the AABB: its -Z face.
    r = s.CastAll(Ray(vec3(4, 2, -10), vec3(0, 0, 1)), &shape);
    EXPECT_EQ(shape, RaycastScene::Shape::AABB);
    EXPECT_TRUE(VecNear(r.normal, vec3(0, 0, -1), tol::kExact));
    // The triangle faces +Z: a ray travelling +Z cannot hit it (docs/book-reference.md §2.0).
    r = s.CastAll(Ray(vec3(0, 2, -10), vec3(0, 0, 1)), &shape);
    EXPECT_NE(shape, RaycastScene::Shape::Triangle);
    // Straight up through empty space misses everything.
    r = s.CastAll(Ray(vec3(0, 10, 0), vec3(0, 1, 0)), &shape);
    EXPECT_FALSE(r.hit);
    EXPECT_EQ(shape, RaycastScene::Shape::None);
}

TEST(RaycastScene, ScriptedCursorSweepsBothRowsAndRepeats) {
    const vec2 size(800, 600);
    const vec2 start = RaycastScene::ScriptedCursor(0, 1.0f, size);
    EXPECT_TRUE(Vec2Near(start, RaycastScene::ScriptedCursor(RaycastScene::kSweepFrames, 1.0f, size), 1e-3f));
    EXPECT_NEAR(start.x, 80.0f, 1e-3f);
    const vec2 right = RaycastScene::ScriptedCursor(RaycastScene::kSweepFrames / 2 - 1, 1.0f, size);
    const vec2 back = RaycastScene::ScriptedCursor(RaycastScene::kSweepFrames / 2 + 1, 1.0f, size);
    EXPECT_LT(right.y, 300.0f);  // upper row first
    EXPECT_GT(back.y, 300.0f);   // then the lower row
    EXPECT_GT(right.x, 700.0f);
    // Speed 0 holds the cursor.
    EXPECT_TRUE(Vec2Near(RaycastScene::ScriptedCursor(77, 0.0f, size), start, 1e-3f));
}

TEST(RaycastScene, ScriptedSweepHitsTheBookShapes) {
    const RaycastScene s;
    DefaultView view;
    bool seen[6] = {};
    for (int f = 0; f < RaycastScene::kSweepFrames; ++f) {
        RaycastScene::Shape shape;
        Ray ray = view.Pick(RaycastScene::ScriptedCursor(f, 1.0f, vec2(800, 600)));
        ray.NormalizeDirection();
        const RaycastResult r = s.CastAll(ray, &shape);
        if (r.hit) {
            EXPECT_NEAR(Magnitude(r.normal), 1.0f, tol::kLoose) << "frame " << f;
            seen[static_cast<int>(shape)] = true;
        }
    }
    EXPECT_TRUE(seen[static_cast<int>(RaycastScene::Shape::Sphere)]);
    EXPECT_TRUE(seen[static_cast<int>(RaycastScene::Shape::AABB)]);
    EXPECT_TRUE(seen[static_cast<int>(RaycastScene::Shape::OBB)]);
    EXPECT_TRUE(seen[static_cast<int>(RaycastScene::Shape::Plane)]);
    EXPECT_FALSE(seen[static_cast<int>(RaycastScene::Shape::Triangle)]);  // one-sided, faces away
}

TEST(RaycastScene, LoadsTheDemoModel) {
    RaycastScene s;
    const std::string path = FirstObjFile(PSB_SOURCE_DIR "/Demos/assets");
    ASSERT_FALSE(path.empty()) << "no OBJ in Demos/assets";
    std::string error;
    ASSERT_TRUE(s.LoadModel(path, &error)) << error;
    EXPECT_TRUE(s.HasModel());
    RaycastScene::Shape shape;
    const RaycastResult r = s.CastAll(Ray(RaycastScene::kModelPosition + vec3(0, 0, -10), vec3(0, 0, 1)), &shape);
    EXPECT_TRUE(r.hit);
    EXPECT_EQ(shape, RaycastScene::Shape::Model);
    std::string missing;
    EXPECT_FALSE(s.LoadModel(PSB_SOURCE_DIR "/Demos/assets/does-not-exist.obj", &missing));
    EXPECT_FALSE(s.HasModel());
    EXPECT_FALSE(missing.empty());
    EXPECT_EQ(FirstObjFile(PSB_SOURCE_DIR "/no-such-directory"), "");
}
