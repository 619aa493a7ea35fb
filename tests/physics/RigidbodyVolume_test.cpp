// RigidbodyVolume: inertia, integration and ApplyImpulse with hand-made manifolds (independent of the
// geometry layer's manifold code).
#include "Physics/RigidbodyVolume.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "tests/support/Approx.h"
#include "tests/support/Volumes.h"

namespace {

CollisionManifold OneContact(const vec3& normal, const vec3& contact, float depth) {
    CollisionManifold m;
    m.colliding = true;
    m.normal = normal;
    m.depth = depth;
    m.contacts.push_back(contact);
    return m;
}

vec3 PointVelocity(const RigidbodyVolume& b, const vec3& point) {
    return b.velocity + Cross(b.angVel, point - b.position);
}

}  // namespace

TEST(RigidbodyVolume, InertiaOfBookBodies) {
    // docs/book-reference.md §3.3: unit cube of mass 1 -> 2/3, mass 5 -> 10/3, unit sphere of mass 1 -> 2/5.
    EXPECT_TRUE(
        VecNear(MakeBox(vec3(), vec3(1, 1, 1), 1.0f).LocalInertia(), vec3(2.f / 3, 2.f / 3, 2.f / 3), tol::kTight));
    EXPECT_TRUE(
        VecNear(MakeBox(vec3(), vec3(1, 1, 1), 5.0f).LocalInertia(), vec3(10.f / 3, 10.f / 3, 10.f / 3), tol::kTight));
    EXPECT_TRUE(VecNear(MakeSphere(vec3(), 1.0f, 1.0f).LocalInertia(), vec3(0.4f, 0.4f, 0.4f), tol::kExact));
    // Non-cubic box, full edges 4 x 2 x 1, mass 3: Ix = 3(4+1)/12, Iy = 3(16+1)/12, Iz = 3(16+4)/12.
    EXPECT_TRUE(VecNear(MakeBox(vec3(), vec3(2, 1, 0.5f), 3.0f).LocalInertia(), vec3(1.25f, 4.25f, 5.0f), tol::kTight));
    EXPECT_TRUE(MatNear(MakeBox(vec3(), vec3(1, 1, 1), 0.0f).InvTensor(), ZeroMat3(), tol::kExact));
    EXPECT_EQ(MakeBox(vec3(), vec3(1, 1, 1), 0.0f).InvMass(), 0.0f);
}

// erratum 5.2-10: the book's InvTensor inverts diag(I, I, I, 1) with the general mat4 Inverse, which returns the
// identity when |det| <= 0.005. A half-size 0.5 box of mass 1 has I = 1/6 (det 0.0046): the book gives an
// inverse inertia of 1 instead of 6, so the same torque impulse spins it 6 times too slowly.
TEST(RigidbodyVolume, Erratum5_2_10_SmallBodyInverseInertiaIsNotIdentity) {
    const RigidbodyVolume small = MakeBox(vec3(), vec3(0.5f, 0.5f, 0.5f), 1.0f);
    EXPECT_TRUE(MatNear(small.InvTensor(), mat3(6, 0, 0, 0, 6, 0, 0, 0, 6), tol::kLoose));
    const RigidbodyVolume ball = MakeSphere(vec3(), 0.5f, 1.0f);  // I = 0.1, det 0.001 (book: identity)
    EXPECT_TRUE(MatNear(ball.InvTensor(), mat3(10, 0, 0, 0, 10, 0, 0, 0, 10), tol::kLoose));
}

