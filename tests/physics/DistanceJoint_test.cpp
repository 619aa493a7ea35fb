// DistanceJoint (book.md 3.8): one projection of both ends onto the rest length, then both particles
// re-solve their constraints; erratum 5.2-6 (coincident particles).
#include "DistanceJoint.h"

#include <gtest/gtest.h>

#include "Approx.h"

namespace {
const std::vector<OBB> kNoConstraints;
}

TEST(DistanceJoint, InitializeStoresPairAndLength) {
    Particle a, b;
    DistanceJoint joint;
    EXPECT_EQ(joint.type, RigidbodyType::Base);
    joint.Initialize(&a, &b, 0.75f);
    EXPECT_EQ(joint.p1, &a);
    EXPECT_EQ(joint.p2, &b);
    EXPECT_EQ(joint.length, 0.75f);
}

TEST(DistanceJoint, StretchedPairMovesBothHalfway) {
    // Distance 3 along x, rest 1: each end moves 1 toward the other; the midpoint stays.
    Particle a, b;
    a.SetPosition(vec3(0, 1, 0));
    b.SetPosition(vec3(3, 1, 0));
    DistanceJoint joint;
    joint.Initialize(&a, &b, 1.0f);
    joint.SolveConstraints(kNoConstraints);
    EXPECT_TRUE(VecNear(a.GetPosition(), vec3(1, 1, 0), tol::kExact));
    EXPECT_TRUE(VecNear(b.GetPosition(), vec3(2, 1, 0), tol::kExact));
    // SetPosition also resets oldPosition (book.md 3.8).
    EXPECT_TRUE(VecNear(a.GetOldPosition(), a.GetPosition(), 0.0f));
    EXPECT_TRUE(VecNear(b.GetOldPosition(), b.GetPosition(), 0.0f));
}

TEST(DistanceJoint, CompressedPairPushedApart) {
    Particle a, b;
    a.SetPosition(vec3(0, 0, 0));
    b.SetPosition(vec3(0, 0.6f, 0.8f));  // distance 1
    DistanceJoint joint;
    joint.Initialize(&a, &b, 2.0f);
    joint.SolveConstraints(kNoConstraints);
    EXPECT_TRUE(VecNear(a.GetPosition(), vec3(0, -0.3f, -0.4f), tol::kTight));
    EXPECT_TRUE(VecNear(b.GetPosition(), vec3(0, 0.9f, 1.2f), tol::kTight));
    EXPECT_NEAR(Magnitude(b.GetPosition() - a.GetPosition()), 2.0f, tol::kTight);
}

// erratum 5.2-6: the book computes (dist - length) / dist with dist = 0 and writes NaN positions.
TEST(DistanceJoint, Erratum5_2_6_CoincidentParticlesStayFinite) {
    Particle a, b;
    a.SetPosition(vec3(1, 2, 3));
    b.SetPosition(vec3(1, 2, 3));
    DistanceJoint joint;
    joint.Initialize(&a, &b, 0.5f);
    joint.SolveConstraints(kNoConstraints);
    EXPECT_TRUE(IsFinite(a.GetPosition()));
    EXPECT_TRUE(IsFinite(b.GetPosition()));
    EXPECT_TRUE(VecNear(a.GetPosition(), vec3(1, 2, 3), 0.0f));
}

TEST(DistanceJoint, ZeroLengthJointMergesThenStaysFinite) {
    Particle a, b;
    a.SetPosition(vec3(-1, 0, 0));
    b.SetPosition(vec3(1, 0, 0));
    DistanceJoint joint;
    joint.Initialize(&a, &b, 0.0f);
    joint.SolveConstraints(kNoConstraints);
    EXPECT_TRUE(VecNear(a.GetPosition(), vec3(0, 0, 0), tol::kExact));
    EXPECT_TRUE(VecNear(b.GetPosition(), vec3(0, 0, 0), tol::kExact));
    joint.SolveConstraints(kNoConstraints);  // now coincident: the book divides by zero here
    EXPECT_TRUE(IsFinite(a.GetPosition()));
    EXPECT_TRUE(IsFinite(b.GetPosition()));
}

TEST(DistanceJoint, WithoutParticlesDoesNothing) {
    DistanceJoint joint;
    joint.SolveConstraints(kNoConstraints);  // must not crash
    SUCCEED();
}
