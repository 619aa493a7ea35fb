// "Nothing is allocated per step in steady state", tested rather than claimed: this test
// binary replaces the global operator new with a counting one, and each scene must run its steps after a
// warm-up without a single allocation. A per-step std::vector, std::function or manifold copy would fail it.

// The replacement operator new/delete below pair malloc with free consistently. When GCC inlines them into
// gtest's `new TestClass` it cannot see that and warns -Wmismatched-new-delete (a false positive, seen in the
// -O2 ASan build), so that one diagnostic is off for this file only.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <new>

#include "Demos/Scenes/Ch14Scene.h"
#include "Demos/Scenes/Ch15Scene.h"
#include "Demos/Scenes/Ch16Scene.h"
#include "Demos/Scenes/JointScene.h"
#include "Demos/Scenes/MomentumScene.h"
#include "Demos/Scenes/SpringsScene.h"
#include "Demos/Scenes/WorldBuilder.h"

namespace {
std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};
int* volatile g_sink = nullptr;  // an allocation stored here escapes, so the compiler cannot elide it

// Counts allocations made while `body` runs.
template <typename F>
long AllocationsDuring(F&& body) {
    g_allocations = 0;
    g_counting = true;
    body();
    g_counting = false;
    return g_allocations.load();
}
}  // namespace

