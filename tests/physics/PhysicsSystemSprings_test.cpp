// Chapter 16 stages inside PhysicsSystem: spring forces integrated by every particle integrator (analytic
// period, energy behaviour and damping), joints in the solve order, degenerate inputs finite.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "Physics/Cloth.h"
#include "Physics/DistanceJoint.h"
#include "Physics/Particle.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/Spring.h"
#include "tests/support/Approx.h"

namespace {

constexpr double kPi = 3.14159265358979323846;

/// A mass on a spring to a fixed anchor (mass 0), no gravity, no per-step damping (friction 1), along x.
struct Oscillator {
    static constexpr float kRest = 1.0f;
    Particle anchor, bob;
    PhysicsSystem system;
    float stiffness;  // |k|, N/m
    float mass;

    Oscillator(Integrator integrator, float period, float massKg, float damping, float x0)
        : stiffness(float(4.0 * kPi * kPi * massKg / (double(period) * period))), mass(massKg) {
        for (Particle* p : {&anchor, &bob}) {
            p->SetGravity(vec3());
            p->SetVelocityRetention(1.0f);
        }
        anchor.SetMass(0.0f);
        bob.SetMass(massKg);
        anchor.SetPosition(vec3());
        bob.SetPosition(vec3(kRest + x0, 0, 0));
        system.settings.integrator = integrator;
        system.AddRigidbody(&anchor);
        system.AddRigidbody(&bob);
        Spring spring(-stiffness, damping, kRest);  // book sign: negative attracts
        spring.SetParticles(&anchor, &bob);
        system.AddSpring(spring);
    }
    double X() const { return double(bob.GetPosition().x) - kRest; }
    double V() const { return bob.GetVelocity().x; }
    double Energy() const { return 0.5 * mass * V() * V() + 0.5 * stiffness * X() * X(); }
};

/// Mean period from linearly interpolated upward zero crossings of the displacement.
double MeasurePeriod(Oscillator& osc, float dt, int steps) {
    std::vector<double> crossings;
    double prev = osc.X();
    for (int i = 1; i <= steps; ++i) {
        osc.system.Update(dt);
        const double x = osc.X();
        if (prev < 0.0 && x >= 0.0) crossings.push_back((i - 1 + prev / (prev - x)) * dt);
        prev = x;
    }
    if (crossings.size() < 2) return 0.0;
    return (crossings.back() - crossings.front()) / double(crossings.size() - 1);
}

class EveryIntegrator : public ::testing::TestWithParam<Integrator> {};

}  // namespace

// Period 2*pi*sqrt(m/k) within 1% at a small step (omega*dt = 0.0063), for every integrator.
TEST_P(EveryIntegrator, UndampedPeriodMatchesAnalytic) {
    const float period = 1.0f, mass = 2.0f, dt = 1e-3f;
    Oscillator osc(GetParam(), period, mass, 0.0f, 0.3f);
    const double analytic = 2.0 * kPi * std::sqrt(double(mass) / osc.stiffness);
    ASSERT_NEAR(analytic, period, 1e-5);
    EXPECT_NEAR(MeasurePeriod(osc, dt, 10500), analytic, 0.01 * analytic) << ToString(GetParam());
}