// erratum 5.2-11: the book applies the body-frame inverse tensor in world space. A 4 x 2 x 1 box turned 90
// degrees about z has its long local x axis along world y, so spin about world y meets Ix (the small moment).
// The book's version returns 1/Iy for world y.
TEST(RigidbodyVolume, Erratum5_2_11_InverseInertiaIsRotatedToWorld) {
    RigidbodyVolume b = MakeBox(vec3(), vec3(2, 1, 0.5f), 3.0f);
    b.SetEulerOrientation(vec3(0, 0, 3.14159265f / 2));
    const vec3 I = b.LocalInertia();
    EXPECT_TRUE(VecNear(MultiplyVector(vec3(0, 1, 0), b.InvTensor()), vec3(0, 1 / I.x, 0), tol::kLoose));
    EXPECT_TRUE(VecNear(MultiplyVector(vec3(1, 0, 0), b.InvTensor()), vec3(1 / I.y, 0, 0), tol::kLoose));
    EXPECT_TRUE(MatNear(b.InvTensor() * b.InertiaTensor(), mat3(), tol::kLoose));
}

TEST(RigidbodyVolume, EulerOrientationMatchesTheBookCh15Box) {
    RigidbodyVolume b = MakeBox(vec3(0.5f, 6, 0), vec3(1, 1, 1), 1.0f);
    b.SetEulerOrientation(vec3(0, 0, 0.4f));
    // docs/book-reference.md §2.5: rows (0.92106, 0.38942, 0), (-0.38942, 0.92106, 0), (0, 0, 1).
    EXPECT_TRUE(MatNear(b.box.orientation, mat3(0.92106f, 0.38942f, 0, -0.38942f, 0.92106f, 0, 0, 0, 1), tol::kBook));
    EXPECT_TRUE(VecNear(b.box.position, vec3(0.5f, 6, 0), tol::kExact));
}

TEST(RigidbodyVolume, UpdateAppliesGravityDampingAndThresholds) {
    RigidbodyVolume b = MakeBox(vec3(0, 10, 0), vec3(1, 1, 1), 2.0f);
    b.velocity = vec3(1.0f, 0.0f, 0.0005f);
    b.ApplyForces();
    EXPECT_TRUE(VecNear(b.forces, vec3(0, -19.64f, 0), tol::kTight));
    const float dt = 0.03f;
    b.Update(dt);
    // v = (v + g dt) * 0.98, then |v_i| < 0.001 -> 0 (the z component 0.00049 is zeroed).
    const vec3 v(0.98f, -9.82f * dt * 0.98f, 0.0f);
    EXPECT_TRUE(VecNear(b.velocity, v, tol::kTight));
    EXPECT_TRUE(VecNear(b.position, vec3(0, 10, 0) + v * dt, tol::kTight));
    EXPECT_TRUE(VecNear(b.box.position, b.position, tol::kExact));
}

// The book's damping (0.98, our velocityRetention) and threshold (0.001) are per step of its 0.03 s. At exactly that
// step they are used as the book does; at any other step they are converted (retention^(dt/ref), eps dt/ref), so
// the per-second rates stay those of a 0.03 s step and the threshold never exceeds the velocity g dt gives a body.
TEST(RigidbodyVolume, RetentionAndThresholdArePerBookStepAndConvertedAtOtherSteps) {
    RigidbodyVolume b = MakeBox(vec3(), vec3(1, 1, 1), 1.0f);
    EXPECT_EQ(b.referenceStep, kBookStep);
    EXPECT_EQ(b.StepRetention(0.03f), 0.98f);
    EXPECT_EQ(b.StepVelocityEpsilon(0.03f), 0.001f);
    const float ref = kBookStep;
    for (float dt : {1e-3f, 1.0f / 60.0f, 0.5f}) {
        EXPECT_NEAR(b.StepRetention(dt), std::pow(0.98f, dt / ref), 1e-6f) << dt;
        EXPECT_NEAR(b.StepVelocityEpsilon(dt), 0.001f * dt / ref, 1e-8f) << dt;
    }
    EXPECT_LT(b.StepVelocityEpsilon(1e-5f), 9.82f * 1e-5f);  // below g dt: free fall is never zeroed
    // Ten steps of ref/10 damp like one step of ref; half a step of 2 ref damps like one of ref.
    float tenth = 1.0f;
    for (int i = 0; i < 10; ++i) tenth *= b.StepRetention(ref / 10.0f);
    EXPECT_NEAR(tenth, 0.98f, 1e-6f);
    EXPECT_NEAR(b.StepRetention(2.0f * ref), 0.98f * 0.98f, 1e-6f);
    // referenceStep 0: the book's per-step values at every dt.
    b.referenceStep = 0.0f;
    EXPECT_EQ(b.StepRetention(1e-5f), 0.98f);
    EXPECT_EQ(b.StepRetention(0.5f), 0.98f);
    EXPECT_EQ(b.StepVelocityEpsilon(1e-5f), 0.001f);
}

