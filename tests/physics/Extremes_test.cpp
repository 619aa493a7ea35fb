// Stability at the extremes (issue 7 item 4): tiny and huge steps, mass ratios 1:1000 and 1000:1, 1,000 m/s,
// 10 km from the origin, zero and huge sizes, zero dt. Each case either runs with finite, bounded state or is
// refused at the API; a stiff spring under explicit Euler must be detected and reported by the
// StabilityMonitor before any non-finite number appears. Small grids: every test runs in milliseconds.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "Ch14Scene.h"
#include "Particle.h"
#include "PhysicsSystem.h"
#include "RigidbodyVolume.h"
#include "Spring.h"
#include "StabilityMonitor.h"

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInfF = std::numeric_limits<float>::infinity();

bool Finite(const Particle& p) { return IsFinite(p.GetPosition()) && IsFinite(p.GetVelocity()); }
bool Finite(const RigidbodyVolume& b) {
    return IsFinite(b.position) && IsFinite(b.velocity) && IsFinite(b.angVel) && IsFinite(b.orientation);
}

/// A world of volumes kept in one vector (reserved, so the system's pointers stay valid).
struct Volumes {
    PhysicsSystem system;
    std::vector<RigidbodyVolume> bodies;
    Volumes() { bodies.reserve(16); }
    RigidbodyVolume& Add(RigidbodyType type, const vec3& position, float mass, float half) {
        bodies.emplace_back(type);
        RigidbodyVolume& b = bodies.back();
        b.position = position;
        b.mass = mass;
        b.box.size = vec3(half, half, half);
        b.sphere.radius = half;
        return b;
    }
    void Finish() {
        for (RigidbodyVolume& b : bodies) {
            b.SynchCollisionVolumes();
            system.AddRigidbody(&b);
        }
    }
    /// Steps and returns false at the first non-finite body.
    bool Run(float dt, int steps) {
        for (int i = 0; i < steps; ++i) {
            system.Update(dt);
            for (const RigidbodyVolume& b : bodies)
                if (!Finite(b)) return false;
        }
        return true;
    }
};

/// Ground slab (static) with its top face at height `top`, centred at (x, ., z).
RigidbodyVolume& AddGround(Volumes* w, float top, float x = 0.0f, float z = 0.0f, float half = 20.0f) {
    RigidbodyVolume& g = w->Add(RigidbodyType::Box, vec3(x, top - 0.5f, z), 0.0f, 0.5f);
    g.box.size = vec3(half, 0.5f, half);
    return g;
}

/// A particle on a ground box (top at y = 0) with the given integrator, dropped from 2 m.
struct ParticleOnGround {
    PhysicsSystem system;
    Particle p;
    explicit ParticleOnGround(Integrator integrator, const vec3& offset = vec3(), float groundHalf = 10.0f) {
        system.integrator = integrator;
        system.AddConstraint(OBB(offset + vec3(0.0f, -1.0f, 0.0f), vec3(groundHalf, 1.0f, groundHalf)));
        p.SetPosition(offset + vec3(0.0f, 2.0f, 0.0f));
        system.AddRigidbody(&p);
    }
};

// ---------------------------------------------------------------------------------------------------------
// Zero, negative and non-finite dt: refused (the step does nothing) by PhysicsSystem and the scenes.

TEST(ExtremesTest, ZeroNegativeAndNonFiniteDtLeaveTheWorldUntouched) {
    for (Integrator integrator : kAllIntegrators) {
        ParticleOnGround w(integrator);
        w.p.SetVelocity(vec3(1.0f, 2.0f, 3.0f));
        for (float dt : {0.0f, -0.01f, kNaN, kInfF, -kInfF}) w.system.Update(dt);
        EXPECT_EQ(w.system.StepCount(), 0) << ToString(integrator);
        EXPECT_EQ(w.p.GetPosition().y, 2.0f);
        EXPECT_EQ(w.p.GetVelocity().z, 3.0f);
    }
    Volumes v;
    AddGround(&v, 0.0f);
    v.Add(RigidbodyType::Box, vec3(0.0f, 0.45f, 0.0f), 1.0f, 0.5f);  // overlapping: would be pushed out
    v.Finish();
    for (float dt : {0.0f, -1.0f, kNaN}) v.system.Update(dt);
    EXPECT_EQ(v.system.StepCount(), 0);
    EXPECT_EQ(v.bodies[1].position.y, 0.45f);
}