// Damped spring against the analytic solution of m x'' + b x' + |k| x = 0, x(0) = x0, v(0) = 0, at omega0*dt =
// 0.0063 over 2 s. Tolerance: 1% of x0 for the first-order Eulers (global error ~ omega0*dt), 0.2% for the
// others. (Position Verlet at a much smaller dt, e.g. 1e-4, sticks at turning points in float: a*dt^2 falls
// below half an ulp of x, so x1 == x0 and the velocity it derives from positions is lost.)
TEST_P(EveryIntegrator, DampedDecayMatchesAnalytic) {
    const double w0 = 2.0 * kPi, x0 = 0.5;
    const float dt = 1e-3f;
    const bool firstOrder = GetParam() == Integrator::ExplicitEuler || GetParam() == Integrator::SemiImplicitEuler;
    const double tolerance = (firstOrder ? 0.01 : 0.002) * x0;
    for (double zeta : {0.2, 1.0, 2.0}) {
        Oscillator osc(GetParam(), 1.0f, 1.0f, float(2.0 * zeta * w0), float(x0));
        double worst = 0.0, lowest = x0;
        int signChanges = 0;
        double prev = osc.X();
        for (int i = 1; i <= 2000; ++i) {
            osc.system.Update(dt);
            const double t = i * double(dt);
            double expected;
            if (zeta < 1.0) {
                const double wd = w0 * std::sqrt(1.0 - zeta * zeta);
                expected = std::exp(-zeta * w0 * t) * (x0 * std::cos(wd * t) + zeta * w0 * x0 / wd * std::sin(wd * t));
            } else if (zeta == 1.0) {
                expected = (x0 + w0 * x0 * t) * std::exp(-w0 * t);
            } else {
                const double s = std::sqrt(zeta * zeta - 1.0);
                const double r1 = -w0 * (zeta - s), r2 = -w0 * (zeta + s);
                expected = (-r2 * x0 * std::exp(r1 * t) + r1 * x0 * std::exp(r2 * t)) / (r1 - r2);
            }
            worst = std::fmax(worst, std::fabs(osc.X() - expected));
            lowest = std::fmin(lowest, osc.X());
            if ((prev > 0.0) != (osc.X() > 0.0)) ++signChanges;
            prev = osc.X();
        }
        EXPECT_LT(worst, tolerance) << ToString(GetParam()) << " zeta " << zeta;
        if (zeta < 1.0) {
            EXPECT_GE(signChanges, 3) << "under-damped must overshoot";
            EXPECT_LT(lowest,
                      -0.2 * x0);  // analytic first undershoot: -x0 * exp(-pi zeta / sqrt(1 - zeta^2)) = -0.27 x0
        } else {
            EXPECT_GT(lowest, -tolerance) << "critically and over-damped must not overshoot";
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Soft, EveryIntegrator, ::testing::ValuesIn(kAllIntegrators),
                         [](const ::testing::TestParamInfo<Integrator>& info) {
                             std::string id = ToString(info.param);
                             for (char& c : id)
                                 if (c == '-') c = '_';
                             return id;
                         });

namespace {

struct EnergyRun {
    double maxDeviation = 0.0;  // max |E/E0 - 1|
    double firstMean = 0.0;     // mean E/E0 over the first 10 periods
    double lastMean = 0.0;      // mean E/E0 over the last 10 periods
    double final = 0.0;         // E/E0 at the end
};

EnergyRun RunEnergy(Integrator integrator, int stepsPerPeriod, int periods) {
    Oscillator osc(integrator, 1.0f, 1.0f, 0.0f, 0.4f);
    const float dt = 1.0f / float(stepsPerPeriod);
    const double e0 = osc.Energy();
    const int steps = stepsPerPeriod * periods, window = 10 * stepsPerPeriod;
    EnergyRun run;
    for (int i = 1; i <= steps; ++i) {
        osc.system.Update(dt);
        const double r = osc.Energy() / e0;
        run.maxDeviation = std::fmax(run.maxDeviation, std::fabs(r - 1.0));
        if (i <= window) run.firstMean += r / window;
        if (i > steps - window) run.lastMean += r / window;
    }
    run.final = osc.Energy() / e0;
    return run;
}

}  // namespace

// Symplectic integrators: energy stays in a band over 1,000 periods (100 steps per period, omega*dt = 0.063)
// and does not drift (means of the first and last 10 periods within 0.5%: measured 0.00003 for the Eulers and
// velocity Verlet, 0.0022 for position Verlet, whose float velocity is rebuilt from positions). Band for semi-implicit
// Euler: its energy error oscillates with relative amplitude about omega*dt/2 = 0.031; stated band 0.04. The
// second-order methods: (omega*dt)^2/4 ~ 0.001; band 0.005.
TEST(PhysicsSystemSprings, SymplecticEnergyBoundedOverThousandPeriods) {
    struct Case {
        Integrator integrator;
        double band;
    };
    for (const Case& c : {Case{Integrator::SemiImplicitEuler, 0.04}, Case{Integrator::VelocityVerlet, 0.005},
                          Case{Integrator::PositionVerlet, 0.005}}) {
        const EnergyRun run = RunEnergy(c.integrator, 100, 1000);
        EXPECT_LT(run.maxDeviation, c.band) << ToString(c.integrator);
        EXPECT_NEAR(run.lastMean, run.firstMean, 0.005) << ToString(c.integrator) << ": secular drift";
    }
}

// Explicit Euler on a harmonic oscillator multiplies the energy by exactly (1 + (omega dt)^2) per step:
// it GAINS energy. Measured over 2 periods at 100 steps per period against that factor (1%).
TEST(PhysicsSystemSprings, ExplicitEulerGainsEnergyAsPredicted) {
    const int steps = 200;
    const EnergyRun run = RunEnergy(Integrator::ExplicitEuler, 100, 2);
    const double wdt = 2.0 * kPi / 100.0;
    const double predicted = std::pow(1.0 + wdt * wdt, steps);
    EXPECT_GT(run.final, 1.5);  // gains, clearly
    EXPECT_NEAR(run.final, predicted, 0.01 * predicted);
}

// RK4 on a harmonic oscillator multiplies the energy by |R(i y)|^2 = 1 - y^6/72 + y^8/576 per step (y = omega
// dt): it LOSES energy slowly. 20 steps per period (y = 0.314), 1,000 periods: predicted 0.768; 1%.
TEST(PhysicsSystemSprings, Rk4LosesEnergySlowlyAsPredicted) {
    const int perPeriod = 20, periods = 1000;
    const EnergyRun run = RunEnergy(Integrator::RK4, perPeriod, periods);
    const double y = 2.0 * kPi / perPeriod;
    const double perStep = 1.0 - std::pow(y, 6) / 72.0 + std::pow(y, 8) / 576.0;
    const double predicted = std::pow(perStep, perPeriod * periods);
    EXPECT_LT(run.final, 1.0);
    EXPECT_NEAR(run.final, predicted, 0.01 * predicted);
    EXPECT_LT(run.maxDeviation, 0.25);
}

// erratum 5.2-20: the spring is a force integrated over the step, so the velocity it gives in one step scales
// with dt (dv = F/m dt). The book added F/m to the velocity every step whatever dt (here dv = 3 at both steps).
TEST(PhysicsSystemSprings, Erratum5_2_20_SpringVelocityChangeScalesWithDt) {
    auto oneStep = [](float dt) {
        Particle a, b;
        for (Particle* p : {&a, &b}) {
            p->SetGravity(vec3());
            p->SetVelocityRetention(1.0f);
        }
        a.SetPosition(vec3(0, 0, 0));
        b.SetPosition(vec3(2, 0, 0));
        PhysicsSystem system;
        system.settings.integrator = Integrator::SemiImplicitEuler;
        system.AddRigidbody(&a);
        system.AddRigidbody(&b);
        Spring spring(-3.0f, 0.0f, 1.0f);  // F = 3 N toward each other
        spring.SetParticles(&a, &b);
        system.AddSpring(spring);
        system.Update(dt);
        return a.GetVelocity().x;
    };
    EXPECT_NEAR(oneStep(0.01f), 0.03f, 1e-6f);
    EXPECT_NEAR(oneStep(0.02f), 0.06f, 1e-6f);
}

TEST(PhysicsSystemSprings, SpringsAreCopiedAndClothSpringsApplied) {
    // System springs are copies (docs/book-reference.md §3.4): editing the original after AddSpring changes nothing.
    Particle a, b;
    for (Particle* p : {&a, &b}) {
        p->SetGravity(vec3());
        p->SetVelocityRetention(1.0f);
    }
    a.SetPosition(vec3(0, 0, 0));
    b.SetPosition(vec3(2, 0, 0));
    PhysicsSystem system;
    system.AddRigidbody(&a);
    system.AddRigidbody(&b);
    Spring spring(-3.0f, 0.0f, 1.0f);
    spring.SetParticles(&a, &b);
    system.AddSpring(spring);
    spring.k = -300.0f;
    system.Update(0.01f);
    EXPECT_NEAR(a.GetVelocity().x, 0.03f, 1e-6f);

    // A cloth's springs act on its particles: a stretched 3x3 cloth without gravity contracts.
    Cloth cloth;
    cloth.Initialize(3, 1.0f, vec3());
    for (Particle& p : cloth.verts) p.SetGravity(vec3());
    cloth.SetStructuralSprings(-10.0f, 0.0f);
    cloth.SetShearSprings(-10.0f, 0.0f);
    cloth.SetBendSprings(-10.0f, 0.0f);
    for (std::vector<Spring>* family : {&cloth.structural, &cloth.shear, &cloth.bend})
        for (Spring& s : *family) s.restingLength *= 0.5f;
    PhysicsSystem clothSystem;
    clothSystem.AddCloth(&cloth);
    clothSystem.Update(0.01f);
    EXPECT_GT(cloth.verts[0].GetVelocity().x, 0.0f);  // corner pulled toward the centre
    EXPECT_GT(cloth.verts[0].GetVelocity().z, 0.0f);
    EXPECT_TRUE(VecNear(cloth.verts[4].GetVelocity(), vec3(), 1e-6f));  // centre: forces cancel
}

// erratum 5.2-6 through the whole step: coincident spring ends, zero rest length and zero-length joints
// (particles inside a box, so the point-in-box path runs) stay finite with every integrator.
TEST(PhysicsSystemSprings, Erratum5_2_6_DegenerateSpringsAndJointsStayFinite) {
    for (Integrator integrator : kAllIntegrators) {
        Particle c1, c2, z1, z2, j1, j2;
        c1.SetPosition(vec3(3, 2, 0));
        c2.SetPosition(vec3(3, 2, 0));  // coincident, rest 1
        z1.SetPosition(vec3(-3, 2, 0));
        z2.SetPosition(vec3(-3, 2.5f, 0));  // zero rest length
        j1.SetPosition(vec3(0, 0.1f, 0));   // inside the ground box, coincident, joint length 0
        j2.SetPosition(vec3(0, 0.1f, 0));
        PhysicsSystem system;
        system.settings.integrator = integrator;
        system.AddConstraint(OBB(vec3(), vec3(10, 0.15f, 10)));
        for (Particle* p : {&c1, &c2, &z1, &z2, &j1, &j2}) system.AddRigidbody(p);
        DistanceJoint joint;
        joint.Initialize(&j1, &j2, 0.0f);
        system.AddRigidbody(&joint);
        Spring coincident(-50.0f, 1.0f, 1.0f), zeroRest(-50.0f, 1.0f, 0.0f);
        coincident.SetParticles(&c1, &c2);
        zeroRest.SetParticles(&z1, &z2);
        system.AddSpring(coincident);
        system.AddSpring(zeroRest);
        for (int i = 0; i < 200; ++i) system.Update(0.03f);
        for (const Particle* p : {&c1, &c2, &z1, &z2, &j1, &j2}) {
            EXPECT_TRUE(IsFinite(p->GetPosition())) << ToString(integrator);
            EXPECT_TRUE(IsFinite(p->GetVelocity())) << ToString(integrator);
        }
    }
}

// Joints run after the free particles' own constraint pass and before cloth particles (docs/book-reference.md §2.8,
// §3.4): after a step the pair is exactly at its length unless a box pushed one end.
TEST(PhysicsSystemSprings, JointHoldsLengthAfterStep) {
    Particle a, b;
    a.SetPosition(vec3(0, 5, 0));
    b.SetPosition(vec3(0.3f, 5.2f, 0.1f));
    PhysicsSystem system;
    system.AddConstraint(OBB(vec3(), vec3(10, 0.15f, 10)));
    system.AddRigidbody(&a);
    system.AddRigidbody(&b);
    DistanceJoint joint;
    joint.Initialize(&a, &b, 0.8f);
    system.AddRigidbody(&joint);
    for (int i = 0; i < 10; ++i) {
        system.Update(0.03f);
        EXPECT_NEAR(Magnitude(b.GetPosition() - a.GetPosition()), 0.8f, 1e-5f) << i;
    }
}