// A body released from rest at dt = 1e-5 s falls (the book's per-step threshold would zero g dt = 9.8e-5 m/s
// every step) close to free fall: 1 - exp(-k t) damping at k = -ln(0.98) / 0.03 = 0.67 / s costs 2% over 0.1 s.
TEST(RigidbodyVolume, TinyStepReleasedFromRestFallsNearlyFreely) {
    RigidbodyVolume b = MakeBox(vec3(0, 10, 0), vec3(1, 1, 1), 1.0f);
    for (int i = 0; i < 10000; ++i) {
        b.ApplyForces();
        b.Update(1e-5f);
    }
    const float freeFall = 0.5f * 9.82f * 0.1f * 0.1f;
    EXPECT_LT(10.0f - b.position.y, freeFall);
    EXPECT_GT(10.0f - b.position.y, 0.95f * freeFall);
    RigidbodyVolume book = MakeBox(vec3(0, 10, 0), vec3(1, 1, 1), 1.0f);
    book.referenceStep = 0.0f;  // the book's per-step values: hangs in the air
    for (int i = 0; i < 100; ++i) {
        book.ApplyForces();
        book.Update(1e-5f);
    }
    EXPECT_EQ(book.position.y, 10.0f);
}

TEST(RigidbodyVolume, ValidateVolumeNamesTheBadValue) {
    std::string error;
    EXPECT_TRUE(ValidateVolume(MakeBox(vec3(), vec3(1, 1, 1), 1.0f), &error)) << error;
    EXPECT_TRUE(ValidateVolume(MakeBox(vec3(), vec3(1e6f, 1e6f, 1e6f), 0.0f), &error)) << error;  // huge, static
    EXPECT_TRUE(ValidateVolume(MakeSphere(vec3(), 0.5f, 2.0f), &error)) << error;
    struct Case {
        RigidbodyVolume body;
        const char* named;
    };
    const float nan = std::nanf("");
    RigidbodyVolume flat = MakeBox(vec3(), vec3(1, 0, 1), 1.0f);
    RigidbodyVolume negative = MakeBox(vec3(), vec3(1, 1, -1), 1.0f);
    RigidbodyVolume infSize = MakeBox(vec3(), vec3(INFINITY, 1, 1), 1.0f);
    RigidbodyVolume point = MakeSphere(vec3(), 0.0f, 1.0f);
    RigidbodyVolume nanRadius = MakeSphere(vec3(), nan, 1.0f);
    RigidbodyVolume negMass = MakeBox(vec3(), vec3(1, 1, 1), -1.0f);
    RigidbodyVolume nanMass = MakeSphere(vec3(), 1.0f, nan);
    RigidbodyVolume farAway = MakeBox(vec3(0, INFINITY, 0), vec3(1, 1, 1), 1.0f);
    RigidbodyVolume nanSpin = MakeBox(vec3(), vec3(1, 1, 1), 1.0f);
    nanSpin.angVel.z = nan;
    RigidbodyVolume zeroQuat = MakeBox(vec3(), vec3(1, 1, 1), 1.0f);
    zeroQuat.orientation = quat(0, 0, 0, 0);
    RigidbodyVolume base;  // Base type: no volume
    const Case cases[] = {{flat, "box.size.y = 0"},
                          {negative, "box.size.z = -1"},
                          {infSize, "box.size.x = inf"},
                          {point, "sphere.radius = 0"},
                          {nanRadius, "sphere.radius = nan"},
                          {negMass, "mass = -1"},
                          {nanMass, "mass = nan"},
                          {farAway, "position.y = inf"},
                          {nanSpin, "angVel.z = nan"},
                          {zeroQuat, "|orientation|^2 = 0"},
                          {base, "type = 0"}};
    for (const Case& c : cases) {
        error.clear();
        EXPECT_FALSE(ValidateVolume(c.body, &error)) << c.named;
        EXPECT_NE(error.find(c.named), std::string::npos) << "expected '" << c.named << "' in: " << error;
    }
    EXPECT_FALSE(ValidateVolume(flat, nullptr));  // error is optional
}

