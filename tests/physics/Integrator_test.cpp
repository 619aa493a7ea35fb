// Integrators against closed forms: the projectile (constant gravity) and the harmonic oscillator (a
// position-dependent force, through the same IntegrateParticleStates that PhysicsSystem uses).
#include "Physics/Integrator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "Physics/Particle.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/WorldSettings.h"
#include "tests/support/Approx.h"
#include "tests/support/TestWorld.h"

namespace {

constexpr float kG = 9.82f;
const vec3 kX0(1.0f, 2.0f, -0.5f);
const vec3 kV0(3.0f, 8.0f, -2.0f);

vec3 ProjectileAt(float t) { return vec3(kX0.x + kV0.x * t, kX0.y + kV0.y * t - 0.5f * kG * t * t, kX0.z + kV0.z * t); }

/// Position error after 2 s of free flight with `integrator`, friction 1 (the pure method), no constraints.
double ProjectileError(Integrator integrator, float dt, vec3* finalVelocity = nullptr) {
    TestWorld w;
    Particle& p = w.AddParticle();
    p.SetVelocityRetention(1.0f);
    p.SetPosition(kX0);
    p.SetVelocity(kV0);
    w.system.settings.integrator = integrator;
    w.Step(dt, static_cast<int>(std::lround(2.0 / dt)));
    if (finalVelocity != nullptr) *finalVelocity = p.GetVelocity();
    const vec3 exact = ProjectileAt(2.0f);
    const vec3 x = p.GetPosition();
    return std::sqrt(double(x.x - exact.x) * (x.x - exact.x) + double(x.y - exact.y) * (x.y - exact.y) +
                     double(x.z - exact.z) * (x.z - exact.z));
}

// ---- harmonic oscillator: force -k x on a unit mass, x(0) = 1, v(0) = 0, so x(t) = cos(w t) ----
struct Spring1D {
    std::vector<Particle*> ps;
    float k = 4.0f;  // w = 2 rad/s
};
void SpringForce(void* context) {
    auto* s = static_cast<Spring1D*>(context);
    for (Particle* p : s->ps) {
        p->SetGravity(vec3());
        p->ApplyForces();  // zero
        p->AddForce(p->GetPosition() * -s->k);
    }
}

double OscillatorError(Integrator integrator, float dt, float duration = 2.0f) {
    Particle p;
    p.SetVelocityRetention(1.0f);
    p.SetPosition(vec3(1.0f, 0.0f, 0.0f));
    Spring1D spring;
    spring.ps.push_back(&p);
    std::vector<IntegratorScratch> scratch(1);
    Particle* list[] = {&p};
    const int steps = static_cast<int>(std::lround(duration / dt));
    for (int i = 0; i < steps; ++i)
        IntegrateParticleStates(integrator, list, 1, scratch.data(), dt, kBookStep, &SpringForce, &spring);
    // Distance in phase space (x, v / w) to the exact state: insensitive to where in the cycle T falls.
    const double dx = double(p.GetPosition().x) - std::cos(2.0 * duration);
    const double dv = (double(p.GetVelocity().x) + 2.0 * std::sin(2.0 * duration)) / 2.0;
    return std::sqrt(dx * dx + dv * dv);
}

}  // namespace

TEST(Integrator, IdsRoundTripAndRejectUnknown) {
    for (Integrator i : kAllIntegrators) {
        Integrator parsed = Integrator::RK4;
        if (i == Integrator::RK4) parsed = Integrator::ExplicitEuler;
        ASSERT_TRUE(ParseIntegrator(ToString(i), &parsed)) << ToString(i);
        EXPECT_EQ(parsed, i);
        EXPECT_NE(IntegratorIds().find(ToString(i)), std::string::npos);
    }
    Integrator untouched = Integrator::VelocityVerlet;
    EXPECT_FALSE(ParseIntegrator("leapfrog", &untouched));
    EXPECT_FALSE(ParseIntegrator("", &untouched));
    EXPECT_EQ(untouched, Integrator::VelocityVerlet);
    EXPECT_EQ(ForceEvaluations(Integrator::RK4), 4);
    EXPECT_EQ(ForceEvaluations(Integrator::VelocityVerlet), 2);
    EXPECT_EQ(ForceEvaluations(Integrator::PositionVerlet), 1);
}

// Explicit and semi-implicit Euler are first order: under constant gravity their position error is exactly
// g t dt / 2 (x_n = x0 + v0 t + g dt^2 n(n -/+ 1)/2), so halving dt halves it.
TEST(Integrator, EulerProjectileErrorIsFirstOrder) {
    for (Integrator i : {Integrator::ExplicitEuler, Integrator::SemiImplicitEuler}) {
        double previous = 0.0;
        for (float dt : {0.02f, 0.01f, 0.005f}) {
            const double err = ProjectileError(i, dt);
            const double predicted = 0.5 * kG * 2.0 * dt;
            EXPECT_NEAR(err, predicted, 0.01 * predicted) << ToString(i) << " dt " << dt;
            if (previous > 0.0) {
                EXPECT_NEAR(previous / err, 2.0, 0.05) << ToString(i) << " dt " << dt;
            }
            previous = err;
        }
    }
}

