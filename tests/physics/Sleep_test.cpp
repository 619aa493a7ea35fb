// Islands and sleep of rigid volumes (Physics/Islands.h, WorldSettings::sleep, docs/sleep.md): bodies that stay slow
// sleep by island, are not moved or tested while asleep, and wake as a whole island on a contact, an impulse or a
// changed property. The scenes use the Accumulated solver (10 passes), with which stacks come to rest; the book's
// solver keeps stacks jittering above the sleep speeds, so only a lone box is tested with it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <vector>

#include "Demos/Scenes/WorldBuilder.h"
#include "Physics/Islands.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/RigidbodyVolume.h"
#include "tests/support/TestWorld.h"
#include "tests/support/Volumes.h"

namespace {

constexpr float kDt = 1.0f / 60.0f;

void UseSleep(PhysicsSystem& system, bool on) {
    system.settings.contactSolver = ContactSolver::Accumulated;
    system.settings.solverIterations = 10;
    system.settings.sleep.enabled = on;
}

/// Steps until every body in [first, last] sleeps; returns the steps taken, or -1 after maxSteps.
int StepUntilAsleep(TestWorld& w, std::size_t first, std::size_t last, int maxSteps) {
    for (int step = 1; step <= maxSteps; ++step) {
        w.system.Update(kDt);
        bool all = true;
        for (std::size_t i = first; i <= last; ++i) all = all && w.Body(i).IsSleeping();
        if (all) return step;
    }
    return -1;
}

/// Ground (index 0) and one unit cube whose bottom is `drop` m above it.
std::vector<BodySpec> DroppedBox(float drop) { return {GroundSlabSpec(), BoxSpec(vec3(0.0f, 1.0f + drop, 0.0f))}; }

/// Ground (index 0) and a tower of `height` unit cubes centred at (x, z).
std::vector<BodySpec> TowerAt(int height, float x, float z, float lift = 0.0f) {
    std::vector<BodySpec> specs = Tower(height, BoxSpec(vec3()));
    for (BodySpec& s : specs) s.position += vec3(x, lift, z);
    return specs;
}

}  // namespace

// A box dropped 2 m falls, bounces, settles and then sleeps, with either solver; from then on its state is
// bit-identical step after step: no gravity reaches its velocity, no integration its position, and its pair with the
// static ground is not even tested (no collisions are found).
TEST(Sleep, DroppedBoxSleepsAndStopsMoving) {
    for (ContactSolver solver : {ContactSolver::Accumulated, ContactSolver::Book}) {
        SCOPED_TRACE(ToString(solver));
        TestWorld w(DroppedBox(2.0f));
        UseSleep(w.system, true);
        w.system.settings.contactSolver = solver;
        const int steps = StepUntilAsleep(w, 1, 1, 600);
        ASSERT_GT(steps, 0) << "never slept";
        ASSERT_GT(steps, 30) << "slept before it landed";
        const RigidbodyVolume& box = w.Body(1);
        EXPECT_NEAR(box.position.y, 1.0f, 0.03f);  // at rest on the ground, not in the air
        EXPECT_EQ(w.system.SleepIslands().SleepingCount(), 1u);
        const std::vector<unsigned char> asleep = Snapshot(w.Bodies());
        for (int i = 0; i < 120; ++i) {
            w.system.Update(kDt);
            EXPECT_EQ(w.system.CollisionCount(), 0u);
        }
        EXPECT_TRUE(box.IsSleeping());
        EXPECT_EQ(Snapshot(w.Bodies()), asleep);
        EXPECT_EQ(box.velocity.y, 0.0f);
    }
}

// Sleep off (the default): the same box never sleeps, its sleep time stays 0 and its ground contact is tested every
// step. Turning sleep off while it sleeps wakes it.
TEST(Sleep, OffNeverSleeps) {
    TestWorld w(DroppedBox(2.0f));
    UseSleep(w.system, false);
    for (int i = 0; i < 600; ++i) {
        w.system.Update(kDt);
        ASSERT_FALSE(w.Body(1).IsSleeping()) << "step " << i;
    }
    EXPECT_EQ(w.Body(1).SleepTime(), 0.0f);
    EXPECT_EQ(w.system.CollisionCount(), 1u);

    w.system.settings.sleep.enabled = true;
    ASSERT_GT(StepUntilAsleep(w, 1, 1, 600), 0);
    w.system.settings.sleep.enabled = false;
    w.system.Update(kDt);
    EXPECT_FALSE(w.Body(1).IsSleeping());
    EXPECT_EQ(w.system.SleepIslands().SleepingCount(), 0u);
    EXPECT_EQ(w.system.CollisionCount(), 1u);
}

