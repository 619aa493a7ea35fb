// WorldSettings: the book's defaults, and per-step factors that keep their per-second rate at any step.
#include "Physics/WorldSettings.h"

#include <gtest/gtest.h>

#include <cmath>

#include "Physics/Particle.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/RigidbodyVolume.h"

TEST(WorldSettings, DefaultsAreTheBooks) {
    const WorldSettings s;
    EXPECT_EQ(s.integrator, Integrator::SemiImplicitEuler);
    EXPECT_EQ(s.particleRetentionStep, 0.03f);
    EXPECT_EQ(s.contactSolver, ContactSolver::Book);
    EXPECT_EQ(s.solverIterations, 5);
    EXPECT_EQ(s.penetrationSlop, 0.01f);
    EXPECT_TRUE(s.linearProjection);
    EXPECT_EQ(s.projectionFraction, 0.45f);
    EXPECT_EQ(kBookStep, 0.03f);
    EXPECT_EQ(Particle().GetVelocityRetention(), 0.95f);
    EXPECT_EQ(RigidbodyVolume().velocityRetention, 0.98f);
    EXPECT_EQ(RigidbodyVolume().referenceStep, kBookStep);
}

TEST(WorldSettings, FactorOverStepKeepsThePerSecondRate) {
    EXPECT_EQ(FactorOverStep(0.95f, 0.03f, 0.03f), 0.95f);  // the book's constant, bit for bit, at its step
    EXPECT_NEAR(FactorOverStep(0.95f, 0.03f, 0.01f), std::cbrt(0.95f), 1e-7f);
    EXPECT_NEAR(FactorOverStep(0.95f, 0.03f, 0.06f), 0.95f * 0.95f, 1e-7f);
    EXPECT_EQ(FactorOverStep(0.95f, 0.0f, 0.01f), 0.95f);  // reference 0: per step at every dt
    EXPECT_EQ(FactorOverStep(1.0f, 0.03f, 0.007f), 1.0f);
}

// A particle coasting without gravity keeps the same fraction of its speed over 0.03 s whether the world steps
// 0.03 s once or 0.01 s three times, for every integrator (the book's 0.95 would be applied three times over).
TEST(WorldSettings, ParticleRetentionIsPerSecondForEveryIntegrator) {
    for (Integrator integrator : kAllIntegrators) {
        auto coast = [integrator](float dt, int steps) {
            Particle p;
            p.SetGravity(vec3(0, 0, 0));
            p.SetVelocity(vec3(2, 0, 0));
            PhysicsSystem world;
            world.settings.integrator = integrator;
            world.AddRigidbody(&p);
            for (int i = 0; i < steps; ++i) world.Update(dt);
            return p.GetVelocity().x;
        };
        const float coarse = coast(0.03f, 1);
        const float fine = coast(0.01f, 3);
        EXPECT_EQ(coarse, 2.0f * 0.95f) << ToString(integrator);
        EXPECT_NEAR(fine, coarse, 1e-5f) << ToString(integrator);
    }
}

// The same for a volume: its retention (the book's damping 0.98 per 0.03 s) does not depend on the step.
TEST(WorldSettings, VolumeRetentionIsPerSecond) {
    auto coast = [](float dt, int steps) {
        RigidbodyVolume box(RigidbodyType::Box);
        box.gravity = vec3(0, 0, 0);
        box.velocity = vec3(3, 0, 0);
        box.SynchCollisionVolumes();
        PhysicsSystem world;
        world.AddRigidbody(&box);
        for (int i = 0; i < steps; ++i) world.Update(dt);
        return box.velocity.x;
    };
    EXPECT_EQ(coast(0.03f, 1), 3.0f * 0.98f);
    EXPECT_NEAR(coast(0.01f, 3), 3.0f * 0.98f, 1e-5f);
    EXPECT_NEAR(coast(1.0f / 60.0f, 9), 3.0f * std::pow(0.98f, 5.0f), 1e-5f);  // 0.15 s = five book steps
}
