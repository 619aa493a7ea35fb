#include "Demos/Scenes/AutoModel.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <limits>
#include <sstream>

#include "Physics/Cloth.h"
#include "Physics/DistanceJoint.h"
#include "Physics/Particle.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/RigidbodyVolume.h"

namespace {

constexpr double kStepLadder[] = {0.1, 0.05, 0.02, 0.01, 0.005, 0.002, 0.001, 0.0005, 0.0002, 0.0001};
constexpr int kIterationLadder[] = {1, 2, 5, 10, 20, 50};
constexpr int kSubstepLadder[] = {1, 2, 4, 8, 16, 32};
/// The particle contact every auto run uses (docs/model-choice.md "Particle contact").
constexpr ParticleContact kAutoParticleContact = ParticleContact::Reflect;

/// Within the key's range, up to the float rounding of its bounds (a range of 0.0005..0.1 s holds the ladder's
/// 0.0005, which its float bound, 0.000500000024, would leave out).
bool InRange(const ParameterSet::Entry& e, double v) {
    const double slack = 1e-6 * std::fabs(v);
    return v >= e.min - slack && v <= e.max + slack;
}

std::string Number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", v);
    return text;
}

/// Volumes with mass (the ones that move).
int MovingVolumes(const PhysicsSystem& world) {
    int n = 0;
    for (const RigidbodyVolume* v : world.Volumes()) n += v->mass > 0.0f ? 1 : 0;
    return n;
}

}  // namespace

CandidateSpace AutoModel::SpaceOf(const ParameterSet& params, const PhysicsSystem& world, double hostStep) {
    CandidateSpace space;
    for (const Cloth* cloth : world.Cloths()) {
        space.particleCount += static_cast<double>(cloth->verts.size());
        space.springCount += static_cast<double>(cloth->structural.size() + cloth->shear.size() + cloth->bend.size());
    }
    space.particleCount += static_cast<double>(world.Particles().size());
    space.springCount += static_cast<double>(world.Springs().size() + world.Joints().size());
    space.volumeCount = static_cast<double>(MovingVolumes(world));
    space.hasParticles = space.particleCount > 0.0;
    space.hasVolumes = space.volumeCount > 0.0;
    space.hasContacts = space.hasParticles && !world.Constraints().empty();
    if (space.hasContacts) {
        // The contact the run will use (Choose sets the parameter first): its offset is a bias no step removes, and
        // only the reflect contact times an impact inside its step.
        ParticleContact contact = world.settings.particleContact;
        if (params.Find("particle-contact") != nullptr) ParseParticleContact(params.Get("particle-contact"), &contact);
        space.contactOffset = ContactOffsetOf(contact);
        space.impactsTimedInStep = contact == ParticleContact::Reflect;
    }
    // Only the book's joints are a first-order splitting; tension joints keep the integrator's order, but a group of
    // joints above kMaxTensionGroup is left to the projection (PlanTensions) and stays first order.
    space.hasJoints = !world.Joints().empty() && (world.settings.jointModel == JointModel::Book ||
                                                  PlanTensions(world.Joints()).joints.size() != world.Joints().size());
    space.hasTensionJoints = !world.Joints().empty() && !space.hasJoints;

    ModelCandidate& base = space.base;
    base.integrator = world.settings.integrator;
    base.solver = world.settings.contactSolver;
    base.iterations = world.settings.solverIterations;
    base.softSubsteps = world.settings.soft.substeps;
    base.step = hostStep;
    if (const ParameterSet::Entry* dt = params.Find("dt")) {
        const double current = std::atof(params.Get("dt").c_str());
        if (current > 0.0) base.step = current;
        for (double s : kStepLadder) {
            if (s > 0.0 && InRange(*dt, s)) space.steps.push_back(s);
        }
    }
    if (const ParameterSet::Entry* e = params.Find("integrator"); e && space.hasParticles) {
        for (Integrator i : kAllIntegrators) {
            if (std::find(e->choices.begin(), e->choices.end(), ToString(i)) != e->choices.end()) {
                space.integrators.push_back(i);
            }
        }
    }
    if (const ParameterSet::Entry* e = params.Find("solver"); e && space.hasVolumes) {
        for (ContactSolver s : {ContactSolver::Book, ContactSolver::Accumulated, ContactSolver::Soft}) {
            if (std::find(e->choices.begin(), e->choices.end(), ToString(s)) != e->choices.end()) {
                space.solvers.push_back(s);
            }
        }
    }
    if (const ParameterSet::Entry* e = params.Find("iterations"); e && space.hasVolumes) {
        for (int n : kIterationLadder) {
            if (InRange(*e, n)) space.iterations.push_back(n);
        }
    }
    if (const ParameterSet::Entry* e = params.Find("soft-substeps"); e && space.hasVolumes) {
        for (int n : kSubstepLadder) {
            if (InRange(*e, n)) space.softSubsteps.push_back(n);
        }
    }
    return space;
}

