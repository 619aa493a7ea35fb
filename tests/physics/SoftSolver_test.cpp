// SoftContactSolver (ContactSolver::Soft): softness formula, warm start by feature id, restitution threshold,
// speculative contacts, determinism. 60 Hz, damping off, cubes of half extent 0.5 and 1 kg on a static ground box
// of half extents (50, 0.5, 50) whose top is y = 0 (docs/soft-solver.md, "The soft-step solver").
#include "Physics/SoftSolver.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "Demos/Scenes/WorldBuilder.h"
#include "Physics/PhysicsSystem.h"
#include "tests/support/TestWorld.h"
#include "tests/support/Volumes.h"

namespace {

constexpr float kDt = 1.0f / 60.0f;

BodySpec Cube(const vec3& position) {
    BodySpec cube = BoxSpec(position, vec3(0.5f, 0.5f, 0.5f), 1.0f);
    cube.restitution = 0.0f;
    cube.velocityRetention = 1.0f;
    cube.velocityEpsilon = 0.0f;
    return cube;
}

BodySpec Ground(float restitution = 0.0f) {
    BodySpec ground = GroundSpec(vec3(50.0f, 0.5f, 50.0f));
    ground.restitution = restitution;
    return ground;
}

}  // namespace

// Softness by hand: 30 Hz, damping ratio 10, h = 1/240 s: omega = 188.50/s, h omega = 0.78540, a1 = 20.7854,
// a2 = 16.3250, a3 = 0.057720; bias rate 9.0689/s, mass scale 0.94228, impulse scale 0.057720. 0 Hz is rigid.
TEST(SoftSolver, SoftnessFormula) {
    const Softness s = MakeSoftness(30.0f, 10.0f, 1.0f / 240.0f);
    EXPECT_NEAR(s.biasRate, 9.0689f, 1e-3f);
    EXPECT_NEAR(s.massScale, 0.94228f, 1e-4f);
    EXPECT_NEAR(s.impulseScale, 0.057720f, 1e-5f);
    EXPECT_NEAR(s.massScale + s.impulseScale, 1.0f, 1e-6f);  // a2 a3 + a3 = 1
    const Softness rigid = MakeSoftness(0.0f, 10.0f, 1.0f / 240.0f);
    EXPECT_EQ(rigid.biasRate, 0.0f);
    EXPECT_EQ(rigid.massScale, 1.0f);
    EXPECT_EQ(rigid.impulseScale, 0.0f);
}

// A cube resting on the ground: from the second step on every contact inherits last step's impulse (same pair,
// same feature id), and what it inherits is the weight's last-substep impulse (m g h summed over the points). With
// warmStartFactor 0 the contacts are still matched but inherit nothing; after ClearRigidbodys (and the cube added
// back) the first step starts cold and the next one warm again.
TEST(SoftSolver, RestingContactsWarmStartById) {
    TestWorld world(WithGround(Ground(), {Cube(vec3(0.0f, 0.5f, 0.0f))}));
    world.system.settings.contactSolver = ContactSolver::Soft;
    for (int i = 0; i < 60; ++i) world.system.Update(kDt);
    const SoftContactSolver& solver = world.system.SoftSolver();
    ASSERT_EQ(solver.PairCount(), 1u);
    ASSERT_GT(solver.ContactCount(), 0u);
    EXPECT_EQ(solver.WarmStartedCount(), solver.ContactCount());
    const float h = kDt / static_cast<float>(world.system.settings.soft.substeps);
    EXPECT_NEAR(solver.InheritedNormalImpulse(), 9.82f * h, 0.01f * 9.82f * h);
    EXPECT_NEAR(solver.TotalNormalImpulse(), 9.82f * h, 0.01f * 9.82f * h);
    EXPECT_LT(solver.DeepestPenetration(), 0.001f);  // g / (2 pi 60 Hz)^2 per unit load, static contact

    world.system.settings.soft.warmStartFactor = 0.0f;
    world.system.Update(kDt);
    EXPECT_EQ(solver.WarmStartedCount(), solver.ContactCount()) << "matched, with a zero impulse";
    EXPECT_EQ(solver.InheritedNormalImpulse(), 0.0f);
    EXPECT_NEAR(solver.TotalNormalImpulse(), 9.82f * h, 0.05f * 9.82f * h);

    world.system.settings.soft.warmStartFactor = 1.0f;
    world.system.ClearRigidbodys();
    for (std::size_t i = 0; i < world.Bodies().size(); ++i) ASSERT_TRUE(world.system.AddRigidbody(&world.Body(i)));
    world.system.Update(kDt);
    EXPECT_EQ(solver.WarmStartedCount(), 0u) << "ClearRigidbodys forgets the kept contacts";
    EXPECT_EQ(solver.InheritedNormalImpulse(), 0.0f);
    world.system.Update(kDt);
    EXPECT_EQ(solver.WarmStartedCount(), solver.ContactCount());
    EXPECT_GT(solver.InheritedNormalImpulse(), 0.0f);
}

