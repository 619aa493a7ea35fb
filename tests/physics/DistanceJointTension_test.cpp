// JointModel::Tension (Physics/DistanceJointTension.cpp, docs/ch16.md "A joint that keeps the integrator's order"):
// the tension of one joint by hand, a hanging chain's tensions in equilibrium, the pendulum's observed order of
// convergence against the exact large-angle motion for each model, and chains held at the extremes.
#include <gtest/gtest.h>

#include <cmath>
#include <deque>
#include <vector>

#include "Physics/DistanceJoint.h"
#include "Physics/PhysicsSystem.h"
#include "tests/support/Approx.h"
#include "tests/support/TestWorld.h"

namespace {

constexpr double kG = 9.82;  // Particle's default gravity magnitude (m/s^2)

/// A pivot of mass 0 at `top` and `links` bobs of 1 kg hung from it in a straight line at theta0 (rad) from the
/// straight-down, each `length` m from the previous, joined in a chain; no per-step damping (retention 1).
struct Chain {
    TestWorld w;
    std::deque<DistanceJoint> joints;
    std::vector<Particle*> bodies;  ///< pivot first
    float length = 1.0f;

    Chain(int links, double theta0, float linkLength, Integrator integrator, JointModel model) : length(linkLength) {
        const vec3 top(0.0f, 2.0f, 0.0f);
        const vec3 dir(float(std::sin(theta0)), -float(std::cos(theta0)), 0.0f);
        for (int i = 0; i <= links; ++i) {
            Particle& p = w.AddParticle();
            p.SetVelocityRetention(1.0f);
            p.SetPosition(top + dir * (linkLength * float(i)));
            if (i == 0) p.SetMass(0.0f);
            bodies.push_back(&p);
        }
        w.system.settings.integrator = integrator;
        w.system.settings.jointModel = model;
        w.Join();
        for (int i = 0; i < links; ++i) {
            joints.emplace_back();
            joints.back().Initialize(bodies[i], bodies[i + 1], linkLength);
            w.system.AddRigidbody(&joints.back());
        }
    }
    /// Largest |distance - length| over the links (m).
    float LengthError() const {
        float worst = 0.0f;
        for (std::size_t i = 1; i < bodies.size(); ++i) {
            const float d = Magnitude(bodies[i]->GetPosition() - bodies[i - 1]->GetPosition());
            worst = std::fmax(worst, std::fabs(d - length));
        }
        return worst;
    }
};

/// The ideal pendulum theta'' = -(g/L) sin theta in double, advanced by classical RK4 at steps of at most 1e-4 s
/// (its error, ~1e-15 rad over seconds, is far below any float run's): the exact large-angle motion.
struct ExactPendulum {
    double length, theta, omega = 0.0;
    void Advance(double dt) {
        const long n = std::lround(std::ceil(dt / 1e-4));
        const double h = dt / double(n);
        auto acc = [this](double a) { return -kG / length * std::sin(a); };
        for (long i = 0; i < n; ++i) {
            const double k1t = omega, k1o = acc(theta);
            const double k2t = omega + 0.5 * h * k1o, k2o = acc(theta + 0.5 * h * k1t);
            const double k3t = omega + 0.5 * h * k2o, k3o = acc(theta + 0.5 * h * k2t);
            const double k4t = omega + h * k3o, k4o = acc(theta + h * k3t);
            theta += h / 6.0 * (k1t + 2.0 * k2t + 2.0 * k3t + k4t);
            omega += h / 6.0 * (k1o + 2.0 * k2o + 2.0 * k3o + k4o);
        }
    }
};

/// The bob's largest distance (m) from the exact pendulum over `seconds` at step dt (every step compared).
double PendulumError(Integrator integrator, JointModel model, double theta0, float length, float dt, double seconds) {
    Chain c(1, theta0, length, integrator, model);
    ExactPendulum exact{length, theta0};
    const long steps = std::lround(seconds / dt);
    double worst = 0.0;
    for (long i = 0; i < steps; ++i) {
        c.w.system.Update(dt);
        exact.Advance(dt);
        const vec3 bob = c.bodies[1]->GetPosition() - c.bodies[0]->GetPosition();
        worst = std::fmax(worst, std::hypot(double(bob.x) - length * std::sin(exact.theta),
                                            double(bob.y) + length * std::cos(exact.theta)));
    }
    return worst;
}

/// Observed orders log2(e(dt) / e(dt/2)) over the steps dt, dt/2, dt/4.
std::vector<double> ObservedOrders(Integrator integrator, JointModel model, float dt) {
    const double theta0 = 120.0 * M_PI / 180.0, seconds = 3.0;
    std::vector<double> errors, orders;
    for (float h : {dt, 0.5f * dt, 0.25f * dt})
        errors.push_back(PendulumError(integrator, model, theta0, 1.0f, h, seconds));
    for (std::size_t i = 1; i < errors.size(); ++i) orders.push_back(std::log2(errors[i - 1] / errors[i]));
    std::printf("%s %s dt %g: errors %.3g %.3g %.3g, orders %.2f %.2f\n", ToString(integrator), ToString(model), dt,
                errors[0], errors[1], errors[2], orders[0], orders[1]);
    return orders;
}

}  // namespace