// erratum 5.2-13: the book never integrates or damps a sphere's angular velocity, so spin from a contact
// persists forever (and keeps feeding the contact's relative velocity). Here spheres rotate and damp like boxes.
TEST(RigidbodyVolume, Erratum5_2_13_SphereSpinIsIntegratedAndDamped) {
    RigidbodyVolume s = MakeSphere(vec3(), 1.0f, 1.0f);
    s.angVel = vec3(0, 0, 2.0f);
    for (int i = 0; i < 10; ++i) s.Update(kBookStep);               // the book's 0.98 per 0.03 s step
    EXPECT_NEAR(s.angVel.z, 2.0f * std::pow(0.98f, 10.0f), 1e-5f);  // book: stays 2
    EXPECT_GT(std::fabs(s.orientation.z), 0.05f);                   // book: never turns
}

// Torque-free spin about a non-principal axis of a 4 x 2 x 1 box (no gravity, damping off): the angular
// momentum L = I_world w and the kinetic energy w.L/2 are invariants. The quaternion + midpoint update keeps
// them within 1e-3 relative over 10 s at 60 Hz. The book's scheme (Euler angles += w dt, w fixed because
// torques are zero) is computed alongside: its L drifts far beyond the bound.
TEST(RigidbodyVolume, Erratum5_2_12_FreeSpinKeepsAngularMomentumAndEnergy) {
    RigidbodyVolume b = MakeBox(vec3(), vec3(2, 1, 0.5f), 1.0f);
    b.gravity = vec3();
    b.velocityRetention = 1.0f;
    b.velocityEpsilon = 0.0f;
    b.angVel = vec3(0.4f, 2.0f, 0.7f);
    const vec3 L0 = MultiplyVector(b.angVel, b.InertiaTensor());
    const float E0 = 0.5f * Dot(b.angVel, L0);
    const float dt = 1.0f / 60.0f;
    const int steps = 600;
    const float kBound = 1e-3f;

    vec3 euler;  // the book: radians, fed to Rotation3x3 in degrees
    const vec3 bookW = b.angVel;
    float worstL = 0, worstE = 0, bookWorstL = 0, bookWorstE = 0;
    for (int i = 0; i < steps; ++i) {
        b.ApplyForces();
        b.Update(dt);
        const vec3 L = MultiplyVector(b.angVel, b.InertiaTensor());
        worstL = std::fmax(worstL, Magnitude(L - L0) / Magnitude(L0));
        worstE = std::fmax(worstE, std::fabs(0.5f * Dot(b.angVel, L) - E0) / E0);

        euler += bookW * dt;
        const mat3 R = Rotation3x3(RAD2DEG(euler.x), RAD2DEG(euler.y), RAD2DEG(euler.z));
        const mat3 Iw = Transpose(R) * mat3(1.25f / 3, 0, 0, 0, 4.25f / 3, 0, 0, 0, 5.0f / 3) * R;
        const vec3 bookL = MultiplyVector(bookW, Iw);
        bookWorstL = std::fmax(bookWorstL, Magnitude(bookL - L0) / Magnitude(L0));
        bookWorstE = std::fmax(bookWorstE, std::fabs(0.5f * Dot(bookW, bookL) - E0) / E0);
    }
    EXPECT_LT(worstL, kBound);
    EXPECT_LT(worstE, kBound);
    EXPECT_GT(bookWorstL, 10 * kBound) << "the book's Euler-angle integration should not conserve L";
    EXPECT_GT(bookWorstE, 10 * kBound);
    std::printf("free spin: worst |dL|/|L| %.2e, |dE|/E %.2e; book Euler angles: %.2e, %.2e\n", worstL, worstE,
                bookWorstL, bookWorstE);
}

