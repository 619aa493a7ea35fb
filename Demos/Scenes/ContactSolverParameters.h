#pragma once
// The contact-solver parameters shared by the rigid-volume scenes (ch15, linear-impulse, momentum and scene files):
// the "solver" choice and the soft solver's settings as `--set` keys. Each soft key is "soft-" and the
// SoftSolverSettings field in kebab-case (docs/app.md, "Contact solvers").

#include <functional>
#include <string>
#include <vector>

#include "Demos/Scenes/Parameters.h"
#include "Physics/ContactSolverSettings.h"
#include "Physics/WorldSettings.h"

/// Solver ids in kAllContactSolvers order ("book", "accumulated", "soft"): the "solver" choice list, so a
/// choice index is the enum's value.
std::vector<std::string> ContactSolverChoices();
/// The solver at an index of ContactSolverChoices(); the book's if out of range.
ContactSolver ContactSolverAt(int index);
/// Index of `solver` in ContactSolverChoices().
int ContactSolverIndex(ContactSolver solver);

/// Ranges of the soft solver's `--set` keys (inclusive; the scene file's world.soft takes the same).
struct SoftSolverLimits {
    static constexpr int kMaxSubsteps = 64;          ///< count
    static constexpr int kMaxIterations = 100;       ///< passes per substep
    static constexpr float kMinContactHertz = 0.1f;  ///< Hz
    static constexpr float kMaxContactHertz = 1000.0f;
    static constexpr float kMaxDampingRatio = 100.0f;
    static constexpr float kMaxPushoutSpeed = 100.0f;  ///< m/s
};

/// The contact-solver choice of a rigid-volume scene (ch15, linear-impulse, momentum, scene files): the one place
/// for the "solver" index, the soft solver's settings and sleep. Not book widgets; off (the book's) by default.
struct ContactSolverChoice {
    /// An index of ContactSolverChoices(), so the enum's value: 0 the book's per-contact solver, 1 accumulated
    /// impulses, 2 the soft step (ContactSolverSettings.h); `--set solver=`.
    int solver = 0;
    /// WorldSettings::soft, used when solver is soft (`--set soft-substeps=...`).
    SoftSolverSettings soft;
    /// Islands and sleep (WorldSettings::sleep.enabled, `--set sleep=1`; docs/sleep.md); off, as in the book.
    bool sleep = false;

    /// Puts the choice into a world's settings: contactSolver, soft and sleep.enabled.
    void ApplyTo(WorldSettings* settings) const;
};

/// Registers "solver" (a choice bound to choice->solver, help `solverHelp`) and the soft solver's settings a user
/// tunes: soft-substeps, soft-iterations, soft-relax-iterations, soft-contact-hertz, soft-contact-damping-ratio,
/// soft-max-pushout-speed (bound to choice->soft), and "sleep" (islands and sleep on or off, bound to
/// choice->sleep, WorldSettings::sleep.enabled; docs/sleep.md). onChange runs after each successful --set.
void AddContactSolverParameters(ParameterSet* set, ContactSolverChoice* choice, const std::string& solverHelp,
                                const std::function<void()>& onChange);

/// The panel row naming a non-book solver in effect ("Contact solver: accumulated", "Contact solver: soft, 6
/// substeps, 90 Hz"); "" for the book's (its panels stay the book's).
std::string ContactSolverRow(ContactSolver solver, const SoftSolverSettings& soft);