// Sleep on while nothing is asleep changes nothing: a tumbling column with an unreachable timeToSleep is bit-identical
// to the same column with sleep off (the hooks only skip sleeping bodies and their pairs).
TEST(Sleep, OnWithoutSleepersIsBitIdenticalToOff) {
    std::vector<BodySpec> specs = WithGround(GroundSlabSpec(), TiltedColumn(6));
    TestWorld off(specs), on(specs);
    UseSleep(off.system, false);
    UseSleep(on.system, true);
    on.system.settings.sleep.timeToSleep = 1e9f;
    for (int i = 0; i < 300; ++i) {
        off.system.Update(kDt);
        on.system.Update(kDt);
    }
    EXPECT_EQ(Snapshot(on.Bodies()), Snapshot(off.Bodies()));
    EXPECT_GT(on.system.SleepIslands().IslandCount(), 0u);
}

// A sleeping tower is woken by a box falling on it: the box floats asleep above the tower (no gravity) until its
// gravity is restored (a changed property wakes it, and only it); the moment it touches the top, the whole tower wakes,
// bottom box included.
TEST(Sleep, DroppedBoxWakesWholeStack) {
    std::vector<BodySpec> specs = WithGround(GroundSlabSpec(), Tower(3, BoxSpec(vec3())));  // tops at y = 6
    specs.push_back(BoxSpec(vec3(0.0f, 9.0f, 0.0f)));                                       // bottom at y = 8
    TestWorld w(specs);
    w.Body(4).gravity = vec3();
    UseSleep(w.system, true);
    ASSERT_GT(StepUntilAsleep(w, 1, 4, 900), 0);

    w.Body(4).gravity = kVolumeGravity;
    w.system.Update(kDt);
    EXPECT_FALSE(w.Body(4).IsSleeping());
    for (std::size_t i = 1; i <= 3; ++i) EXPECT_TRUE(w.Body(i).IsSleeping()) << "tower box " << i;

    auto touching = [&w] {
        for (std::size_t k = 0; k < w.system.CollisionCount(); ++k)
            if (w.system.Collisions()[k].indexA == 3 && w.system.Collisions()[k].indexB == 4) return true;
        return false;
    };
    int step = 0;
    while (!touching() && step < 120) {
        w.system.Update(kDt);
        ++step;
    }
    ASSERT_LT(step, 120) << "the falling box never reached the tower";
    // Woken in the step of the first contact, before the solver: the contact is solved with the tower awake.
    for (std::size_t i = 1; i <= 3; ++i) EXPECT_FALSE(w.Body(i).IsSleeping()) << "tower box " << i;
}

// A velocity change or an impulse through the body's API on one box of a sleeping tower wakes the whole tower.
TEST(Sleep, ImpulseWakesWholeIsland) {
    for (int kind = 0; kind < 2; ++kind) {
        TestWorld w(WithGround(GroundSlabSpec(), Tower(3, BoxSpec(vec3()))));
        UseSleep(w.system, true);
        ASSERT_GT(StepUntilAsleep(w, 1, 3, 900), 0);
        RigidbodyVolume& top = w.Body(3);
        if (kind == 0) {
            top.AddVelocityChange(vec3(0.5f, 0.0f, 0.0f));
        } else {
            top.AddRotationalImpulse(top.position + vec3(1.0f, 0.0f, 0.0f), vec3(0.0f, 0.0f, 0.3f));
        }
        // The body's API wakes it at once (not only the next step's snapshot compare).
        EXPECT_FALSE(top.IsSleeping()) << "kind " << kind;
        w.system.Update(kDt);
        for (std::size_t i = 1; i <= 3; ++i) EXPECT_FALSE(w.Body(i).IsSleeping()) << "kind " << kind << " box " << i;
        EXPECT_GT(w.system.CollisionCount(), 0u);
    }
}

// A changed mass, or a position set from outside, wakes the body: lifted 0.5 m, the box falls back.
TEST(Sleep, ChangedPropertyWakes) {
    {
        TestWorld w(DroppedBox(0.0f));
        UseSleep(w.system, true);
        ASSERT_GT(StepUntilAsleep(w, 1, 1, 600), 0);
        w.Body(1).mass = 2.0f;
        w.system.Update(kDt);
        EXPECT_FALSE(w.Body(1).IsSleeping());
    }
    {
        TestWorld w(DroppedBox(0.0f));
        UseSleep(w.system, true);
        ASSERT_GT(StepUntilAsleep(w, 1, 1, 600), 0);
        RigidbodyVolume& box = w.Body(1);
        box.position.y += 0.5f;
        box.SynchCollisionVolumes();
        const float lifted = box.position.y;
        w.system.Update(kDt);
        EXPECT_FALSE(box.IsSleeping());
        EXPECT_LT(box.position.y, lifted);
    }
}