TEST(RigidbodyVolume, AddRotationalImpulseUsesWorldLever) {
    RigidbodyVolume b = MakeBox(vec3(1, 0, 0), vec3(1, 1, 1), 1.0f);
    b.AddRotationalImpulse(vec3(2, 0, 0), vec3(0, 3, 0));  // lever (1,0,0) x (0,3,0) = (0,0,3); I^-1 = 1.5
    EXPECT_TRUE(VecNear(b.angVel, vec3(0, 0, 4.5f), tol::kTight));
}

// Head-on sphere collision, cor 0.5 vs 0.8 (e = min = 0.5), masses 1 and 3.
TEST(RigidbodyVolume, HeadOnSpheresConserveMomentumAndRestitution) {
    RigidbodyVolume a = MakeSphere(vec3(0, 0, 0), 1.0f, 1.0f);
    RigidbodyVolume b = MakeSphere(vec3(1.99f, 0, 0), 1.0f, 3.0f);
    a.cor = 0.8f;
    b.cor = 0.5f;
    a.velocity = vec3(4, 0, 0);
    b.velocity = vec3(-1, 0, 0);
    const CollisionManifold m = OneContact(vec3(1, 0, 0), vec3(0.995f, 0, 0), 0.01f);
    const vec3 p0 = a.velocity * a.mass + b.velocity * b.mass;
    const float vn0 = Dot(b.velocity - a.velocity, m.normal);
    ApplyImpulse(a, b, m, 0);
    const vec3 p1 = a.velocity * a.mass + b.velocity * b.mass;
    EXPECT_LE(Magnitude(p1 - p0), 1e-5f * Magnitude(p0));
    EXPECT_NEAR(Dot(b.velocity - a.velocity, m.normal), -0.5f * vn0, 1e-5f * std::fabs(vn0));
    // Hand-computed: j = 1.5 * 5 / (1 + 1/3) = 5.625 -> vA = 4 - 5.625, vB = -1 + 5.625/3.
    EXPECT_TRUE(VecNear(a.velocity, vec3(-1.625f, 0, 0), tol::kTight));
    EXPECT_TRUE(VecNear(b.velocity, vec3(0.875f, 0, 0), tol::kTight));
    EXPECT_TRUE(VecNear(a.angVel, vec3(), tol::kExact));
}

// Oblique hit with friction: the friction impulse is tangential and equal and opposite, so linear momentum is
// still conserved and the relative NORMAL speed still scales by e; the spheres pick up spin.
TEST(RigidbodyVolume, ObliqueSpheresConserveMomentumAndRestitution) {
    const vec3 n = Normalized(vec3(0.6f, 0.8f, 0.1f));
    RigidbodyVolume a = MakeSphere(vec3(0.3f, -0.2f, 0.1f), 1.0f, 2.0f);
    RigidbodyVolume b = MakeSphere(a.position + n * 1.98f, 1.0f, 0.5f);
    a.velocity = vec3(2.0f, 1.5f, -0.3f);
    b.velocity = vec3(-1.0f, -0.5f, 0.8f);
    const CollisionManifold m = OneContact(n, a.position + n * 0.99f, 0.02f);
    const vec3 p0 = a.velocity * a.mass + b.velocity * b.mass;
    const float vn0 = Dot(PointVelocity(b, m.contacts[0]) - PointVelocity(a, m.contacts[0]), n);
    ASSERT_LT(vn0, 0.0f);
    ApplyImpulse(a, b, m, 0);
    const vec3 p1 = a.velocity * a.mass + b.velocity * b.mass;
    EXPECT_LE(Magnitude(p1 - p0), 1e-5f * Magnitude(p0));
    const float vn1 = Dot(PointVelocity(b, m.contacts[0]) - PointVelocity(a, m.contacts[0]), n);
    EXPECT_NEAR(vn1, -0.5f * vn0, 1e-5f * std::fabs(vn0));
    EXPECT_GT(Magnitude(a.angVel), 0.01f);  // friction acted
}

