// ParticleContact::Reflect (Physics/Particle.cpp, docs/ch14.md "Contact that converges"): a bounce against the exact
// ideal bounce computed here in double, on a flat and on a rotated face; a particle resting or sliding on a face;
// leaving a face; edges and corners.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "Physics/Particle.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/Spring.h"
#include "tests/support/TestWorld.h"

namespace {

constexpr double kG = 9.82;       // m/s^2 along -n
constexpr double kOmega2 = 25.0;  // 1/s^2: the spring's K / m
constexpr double kAnchor = -0.5;  // m: the spring's anchor, under the face (rest length 0)
constexpr double kRestitution = 0.5;

/// Height over the face of the exact ideal bounce at time T: y'' = -g - w^2 (y - anchor) in flight (a harmonic
/// motion about yEq), each crossing of y = 0 downward reflecting the velocity with -e. Found by a fine scan and
/// bisection in double.
double ExactHeight(double y0, double T) {
    const double w = std::sqrt(kOmega2), yEq = kAnchor - kG / kOmega2;
    double t0 = 0.0, A = y0 - yEq, B = 0.0;  // y(t) = yEq + A cos(w (t - t0)) + B sin(w (t - t0))
    auto y = [&](double t) { return yEq + A * std::cos(w * (t - t0)) + B * std::sin(w * (t - t0)); };
    auto v = [&](double t) { return w * (-A * std::sin(w * (t - t0)) + B * std::cos(w * (t - t0))); };
    for (double t = t0 + 1e-6; t < T;) {
        const double next = std::min(t + 1e-4, T);
        if (y(next) >= 0.0) {
            t = next;
            continue;
        }
        double lo = t, hi = next;  // y(lo) >= 0 > y(hi)
        for (int i = 0; i < 80; ++i) (y(0.5 * (lo + hi)) >= 0.0 ? lo : hi) = 0.5 * (lo + hi);
        const double vUp = -kRestitution * v(lo);
        t0 = lo;
        A = -yEq;
        B = vUp / w;
        t = t0 + 1e-9;
    }
    return y(T);
}

/// One particle on the spring, started at rest `y0` over the face of `box` through its local +y face's centre,
/// gravity along that face's -normal, stepped to T (whole steps) with `contact` and RK4 (fourth order in flight,
/// so the contact's error is what is left). Returns the distance from the exact ideal bounce at the last step.
double BounceError(const OBB& box, ParticleContact contact, double y0, float dt, double T) {
    const float* m = box.orientation.asArray;
    const vec3 n(m[3], m[4], m[5]);
    const vec3 face = box.position + n * std::fabs(box.size.y);
    TestWorld w;
    w.system.settings.particleContact = contact;
    w.system.settings.integrator = Integrator::RK4;
    w.system.AddConstraint(box);
    Particle anchor;  // not in the world: it only holds the spring's end
    anchor.SetMass(0.0f);
    anchor.SetPosition(face + n * static_cast<float>(kAnchor));
    Particle& p = w.AddParticle();
    p.SetVelocityRetention(1.0f);
    p.SetBounce(static_cast<float>(kRestitution));
    p.SetGravity(n * static_cast<float>(-kG));
    p.SetPosition(face + n * static_cast<float>(y0));
    Spring spring(static_cast<float>(-kOmega2), 0.0f, 0.0f);
    spring.SetParticles(&p, &anchor);
    w.system.AddSpring(spring);
    const int steps = static_cast<int>(std::floor(T / dt + 1e-9));
    w.Step(dt, steps);
    const double t = static_cast<double>(steps) * dt;
    return Magnitude(p.GetPosition() - (face + n * static_cast<float>(ExactHeight(y0, t))));
}

/// The largest BounceError over start heights that put the impact at different phases within the step.
double WorstBounceError(const OBB& box, ParticleContact contact, float dt) {
    double worst = 0.0;
    for (double y0 = 0.9; y0 < 1.15; y0 += 0.02) worst = std::max(worst, BounceError(box, contact, y0, dt, 0.45));
    return worst;
}

const OBB kFlat(vec3(0, -1, 0), vec3(20, 1, 20));
const OBB kRotated(vec3(1, -2, 0.5f), vec3(20, 1, 20), Rotation3x3(25, 40, -30));

/// Errors halve-by-halve at dt = 16, 8, 4, 2 ms: each step halving cuts it about 4x (second order).
void ExpectSecondOrder(const OBB& box) {
    std::vector<double> errors;
    for (float dt : {0.016f, 0.008f, 0.004f, 0.002f})
        errors.push_back(WorstBounceError(box, ParticleContact::Reflect, dt));
    for (std::size_t i = 1; i < errors.size(); ++i) EXPECT_GT(errors[i - 1] / errors[i], 2.8) << i;
    const double order = std::log2(errors.front() / errors.back()) / 3.0;
    EXPECT_GT(order, 1.8);
    EXPECT_LT(errors.back(), 3e-4);
    // The offset contacts stay off by about their offset whatever the step (first order at best above it).
    for (ParticleContact c : {ParticleContact::Book, ParticleContact::Skin})
        EXPECT_GT(WorstBounceError(box, c, 0.002f), 0.5 * Particle::kContactOffset) << ToString(c);
}

}  // namespace