void* operator new(std::size_t size) {
    if (g_counting) ++g_allocations;
    if (void* p = std::malloc(size ? size : 1)) return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return operator new(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

constexpr int kWarmup = 200;  // long enough for contacts to form and buffers to reach their size
constexpr int kMeasured = 300;

TEST(SteadyStateAllocation, CountingOperatorNewSeesAllocations) {
    // Guards the guard: if the replacement were not linked in, every test below would pass vacuously.
    EXPECT_GT(AllocationsDuring([] { g_sink = new int(3); }), 0);
    delete g_sink;
}

TEST(SteadyStateAllocation, Ch14ParticlesEveryIntegrator) {
    for (Integrator integrator : {Integrator::ExplicitEuler, Integrator::SemiImplicitEuler, Integrator::VelocityVerlet,
                                  Integrator::PositionVerlet, Integrator::RK4}) {
        Ch14Params params;
        params.integrator = integrator;
        Ch14Scene scene(params);
        for (int i = 0; i < kWarmup; ++i) scene.Step(scene.Params().dt);
        EXPECT_EQ(AllocationsDuring([&] {
                      for (int i = 0; i < kMeasured; ++i) scene.Step(scene.Params().dt);
                  }),
                  0)
            << ToString(integrator);
    }
}

TEST(SteadyStateAllocation, Ch15BoxesWithContacts) {
    Ch15Scene scene;
    for (int i = 0; i < kWarmup; ++i) scene.Step(0.03f);
    ASSERT_GT(scene.System().CollisionCount(), 0u) << "the boxes should be in contact after the warm-up";
    EXPECT_EQ(AllocationsDuring([&] {
                  for (int i = 0; i < kMeasured; ++i) scene.Step(0.03f);
              }),
              0);
}

TEST(SteadyStateAllocation, Ch15BoxesAccumulatedSolver) {
    Ch15Params params;
    params.contact.solver = 1;  // --set solver=accumulated
    Ch15Scene scene(params);
    for (int i = 0; i < kWarmup; ++i) scene.Step(0.03f);
    ASSERT_EQ(scene.System().settings.contactSolver, ContactSolver::Accumulated);
    // The arbiter's buffers must be reused, not regrown.
    ASSERT_GT(scene.System().AccumulatedSolver().ContactCount(), 0u) << "the boxes should be in contact";
    EXPECT_EQ(AllocationsDuring([&] {
                  for (int i = 0; i < kMeasured; ++i) scene.Step(0.03f);
              }),
              0);
}

// The soft solver (solver=soft) on a pile of 200 boxes found by the broadphase: its contact and body arrays, the
// broadphase's and the candidate list are reused, not regrown, once the pile has settled. The cubes are inelastic
// (as the peer benchmark's): columns of ten cubes dropped onto each other with e = 0.5 bounce, and some topple long
// after the warm-up, which is motion, not a steady state.
TEST(SteadyStateAllocation, BoxpileSoftSolver) {
    BodySpec cube = BoxSpec(vec3(), vec3(0.5f, 0.5f, 0.5f), 1.0f);
    cube.velocityRetention = 1.0f;
    cube.velocityEpsilon = 0.0f;
    cube.restitution = 0.0f;
    RigidWorld world(WithGround(GroundSpec(vec3(50.0f, 0.5f, 50.0f)), Boxpile(200, cube)));
    world.system.settings.contactSolver = ContactSolver::Soft;
    ASSERT_GE(world.system.Volumes().size(), world.system.settings.broadphaseMinVolumes);
    for (int i = 0; i < kWarmup; ++i) world.system.Update(1.0f / 60.0f);
    ASSERT_GT(world.system.SoftSolver().ContactCount(), 0u) << "the boxes should be in contact after the warm-up";
    EXPECT_EQ(AllocationsDuring([&] {
                  for (int i = 0; i < kMeasured; ++i) world.system.Update(1.0f / 60.0f);
              }),
              0);
}

TEST(SteadyStateAllocation, MomentumSpheres) {
    MomentumScene scene;
    for (int i = 0; i < kWarmup; ++i) scene.Step(0.03f);
    ASSERT_GT(scene.System().CollisionCount(), 0u) << "the spheres should be in contact after the warm-up";
    EXPECT_EQ(AllocationsDuring([&] {
                  for (int i = 0; i < kMeasured; ++i) scene.Step(0.03f);
              }),
              0);
}

TEST(SteadyStateAllocation, Ch16ClothEveryIntegrator) {
    for (Integrator integrator : {Integrator::SemiImplicitEuler, Integrator::VelocityVerlet, Integrator::RK4}) {
        Ch16Params params;
        params.integrator = integrator;
        Ch16Scene scene(params);
        for (int i = 0; i < kWarmup; ++i) scene.Step(scene.Params().dt);
        EXPECT_EQ(AllocationsDuring([&] {
                      for (int i = 0; i < kMeasured; ++i) scene.Step(scene.Params().dt);
                  }),
                  0)
            << ToString(integrator);
    }
}

TEST(SteadyStateAllocation, SpringsAndJoints) {
    SpringsScene springs;
    JointScene joints;
    for (int i = 0; i < kWarmup; ++i) {
        springs.Step(springs.Params().dt);
        joints.Step(joints.Params().dt);
    }
    EXPECT_EQ(AllocationsDuring([&] {
                  for (int i = 0; i < kMeasured; ++i) springs.Step(springs.Params().dt);
              }),
              0);
    EXPECT_EQ(AllocationsDuring([&] {
                  for (int i = 0; i < kMeasured; ++i) joints.Step(joints.Params().dt);
              }),
              0);
}

// Islands and sleep (docs/sleep.md): once a pile has settled, steps asleep, an island woken by a velocity change and
// falling asleep again allocate nothing.
TEST(SteadyStateAllocation, BoxpileWithSleep) {
    RigidWorld w(BoxpileScene(200));
    w.system.settings.contactSolver = ContactSolver::Accumulated;
    w.system.settings.solverIterations = 10;
    w.system.settings.sleep.enabled = true;
    for (int i = 0; i < 1500; ++i) w.system.Update(1.0f / 60.0f);
    ASSERT_EQ(w.system.SleepIslands().SleepingCount(), 200u) << "the pile should have settled";
    std::size_t fewestAsleep = 200;  // after the wake: the island may settle and sleep again within the 4 s
    EXPECT_EQ(AllocationsDuring([&] {
                  for (int i = 0; i < 60; ++i) w.system.Update(1.0f / 60.0f);
                  w.Body(5).AddVelocityChange(vec3(0.0f, 2.0f, 0.0f));
                  for (int i = 0; i < 240; ++i) {
                      w.system.Update(1.0f / 60.0f);
                      fewestAsleep = std::min(fewestAsleep, w.system.SleepIslands().SleepingCount());
                  }
              }),
              0);
    EXPECT_LT(fewestAsleep, 200u) << "the velocity change should have woken an island";
}