// Two spheres meeting exactly head-on along a diagonal: after the normal impulse the relative velocity is
// parallel to n up to rounding, and the rounding residue (about 1e-6 of |vr|) has no meaningful direction.
// Normalising it (a bare |t| > 0 test) produced a friction impulse of 0.66 N s in a random direction and a
// spin of 1.4 rad/s; a tangent below 1e-4 |vr| is skipped.
TEST(RigidbodyVolume, HeadOnImpactGetsNoSpuriousFriction) {
    RigidbodyVolume a = MakeSphere(vec3(-3.277732f, 2.414879f, -1.638866f), 1.0f, 1.0f);
    RigidbodyVolume b = MakeSphere(vec3(-1.722267f, 2.414879f, -0.861134f), 1.0f, 1.0f);
    a.velocity = vec3(10.427034f, -0.925167f, 5.213517f);
    b.velocity = vec3(-10.427034f, -0.925167f, -5.213517f);
    const vec3 n = Normalized(b.position - a.position);
    ApplyImpulse(a, b, OneContact(n, (a.position + b.position) * 0.5f, 0.26f), 0);
    EXPECT_LT(Magnitude(a.angVel), 1e-3f);
    EXPECT_TRUE(VecNear(a.velocity, vec3(-10.427034f * 0.5f, -0.925167f, -5.213517f * 0.5f), 1e-3f));
}

TEST(RigidbodyVolume, SeparatingOrStaticPairsAreLeftAlone) {
    RigidbodyVolume a = MakeSphere(vec3(), 1.0f, 1.0f);
    RigidbodyVolume b = MakeSphere(vec3(1.9f, 0, 0), 1.0f, 1.0f);
    a.velocity = vec3(-1, 0, 0);
    const CollisionManifold m = OneContact(vec3(1, 0, 0), vec3(0.95f, 0, 0), 0.1f);
    ApplyImpulse(a, b, m, 0);
    EXPECT_TRUE(VecNear(a.velocity, vec3(-1, 0, 0), tol::kExact));
    a.mass = b.mass = 0.0f;
    a.velocity = vec3(1, 0, 0);
    ApplyImpulse(a, b, m, 0);
    EXPECT_TRUE(VecNear(a.velocity, vec3(1, 0, 0), tol::kExact));
    ApplyImpulse(a, b, m, 3);  // out-of-range contact index: nothing
    EXPECT_TRUE(VecNear(a.velocity, vec3(1, 0, 0), tol::kExact));
}

// Coulomb clamp with mu = sqrt(muA muB): 0.4 and 0.9 give 0.6 (not the min 0.4 or the mean 0.65).
// Box (mass 1, unit) sliding at 5 m/s onto static ground, contact under its centre, n = +y, e = 0.5:
// j = 1.5 * 1 / 1 = 1.5; unclamped jt = -5 / (1 + 1.5) = -2 -> clamped to -mu j = -0.9, so vx = 4.1 and the
// box starts to tip forward: angVel.z = 1.5 * (r x t jt).z = 1.5 * (-0.9) = -1.35.
TEST(RigidbodyVolume, FrictionIsClampedByMuTimesNormalImpulse) {
    RigidbodyVolume ground = MakeBox(vec3(0, -1, 0), vec3(10, 1, 10), 0.0f);
    RigidbodyVolume box = MakeBox(vec3(0, 1, 0), vec3(1, 1, 1), 1.0f);
    ground.friction = 0.4f;
    box.friction = 0.9f;
    box.velocity = vec3(5, -1, 0);
    ApplyImpulse(ground, box, OneContact(vec3(0, 1, 0), vec3(0, 0, 0), 0.01f), 0);
    EXPECT_TRUE(VecNear(box.velocity, vec3(4.1f, 0.5f, 0), tol::kTight));
    EXPECT_TRUE(VecNear(box.angVel, vec3(0, 0, -1.35f), tol::kTight));
}