TEST(ReflectContact, ABounceConvergesToTheIdealBounceAtSecondOrderOnAFlatFace) { ExpectSecondOrder(kFlat); }

TEST(ReflectContact, ABounceConvergesToTheIdealBounceAtSecondOrderOnARotatedFace) { ExpectSecondOrder(kRotated); }

namespace {

/// A particle put on the top face of `box` (through its centre, plus `along` in the face) with tangential velocity
/// `slide`, stepped `seconds` at dt with `integrator`; returns the largest |distance off the face's plane| seen.
double LargestGapOffTheFace(const OBB& box, Integrator integrator, float dt, float seconds, const vec3& slide,
                            vec3* endVelocity, float restitution = 0.5f) {
    const float* m = box.orientation.asArray;
    const vec3 n(m[3], m[4], m[5]);
    const vec3 face = box.position + n * std::fabs(box.size.y);
    TestWorld w;
    w.system.settings.particleContact = ParticleContact::Reflect;
    w.system.settings.integrator = integrator;
    w.system.AddConstraint(box);
    Particle& p = w.AddParticle();
    p.SetVelocityRetention(1.0f);
    p.SetBounce(restitution);
    p.SetGravity(n * static_cast<float>(-kG));
    p.SetPosition(face);
    p.SetVelocity(slide);
    w.Join();
    double gap = 0.0;
    const int steps = static_cast<int>(std::lround(seconds / dt));
    for (int i = 0; i < steps; ++i) {
        w.system.Update(dt);
        gap = std::max(gap, std::fabs(static_cast<double>(Dot(p.GetPosition() - face, n))));
    }
    *endVelocity = p.GetVelocity();
    return gap;
}

}  // namespace

TEST(ReflectContact, AParticleAtRestOnAFaceStaysOnItForEveryIntegrator) {
    for (const OBB& box : {kFlat, kRotated}) {
        for (Integrator integrator : kAllIntegrators) {
            for (float dt : {0.01f, 0.001f}) {
                for (float e : {0.3f, 0.5f, 0.7f, 1.0f}) {
                    vec3 v;
                    const double gap = LargestGapOffTheFace(box, integrator, dt, 10.0f, vec3(), &v, e);
                    EXPECT_LT(gap, kG * dt * dt + 1e-5) << ToString(integrator) << " dt " << dt << " e " << e;
                    EXPECT_LT(Magnitude(v), kG * dt + 1e-4) << ToString(integrator) << " dt " << dt << " e " << e;
                }
            }
        }
    }
}

TEST(ReflectContact, AParticleSlidingAlongAFaceStaysOnItAndKeepsItsSpeed) {
    const float* m = kRotated.orientation.asArray;
    const vec3 tangent(m[0], m[1], m[2]);  // the box's local x: along its top face
    for (int k = 0; k < 2; ++k) {
        const OBB& box = k == 0 ? kFlat : kRotated;
        const vec3 slide = (k == 0 ? vec3(1, 0, 0) : tangent) * 2.0f;
        for (float dt : {0.01f, 0.001f}) {
            vec3 v;
            const double gap = LargestGapOffTheFace(box, Integrator::VelocityVerlet, dt, 4.0f, slide, &v);
            EXPECT_LT(gap, kG * dt * dt + 1e-5) << "dt " << dt;
            EXPECT_NEAR(Magnitude(v), 2.0f, 1e-3f) << "dt " << dt;  // no friction: the tangential part is kept
        }
    }
}