// A cube sliding fast along the ground (5 m/s: its contact points move 8 cm per step) keeps every contact's
// warm start, because matching is by feature id, not by distance.
TEST(SoftSolver, SlidingContactsStayMatched) {
    BodySpec cube = Cube(vec3(0.0f, 0.5f, 0.0f));
    cube.friction = 0.0f;
    cube.velocity = vec3(5.0f, 0.0f, 0.0f);
    TestWorld world(WithGround(Ground(), {cube}));
    world.system.settings.contactSolver = ContactSolver::Soft;
    for (int i = 0; i < 30; ++i) {
        world.system.Update(kDt);
        if (i > 2) {
            EXPECT_EQ(world.system.SoftSolver().WarmStartedCount(), world.system.SoftSolver().ContactCount());
        }
    }
    EXPECT_NEAR(world.Body(1).velocity.x, 5.0f, 1e-3f);  // frictionless: nothing slows it
    EXPECT_NEAR(world.Body(1).position.y, 0.5f, 0.002f);
}

// Restitution only above the threshold (1 m/s): a sphere with e = 1 hitting at 0.8 m/s stays down, at 3 m/s it
// comes back up at 3 m/s (within the g h it gains in its last substep before contact).
TEST(SoftSolver, RestitutionThreshold) {
    for (float speed : {0.8f, 3.0f}) {
        BodySpec ball = SphereSpec(vec3(0.0f, 0.5f + 0.5f * speed * kDt, 0.0f), 0.5f, 1.0f);
        ball.restitution = 1.0f;
        ball.velocityRetention = 1.0f;
        ball.velocityEpsilon = 0.0f;
        ball.velocity = vec3(0.0f, -speed, 0.0f);
        TestWorld world(WithGround(Ground(1.0f), {ball}));
        world.system.settings.contactSolver = ContactSolver::Soft;
        for (int i = 0; i < 2; ++i) world.system.Update(kDt);
        const float vy = world.Body(1).velocity.y;
        std::printf("soft restitution, impact %.1f m/s: vy after %.4f m/s\n", speed, vy);
        if (speed < 1.0f) {
            EXPECT_LT(std::fabs(vy), 0.2f);
        } else {
            EXPECT_NEAR(vy, speed - 9.82f * kDt, 0.1f);
        }
    }
}