// Velocity Verlet, position Verlet (with its Taylor start) and RK4 reproduce a parabola exactly, so only
// float rounding remains: positions reach ~8 m, float spacing there is ~1e-6 m, and a few hundred steps of
// rounding stay far below 1e-3 m while Euler's error at the same dt is 0.05-0.2 m.
TEST(Integrator, SecondOrderAndRK4ProjectileAreExactToFloatPrecision) {
    for (Integrator i : {Integrator::VelocityVerlet, Integrator::PositionVerlet, Integrator::RK4}) {
        for (float dt : {0.02f, 0.01f, 0.005f}) {
            vec3 v;
            EXPECT_LT(ProjectileError(i, dt, &v), 5e-4) << ToString(i) << " dt " << dt;
            EXPECT_TRUE(VecNear(v, vec3(kV0.x, kV0.y - kG * 2.0f, kV0.z), 1e-3f)) << ToString(i) << " dt " << dt;
        }
    }
}

// Orders on a position-dependent force (w = 2, 2 s): 1 for both Eulers, 2 for both Verlets, 4 for RK4. The
// step sizes keep every error well above float rounding (~1e-7).
TEST(Integrator, OscillatorErrorShrinksAtEachIntegratorsOrder) {
    struct Case {
        Integrator integrator;
        float dt;
        double ratio;  // expected error(dt) / error(dt / 2)
    };
    const Case cases[] = {{Integrator::ExplicitEuler, 0.004f, 2.0},
                          {Integrator::SemiImplicitEuler, 0.004f, 2.0},
                          {Integrator::VelocityVerlet, 0.04f, 4.0},
                          {Integrator::PositionVerlet, 0.04f, 4.0},
                          {Integrator::RK4, 0.1f, 16.0}};
    for (const Case& c : cases) {
        const double coarse = OscillatorError(c.integrator, c.dt);
        const double fine = OscillatorError(c.integrator, c.dt / 2);
        EXPECT_GT(fine, 1e-6) << ToString(c.integrator);
        EXPECT_NEAR(coarse / fine, c.ratio, 0.15 * c.ratio)
            << ToString(c.integrator) << " errors " << coarse << " / " << fine;
    }
}

// Per-step damping f scales the carried velocity: v = v f + g dt, so the terminal speed under gravity is
// g dt / (1 - f): the book's 5.892 m/s at dt 0.03, f 0.95 (docs/book-reference.md §3.2).
TEST(Integrator, FrictionGivesTheBooksTerminalSpeed) {
    for (Integrator i :
         {Integrator::ExplicitEuler, Integrator::SemiImplicitEuler, Integrator::VelocityVerlet, Integrator::RK4}) {
        TestWorld w;
        const Particle& p = w.AddParticle();
        w.system.settings.integrator = i;
        w.Step(0.03f, 2000);
        EXPECT_NEAR(-p.GetVelocity().y, 9.82f * 0.03f / 0.05f, 1e-3) << ToString(i);
        EXPECT_NEAR(-p.GetVelocity().y, 5.892f, 1e-3) << ToString(i);
    }
}

// Erratum 5.2-22: the book's Verlet adds forces * dt^2 with forces = g m, so a 3 kg particle falls three times
// as far as a 1 kg one. Here the mass is divided out: every mass follows the closed form.
TEST(Integrator, PositionVerletFallIsIndependentOfMass) {
    for (float mass : {1.0f, 3.0f, 0.25f}) {
        TestWorld w;
        Particle& p = w.AddParticle();
        p.SetVelocityRetention(1.0f);
        p.SetMass(mass);
        p.SetPosition(vec3(0, 100, 0));
        w.system.settings.integrator = Integrator::PositionVerlet;
        w.Step(0.02f, 50);
        EXPECT_NEAR(p.GetPosition().y, 100.0f - 0.5f * kG * 1.0f, 1e-3f) << "mass " << mass;
    }
}

TEST(Integrator, OldPositionIsTheStartOfTheStepForEveryIntegrator) {
    for (Integrator i : kAllIntegrators) {
        TestWorld w;
        Particle& p = w.AddParticle();
        p.SetPosition(vec3(1, 5, 2));
        p.SetVelocity(vec3(1, 0, 0));
        w.system.settings.integrator = i;
        w.Step(0.03f);
        const vec3 first = p.GetPosition();
        w.Step(0.03f);
        EXPECT_EQ(p.GetOldPosition().x, first.x) << ToString(i);
        EXPECT_EQ(p.GetOldPosition().y, first.y) << ToString(i);
        EXPECT_EQ(p.GetOldPosition().z, first.z) << ToString(i);
    }
}

TEST(Integrator, NonPositiveDtDoesNothing) {
    Particle p;
    p.SetPosition(vec3(0, 1, 0));
    p.SetVelocity(vec3(1, 1, 1));
    std::vector<IntegratorScratch> scratch(1);
    Particle* list[] = {&p};
    for (Integrator i : kAllIntegrators) {
        IntegrateParticleStates(i, list, 1, scratch.data(), 0.0f, kBookStep, &SpringForce, nullptr);
        IntegrateParticleStates(i, list, 1, scratch.data(), -1.0f, kBookStep, &SpringForce, nullptr);
    }
    EXPECT_TRUE(VecNear(p.GetPosition(), vec3(0, 1, 0), 0.0f));
    EXPECT_TRUE(VecNear(p.GetVelocity(), vec3(1, 1, 1), 0.0f));
}