// A bob circling a fixed pivot at speed v without gravity needs the centripetal pull m v^2 / L, and nothing along its
// velocity. Here 2 kg at 3 m/s on 0.5 m: 36 N toward the pivot.
TEST(DistanceJointTension, OneJointPullsWithTheCentripetalForce) {
    Particle pivot, bob;
    pivot.SetMass(0.0f);
    pivot.SetPosition(vec3(1, 1, 1));
    bob.SetMass(2.0f);
    bob.SetPosition(vec3(1.5f, 1, 1));
    bob.SetVelocity(vec3(0, 0, 3));
    DistanceJoint joint;
    joint.Initialize(&pivot, &bob, 0.5f);
    DistanceJoint* list[] = {&joint};
    AddJointTensions(list, 1);
    EXPECT_TRUE(VecNear(bob.GetForces(), vec3(-36, 0, 0), 1e-4f));
    EXPECT_TRUE(VecNear(pivot.GetForces(), vec3(0, 0, 0), 0.0f));  // a mass-0 end gets nothing
}

// Two free 1 kg ends pulled apart by 4 N each (their own forces): the joint cancels both, equal and opposite.
TEST(DistanceJointTension, FreeEndsGetEqualAndOppositeForces) {
    Particle a, b;
    a.SetPosition(vec3(0, 0, 0));
    b.SetPosition(vec3(0, 2, 0));
    a.AddForce(vec3(0, -4, 0));
    b.AddForce(vec3(0, 4, 0));
    DistanceJoint joint;
    joint.Initialize(&a, &b, 2.0f);
    DistanceJoint* list[] = {&joint};
    AddJointTensions(list, 1);
    EXPECT_TRUE(VecNear(a.GetForces(), vec3(0, 0, 0), 1e-5f));
    EXPECT_TRUE(VecNear(b.GetForces(), vec3(0, 0, 0), 1e-5f));
}

// Joints sharing a movable particle are left to the projection; a mass-0 particle may be shared (two pendulums on
// one pivot are independent).
TEST(DistanceJointTension, OnlyJointsWithoutSharedMovableEndsArePulled) {
    Particle pivot, a, b, c;
    pivot.SetMass(0.0f);
    DistanceJoint pa, pb, bc;
    pa.Initialize(&pivot, &a, 1.0f);
    pb.Initialize(&pivot, &b, 1.0f);
    bc.Initialize(&b, &c, 1.0f);
    EXPECT_EQ(TensionJoints({&pa, &pb}), (std::vector<DistanceJoint*>{&pa, &pb}));
    EXPECT_EQ(TensionJoints({&pa, &pb, &bc}), (std::vector<DistanceJoint*>{&pa}));
}