TEST(ExtremesTest, SceneSetDtRefusesZeroAndNonFiniteSteps) {
    Ch14Scene scene;
    const float before = scene.Params().dt;
    for (float dt : {0.0f, -0.03f, kNaN, kInfF}) scene.SetDt(dt);
    EXPECT_EQ(scene.Params().dt, before);
}

// ---------------------------------------------------------------------------------------------------------
// Time steps of 1e-5 s and 0.5 s.

TEST(ExtremesTest, TinyStepParticlesFallAsExpected) {
    // 2,000 steps of 1e-5 s = 0.02 s of free fall: y = 2 - g t^2 / 2 to float rounding of 2,000 small steps.
    for (Integrator integrator : kAllIntegrators) {
        ParticleOnGround w(integrator);
        w.p.SetFriction(1.0f);
        for (int i = 0; i < 2000; ++i) w.system.Update(1e-5f);
        ASSERT_TRUE(Finite(w.p)) << ToString(integrator);
        EXPECT_NEAR(w.p.GetPosition().y, 2.0f - 0.5f * 9.82f * 0.02f * 0.02f, 2e-4f) << ToString(integrator);
        EXPECT_NEAR(w.p.GetVelocity().y, -9.82f * 0.02f, 1e-3f) << ToString(integrator);
    }
}

TEST(ExtremesTest, HugeStepParticlesLandOnTheGroundWithoutTunnelling) {
    // 0.5 s steps: the particle crosses the 2 m thick ground box in one step, yet the travelled-segment test
    // must stop it on top. Explicit Euler gains height on the first bounces at this step (its energy error)
    // but levels off near 10 m (2,000 steps: 9.4 m); 20 m is the bound.
    for (Integrator integrator : kAllIntegrators) {
        ParticleOnGround w(integrator);
        for (int i = 0; i < 40; ++i) {
            w.system.Update(0.5f);
            ASSERT_TRUE(Finite(w.p)) << ToString(integrator) << " step " << i;
            ASSERT_GE(w.p.GetPosition().y, 0.0f) << ToString(integrator) << " step " << i;
            ASSERT_LT(w.p.GetPosition().y, 20.0f) << ToString(integrator) << " step " << i;
        }
    }
}

/// Three unit boxes on a ground slab `thickness` m thick, stepped 40 times at 0.5 s; false if not finite.
bool HugeStepStack(float thickness, int projection, Volumes* w) {
    w->system.DoLinearProjection = projection != 0;
    RigidbodyVolume& g = AddGround(w, 0.0f);
    g.position.y = -0.5f * thickness;
    g.box.size.y = 0.5f * thickness;
    for (int i = 0; i < 3; ++i) w->Add(RigidbodyType::Box, vec3(0.0f, 0.5f + float(i), 0.0f), 1.0f, 0.5f);
    w->Finish();
    return w->Run(0.5f, 40);
}

TEST(ExtremesTest, HugeStepVolumeStackStaysFinite) {
    for (int projection : {0, 1}) {
        Volumes w;
        EXPECT_TRUE(HugeStepStack(1.0f, projection, &w)) << "projection " << projection;
    }
}

// Disabled: documents a limit for the lead (PhysicsSystem::Update, issue 5). Volumes have no continuous
// collision: one 0.5 s step moves a box resting on the ground 2.4 m down, past the contact that existed at the
// start of the step, and once a box is inside the slab the manifold does not push it out, so the stack falls
// for ever (finite but unbounded: 1,400 m and 130 m/s after 20 s), even on a 10 m thick slab. Enable once
// Update refuses (with a message naming dt) or subdivides a step whose travel exceeds the thinnest volume.
TEST(ExtremesTest, DISABLED_HugeStepVolumeStackStaysOnTheGround) {
    for (float thickness : {1.0f, 10.0f})
        for (int projection : {0, 1}) {
            Volumes w;
            ASSERT_TRUE(HugeStepStack(thickness, projection, &w));
            for (std::size_t i = 1; i < w.bodies.size(); ++i)
                EXPECT_GT(w.bodies[i].position.y, -1.0f) << "slab " << thickness << " m, box " << i;
        }
}