TEST(ReflectContact, AParticleDroppedOnAFaceComesToRestOnItAndNotAboveIt) {
    // Semi-implicit Euler (the default): its step reaches the face at g dt / 2 from rest, and the bounces that
    // follow within the step end in it (BounceTrain), so it settles on the face.
    for (float dt : {0.01f, 0.001f}) {
        TestWorld w;
        w.system.settings.particleContact = ParticleContact::Reflect;
        w.system.AddConstraint(kFlat);
        Particle& p = w.AddParticle();
        p.SetVelocityRetention(1.0f);
        p.SetBounce(0.5f);
        p.SetPosition(vec3(0, 1, 0));
        w.Step(dt, static_cast<int>(std::lround(4.0f / dt)));  // the ideal bounces end after 1.36 s
        EXPECT_NEAR(p.GetPosition().y, 0.0f, 1e-5f) << "dt " << dt;
        EXPECT_LT(std::fabs(p.GetVelocity().y), 1e-4f) << "dt " << dt;
    }
}

TEST(ReflectContact, LeavingTheFaceAParticleRestsOnIsNoHit) {
    TestWorld w;
    w.system.settings.particleContact = ParticleContact::Reflect;
    w.system.AddConstraint(kFlat);
    Particle& p = w.AddParticle();
    p.SetVelocityRetention(1.0f);
    p.SetPosition(vec3(0, 0, 0));
    p.SetVelocity(vec3(0.5f, 3.0f, 0));
    w.Step(0.01f);
    // Semi-implicit Euler: v = 3 - g dt, y = v dt, untouched by the contact.
    EXPECT_FLOAT_EQ(p.GetVelocity().y, 3.0f - 9.82f * 0.01f);
    EXPECT_FLOAT_EQ(p.GetPosition().y, (3.0f - 9.82f * 0.01f) * 0.01f);
}

TEST(ReflectContact, AParticleFiredAtEdgesAndCornersNeverEndsAStepInsideTheBox) {
    // Aimed at points on and near the edges and corners of an upright and a rotated box from every side, fast enough
    // to cross the whole box in one step: after every step the particle is outside (or on) the box.
    int hits = 0, shots = 0;
    for (const OBB& box : {OBB(vec3(0, 0, 0), vec3(0.5f, 0.3f, 0.4f)),
                           OBB(vec3(1, 2, 3), vec3(0.5f, 0.3f, 0.4f), Rotation3x3(30, 45, 10))}) {
        const float* m = box.orientation.asArray;
        const vec3 axes[3] = {vec3(m[0], m[1], m[2]), vec3(m[3], m[4], m[5]), vec3(m[6], m[7], m[8])};
        for (int corner = 0; corner < 27; ++corner) {
            const float c[3] = {float(corner % 3 - 1), float(corner / 3 % 3 - 1), float(corner / 9 - 1)};
            if (c[0] * c[0] + c[1] * c[1] + c[2] * c[2] < 2.0f) continue;  // edges (two +-1) and corners (three)
            vec3 target = box.position;
            for (int i = 0; i < 3; ++i) target = target + axes[i] * (c[i] * box.size[i] * 0.999f);
            for (int from = 0; from < 6; ++from) {
                const vec3 dir = axes[from % 3] * (from < 3 ? 1.0f : -1.0f);
                TestWorld w;
                w.system.settings.particleContact = ParticleContact::Reflect;
                w.system.AddConstraint(box);
                Particle& p = w.AddParticle();
                p.SetVelocityRetention(1.0f);
                p.SetGravity(vec3());
                p.SetPosition(target + dir * 2.0f);
                p.SetVelocity(dir * -60.0f);
                w.Join();
                for (int step = 0; step < 5; ++step) {
                    w.system.Update(0.03f);
                    const vec3 rel = p.GetPosition() - box.position;
                    float outside = -1e9f;  // largest signed distance outside a face: <= 0 means inside
                    for (int i = 0; i < 3; ++i) outside = std::max(outside, std::fabs(Dot(rel, axes[i])) - box.size[i]);
                    EXPECT_GT(outside, -1e-5f) << "corner " << corner << " from " << from << " step " << step;
                }
                hits += Dot(p.GetVelocity(), dir) > 0.0f;  // it bounced back
                ++shots;
            }
        }
    }
    EXPECT_EQ(hits, shots);  // every shot met the box (the test is not all misses)
    EXPECT_GT(shots, 200);
}
