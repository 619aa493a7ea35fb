// The budget, the candidates and the quantities a budget bounds (docs/model-choice.md, "The budget" and "The
// candidates").
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "Physics/Cloth.h"
#include "Physics/DistanceJoint.h"
#include "Physics/ModelChoice/ModelChoice.h"
#include "Physics/Particle.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/RigidbodyVolume.h"
#include "Physics/StabilityMonitor.h"

namespace {

/// Contact passes per step of a candidate (the solver's work multiplier).
double PassWork(const ModelCandidate& c) {
    if (c.solver == ContactSolver::Soft) return 3.0 + 1.0 * c.softSubsteps;
    return 4.0 + c.iterations;
}

}  // namespace

const char* ToString(BudgetQuantity quantity) {
    switch (quantity) {
        case BudgetQuantity::Position:
            return "position";
        case BudgetQuantity::Energy:
            return "energy";
        case BudgetQuantity::Constraint:
            return "constraint";
    }
    return "?";
}

bool ParseBudgetQuantity(const std::string& text, BudgetQuantity* out) {
    for (BudgetQuantity q : {BudgetQuantity::Position, BudgetQuantity::Energy, BudgetQuantity::Constraint}) {
        if (text == ToString(q)) {
            *out = q;
            return true;
        }
    }
    return false;
}

const char* BudgetUnit(BudgetQuantity quantity) { return quantity == BudgetQuantity::Energy ? "(relative)" : "m"; }

bool ValidateBudget(const ErrorBudget& budget, std::string* error) {
    if (std::isfinite(budget.bound) && budget.bound > 0.0) return true;
    char text[160];
    std::snprintf(text, sizeof text, "error budget %g %s (%s): must be finite and > 0", budget.bound,
                  BudgetUnit(budget.quantity), ToString(budget.quantity));
    *error = text;
    return false;
}

std::string ModelCandidate::Describe(bool particles, bool volumes) const {
    char text[160];
    std::string out;
    if (particles) out += ToString(integrator);
    if (volumes) {
        if (!out.empty()) out += ", ";
        if (solver == ContactSolver::Soft) {
            std::snprintf(text, sizeof text, "soft solver %d substeps", softSubsteps);
        } else {
            std::snprintf(text, sizeof text, "%s solver %d iterations", ToString(solver), iterations);
        }
        out += text;
    }
    std::snprintf(text, sizeof text, "%sdt %g s", out.empty() ? "" : ", ", step);
    return out + text;
}

std::vector<ModelCandidate> EnumerateCandidates(const CandidateSpace& space) {
    const ModelCandidate& base = space.base;
    std::vector<Integrator> integrators = space.integrators;
    if (!space.hasParticles || integrators.empty()) integrators = {base.integrator};
    std::vector<double> steps = space.steps;
    if (steps.empty()) steps = {base.step};
    std::vector<ContactSolver> solvers = space.solvers;
    if (!space.hasVolumes || solvers.empty()) solvers = {base.solver};

    std::vector<ModelCandidate> out;
    for (Integrator integrator : integrators) {
        for (ContactSolver solver : solvers) {
            std::vector<int> passes;
            const bool soft = solver == ContactSolver::Soft;
            if (space.hasVolumes) passes = soft ? space.softSubsteps : space.iterations;
            if (passes.empty()) passes = {soft ? base.softSubsteps : base.iterations};
            for (int p : passes) {
                for (double step : steps) {
                    ModelCandidate c = base;
                    c.integrator = integrator;
                    c.solver = solver;
                    c.step = step;
                    (soft ? c.softSubsteps : c.iterations) = p;
                    out.push_back(c);
                }
            }
        }
    }
    return out;
}

ModelCandidate Refine(const ModelCandidate& candidate, const CandidateSpace& space) {
    ModelCandidate r = candidate;
    // The soft step already splits each step into substeps: twice the substeps refines its time resolution at
    // twice the cost. Everything else (particles, the book and accumulated solvers): half the step.
    if (space.hasVolumes && !space.hasParticles && r.solver == ContactSolver::Soft) {
        r.softSubsteps *= 2;
    } else {
        r.step = candidate.step * 0.5;
    }
    return r;
}

double PredictedWork(const ModelCandidate& c, const CandidateSpace& space) {
    const double particleWork =
        (space.particleCount + space.springCount) * ForceEvaluations(c.integrator) + space.particleCount;
    const double volumeWork = space.volumeCount * PassWork(c);
    return (particleWork + volumeWork + 1.0) / c.step;
}

void WorldPositions(const PhysicsSystem& world, std::vector<double>* out) {
    out->clear();
    auto add = [out](const vec3& x) {
        out->push_back(x.x);
        out->push_back(x.y);
        out->push_back(x.z);
    };
    for (const Rigidbody* body : world.Bodies()) {
        if (body->type == RigidbodyType::Particle) {
            add(static_cast<const Particle*>(body)->GetPosition());
        } else if (body->type == RigidbodyType::Box || body->type == RigidbodyType::Sphere) {
            add(static_cast<const RigidbodyVolume*>(body)->position);
        }
    }
    for (const Cloth* cloth : world.Cloths()) {
        for (const Particle& p : cloth->verts) add(p.GetPosition());
    }
}

double WorldEnergy(const PhysicsSystem& world) {
    double energy = StabilityMonitor::MechanicalEnergy(world);
    for (const RigidbodyVolume* v : world.Volumes()) {
        if (!(v->mass > 0.0f)) continue;
        const double m = v->mass;
        const vec3& u = v->velocity;
        energy += 0.5 * m * (double(u.x) * u.x + double(u.y) * u.y + double(u.z) * u.z);
        const vec3 iw = MultiplyVector(v->angVel, v->InertiaTensor());
        energy += 0.5 * (double(iw.x) * v->angVel.x + double(iw.y) * v->angVel.y + double(iw.z) * v->angVel.z);
        const vec3& g = v->gravity;
        energy -= m * (double(g.x) * v->position.x + double(g.y) * v->position.y + double(g.z) * v->position.z);
    }
    return energy;
}

double WorldConstraintError(const PhysicsSystem& world) {
    double worst = 0.0;
    for (const DistanceJoint* j : world.Joints()) {
        if (!j->p1 || !j->p2) continue;
        const vec3 d = j->p2->GetPosition() - j->p1->GetPosition();
        const double length = std::sqrt(double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z);
        worst = std::max(worst, std::fabs(length - j->length));
    }
    return worst;
}
