// PhysicsSystem's particle stages (PhysicsSystemParticles.cpp): forces -> integrate -> constraints, with every
// integrator: no tunnelling at any speed, bounce apex heights, resting on the CH14 boards, determinism.
#include "Physics/PhysicsSystem.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "Demos/Scenes/Ch14Scene.h"
#include "Physics/Particle.h"
#include "tests/support/Approx.h"

namespace {

bool Finite(const vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

/// Coordinates of p in the box's frame (x, y, z along its rows).
vec3 Local(const OBB& box, const vec3& p) {
    const vec3 r = p - box.position;
    return vec3(Dot(r, GetRow(box.orientation, 0)), Dot(r, GetRow(box.orientation, 1)),
                Dot(r, GetRow(box.orientation, 2)));
}

}  // namespace

TEST(PhysicsSystem, ParticleFallingOntoABoxIsStoppedInTheSameStep) {
    for (Integrator i : kAllIntegrators) {
        Particle p;
        p.SetPosition(vec3(0, 1.2f, 0));
        p.SetVelocity(vec3(0, -20, 0));
        PhysicsSystem system;
        system.settings.integrator = i;
        system.AddConstraint(OBB(vec3(0, 0, 0), vec3(10, 0.15f, 10)));
        system.AddRigidbody(&p);
        system.Update(0.1f);  // would travel ~2 m down, through the box
        EXPECT_NEAR(p.GetPosition().y, 0.15f + Particle::kContactOffset, tol::kTight) << ToString(i);
        EXPECT_GT(p.GetVelocity().y, 0.0f) << ToString(i);
        EXPECT_EQ(system.StepCount(), 1);
    }
}

// 1, 100 and 10,000 m/s against a 0.3 m thick box, straight on and at grazing angles, flat and tilted, at the
// book's step and a small one. After every step the particle is still on the near side of the top face.
TEST(PhysicsSystem, NoTunnellingAtAnySpeedOrAngle) {
    for (float tilt : {0.0f, 25.0f, -60.0f}) {
        const OBB box(vec3(0.5f, -1.0f, 0.3f), vec3(8, 0.15f, 8), Rotation3x3(tilt, 10.0f, 0.5f * tilt));
        const vec3 n = GetRow(box.orientation, 1), side = GetRow(box.orientation, 0);
        for (float angle : {0.0f, 30.0f, 60.0f, 85.0f}) {
            const float a = angle * 0.0174533f;
            const vec3 dir = n * -std::cos(a) + side * std::sin(a);  // into the top face
            for (float speed : {1.0f, 100.0f, 1e4f}) {
                for (float dt : {0.03f, 1.0f / 240.0f}) {
                    for (Integrator i : kAllIntegrators) {
                        Particle p;
                        p.SetGravity(vec3());
                        p.SetVelocityRetention(1.0f);
                        p.SetBounce(0.5f);
                        // Start 0.5 m above the face, aimed at the box centre region.
                        p.SetPosition(box.position + n * 0.65f - side * (0.5f * std::tan(a)));
                        p.SetVelocity(dir * speed);
                        PhysicsSystem system;
                        system.settings.integrator = i;
                        system.AddConstraint(box);
                        system.AddRigidbody(&p);
                        for (int s = 0; s < 200; ++s) {
                            system.Update(dt);
                            const vec3 l = Local(box, p.GetPosition());
                            ASSERT_TRUE(Finite(p.GetPosition())) << ToString(i);
                            ASSERT_GE(l.y, 0.15f - 1e-4f) << ToString(i) << " speed " << speed << " angle " << angle
                                                          << " tilt " << tilt << " dt " << dt << " step " << s;
                        }
                    }
                }
            }
        }
    }
}

// A particle dropped from h0 with bounce e and no damping reaches apexes e^(2n) h0 (height above the resting
// height, the surface + offset). Discrete-time error per bounce: the hit is found at the end of a step, so the
// reflected speed can differ from the impact speed by up to g dt, which moves the apex by up to v dt (v the
// impact speed, h = v^2/2g); the integrator's own first-order error is of the same size for the Eulers. With
// dt = 0.5 ms and h0 = 2 m (v = 6.3 m/s) that is 3 mm per bounce, so the tolerance is 2 v dt (n + 1) + offset.
TEST(PhysicsSystem, BounceApexHeightsFollowERaisedTo2N) {
    const float dt = 0.0005f, h0 = 2.0f, rest = 0.15f + Particle::kContactOffset;
    const float v = std::sqrt(2.0f * 9.82f * h0);
    for (float e : {0.3f, 0.7f, 1.0f}) {
        for (Integrator i : kAllIntegrators) {
            Particle p;
            p.SetVelocityRetention(1.0f);
            p.SetBounce(e);
            p.SetPosition(vec3(0, rest + h0, 0));
            PhysicsSystem system;
            system.settings.integrator = i;
            system.AddConstraint(OBB(vec3(0, 0, 0), vec3(10, 0.15f, 10)));
            system.AddRigidbody(&p);
            std::vector<float> apexes;
            float prevY = p.GetPosition().y, prevVy = 0.0f, maxY = 0.0f;
            bool rising = false;
            for (int s = 0; s < 20000 && apexes.size() < 3; ++s) {
                system.Update(dt);
                const float y = p.GetPosition().y, vy = p.GetVelocity().y;
                if (vy > 0.0f && prevVy <= 0.0f) {
                    rising = true;
                    maxY = y;
                }
                if (rising) maxY = std::fmax(maxY, y);
                if (rising && vy <= 0.0f && prevVy > 0.0f) {
                    apexes.push_back(maxY - rest);
                    rising = false;
                }
                prevY = y;
                prevVy = vy;
            }
            (void)prevY;
            for (std::size_t n = 1; n <= apexes.size(); ++n) {
                const float expected = std::pow(e, 2.0f * n) * h0;
                const float tolerance = 2.0f * v * dt * (n + 1) + Particle::kContactOffset;
                if (expected < 2.0f * tolerance) break;  // too small to resolve
                EXPECT_NEAR(apexes[n - 1], expected, tolerance) << ToString(i) << " e " << e << " n " << n;
            }
            EXPECT_GE(apexes.size(), e > 0.5f ? 3u : 1u) << ToString(i) << " e " << e;
        }
    }
}

// Rest: a particle put on the middle of each CH14 board (ground flat, boards tilted) for 10,000 steps at the
// book's dt: its state stays finite and, whenever it is over the board, it is never below the top surface by
// more than the contact offset. On the ground it also stays put: no sinking, and no creeping upwards - it keeps
// hopping by millimetres to centimetres because each contact reflects the end-of-step velocity (explicit Euler,
// which moves with the start-of-step velocity, hops highest, ~5 cm at e = 0.7), but the hop stays bounded.
TEST(PhysicsSystem, ParticleRestsOnEachCh14BoardWithoutSinking) {
    const auto boards = Ch14Scene::Constraints();
    for (std::size_t b = 0; b < boards.size(); ++b) {
        const OBB& board = boards[b];
        const vec3 n = GetRow(board.orientation, 1);
        for (Integrator i : kAllIntegrators) {
            Particle p;
            p.SetPosition(board.position + n * (board.size.y + Particle::kContactOffset));
            PhysicsSystem system;
            system.settings.integrator = i;
            for (const OBB& c : boards) system.AddConstraint(c);
            system.AddRigidbody(&p);
            for (int s = 0; s < 10000; ++s) {
                system.Update(0.03f);
                ASSERT_TRUE(Finite(p.GetPosition()) && Finite(p.GetVelocity())) << ToString(i) << " step " << s;
                const vec3 l = Local(board, p.GetPosition());
                const bool over =
                    std::fabs(l.x) <= board.size.x && std::fabs(l.z) <= board.size.z && l.y > -board.size.y;
                if (over) {
                    ASSERT_GE(l.y, board.size.y - Particle::kContactOffset)
                        << "board " << b << " " << ToString(i) << " step " << s;
                }
                if (b == 0) {
                    ASSERT_TRUE(over) << ToString(i) << " step " << s;
                    ASSERT_LE(l.y, board.size.y + 0.06f) << ToString(i) << " step " << s;
                }
            }
            if (b == 0) {
                EXPECT_NEAR(p.GetPosition().y, 0.15f, 0.06f) << ToString(i);
            }
        }
    }
}

TEST(PhysicsSystem, TwoRunsAreBitwiseIdentical) {
    for (Integrator i : kAllIntegrators) {
        Ch14Params params;
        params.particleCount = 120;
        params.integrator = i;
        Ch14Scene a(params), b(params);
        for (int s = 0; s < 400; ++s) {
            a.Step(a.Params().dt);
            b.Step(b.Params().dt);
        }
        ASSERT_EQ(a.Particles().size(), 120u);
        ASSERT_EQ(b.Particles().size(), 120u);
        for (std::size_t k = 0; k < a.Particles().size(); ++k) {
            const vec3 pa = a.Particles()[k].GetPosition(), pb = b.Particles()[k].GetPosition();
            const vec3 va = a.Particles()[k].GetVelocity(), vb = b.Particles()[k].GetVelocity();
            ASSERT_EQ(0, std::memcmp(&pa, &pb, sizeof(vec3))) << ToString(i) << " particle " << k;
            ASSERT_EQ(0, std::memcmp(&va, &vb, sizeof(vec3))) << ToString(i) << " particle " << k;
        }
    }
}

TEST(PhysicsSystem, ParticleOnlyStepDoesNoPairWork) {
    Ch14Scene scene;
    for (int s = 0; s < 10; ++s) scene.Step(scene.Params().dt);
    EXPECT_EQ(scene.System().CollisionCount(), 0u);
    EXPECT_EQ(scene.System().Particles().size(), 50u);
    EXPECT_EQ(scene.System().StepCount(), 10);
}

TEST(PhysicsSystem, InvalidDtDoesNothing) {
    Particle p;
    p.SetPosition(vec3(0, 3, 0));
    PhysicsSystem system;
    system.AddRigidbody(&p);
    system.Update(0.0f);
    system.Update(-0.03f);
    system.Update(std::nanf(""));
    EXPECT_TRUE(VecNear(p.GetPosition(), vec3(0, 3, 0), 0.0f));
    EXPECT_EQ(system.StepCount(), 0);
}