// A cube dropped flat (its bottom 2 m above the ground, e = 0.5 against a ground of e = 1) bounces straight back up:
// its four corners hit together, so the bounce gives it no spin. Measured after the bounce: 3e-4 rad/s about x and z
// (ApplyRestitution's four passes); one pass left 1.0 rad/s (0.62, 0.84), the first corner's impulse unbalanced.
TEST(SoftSolver, FlatBounceDoesNotSpin) {
    BodySpec cube = Cube(vec3(0.0f, 2.5f, 0.0f));
    cube.restitution = 0.5f;
    TestWorld world(WithGround(Ground(1.0f), {cube}));
    world.system.settings.contactSolver = ContactSolver::Soft;
    const RigidbodyVolume& b = world.Body(1);
    bool bounced = false;
    for (int i = 0; i < 60 && !bounced; ++i) {
        world.system.Update(kDt);
        bounced = b.velocity.y > 0.0f;
    }
    std::printf("soft flat bounce: vy %.4f m/s, w (%.5f, %.5f, %.5f) rad/s\n", b.velocity.y, b.angVel.x, b.angVel.y,
                b.angVel.z);
    ASSERT_TRUE(bounced);
    EXPECT_GT(b.velocity.y, 2.5f);  // e times the impact speed of about 6.3 m/s, less the rest of the step's g
    EXPECT_LT(std::fabs(b.angVel.x), 0.01f);
    EXPECT_LT(std::fabs(b.angVel.z), 0.01f);
}

// Speculative contact: a cube 1.5 cm above the ground (inside the 2 cm margin) falling at 5 m/s would sink 6.8 cm
// in one step; the speculative contact lets it close the gap and no more: after the step it is within 1 mm below
// and 2 mm above the surface (measured 0.6 mm above)
// and is not pushed back up (no pop: vertical speed below 0.05 m/s).
TEST(SoftSolver, SpeculativeContactStopsFastBodyWithoutPopping) {
    BodySpec cube = Cube(vec3(0.0f, 0.515f, 0.0f));
    cube.velocity = vec3(0.0f, -5.0f, 0.0f);
    TestWorld world(WithGround(Ground(), {cube}));
    world.system.settings.contactSolver = ContactSolver::Soft;
    world.system.Update(kDt);
    const RigidbodyVolume& b = world.Body(1);
    std::printf("soft speculative: y %.5f vy %.5f\n", b.position.y, b.velocity.y);
    EXPECT_GT(b.position.y, 0.499f);
    EXPECT_LT(b.position.y, 0.502f);
    EXPECT_LT(std::fabs(b.velocity.y), 0.05f);
    for (int i = 0; i < 5; ++i) {
        world.system.Update(kDt);
        EXPECT_LT(b.velocity.y, 0.05f) << "popped at step " << i + 1;
    }
}

// Determinism: the same scene run twice is bit-for-bit identical (fixed orders everywhere).
TEST(SoftSolver, Deterministic) {
    std::vector<unsigned char> first;
    for (int run = 0; run < 2; ++run) {
        TestWorld world(TiltedColumn(12));
        world.system.settings.contactSolver = ContactSolver::Soft;
        std::size_t contacts = 0;
        for (int i = 0; i < 240; ++i) {
            world.system.Update(kDt);
            contacts = std::max(contacts, world.system.SoftSolver().ContactCount());
        }
        EXPECT_GT(contacts, 0u);
        const std::vector<unsigned char> snap = Snapshot(world.Bodies());
        if (run == 0) {
            first = snap;
        } else {
            EXPECT_EQ(snap, first);
        }
    }
}

// Switching a world between solvers: after book steps the soft step starts cold (nothing inherited from a step
// that was not the one before) and the book's collision list is replaced by the soft step's touching pair.
TEST(SoftSolver, StartsColdAfterAnotherSolver) {
    TestWorld world(WithGround(Ground(), {Cube(vec3(0.0f, 0.5f, 0.0f))}));
    world.system.settings.contactSolver = ContactSolver::Soft;
    for (int i = 0; i < 10; ++i) world.system.Update(kDt);
    world.system.settings.contactSolver = ContactSolver::Book;
    world.system.Update(kDt);
    EXPECT_GT(world.system.CollisionCount(), 0u);
    world.system.settings.contactSolver = ContactSolver::Soft;
    world.system.Update(kDt);
    EXPECT_EQ(world.system.SoftSolver().WarmStartedCount(), 0u);
    ASSERT_EQ(world.system.CollisionCount(), 1u);
    EXPECT_EQ(world.system.Collisions()[0].manifold.depth, world.system.SoftSolver().DeepestPenetration());
    EXPECT_EQ(world.system.LastVolumeSubsteps(), world.system.settings.soft.substeps);
}

