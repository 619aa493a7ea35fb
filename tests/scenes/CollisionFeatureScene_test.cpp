// CollisionFeatureScene: the book's static start, and the scripted approach that makes contacts appear.
#include "Demos/Scenes/CollisionFeatureScene.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/Approx.h"

TEST(CollisionFeatureScene, BookStartHasNoContacts) {
    CollisionFeatureScene s;
    s.Compute();
    for (int i = 0; i < CollisionFeatureScene::kShapeCount; ++i) EXPECT_FALSE(s.Colliding(i)) << "shape " << i;
    EXPECT_TRUE(VecNear(s.obb[0].position, vec3(4, 2, 0), tol::kExact));
    EXPECT_TRUE(VecNear(s.sphere[1].position, vec3(4, -2, 0), tol::kExact));
    EXPECT_FLOAT_EQ(s.sphere[1].radius, 0.5f);
}

TEST(CollisionFeatureScene, FrameZeroOfTheScriptIsTheStart) {
    CollisionFeatureScene scripted, book;
    scripted.Script(0, 1.0f);
    EXPECT_TRUE(VecNear(scripted.obb[1].position, book.obb[1].position, tol::kExact));
    EXPECT_TRUE(MatNear(scripted.obb[1].orientation, book.obb[1].orientation, tol::kTight));
    EXPECT_TRUE(MatNear(scripted.obb[0].orientation, book.obb[0].orientation, tol::kTight));
}

TEST(CollisionFeatureScene, EveryPairCollidesAtTheClosestAndContactsAreFinite) {
    CollisionFeatureScene s;
    s.Script(CollisionFeatureScene::kCycleFrames / 2, 1.0f);  // closest approach
    s.Compute();
    for (std::size_t p = 0; p < s.results.size(); ++p) {
        EXPECT_TRUE(s.results[p].colliding) << "pair r" << p + 1;
        EXPECT_FALSE(s.results[p].contacts.empty()) << "pair r" << p + 1;
        for (const vec3& c : s.results[p].contacts)
            EXPECT_TRUE(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z)) << "pair r" << p + 1;
    }
}

TEST(CollisionFeatureScene, ContactsComeAndGoOverACycle) {
    CollisionFeatureScene s;
    int framesWithContacts = 0, framesWithout = 0;
    for (int f = 0; f < CollisionFeatureScene::kCycleFrames; ++f) {
        s.Script(f, 1.0f);
        s.Compute();
        bool any = false;
        for (const CollisionManifold& m : s.results) any = any || m.colliding;
        (any ? framesWithContacts : framesWithout)++;
    }
    EXPECT_GT(framesWithContacts, 0);
    EXPECT_GT(framesWithout, 0);
}

TEST(CollisionFeatureScene, ScriptIsDeterministic) {
    CollisionFeatureScene a, b;
    for (int f : {13, 97, 200}) {
        a.Script(f, 1.5f);
        b.Script(f, 1.5f);
        a.Compute();
        b.Compute();
        for (std::size_t p = 0; p < a.results.size(); ++p) {
            ASSERT_EQ(a.results[p].contacts.size(), b.results[p].contacts.size());
            for (std::size_t c = 0; c < a.results[p].contacts.size(); ++c)
                EXPECT_TRUE(VecNear(a.results[p].contacts[c], b.results[p].contacts[c], 0.0f));
        }
    }
}
