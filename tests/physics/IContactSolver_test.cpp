// IContactSolver (Physics/IContactSolver.h): a world's solver setting picks the object that steps its volumes, made
// when the setting changes and not per step; a world switched to another solver and back steps as a fresh world with
// the same bodies does. A column of three unit boxes on a static slab, dt 1/60 s, one thread.
#include "Physics/IContactSolver.h"

#include <gtest/gtest.h>

#include <vector>

#include "Demos/Scenes/WorldBuilder.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/RigidbodyVolume.h"
#include "Physics/WorldCopy.h"
#include "tests/support/TestWorld.h"
#include "tests/support/Volumes.h"

namespace {

constexpr float kDt = 1.0f / 60.0f;

/// Ground, then three unit boxes resting on each other (0.01 m gaps), on one thread, solved by `kind`; `steps`
/// steps of kDt run.
void BuildColumn(TestWorld* w, ContactSolver kind = ContactSolver::Book, int steps = 0) {
    w->Add(GroundSpec(vec3(10.0f, 1.0f, 10.0f)));
    for (int i = 0; i < 3; ++i) w->Add(BoxSpec(vec3(0.0f, 1.01f + 2.01f * static_cast<float>(i), 0.0f)));
    w->system.settings.threads = 1;
    w->system.settings.contactSolver = kind;
    w->Join();
    if (steps > 0) w->Step(kDt, steps);
}

/// Position, velocity, angular velocity and orientation of every volume of `world`, as raw bytes.
std::vector<unsigned char> StateOf(const PhysicsSystem& world) {
    std::vector<RigidbodyVolume> copies;
    for (const RigidbodyVolume* v : world.Volumes()) copies.push_back(*v);
    return Snapshot(copies);
}

}  // namespace

TEST(IContactSolver, EachSolverSettingIsSteppedByTheSolverOfThatKind) {
    for (ContactSolver kind : kAllContactSolvers) {
        SCOPED_TRACE(ToString(kind));
        TestWorld w;
        BuildColumn(&w, kind, 10);
        EXPECT_EQ(w.system.Solver().Kind(), kind);
        // Only the solver in use holds contacts; the book's keeps none, and only the soft one substeps every step.
        EXPECT_EQ(w.system.AccumulatedSolver().ContactCount() > 0, kind == ContactSolver::Accumulated);
        EXPECT_EQ(w.system.SoftSolver().PairCount() > 0, kind == ContactSolver::Soft);
        EXPECT_EQ(w.system.LastVolumeSubsteps() > 1, kind == ContactSolver::Soft);
        EXPECT_GT(w.system.CollisionCount(), 0u) << "the boxes rest on each other";
    }
}

TEST(IContactSolver, TheSolverObjectIsMadeWhenTheSettingChangesNotEveryStep) {
    TestWorld w;
    BuildColumn(&w, ContactSolver::Soft, 1);
    const IContactSolver* soft = &w.system.Solver();
    w.Step(kDt, 5);
    EXPECT_EQ(&w.system.Solver(), soft) << "the same setting keeps the same object";

    w.system.settings.contactSolver = ContactSolver::Accumulated;
    EXPECT_EQ(&w.system.Solver(), soft) << "the object changes at the next step, not when the setting is written";
    w.Step(kDt);
    EXPECT_EQ(w.system.Solver().Kind(), ContactSolver::Accumulated);
    EXPECT_GT(w.system.AccumulatedSolver().ContactCount(), 0u);
    EXPECT_EQ(w.system.SoftSolver().PairCount(), 0u) << "the soft solver's contacts went with it";
}

TEST(IContactSolver, AWorldSwitchedAwayAndBackStepsAsAFreshWorldWithItsBodies) {
    for (ContactSolver kind : kAllContactSolvers) {
        SCOPED_TRACE(ToString(kind));
        TestWorld w;
        BuildColumn(&w, kind, 20);
        // Twenty steps on another solver, then back.
        w.system.settings.contactSolver =
            kind == ContactSolver::Soft ? ContactSolver::Accumulated : ContactSolver::Soft;
        w.Step(kDt, 20);
        w.system.settings.contactSolver = kind;
        WorldCopy fresh(w.system);  // the same bodies and settings in a new world, its solver made afresh
        ASSERT_EQ(StateOf(fresh.System()), StateOf(w.system));
        w.Step(kDt, 30);
        for (int i = 0; i < 30; ++i) fresh.System().Update(kDt);
        EXPECT_EQ(fresh.System().Solver().Kind(), kind);
        EXPECT_EQ(StateOf(fresh.System()), StateOf(w.system));
    }
}