TEST(ExtremesTest, TinyStepVolumeSettlesOnTheGround) {
    // A box dropped 1 cm at dt = 1e-4 s comes to rest on the ground, finite, without sinking through it.
    Volumes w;
    AddGround(&w, 0.0f);
    w.Add(RigidbodyType::Box, vec3(0.0f, 0.51f, 0.0f), 1.0f, 0.5f);
    w.Finish();
    ASSERT_TRUE(w.Run(1e-4f, 5000));
    EXPECT_GT(w.bodies[1].position.y, 0.4f);
    EXPECT_LT(w.bodies[1].position.y, 0.52f);
}

// Disabled: documents a defect for the lead (RigidbodyVolume::IntegrateVelocity, owned by issue 5). The book's
// velocityEpsilon (0.001 m/s) zeroes every velocity component below it AFTER gravity is added, so for
// g dt < 0.001 (dt < 1.02e-4 s) a body released from rest never starts to fall: at dt = 1e-5 it hangs in
// the air forever. Enable once the threshold scales with dt or is applied to contact-resolved bodies only.
TEST(ExtremesTest, DISABLED_TinyStepVolumeReleasedFromRestFalls) {
    Volumes w;
    w.Add(RigidbodyType::Box, vec3(0.0f, 10.0f, 0.0f), 1.0f, 0.5f);
    w.Finish();
    ASSERT_TRUE(w.Run(1e-5f, 10000));  // 0.1 s
    EXPECT_LT(w.bodies[0].position.y, 10.0f - 0.04f);
}

// ---------------------------------------------------------------------------------------------------------
// Mass ratios 1:1000 and 1000:1.

TEST(ExtremesTest, MassRatioStacksStayFiniteAndBounded) {
    for (float topMass : {0.001f, 1000.0f}) {
        Volumes w;
        AddGround(&w, 0.0f);
        w.Add(RigidbodyType::Box, vec3(0.0f, 0.5f, 0.0f), 1.0f, 0.5f);
        w.Add(RigidbodyType::Box, vec3(0.0f, 1.5f, 0.0f), topMass, 0.5f);
        w.Finish();
        ASSERT_TRUE(w.Run(1.0f / 60.0f, 300)) << "top mass " << topMass;
        for (std::size_t i = 1; i < w.bodies.size(); ++i) {
            EXPECT_LT(Magnitude(w.bodies[i].position), 20.0f) << "top mass " << topMass << " box " << i;
            EXPECT_LT(Magnitude(w.bodies[i].velocity), 50.0f) << "top mass " << topMass << " box " << i;
            EXPECT_GT(w.bodies[i].position.y, -1.0f) << "top mass " << topMass << " box " << i;
        }
    }
}

TEST(ExtremesTest, MassRatioHeadOnCollisionConservesMomentum) {
    // No gravity, no damping, spheres 1 m apart closing at 2 m/s: whatever the ratio, the impulses are equal and
    // opposite, so total momentum is kept and nothing becomes non-finite.
    for (float ratio : {0.001f, 1000.0f}) {
        Volumes w;
        RigidbodyVolume& a = w.Add(RigidbodyType::Sphere, vec3(-1.0f, 0.0f, 0.0f), 1.0f, 0.5f);
        RigidbodyVolume& b = w.Add(RigidbodyType::Sphere, vec3(0.05f, 0.0f, 0.0f), ratio, 0.5f);
        for (RigidbodyVolume* s : {&a, &b}) {
            s->gravity = vec3();
            s->damping = 1.0f;
        }
        a.velocity = vec3(2.0f, 0.0f, 0.0f);
        w.Finish();
        const float p0 = w.bodies[0].mass * w.bodies[0].velocity.x;
        ASSERT_TRUE(w.Run(1.0f / 60.0f, 120)) << "ratio " << ratio;
        const float p1 = w.bodies[0].mass * w.bodies[0].velocity.x + w.bodies[1].mass * w.bodies[1].velocity.x;
        EXPECT_NEAR(p1, p0, 1e-3f * std::fmax(1.0f, ratio)) << "ratio " << ratio;
        EXPECT_LT(w.bodies[0].velocity.x, w.bodies[1].velocity.x + 1e-4f) << "ratio " << ratio << ": still closing";
    }
}