// Two towers 20 m apart are two islands: the one dropped from higher settles later, so the first sleeps while the
// second still moves; an impulse on the second, once both sleep, leaves the first asleep.
TEST(Sleep, SeparatePilesSleepIndependently) {
    std::vector<BodySpec> specs{GroundSlabSpec()};
    for (const BodySpec& s : TowerAt(2, -10.0f, 0.0f)) specs.push_back(s);       // 1, 2: resting
    for (const BodySpec& s : TowerAt(2, 10.0f, 0.0f, 3.0f)) specs.push_back(s);  // 3, 4: dropped 3 m
    TestWorld w(specs);
    UseSleep(w.system, true);
    w.system.Update(kDt);
    const int first = StepUntilAsleep(w, 1, 2, 900);
    ASSERT_GT(first, 0);
    EXPECT_EQ(w.system.SleepIslands().IslandsPutToSleep(), 1u);
    EXPECT_FALSE(w.Body(3).IsSleeping());
    EXPECT_FALSE(w.Body(4).IsSleeping());
    // The second tower sleeps later, as one island of two boxes (the sleeping tower is no longer counted).
    ASSERT_GT(StepUntilAsleep(w, 3, 4, 900), 0);
    EXPECT_EQ(w.system.SleepIslands().IslandCount(), 1u);
    EXPECT_EQ(w.system.SleepIslands().IslandsPutToSleep(), 1u);
    EXPECT_EQ(w.system.SleepIslands().SleepingCount(), 4u);

    w.Body(4).AddVelocityChange(vec3(0.0f, 0.0f, 0.3f));
    w.system.Update(kDt);
    EXPECT_FALSE(w.Body(3).IsSleeping());
    EXPECT_FALSE(w.Body(4).IsSleeping());
    EXPECT_TRUE(w.Body(1).IsSleeping());
    EXPECT_TRUE(w.Body(2).IsSleeping());
}

// Determinism: a 60-box pile (broadphase path) with sleep on, run twice, is bit-identical, sleepers included.
TEST(Sleep, Deterministic) {
    auto run = [](std::vector<unsigned char>* state, std::vector<bool>* sleeping) {
        TestWorld w(BoxpileScene(60));
        UseSleep(w.system, true);
        for (int i = 0; i < 600; ++i) w.system.Update(kDt);
        *state = Snapshot(w.Bodies());
        for (const RigidbodyVolume& b : w.Bodies()) sleeping->push_back(b.IsSleeping());
        return w.system.SleepIslands().SleepingCount();
    };
    std::vector<unsigned char> a, b;
    std::vector<bool> sa, sb;
    const std::size_t asleepA = run(&a, &sa);
    const std::size_t asleepB = run(&b, &sb);
    EXPECT_GT(asleepA, 0u);
    EXPECT_EQ(asleepA, asleepB);
    EXPECT_EQ(a, b);
    EXPECT_EQ(sa, sb);
}

// timeToSleep 0 still needs slow bodies: a falling box does not sleep in the air, and sleeps once it rests.
TEST(Sleep, ZeroTimeToSleepNeedsSlowBodies) {
    TestWorld w(DroppedBox(2.0f));
    UseSleep(w.system, true);
    w.system.settings.sleep.timeToSleep = 0.0f;
    for (int i = 0; i < 20; ++i) {
        w.system.Update(kDt);
        ASSERT_FALSE(w.Body(1).IsSleeping()) << "step " << i;
    }
    ASSERT_GT(StepUntilAsleep(w, 1, 1, 600), 0);
    EXPECT_NEAR(w.Body(1).position.y, 1.0f, 0.03f);
}

// The soft step sleeps too: a tower of three settles and sleeps as one island; asleep, its state is bit-identical
// step after step and no pair is searched or solved; a box falling on it wakes the whole island in the step its grown
// box meets the tower's top, and an impulse on the top box wakes all three.
TEST(Sleep, SoftStepSleepsAndWakesByIsland) {
    std::vector<BodySpec> specs = WithGround(GroundSlabSpec(), Tower(3, BoxSpec(vec3())));  // tops at y = 6
    specs.push_back(BoxSpec(vec3(0.0f, 9.0f, 0.0f)));                                       // bottom at y = 8
    TestWorld w(specs);
    w.Body(4).gravity = vec3();
    UseSleep(w.system, true);
    w.system.settings.contactSolver = ContactSolver::Soft;
    ASSERT_GT(StepUntilAsleep(w, 1, 4, 900), 0) << "the soft step never put the tower to sleep";
    const std::vector<unsigned char> asleep = Snapshot(w.Bodies());
    for (int i = 0; i < 60; ++i) {
        w.system.Update(kDt);
        EXPECT_EQ(w.system.SoftSolver().PairCount(), 0u);
    }
    EXPECT_EQ(Snapshot(w.Bodies()), asleep);

    w.Body(4).gravity = kVolumeGravity;  // a changed property wakes the floating box alone
    w.system.Update(kDt);
    EXPECT_FALSE(w.Body(4).IsSleeping());
    for (std::size_t i = 1; i <= 3; ++i) EXPECT_TRUE(w.Body(i).IsSleeping()) << "tower box " << i;
    int step = 0;
    while (w.Body(1).IsSleeping() && step < 120) {
        w.system.Update(kDt);
        ++step;
    }
    ASSERT_LT(step, 120) << "the falling box never woke the tower";
    EXPECT_GT(w.Body(4).position.y, 7.0f) << "woken only after the box had sunk into the top";
    for (std::size_t i = 1; i <= 3; ++i) EXPECT_FALSE(w.Body(i).IsSleeping()) << "tower box " << i;

    ASSERT_GT(StepUntilAsleep(w, 1, 4, 1200), 0) << "the four boxes never slept again";
    w.Body(4).AddVelocityChange(vec3(0.3f, 0.0f, 0.0f));
    w.system.Update(kDt);
    for (std::size_t i = 1; i <= 4; ++i) EXPECT_FALSE(w.Body(i).IsSleeping()) << "box " << i;
    EXPECT_GT(w.system.SoftSolver().PairCount(), 0u);
}