// Between contacts the soft step turns a box as a free body turns: a 0.4 x 1 x 2 m, 2 kg box spun at (2, 1, 0.5)
// rad/s without gravity keeps its world angular momentum I_world w (a constant w would not: I_world turns with
// the box). Same body and tolerance as the book path's RigidbodyVolume test.
TEST(SoftSolver, FreeBoxKeepsItsAngularMomentum) {
    BodySpec spec = BoxSpec(vec3(0.0f, 5.0f, 0.0f), vec3(0.2f, 0.5f, 1.0f), 2.0f);
    spec.velocityRetention = 1.0f;
    spec.velocityEpsilon = 0.0f;
    spec.angularVelocity = vec3(2.0f, 1.0f, 0.5f);
    TestWorld world({spec});
    world.Body(0).gravity = vec3();
    world.system.settings.contactSolver = ContactSolver::Soft;
    const RigidbodyVolume& box = world.Bodies()[0];
    const vec3 L0 = MultiplyVector(box.angVel, box.InertiaTensor());
    for (int i = 0; i < 600; ++i) world.system.Update(kDt);  // 10 s
    const vec3 L = MultiplyVector(box.angVel, box.InertiaTensor());
    EXPECT_LT(Magnitude(L - L0) / Magnitude(L0), 1e-3f)
        << "L0 (" << L0.x << ", " << L0.y << ", " << L0.z << "), L (" << L.x << ", " << L.y << ", " << L.z << ")";
}

// A free cube (equal principal moments, so w stays constant) spinning for 1 s turns by exactly exp(w t / 2): the soft
// step's small-turn series (SmallTurn, |w| h / 2 < 0.1 rad) and, at 100 rad/s, the exponential map itself. Measured
// angle from the exact orientation: 1.0e-6 rad at |w| = 3.7 rad/s, 1.3e-6 rad at 100 rad/s (a first-order turn,
// sin x / x and cos x cut after their first terms, was measured 3.4e-5 rad off at 3.7 rad/s).
TEST(SoftSolver, FreeCubeTurnsByTheExponentialMap) {
    for (const vec3 w : {vec3(1.0f, 2.0f, 3.0f), vec3(0.0f, 60.0f, 80.0f)}) {
        BodySpec spec = Cube(vec3(0.0f, 5.0f, 0.0f));
        spec.angularVelocity = w;
        spec.eulerRadians = vec3(0.3f, -0.2f, 0.1f);
        TestWorld world({spec});
        world.Body(0).gravity = vec3();
        world.system.settings.contactSolver = ContactSolver::Soft;
        const RigidbodyVolume& cube = world.Bodies()[0];
        const quat exact = Integrate(cube.orientation, w, 1.0f);
        for (int i = 0; i < 60; ++i) world.system.Update(kDt);
        const quat off = cube.orientation * Conjugate(exact);  // the turn between them (sin of half its angle)
        const float angle = 2.0f * std::asin(std::fmin(Magnitude(vec3(off.x, off.y, off.z)), 1.0f));
        std::printf("soft free cube, |w| %.1f rad/s: %.2e rad from exp(w t / 2) after 1 s\n", Magnitude(w), angle);
        EXPECT_LT(angle, 1e-5f) << "|w| " << Magnitude(w);
        EXPECT_LT(Magnitude(cube.angVel - w), 1e-4f * Magnitude(w));
    }
}