// ---------------------------------------------------------------------------------------------------------
// Speeds of 1,000 m/s.

TEST(ExtremesTest, ThousandMetresPerSecondParticleStopsAtAThinWall) {
    // A 0.2 m wall at x = 10 crossed in a single 1/60 s step (16.7 m): the segment test must catch it.
    for (Integrator integrator : kAllIntegrators) {
        PhysicsSystem system;
        system.integrator = integrator;
        system.AddConstraint(OBB(vec3(10.0f, 0.0f, 0.0f), vec3(0.1f, 5.0f, 5.0f)));
        Particle p;
        p.SetPosition(vec3());
        p.SetGravity(vec3());
        p.SetBounce(0.5f);
        p.SetVelocity(vec3(1000.0f, 0.0f, 0.0f));
        system.AddRigidbody(&p);
        for (int i = 0; i < 10; ++i) {
            system.Update(1.0f / 60.0f);
            ASSERT_TRUE(Finite(p)) << ToString(integrator);
            ASSERT_LT(p.GetPosition().x, 9.9f) << ToString(integrator) << " tunnelled at step " << i;
        }
        EXPECT_LE(Magnitude(p.GetVelocity()), 1000.0f) << ToString(integrator);
    }
}

TEST(ExtremesTest, ThousandMetresPerSecondVolumesStayFinite) {
    // Volumes have no continuous collision: a sphere at 1,000 m/s may pass a box, but it must not gain speed
    // or produce NaN, and a direct hit on a deep box must not send it faster than it came.
    Volumes w;
    RigidbodyVolume& wall = w.Add(RigidbodyType::Box, vec3(10.0f, 0.0f, 0.0f), 0.0f, 0.5f);
    wall.box.size = vec3(20.0f, 5.0f, 5.0f);
    RigidbodyVolume& ball = w.Add(RigidbodyType::Sphere, vec3(-11.0f, 0.0f, 0.0f), 1.0f, 0.5f);
    ball.gravity = vec3();
    ball.damping = 1.0f;
    ball.velocity = vec3(1000.0f, 0.0f, 0.0f);
    w.Finish();
    ASSERT_TRUE(w.Run(1.0f / 60.0f, 30));
    EXPECT_LE(Magnitude(w.bodies[1].velocity), 1000.0f * 1.001f);
}

// ---------------------------------------------------------------------------------------------------------
// 10 km from the origin: float spacing there is ~1 mm.

TEST(ExtremesTest, ParticleRestsOnGroundTenKilometresOut) {
    const vec3 far(10000.0f, 10000.0f, -10000.0f);
    for (Integrator integrator : kAllIntegrators) {
        ParticleOnGround w(integrator, far);
        w.p.SetBounce(0.0f);
        for (int i = 0; i < 300; ++i) w.system.Update(1.0f / 60.0f);
        ASSERT_TRUE(Finite(w.p)) << ToString(integrator);
        const float height = w.p.GetPosition().y - far.y;
        EXPECT_GE(height, -0.002f) << ToString(integrator) << ": below the ground";
        EXPECT_LT(height, 0.02f) << ToString(integrator) << ": not resting";
    }
}

TEST(ExtremesTest, VolumeRestsOnGroundTenKilometresOut) {
    const vec3 far(10000.0f, 10000.0f, -10000.0f);
    Volumes w;
    AddGround(&w, far.y, far.x, far.z);
    w.Add(RigidbodyType::Box, far + vec3(0.0f, 0.5f, 0.0f), 1.0f, 0.5f);
    w.Finish();
    ASSERT_TRUE(w.Run(1.0f / 60.0f, 300));
    EXPECT_LT(Magnitude(w.bodies[1].position - (far + vec3(0.0f, 0.5f, 0.0f))), 0.1f);
}