// Two soft towers whose grown boxes meet (3 mm apart, within twice the speculative margin) but which never touch:
// the pair that would wake one from the other also links them, so they are one island and fall asleep together
// instead of waking each other in turn.
TEST(Sleep, SoftStepNearbyTowersSleep) {
    std::vector<BodySpec> specs = WithGround(GroundSlabSpec(), TowerAt(3, 0.0f, 0.0f));
    for (const BodySpec& s : TowerAt(1, 2.003f, 0.0f)) specs.push_back(s);
    TestWorld w(specs);
    UseSleep(w.system, true);
    w.system.settings.contactSolver = ContactSolver::Soft;
    ASSERT_GT(StepUntilAsleep(w, 1, 4, 900), 0) << "the two towers kept each other awake";
    EXPECT_EQ(w.system.SleepIslands().SleepingCount(), 4u);
}

namespace {

/// Steps of `dt` of one free box (no contacts) moved by hand along x by `amplitude` m at `omega` rad/s and turned
/// about z by `turn` rad at the same rate, through Islands alone; the step it first sleeps, or -1 after `steps`.
int StepsUntilOscillationSleeps(float amplitude, float turn, float omega, int steps) {
    RigidbodyVolume box = MakeBody(BoxSpec(vec3(0.0f, 5.0f, 0.0f)));
    const std::vector<RigidbodyVolume*> volumes = {&box};
    SleepSettings settings;
    settings.enabled = true;
    Islands islands;
    for (int step = 1; step <= steps; ++step) {
        if (!islands.BeginStep(volumes, settings)) return -2;
        const float t = static_cast<float>(step) * kDt;
        box.position.x = amplitude * std::sin(omega * t);
        box.velocity.x = amplitude * omega * std::cos(omega * t);
        box.orientation = AngleAxis(vec3(0.0f, 0.0f, 1.0f), turn * std::sin(omega * t));
        box.angVel.z = turn * omega * std::cos(omega * t);
        islands.BeginUpdate(volumes, kDt, settings);
        islands.EndUpdate(volumes, settings);
        if (box.IsSleeping()) return step;
    }
    return -1;
}

}  // namespace

// A body that sways in place sleeps although its speed peaks above the thresholds (docs/sleep.md, "still"): moving
// 5 mm either way at 0.1 m/s (twice linearSpeed), or turning 0.005 rad either way at 0.1 rad/s (three times
// angularSpeed), it stays inside the window's ball (linearSpeed * timeToSleep = 2.5 cm, angularSpeed * timeToSleep =
// 0.0175 rad) and sleeps after timeToSleep; the speed test alone restarts its sleep time every half period. Swaying
// 3 cm either way (or 0.05 rad) it leaves the ball and never sleeps.
TEST(Sleep, BodySwayingInPlaceSleepsThoughItsSpeedPeaksAboveTheThresholds) {
    const int linear = StepsUntilOscillationSleeps(0.005f, 0.0f, 20.0f, 600);
    EXPECT_GT(linear, 30) << "slept before timeToSleep";
    EXPECT_LE(linear, 60) << "a body swaying within the ball never slept";
    const int angular = StepsUntilOscillationSleeps(0.0f, 0.005f, 20.0f, 600);
    EXPECT_GT(angular, 30) << "slept before timeToSleep";
    EXPECT_LE(angular, 60) << "a body rocking within the ball never slept";
    EXPECT_EQ(StepsUntilOscillationSleeps(0.03f, 0.0f, 10.0f, 600), -1) << "slept while swaying 6 cm";
    EXPECT_EQ(StepsUntilOscillationSleeps(0.0f, 0.05f, 10.0f, 600), -1) << "slept while rocking 0.1 rad";
}