namespace {

/// Every body's pose and velocities, bit for bit.
std::vector<float> StateOf(const TestWorld& world) {
    std::vector<float> out;
    for (const RigidbodyVolume& b : world.Bodies())
        for (float f : {b.position.x, b.position.y, b.position.z, b.orientation.x, b.orientation.y, b.orientation.z,
                        b.orientation.w, b.velocity.x, b.velocity.y, b.velocity.z, b.angVel.x, b.angVel.y, b.angVel.z})
            out.push_back(f);
    return out;
}

}  // namespace

// Graph colouring (docs/soft-solver.md, "Graph colouring"), on a pyramid of base 12 (78 cubes): every pair is in
// exactly one lane of one batch or in the overflow; no moving body is in two pairs of one colour (static ones may be);
// lanes and batches follow the pair order within a colour, and colours come in increasing order.
TEST(SoftSolverGraph, ColoursShareNoMovingBody) {
    TestWorld world(PeerPyramid(12));
    world.system.settings.contactSolver = ContactSolver::Soft;
    for (int i = 0; i < 60; ++i) world.system.Update(kDt);
    const SoftContactSolver& solver = world.system.SoftSolver();
    const std::vector<SoftContactSolver::Pair>& pairs = solver.Pairs();
    ASSERT_GT(pairs.size(), 78u);
    std::vector<int> seen(pairs.size(), 0);
    std::vector<std::vector<int>> bodiesOfColour(SoftContactSolver::kColours);
    int lastColour = 0, lastPair = -1;
    for (const SoftContactSolver::WideBatch& batch : solver.Batches()) {
        ASSERT_GE(batch.colour, lastColour);
        if (batch.colour != lastColour) lastPair = -1;
        lastColour = batch.colour;
        for (int lane = 0; lane < 4; ++lane) {
            const int p = batch.pair[lane];
            if (p < 0) continue;
            EXPECT_GT(p, lastPair) << "pair order within a colour";
            lastPair = p;
            ++seen[static_cast<std::size_t>(p)];
            for (int body : {pairs[static_cast<std::size_t>(p)].a, pairs[static_cast<std::size_t>(p)].b})
                if (world.Body(static_cast<std::size_t>(body)).mass > 0.0f)
                    bodiesOfColour[static_cast<std::size_t>(batch.colour)].push_back(body);
        }
    }
    for (int p : solver.OverflowPairs()) ++seen[static_cast<std::size_t>(p)];
    for (std::size_t p = 0; p < pairs.size(); ++p) EXPECT_EQ(seen[p], 1) << "pair " << p;
    EXPECT_GT(lastColour, 2) << "a pile needs several colours";
    for (std::vector<int>& bodies : bodiesOfColour) {
        std::sort(bodies.begin(), bodies.end());
        EXPECT_TRUE(std::adjacent_find(bodies.begin(), bodies.end()) == bodies.end());
    }
    std::printf("pyramid 12: %zu pairs in %zu batches, %zu overflow\n", pairs.size(), solver.Batches().size(),
                solver.OverflowPairs().size());
}