// The book's joint is first order for every integrator; with the tension in the force evaluation velocity Verlet and
// RK4 keep at least their own order. Observed orders log2(e(h) / e(h/2)) of the bob's largest error against the exact
// 120 degree pendulum over 3 s. Measured: velocity-verlet 2.9 and 3.2 from dt 0.01 (above its formal 2 on this
// problem), rk4 5.3 and 5.1 from 0.08 (below 0.02 s it meets float rounding, ~1e-6 m); euler keeps the book's joint
// (TensionKeepsOrder), 0.8 and 0.9; the book's joint 0.8 and 0.9 for both (under the book's joint the force is
// gravity alone, constant over a step, so velocity Verlet and RK4 give the same bits).
TEST(DistanceJointTension, PendulumConvergesAtLeastAtTheIntegratorsOrder) {
    for (double p : ObservedOrders(Integrator::VelocityVerlet, JointModel::Tension, 0.01f)) EXPECT_GT(p, 1.7);
    for (double p : ObservedOrders(Integrator::RK4, JointModel::Tension, 0.08f)) EXPECT_GT(p, 3.7);
    for (double p : ObservedOrders(Integrator::SemiImplicitEuler, JointModel::Tension, 0.01f)) EXPECT_NEAR(p, 1.0, 0.3);
}

TEST(DistanceJointTension, TheBookJointStaysFirstOrder) {
    for (Integrator i : {Integrator::VelocityVerlet, Integrator::RK4})
        for (double p : ObservedOrders(i, JointModel::Book, 0.01f)) EXPECT_NEAR(p, 1.0, 0.35) << ToString(i);
}

/// Runs `steps` of dt on a chain with each joint model; true when every body ends at the same bits.
bool SameAsTheBook(int links, Integrator integrator, float dt, int steps) {
    Chain book(links, 150.0 * M_PI / 180.0, 0.4f, integrator, JointModel::Book);
    Chain tension(links, 150.0 * M_PI / 180.0, 0.4f, integrator, JointModel::Tension);
    for (int i = 0; i < steps; ++i) {
        book.w.system.Update(dt);
        tension.w.system.Update(dt);
    }
    for (std::size_t i = 0; i < book.bodies.size(); ++i)
        if (!VecNear(tension.bodies[i]->GetPosition(), book.bodies[i]->GetPosition(), 0.0f)) return false;
    return true;
}

// The extremes: a pendulum released at 150 degrees for 60 s at 0.01 s holds its length and never gains energy beyond
// a thousandth of g L under velocity Verlet and RK4. The first-order integrators keep the book's joint bit for bit
// (with the tension, euler gained 5,000 g L in that run and explicit Euler overflowed).
TEST(DistanceJointTension, PendulumHoldsAtTheExtremes) {
    for (Integrator integrator : kAllIntegrators) {
        if (!TensionKeepsOrder(integrator)) {
            EXPECT_TRUE(SameAsTheBook(1, integrator, 0.01f, 6000)) << ToString(integrator);
            continue;
        }
        Chain one(1, 150.0 * M_PI / 180.0, 1.0f, integrator, JointModel::Tension);
        const float y0 = one.bodies[1]->GetPosition().y;
        double worstGain = 0.0;
        float worstLength = 0.0f;
        for (int i = 0; i < 6000; ++i) {
            one.w.system.Update(0.01f);
            const vec3 v = one.bodies[1]->GetVelocity();
            worstGain =
                std::fmax(worstGain, 0.5 * double(Dot(v, v)) + kG * double(one.bodies[1]->GetPosition().y - y0));
            worstLength = std::fmax(worstLength, one.LengthError());
        }
        EXPECT_LT(worstLength, 1e-5f) << ToString(integrator);
        EXPECT_LT(worstGain, 1e-3 * kG) << ToString(integrator);
    }
}

// A chain (5 links of 0.4 m at 150 degrees, 20 s), whose joints tension leaves to the projection, runs bit for bit as
// with the book's joints: it holds its lengths as well as they do and never blows up.
TEST(DistanceJointTension, ChainRunsAsWithTheBooksJoints) {
    for (Integrator integrator : kAllIntegrators)
        EXPECT_TRUE(SameAsTheBook(5, integrator, 0.01f, 2000)) << ToString(integrator);
}