// Below the clamp, friction stops the tangential motion of the contact point (static friction).
TEST(RigidbodyVolume, FrictionBelowTheClampStopsTheContactPoint) {
    RigidbodyVolume ground = MakeBox(vec3(0, -1, 0), vec3(10, 1, 10), 0.0f);
    RigidbodyVolume box = MakeBox(vec3(0, 1, 0), vec3(1, 1, 1), 1.0f);
    box.velocity = vec3(0.2f, -2, 0);
    const CollisionManifold m = OneContact(vec3(0, 1, 0), vec3(0, 0, 0), 0.01f);
    ApplyImpulse(ground, box, m, 0);
    const vec3 v = PointVelocity(box, m.contacts[0]);
    EXPECT_NEAR(v.x, 0.0f, 1e-5f);
    EXPECT_NEAR(v.y, 1.0f, 1e-5f);  // e * 2
}

// erratum 5.2-14: friction from the relative velocity AFTER the normal impulse. A box falling straight down
// onto one corner contact has no tangential velocity before the impulse, so the book applies no friction; the
// normal impulse then spins the box and the contact point slides sideways. With the fix friction acts on that
// sliding: the tangential speed of the contact point is smaller than with friction switched off. (The book's
// version gives identical results with and without friction.)
TEST(RigidbodyVolume, Erratum5_2_14_FrictionSeesThePostImpulseVelocity) {
    const CollisionManifold m = OneContact(vec3(0, 1, 0), vec3(1, 0, 0), 0.01f);
    auto run = [&](float friction) {
        RigidbodyVolume ground = MakeBox(vec3(0, -1, 0), vec3(10, 1, 10), 0.0f);
        RigidbodyVolume box = MakeBox(vec3(0, 1, 0), vec3(1, 1, 1), 1.0f);
        ground.friction = box.friction = friction;
        box.velocity = vec3(0, -2, 0);
        ApplyImpulse(ground, box, m, 0);
        return box;
    };
    const RigidbodyVolume frictionless = run(0.0f);
    const RigidbodyVolume rough = run(0.6f);
    const float slideFree = std::fabs(PointVelocity(frictionless, m.contacts[0]).x);
    const float slideRough = std::fabs(PointVelocity(rough, m.contacts[0]).x);
    ASSERT_GT(slideFree, 0.1f);  // the normal impulse alone makes the contact slide
    EXPECT_LT(slideRough, 0.5f * slideFree);
    EXPECT_NE(rough.velocity.x, frictionless.velocity.x);
}

TEST(RigidbodyVolume, ImpulseIsSharedBetweenContacts) {
    // Two contacts under a falling box: contact 0 gets the impulse its own contact would need, divided by the
    // contact count (the book's j /= contacts.size()).
    RigidbodyVolume ground = MakeBox(vec3(0, -1, 0), vec3(10, 1, 10), 0.0f);
    RigidbodyVolume box = MakeBox(vec3(0, 1, 0), vec3(1, 1, 1), 1.0f);
    box.friction = ground.friction = 0.0f;
    box.velocity = vec3(0, -2, 0);
    CollisionManifold m = OneContact(vec3(0, 1, 0), vec3(1, 0, 0), 0.0f);
    m.contacts.push_back(vec3(-1, 0, 0));
    ApplyImpulse(ground, box, m, 0);
    // j0 = 1.5 * 2 / (1 + 1.5) / 2 = 0.6 at (1,0,0): vy = -1.4, w_z = 1.5 * 0.6 = 0.9.
    EXPECT_NEAR(box.velocity.y, -1.4f, 1e-5f);
    EXPECT_NEAR(box.angVel.z, 0.9f, 1e-5f);
}