// Blocks (docs/soft-solver.md, "Blocks"): the 1,000-cube pile of the peer bench is a hundred columns, each an island.
// Every moving body is in exactly one block, in index order; every pair is solved in the block of its moving bodies (an
// island is never split), once, in a batch or the block's overflow; each block but the last holds at least
// kBlockPairs pairs; blocks come in order of their first body; within a block, colours increase and a colour keeps
// the pair order.
TEST(SoftSolverGraph, BlocksHoldWholeIslandsInOrder) {
    TestWorld world(PeerBoxpile(1000));
    world.system.settings.contactSolver = ContactSolver::Soft;
    world.system.settings.sleep.enabled = false;
    for (int i = 0; i < 60; ++i) world.system.Update(kDt);
    const SoftContactSolver& solver = world.system.SoftSolver();
    const std::vector<SoftContactSolver::Pair>& pairs = solver.Pairs();
    const std::vector<SoftContactSolver::Block>& blocks = solver.Blocks();
    ASSERT_GT(blocks.size(), 2u);
    std::vector<int> blockOf(world.Bodies().size(), -1);
    int previousFirst = -1;
    for (std::size_t b = 0; b < blocks.size(); ++b) {
        const SoftContactSolver::Block& block = blocks[b];
        ASSERT_LT(block.bodyBegin, block.bodyEnd);
        EXPECT_GT(solver.BlockBodies()[block.bodyBegin], previousFirst) << "blocks in order of their first body";
        previousFirst = solver.BlockBodies()[block.bodyBegin];
        for (std::size_t k = block.bodyBegin; k < block.bodyEnd; ++k) {
            const int body = solver.BlockBodies()[k];
            if (k > block.bodyBegin) {
                EXPECT_GT(body, solver.BlockBodies()[k - 1]);
            }
            EXPECT_EQ(blockOf[static_cast<std::size_t>(body)], -1) << "body " << body << " in two blocks";
            blockOf[static_cast<std::size_t>(body)] = static_cast<int>(b);
        }
    }
    for (std::size_t i = 0; i < world.Bodies().size(); ++i)
        EXPECT_EQ(blockOf[i] >= 0, world.Body(i).mass > 0.0f) << "body " << i;
    std::vector<int> seen(pairs.size(), 0);
    for (std::size_t b = 0; b < blocks.size(); ++b) {
        const SoftContactSolver::Block& block = blocks[b];
        std::size_t count = block.overflowEnd - block.overflowBegin;
        int lastColour = 0, lastPair = -1;
        std::vector<int> blockPairs;
        for (std::size_t k = block.batchBegin; k < block.batchEnd; ++k) {
            const SoftContactSolver::WideBatch& batch = solver.Batches()[k];
            EXPECT_GE(batch.colour, lastColour);
            if (batch.colour != lastColour) lastPair = -1;
            lastColour = batch.colour;
            for (int lane = 0; lane < 4; ++lane) {
                if (batch.pair[lane] < 0) continue;
                EXPECT_GT(batch.pair[lane], lastPair) << "pair order within a colour";
                lastPair = batch.pair[lane];
                blockPairs.push_back(batch.pair[lane]);
                ++count;
            }
        }
        for (std::size_t k = block.overflowBegin; k < block.overflowEnd; ++k)
            blockPairs.push_back(solver.OverflowPairs()[k]);
        for (int p : blockPairs) {
            ++seen[static_cast<std::size_t>(p)];
            const SoftContactSolver::Pair& pair = pairs[static_cast<std::size_t>(p)];
            for (int body : {pair.a, pair.b}) {
                if (blockOf[static_cast<std::size_t>(body)] >= 0) {
                    EXPECT_EQ(blockOf[static_cast<std::size_t>(body)], static_cast<int>(b)) << "pair " << p;
                }
            }
        }
        if (b + 1 < blocks.size()) {
            EXPECT_GE(count, SoftContactSolver::kBlockPairs) << "block " << b;
        }
    }
    for (std::size_t p = 0; p < pairs.size(); ++p) EXPECT_EQ(seen[p], 1) << "pair " << p;
}

// Four cubes apart on the ground, one dropped, one sliding, one spinning: the four pairs share only the static
// ground, so they are one batch in pair order, which is the order of the one-by-one solve: both give the same
// bits. (Where colouring reorders pairs, the results differ as any change of Gauss-Seidel order does.)
TEST(SoftSolverGraph, OneBatchInPairOrderEqualsTheOneByOneSolveBitForBit) {
    std::vector<BodySpec> cubes = {Cube(vec3(-6.0f, 0.5f, 0.0f)), Cube(vec3(-2.0f, 1.5f, 0.0f)),
                                   Cube(vec3(2.0f, 0.5f, 0.0f)), Cube(vec3(6.0f, 0.5f, 0.0f))};
    cubes[2].velocity = vec3(3.0f, 0.0f, 1.0f);
    cubes[3].angularVelocity = vec3(0.0f, 4.0f, 0.0f);
    TestWorld wide(WithGround(Ground(), cubes)), single(WithGround(Ground(), cubes));
    for (TestWorld* w : {&wide, &single}) w->system.settings.contactSolver = ContactSolver::Soft;
    single.system.settings.softGraphColouring = false;
    for (int i = 0; i < 120; ++i) {
        wide.system.Update(kDt);
        single.system.Update(kDt);
        ASSERT_EQ(StateOf(wide), StateOf(single)) << "step " << i;
    }
    EXPECT_EQ(wide.system.SoftSolver().Batches().size(), 1u);
    EXPECT_EQ(single.system.SoftSolver().Batches().size(), 0u);
    EXPECT_GT(wide.Body(3).position.x, 2.5f);  // the slider moved
}

