#include "Demos/Scenes/ContactSolverParameters.h"

#include <cstdio>
#include <iterator>

std::vector<std::string> ContactSolverChoices() {
    std::vector<std::string> ids;
    for (ContactSolver solver : kAllContactSolvers) ids.emplace_back(ToString(solver));
    return ids;
}

ContactSolver ContactSolverAt(int index) {
    if (index < 0 || index >= static_cast<int>(std::size(kAllContactSolvers))) return ContactSolver::Book;
    return kAllContactSolvers[index];
}

int ContactSolverIndex(ContactSolver solver) {
    for (std::size_t i = 0; i < std::size(kAllContactSolvers); ++i)
        if (kAllContactSolvers[i] == solver) return static_cast<int>(i);
    return 0;
}

std::string ContactSolverRow(ContactSolver solver, const SoftSolverSettings& soft) {
    if (solver == ContactSolver::Book) return "";
    if (solver != ContactSolver::Soft) return std::string("Contact solver: ") + ToString(solver);
    char row[96];
    std::snprintf(row, sizeof row, "Contact solver: soft, %d substeps, %g Hz", soft.substeps,
                  static_cast<double>(soft.contactHertz));
    return row;
}

void ContactSolverChoice::ApplyTo(WorldSettings* settings) const {
    settings->contactSolver = ContactSolverAt(solver);
    settings->soft = soft;
    settings->sleep.enabled = sleep;
}

void AddContactSolverParameters(ParameterSet* set, ContactSolverChoice* choice, const std::string& solverHelp,
                                const std::function<void()>& onChange) {
    using L = SoftSolverLimits;
    SoftSolverSettings* soft = &choice->soft;
    set->AddChoice("solver", &choice->solver, ContactSolverChoices(), solverHelp, onChange);
    set->AddInt("soft-substeps", &soft->substeps, 1, L::kMaxSubsteps, "soft solver: substeps per step", onChange);
    set->AddInt("soft-iterations", &soft->iterations, 1, L::kMaxIterations,
                "soft solver: biased solve passes per substep", onChange);
    set->AddInt("soft-relax-iterations", &soft->relaxIterations, 0, L::kMaxIterations,
                "soft solver: relax passes (no bias) per substep", onChange);
    set->AddFloat("soft-contact-hertz", &soft->contactHertz, L::kMinContactHertz, L::kMaxContactHertz,
                  "soft solver: contact stiffness (Hz), capped at a quarter of the substep rate", onChange);
    set->AddFloat("soft-contact-damping-ratio", &soft->contactDampingRatio, 0.0f, L::kMaxDampingRatio,
                  "soft solver: damping ratio of the contact spring (1 critical)", onChange);
    set->AddFloat("soft-max-pushout-speed", &soft->maxPushoutSpeed, 0.0f, L::kMaxPushoutSpeed,
                  "soft solver: fastest push-out of a penetrating contact (m/s)", onChange);
    set->AddBool("sleep", &choice->sleep,
                 "islands of slow bodies sleep until touched, pushed or changed (docs/sleep.md)", onChange);
}