// ---------------------------------------------------------------------------------------------------------
// Zero and huge sizes.

/// Ground, a radius-0 sphere, a half-size-0 box and a flat box (half-height 0) dropped 1 m, 120 steps.
bool DropZeroSizeVolumes(Volumes* w) {
    AddGround(w, 0.0f);
    w->Add(RigidbodyType::Sphere, vec3(0.0f, 1.0f, 0.0f), 1.0f, 0.0f);
    w->Add(RigidbodyType::Box, vec3(0.0f, 1.0f, 0.0f), 1.0f, 0.0f);  // coincident with the sphere
    w->Add(RigidbodyType::Box, vec3(3.0f, 1.0f, 0.0f), 1.0f, 0.5f).box.size.y = 0.0f;
    w->Finish();
    w->bodies[2].angVel = vec3(1.0f, 2.0f, 3.0f);  // spin with a zero inertia tensor
    return w->Run(1.0f / 60.0f, 120);
}

TEST(ExtremesTest, ZeroSizeVolumesStayFinite) {
    Volumes w;
    ASSERT_TRUE(DropZeroSizeVolumes(&w));
    for (int i = 0; i < 480; ++i) w.system.Update(1.0f / 60.0f);
    ASSERT_TRUE(Finite(w.bodies[1]));
    // A radius-0 sphere is a point: it sinks into the slab by what projection leaves, but never through it.
    EXPECT_GT(w.bodies[1].position.y, -0.5f);
}

// Disabled: documents a gap for the lead (RigidbodyVolume / PhysicsSystem::AddRigidbody, issue 5). Zero-size
// boxes (all half-sizes 0, or a flat box with half-height 0) are accepted and then fall through the ground for
// ever (finite, unbounded). Enable once AddRigidbody refuses a non-positive or non-finite size or mass with a
// message naming the value, or the box manifold handles flat boxes.
TEST(ExtremesTest, DISABLED_ZeroSizeBoxesAreRefusedOrCollide) {
    Volumes w;
    ASSERT_TRUE(DropZeroSizeVolumes(&w));
    for (std::size_t i = 2; i < w.bodies.size(); ++i) EXPECT_GT(w.bodies[i].position.y, -0.01f) << "body " << i;
}

TEST(ExtremesTest, ZeroSizeConstraintAndZeroMassParticleStayFinite) {
    PhysicsSystem system;
    system.AddConstraint(OBB(vec3(0.0f, 0.5f, 0.0f), vec3(0.0f, 0.0f, 0.0f)));  // a point box in the path
    system.AddConstraint(OBB(vec3(0.0f, -1.0f, 0.0f), vec3(10.0f, 1.0f, 10.0f)));
    Particle falling, massless;
    falling.SetPosition(vec3(0.0f, 2.0f, 0.0f));
    massless.SetMass(0.0f);
    massless.SetPosition(vec3(1.0f, 2.0f, 0.0f));
    system.AddRigidbody(&falling);
    system.AddRigidbody(&massless);
    for (int i = 0; i < 120; ++i) system.Update(1.0f / 60.0f);
    ASSERT_TRUE(Finite(falling));
    ASSERT_TRUE(Finite(massless));
    EXPECT_GE(falling.GetPosition().y, 0.0f);
    EXPECT_EQ(massless.GetPosition().y, 2.0f);  // mass 0 = immovable
}

TEST(ExtremesTest, HugeGroundAndHugeBodiesStayFinite) {
    // A 1e6 m ground slab under a particle and a 1,000 m box; a 1,000 m sphere on it.
    PhysicsSystem particles;
    particles.AddConstraint(OBB(vec3(0.0f, -1.0f, 0.0f), vec3(1e6f, 1.0f, 1e6f)));
    Particle p;
    p.SetPosition(vec3(5e5f, 2.0f, -5e5f));
    particles.AddRigidbody(&p);
    for (int i = 0; i < 120; ++i) particles.Update(1.0f / 60.0f);
    ASSERT_TRUE(Finite(p));
    EXPECT_GE(p.GetPosition().y, 0.0f);

    Volumes w;
    AddGround(&w, 0.0f, 0.0f, 0.0f, 1e6f);
    w.Add(RigidbodyType::Box, vec3(0.0f, 1000.0f, 0.0f), 1.0f, 1000.0f);
    w.Add(RigidbodyType::Sphere, vec3(5000.0f, 1000.0f, 0.0f), 1.0f, 1000.0f);
    w.Finish();
    ASSERT_TRUE(w.Run(1.0f / 60.0f, 120));
    EXPECT_GT(w.bodies[1].position.y, 900.0f);
    EXPECT_GT(w.bodies[2].position.y, 900.0f);
}

