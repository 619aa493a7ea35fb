// StabilityMonitor: energy bookkeeping by hand, and blow-ups detected with the step and the body named.
#include "Physics/StabilityMonitor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "Physics/Cloth.h"
#include "Physics/Particle.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/Spring.h"
#include "tests/support/Approx.h"
#include "tests/support/TestWorld.h"

namespace {

/// Anchor (mass 0) + 1 kg bob on the book's stiffest spring (k_book = -5 -> 166.7 N/m), no gravity or damping, in a
/// world (tests/support/TestWorld.h) of the given integrator.
struct SpringBodies {
    Particle& anchor;
    Particle& bob;
};
SpringBodies AddStiffSpring(TestWorld* w, Integrator integrator) {
    Particle& anchor = w->AddParticle();
    Particle& bob = w->AddParticle();
    for (Particle* p : {&anchor, &bob}) {
        p->SetGravity(vec3());
        p->SetVelocityRetention(1.0f);
    }
    anchor.SetMass(0.0f);
    anchor.SetPosition(vec3(0, 3, 0));
    bob.SetPosition(vec3(1.5f, 3, 0));
    w->system.settings.integrator = integrator;
    w->Join();
    Spring spring(FromBookSpringConstant(-5.0f), 0.0f, 1.0f);
    spring.SetParticles(&anchor, &bob);
    w->system.AddSpring(spring);
    return {anchor, bob};
}

}  // namespace

TEST(StabilityMonitor, MechanicalEnergyByHand) {
    Particle p, q;
    p.SetMass(2.0f);
    p.SetPosition(vec3(0, 3, 0));
    p.SetVelocity(vec3(1, 0, 0));
    q.SetPosition(vec3(0, 5, 0));  // mass 1, at rest
    PhysicsSystem system;
    system.AddRigidbody(&p);
    system.AddRigidbody(&q);
    // KE 0.5*2*1 = 1; gravity 2*9.82*3 + 1*9.82*5 = 108.02; spring 0.5*4*(2 - 1.5)^2 = 0.5.
    Spring spring(-4.0f, 0.0f, 1.5f);
    spring.SetParticles(&p, &q);
    system.AddSpring(spring);
    EXPECT_NEAR(StabilityMonitor::MechanicalEnergy(system), 1.0 + 108.02 + 0.5, 1e-4);
}

TEST(StabilityMonitor, CalmSystemStaysStable) {
    TestWorld s;
    AddStiffSpring(&s, Integrator::SemiImplicitEuler);  // omega*dt = 0.39 < 2: stable
    StabilityMonitor monitor;
    monitor.Start(s.system);
    for (int i = 0; i < 2000; ++i) {
        s.system.Update(0.03f);
        ASSERT_TRUE(monitor.Check(s.system)) << monitor.Report().message;
    }
    EXPECT_EQ(monitor.Report().cause, InstabilityCause::None);
}

// Explicit Euler multiplies this spring's energy by 1 + (omega dt)^2 = 1.15 per step at the book's dt:
// the blow-up is reported as runaway energy, at a step, on the bob (particle 1).
TEST(StabilityMonitor, StiffExplicitEulerBlowUpIsReportedWithStepAndBody) {
    TestWorld s;
    const SpringBodies spring = AddStiffSpring(&s, Integrator::ExplicitEuler);
    StabilityMonitor monitor;
    monitor.Start(s.system);
    long long failedAt = 0;
    for (int i = 0; i < 2000 && failedAt == 0; ++i) {
        s.system.Update(0.03f);
        if (!monitor.Check(s.system)) failedAt = s.system.StepCount();
    }
    ASSERT_GT(failedAt, 1);
    const StabilityReport& r = monitor.Report();
    EXPECT_EQ(r.step, failedAt);
    EXPECT_TRUE(r.cause == InstabilityCause::Energy || r.cause == InstabilityCause::Speed) << ToString(r.cause);
    EXPECT_STREQ(r.kind, "particle");
    EXPECT_EQ(r.body, 1);
    EXPECT_EQ(r.cloth, -1);
    EXPECT_TRUE(std::isfinite(spring.bob.GetPosition().x));  // caught before it turned into inf/NaN
    EXPECT_NE(r.message.find("step " + std::to_string(failedAt)), std::string::npos) << r.message;
    EXPECT_NE(r.message.find("particle 1"), std::string::npos) << r.message;
    // The first report is kept.
    s.system.Update(0.03f);
    EXPECT_FALSE(monitor.Check(s.system));
    EXPECT_EQ(monitor.Report().step, failedAt);
}

TEST(StabilityMonitor, NonFiniteParticleIsNamed) {
    Particle a, b, c;
    PhysicsSystem system;
    for (Particle* p : {&a, &b, &c}) system.AddRigidbody(p);
    StabilityMonitor monitor;
    monitor.Start(system);
    system.Update(0.01f);
    ASSERT_TRUE(monitor.Check(system));
    c.SetVelocity(vec3(0, std::numeric_limits<float>::quiet_NaN(), 0));
    EXPECT_FALSE(monitor.Check(system));
    EXPECT_EQ(monitor.Report().cause, InstabilityCause::NonFinite);
    EXPECT_STREQ(monitor.Report().kind, "particle");
    EXPECT_EQ(monitor.Report().body, 2);
    EXPECT_EQ(monitor.Report().step, 1);
    // Start clears the report.
    c.SetVelocity(vec3());
    monitor.Start(system);
    EXPECT_TRUE(monitor.Stable());
}

TEST(StabilityMonitor, ClothParticleAndSpeedAreNamed) {
    Cloth cloth;
    cloth.Initialize(4, 0.5f, vec3(0, 2, 0));
    PhysicsSystem system;
    Particle free;
    system.AddRigidbody(&free);
    system.AddCloth(&cloth);
    StabilityMonitor monitor;
    monitor.Start(system);
    cloth.verts[6].SetVelocity(vec3(2000, 0, 0));  // beyond the default 1000 m/s
    EXPECT_FALSE(monitor.Check(system));
    EXPECT_EQ(monitor.Report().cause, InstabilityCause::Speed);
    EXPECT_STREQ(monitor.Report().kind, "cloth-particle");
    EXPECT_EQ(monitor.Report().body, 6);
    EXPECT_EQ(monitor.Report().cloth, 0);
    EXPECT_NEAR(monitor.Report().value, 2000.0, 1e-3);
    EXPECT_NE(monitor.Report().message.find("cloth-particle 6 of cloth 0"), std::string::npos);
}