std::vector<std::pair<std::string, std::string>> AutoModel::Assignments(const ParameterSet& params,
                                                                        const ModelCandidate& model) {
    std::vector<std::pair<std::string, std::string>> out;
    auto want = [&](const char* key, const std::string& value, bool numeric) {
        if (params.Find(key) == nullptr) return;
        const std::string now = params.Get(key);
        const bool same = numeric ? std::fabs(std::atof(now.c_str()) - std::atof(value.c_str())) <=
                                        1e-6 * std::fabs(std::atof(value.c_str()))
                                  : now == value;
        if (!same) out.emplace_back(key, value);
    };
    want("integrator", ToString(model.integrator), false);
    want("solver", ToString(model.solver), false);
    want("iterations", Number(model.iterations), true);
    want("soft-substeps", Number(model.softSubsteps), true);
    want("dt", Number(model.step), true);
    return out;
}

namespace {

bool ApplyModel(ParameterSet* params, const ModelCandidate& model, std::string* error) {
    for (const auto& [key, value] : AutoModel::Assignments(*params, model)) {
        if (!params->Set(key, value, error)) return false;
    }
    return true;
}

/// Why no model was chosen: what the safety factor asks of an estimate, the best reliable estimate reached, the
/// candidates found unreliable, and whether the CPU limit or the evaluation limit stopped the search.
std::string RefusalText(const ModelChoiceResult& choice, const CandidateSpace& space, const ErrorBudget& budget,
                        const ChoiceSettings& settings) {
    const char* unit = BudgetUnit(budget.quantity);
    char text[1024];
    std::snprintf(text, sizeof text,
                  "no model meets the %s error budget %g %s: it needs an estimate within %.3g %s (the budget over the "
                  "safety factor %g)",
                  ToString(budget.quantity), budget.bound, unit, budget.bound / settings.safety, unit, settings.safety);
    std::string out = text;
    auto add = [&out, &text](int n) {
        if (n > 0) out.append(text, static_cast<std::size_t>(std::min<int>(n, sizeof text - 1)));
    };
    const CandidateEstimate* best = choice.best >= 0 ? &choice.candidates[choice.best] : nullptr;
    if (best && !best->partial && !best->unreliable) {
        add(std::snprintf(text, sizeof text, "; the best reached %.3g %s (%s)", best->estimate, unit,
                          best->model.Describe(space.hasParticles, space.hasVolumes).c_str()));
    } else if (best && !best->partial) {
        add(std::snprintf(text, sizeof text, "; no estimate can be trusted (the smallest, %.3g %s from %s, is not)",
                          best->estimate, unit, best->model.Describe(space.hasParticles, space.hasVolumes).c_str()));
    } else if (best) {
        add(std::snprintf(text, sizeof text, "; the best reached is at least %.3g %s (%s, %s)", best->estimate, unit,
                          best->model.Describe(space.hasParticles, space.hasVolumes).c_str(), best->note.c_str()));
    } else if (choice.evaluatedCount == 0) {
        add(std::snprintf(text, sizeof text, "; no candidate was estimated"));
    } else {
        add(std::snprintf(text, sizeof text, "; every candidate estimated was unstable"));
    }
    if (choice.unreliableCount > 0) {
        add(std::snprintf(text, sizeof text,
                          "; %d candidates were unreliable: their error did not shrink with the step at the order "
                          "their estimate assumes",
                          choice.unreliableCount));
    }
    // What the host allows: a budget can be out of its reach rather than the scene's.
    if (space.steps.size() <= 1) {
        add(std::snprintf(text, sizeof text, "; this host's step is fixed at %g s", space.base.step));
    } else {
        const double finest = *std::min_element(space.steps.begin(), space.steps.end());
        bool tried = false;
        for (const CandidateEstimate& e : choice.candidates) tried = tried || (e.evaluated && e.model.step <= finest);
        if (tried) add(std::snprintf(text, sizeof text, "; the finest step this host allows, %g s, was tried", finest));
    }
    if (choice.stoppedAtLimit) {
        add(std::snprintf(text, sizeof text,
                          "; choosing stopped at its CPU limit of %.3g s (%.3g s spent), so finer candidates were not "
                          "tried",
                          choice.cpuLimit, choice.calibrationCpuSeconds));
    } else if (choice.evaluatedShare >= settings.maxEvaluations) {
        add(std::snprintf(text, sizeof text,
                          "; the evaluation limit of %d candidates' spans was reached, so finer candidates were not "
                          "tried",
                          settings.maxEvaluations));
    }
    add(std::snprintf(text, sizeof text, " (%d candidates estimated; --explain-model lists them)",
                      choice.evaluatedCount));
    return out;
}

/// Sets the host's `key` to `id` before any probe is made, where the host has that key (a demo without it keeps its
/// own model); false, with `error`, when the host refuses the value.
bool UseModel(ParameterSet* params, const char* key, const char* id, std::string* error) {
    return params->Find(key) == nullptr || params->Get(key) == id || params->Set(key, id, error);
}

}  // namespace