// ---------------------------------------------------------------------------------------------------------
// Inherently unstable: explicit Euler on a stiff spring must be detected and reported, not rendered as NaN.

struct StiffSpring {
    PhysicsSystem system;
    Particle anchor, bob;
    explicit StiffSpring(Integrator integrator, float stiffness) {
        system.integrator = integrator;
        anchor.SetMass(0.0f);
        anchor.SetPosition(vec3());
        bob.SetPosition(vec3(1.1f, 0.0f, 0.0f));
        for (Particle* p : {&anchor, &bob}) {
            p->SetGravity(vec3());
            p->SetFriction(1.0f);
            system.AddRigidbody(p);
        }
        Spring s(-stiffness, 0.0f, 1.0f);
        s.SetParticles(&anchor, &bob);
        system.AddSpring(s);
    }
};

TEST(ExtremesTest, ExplicitEulerOnAStiffSpringIsReportedBeforeAnyNaN) {
    // omega dt = 100 * 0.01 = 1: explicit Euler grows the energy by (1 + omega^2 dt^2) = 2x per step.
    StiffSpring w(Integrator::ExplicitEuler, 1e4f);
    StabilityMonitor monitor;
    monitor.Start(w.system);
    int steps = 0;
    while (steps < 1000 && monitor.Check(w.system)) {
        w.system.Update(0.01f);
        ++steps;
        ASSERT_TRUE(Finite(w.bob)) << "non-finite state at step " << steps << " before the monitor fired";
    }
    ASSERT_FALSE(monitor.Stable()) << "explicit Euler at omega dt = 1 ran 1,000 steps unreported";
    const StabilityReport& r = monitor.Report();
    EXPECT_NE(r.cause, InstabilityCause::NonFinite) << "caught only after NaN: " << r.message;
    EXPECT_GT(r.step, 0);
    EXPECT_LT(r.step, 100);
    EXPECT_FALSE(r.message.empty());
}

TEST(ExtremesTest, SymplecticIntegratorsOnTheSameSpringStayStable) {
    // Same spring and step: semi-implicit Euler and both Verlets are stable for omega dt < 2, so the monitor
    // must stay quiet (no false alarm) over 1,000 steps.
    for (Integrator integrator :
         {Integrator::SemiImplicitEuler, Integrator::VelocityVerlet, Integrator::PositionVerlet}) {
        StiffSpring w(integrator, 1e4f);
        StabilityMonitor monitor;
        monitor.Start(w.system);
        for (int i = 0; i < 1000; ++i) {
            w.system.Update(0.01f);
            ASSERT_TRUE(monitor.Check(w.system)) << ToString(integrator) << ": " << monitor.Report().message;
        }
    }
}

TEST(ExtremesTest, EveryIntegratorBeyondItsLimitIsReported) {
    // omega dt = 1000 * 0.01 = 10, beyond every integrator's stability limit (2 for the symplectic ones, 2.83 for
    // RK4): each must be reported within 100 steps, with the state still finite when it is.
    for (Integrator integrator : kAllIntegrators) {
        StiffSpring w(integrator, 1e6f);
        StabilityMonitor monitor;
        monitor.Start(w.system);
        int steps = 0;
        while (steps < 100 && monitor.Check(w.system)) {
            w.system.Update(0.01f);
            ++steps;
        }
        ASSERT_FALSE(monitor.Stable()) << ToString(integrator);
        EXPECT_NE(monitor.Report().cause, InstabilityCause::NonFinite) << ToString(integrator);
    }
}

}  // namespace