// A column of 10 cubes is 10 pairs in two colours of five (ground-cube 0, cubes 1-2, ... and cubes 0-1, 2-3, ...):
// each colour is a batch of four and a lone fifth pair, which is solved one by one with the overflow instead of
// as a batch of four lanes with three empty. The column still stands.
TEST(SoftSolverGraph, ALonePairIsSolvedOneByOne) {
    TestWorld world(PeerTower(10));
    world.system.settings.contactSolver = ContactSolver::Soft;
    for (int i = 0; i < 120; ++i) world.system.Update(kDt);
    const SoftContactSolver& solver = world.system.SoftSolver();
    ASSERT_EQ(solver.Pairs().size(), 10u);
    EXPECT_EQ(solver.Batches().size(), 2u);
    for (const SoftContactSolver::WideBatch& batch : solver.Batches()) {
        int lanes = 0;
        for (int lane = 0; lane < 4; ++lane) lanes += batch.pair[lane] >= 0 ? 1 : 0;
        EXPECT_EQ(lanes, 4);
    }
    EXPECT_EQ(solver.OverflowPairs().size(), 2u);
    EXPECT_LT(world.MaxDisplacement(), 0.01f);
}

// A plate carrying 36 cubes is in 37 pairs, more than there are colours: the pairs past the last colour are
// solved one by one after the batches, and the cubes rest on the plate as the others do.
TEST(SoftSolverGraph, PairsBeyondTheColoursAreSolvedOneByOne) {
    BodySpec plate = BoxSpec(vec3(0.0f, 0.25f, 0.0f), vec3(4.0f, 0.25f, 4.0f), 20.0f);
    plate.restitution = 0.0f;
    plate.velocityRetention = 1.0f;
    plate.velocityEpsilon = 0.0f;
    std::vector<BodySpec> bodies = {plate};
    for (int i = 0; i < 36; ++i) {
        BodySpec cube = Cube(vec3(-3.0f + 1.2f * static_cast<float>(i % 6), 1.0f, -3.0f + 1.2f * (i / 6)));
        bodies.push_back(cube);
    }
    TestWorld world(WithGround(Ground(), bodies));
    world.system.settings.contactSolver = ContactSolver::Soft;
    for (int i = 0; i < 120; ++i) world.system.Update(kDt);
    const SoftContactSolver& solver = world.system.SoftSolver();
    EXPECT_GT(solver.OverflowPairs().size(), 0u);
    std::size_t inBatches = 0;
    for (const SoftContactSolver::WideBatch& batch : solver.Batches())
        for (int lane = 0; lane < 4; ++lane) inBatches += batch.pair[lane] >= 0 ? 1u : 0u;
    EXPECT_EQ(inBatches + solver.OverflowPairs().size(), solver.Pairs().size());
    for (std::size_t i = 2; i < world.Bodies().size(); ++i) {
        EXPECT_NEAR(world.Body(i).position.y, 1.0f, 0.01f) << "cube " << i - 2;
        EXPECT_LT(Magnitude(world.Body(i).velocity), 0.01f) << "cube " << i - 2;
    }
}