bool AutoModel::Choose(ParameterSet* params, const PhysicsSystem& world, double step, double runSeconds,
                       const AutoModelRequest& r, std::string* error, const ChoiceSettings& tuning) {
    request = r;
    const ErrorBudget budget = r.Budget();
    if (!ValidateBudget(budget, error)) return false;
    hostStep = step;
    // Step doubling needs a model that converges as its step shrinks: the book's particle contact does not (a resting
    // particle hops by a step-independent amount), so an auto run uses the reflect contact, which converges to the
    // rigid answer at second order with no offset, before any probe is made (docs/model-choice.md "Particle contact").
    if (!UseModel(params, "particle-contact", ToString(kAutoParticleContact), error)) return false;
    // Likewise the book's distance joint is first order whatever the integrator (its projection's error does not
    // shrink at the integrator's order), so a world with joints runs them as tension (docs/ch16.md).
    if (!world.Joints().empty() && !UseModel(params, "joint-model", ToString(JointModel::Tension), error)) return false;
    // A world of one moving volume moves it by each (sub)step's mean velocity, exact for constant acceleration (free
    // fall, a steady slide; docs/ch15.md "A position update exact for constant acceleration"). Only there: its
    // candidates are compared over whole runs, which include every contact, while a world of several volumes is
    // calibrated on spans that may end before the first contact, and an exact free flight then reads as no error.
    if (MovingVolumes(world) == 1 && !UseModel(params, "volume-positions", ToString(VolumePositions::Average), error))
        return false;
    space = SpaceOf(*params, world, hostStep);
    settings = tuning;
    settings.runSeconds = runSeconds;
    choice = ChooseModel(ProbesOf(world), space, budget, settings);
    if (!choice.feasible) {
        *error = RefusalText(choice, space, budget, settings);
        return false;
    }
    const CandidateEstimate& chosen = choice.candidates[choice.chosen];
    if (!ApplyModel(params, chosen.model, error)) return false;
    watch = std::make_unique<ModelWatch>(space, budget, settings, chosen);
    active = true;
    return true;
}

void AutoModel::AfterFrame(ParameterSet* params, const PhysicsSystem& world, double time) {
    if (!active) return;
    watch->Observe(time, world);
    if (watch->WantsSnapshot(time)) watch->TakeSnapshot(time, ProbesNow(world));
    if (!watch->Due(time)) return;
    std::string line;
    const bool changed = watch->Check(time, ProbesOf(world), &line);
    if (changed) {
        std::string error;
        if (!ApplyModel(params, watch->Current(), &error)) line += " (not applied: " + error + ")";
    }
    if (!line.empty()) log.push_back(line);
}

const ModelCandidate& AutoModel::Current() const {
    if (watch) return watch->Current();
    return space.base;
}

double AutoModel::RunningEstimate() const { return watch ? watch->RunningEstimate() : 0.0; }

bool AutoModel::MissedBudget(double* estimate, double* time) const {
    if (!active || !watch || !watch->Missed()) return false;
    *estimate = watch->RunningEstimate();
    *time = watch->MissedAt();
    return true;
}

double AutoModel::OverheadCpuSeconds() const {
    return choice.calibrationCpuSeconds + (watch ? watch->CpuSeconds() : 0.0);
}

