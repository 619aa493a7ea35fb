// tests/support/TestWorld.h, the physics tests' world fixture: bodies join the system in the order added, a refused
// body is named and left out, and the measures read the bodies the system stepped.
#include "tests/support/TestWorld.h"

#include <gtest/gtest.h>

#include <string>

TEST(TestWorld, BodiesJoinTheSystemInTheOrderAdded) {
    TestWorld w;
    RigidbodyVolume& ground = w.Add(GroundSpec(vec3(5.0f, 0.5f, 5.0f)));
    Particle& p = w.AddParticle();
    RigidbodyVolume& box = w.Add(BoxSpec(vec3(0.0f, 2.0f, 0.0f), vec3(0.5f, 0.5f, 0.5f), 1.0f));
    EXPECT_TRUE(w.system.Bodies().empty()) << "nothing joins before Join or Step";
    ASSERT_TRUE(w.Join()) << w.system.LastError();
    ASSERT_EQ(w.system.Bodies().size(), 3u);
    EXPECT_EQ(w.system.Bodies()[0], &ground);
    EXPECT_EQ(w.system.Bodies()[1], &p);
    EXPECT_EQ(w.system.Bodies()[2], &box);
    EXPECT_FALSE(w.JoinNext()) << "every body has joined";
}

TEST(TestWorld, ARefusedBodyIsNamedAndTheOthersStillJoin) {
    TestWorld w;
    w.Add(BoxSpec(vec3(), vec3(0.5f, 0.5f, 0.5f), 1.0f)).mass = -2.0f;
    w.Add(SphereSpec(vec3(3.0f, 0.0f, 0.0f), 0.5f, 1.0f));
    EXPECT_FALSE(w.Join());
    EXPECT_NE(w.system.LastError().find("mass = -2"), std::string::npos) << w.system.LastError();
    EXPECT_EQ(w.system.Volumes().size(), 1u);
}

TEST(TestWorld, MeasuresReadTheSteppedBodies) {
    TestWorld w;
    RigidbodyVolume& box = w.Add(BoxSpec(vec3(1.0f, 10.0f, 0.0f), vec3(0.5f, 0.5f, 0.5f), 2.0f));
    box.velocityRetention = 1.0f;
    w.Step(0.01f, 10);  // free fall, 0.1 s
    EXPECT_EQ(w.system.StepCount(), 10);
    EXPECT_EQ(w.StartOf(0).y, 10.0f);
    const float fell = 10.0f - box.position.y;
    EXPECT_GT(fell, 0.04f);
    EXPECT_FLOAT_EQ(w.MaxVerticalMove(), fell);
    EXPECT_FLOAT_EQ(w.MaxDisplacement(), fell);
    EXPECT_EQ(w.MaxHorizontalDrift(), 0.0f);
    EXPECT_FLOAT_EQ(w.KineticEnergy(), 0.5f * 2.0f * MagnitudeSq(box.velocity));
    EXPECT_TRUE(w.AllFinite());
    EXPECT_EQ(w.Snapshot().size(), 13u * sizeof(float));
}