std::string AutoModel::Explain() const {
    const ErrorBudget budget = request.Budget();
    std::ostringstream out;
    char line[512];
    std::snprintf(line, sizeof line,
                  "auto model: %s error budget %g %s, safety factor %g; calibration span %g s of a %g s run; %d "
                  "of %zu candidates estimated (%.3g candidates' worth of spans; limit %d) in %.3g s CPU\n",
                  ToString(budget.quantity), budget.bound, BudgetUnit(budget.quantity), settings.safety,
                  choice.spanSeconds, settings.runSeconds, choice.evaluatedCount, choice.candidates.size(),
                  choice.evaluatedShare, settings.maxEvaluations, choice.calibrationCpuSeconds);
    out << line;
    std::snprintf(line, sizeof line, "  %-6s %-44s %-12s %-12s %-12s %s\n", "chosen", "candidate", "estimate",
                  "work/sim-s", "cpu-s/sim-s", "note");
    out << line;
    std::vector<std::size_t> order(choice.candidates.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    // Ties keep enumeration order (the index breaks them; std::sort, as libstdc++'s stable_sort buffer trips ASan's
    // alloc-dealloc check).
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        const double wa = choice.candidates[a].predictedWork, wb = choice.candidates[b].predictedWork;
        return wa < wb || (wa == wb && a < b);
    });
    for (std::size_t i : order) {
        const CandidateEstimate& c = choice.candidates[i];
        char estimate[32] = "-", cpu[32] = "-";
        if (c.evaluated) {
            std::snprintf(estimate, sizeof estimate, "%.3g", c.estimate);
            std::snprintf(cpu, sizeof cpu, "%.3g", c.cpuPerSimSecond);
        }
        std::string note = c.note;
        if (c.evaluated && c.meets) {
            note = "meets the budget";
            if (c.finerDifference >= 0.0) {
                char ratio[160];
                std::snprintf(ratio, sizeof ratio, "; shrinks with its step (%.3g, then %.3g at half the step)",
                              c.pairDifference, c.finerDifference);
                note += ratio;
            }
        }
        if (c.evaluated && !c.meets && c.stable && note.empty()) note = "misses the budget";
        std::snprintf(line, sizeof line, "  %-6s %-44s %-12s %-12.4g %-12s %s\n",
                      static_cast<int>(i) == choice.chosen ? "*" : "",
                      c.model.Describe(space.hasParticles, space.hasVolumes).c_str(), estimate, c.predictedWork, cpu,
                      note.c_str());
        out << line;
    }
    return out.str();
}

std::string AutoModel::Summary() const {
    if (!active) return "";
    const ErrorBudget budget = request.Budget();
    const CandidateEstimate& chosen = choice.candidates[choice.chosen];
    char text[512];
    std::snprintf(text, sizeof text,
                  "Model: auto, %s; estimated %s error %.3g %s (budget %g, safety %g); %.3g s CPU per simulated s; "
                  "auto overhead %.3g s CPU (calibration %.3g s, %d candidates; %d checks, %d switches)",
                  Current().Describe(space.hasParticles, space.hasVolumes).c_str(), ToString(budget.quantity),
                  RunningEstimate(), BudgetUnit(budget.quantity), budget.bound, settings.safety, chosen.cpuPerSimSecond,
                  OverheadCpuSeconds(), choice.calibrationCpuSeconds, choice.evaluatedCount,
                  watch ? watch->Checks() : 0, watch ? watch->Switches() : 0);
    return text;
}

std::string AutoModel::PanelText() const {
    if (!active) return "";
    const ErrorBudget budget = request.Budget();
    const double runWork = watch->CurrentWork() * settings.runSeconds;
    const double overhead = runWork > 0.0 ? (choice.calibrationWork + watch->Work()) / runWork : 0.0;
    char text[512];
    std::snprintf(text, sizeof text,
                  "Model: auto, %s\nEstimated %s error %.3g %s (budget %g)\nCost %.4g work units per simulated s\n"
                  "Auto overhead %.0f%% of the run's work (%d candidates, %d checks, %d switches)",
                  Current().Describe(space.hasParticles, space.hasVolumes).c_str(), ToString(budget.quantity),
                  RunningEstimate(), BudgetUnit(budget.quantity), budget.bound, watch->CurrentWork(), 100.0 * overhead,
                  choice.evaluatedCount, watch->Checks(), watch->Switches());
    return text;
}
