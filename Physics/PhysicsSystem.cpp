#include "Physics/PhysicsSystem.h"

#include <cmath>
#include <cstdio>

#include "Physics/Cloth.h"
#include "Physics/DistanceJoint.h"
#include "Physics/ImpulseSolvers.h"
#include "Physics/JobPool.h"
#include "Physics/Particle.h"
#include "Physics/RigidbodyVolume.h"
#include "Physics/SoftStepSolver.h"
#include "Physics/Spring.h"

namespace {

/// The one place a solver setting becomes a solver object.
std::unique_ptr<IContactSolver> MakeContactSolver(ContactSolver kind) {
    switch (kind) {
        case ContactSolver::Accumulated:
            return std::make_unique<AccumulatedImpulseSolver>();
        case ContactSolver::Soft:
            return std::make_unique<SoftStepSolver>();
        case ContactSolver::Book:
            break;
    }
    return std::make_unique<BookImpulseSolver>();
}

}  // namespace

PhysicsSystem::PhysicsSystem() : solver(MakeContactSolver(settings.contactSolver)) {}
PhysicsSystem::~PhysicsSystem() = default;

void PhysicsSystem::MatchSolverToSettings() {
    // Settings are a public struct that scenes write between steps: the world compares once per step and makes a new
    // object only when the setting changed. The old one's kept contacts go with it, as they would have gone cold
    // anyway (each solver warm-starts only from the step or substep just before its own last one).
    if (solver->Kind() != settings.contactSolver) solver = MakeContactSolver(settings.contactSolver);
}

const AccumulatedContactSolver& PhysicsSystem::AccumulatedSolver() const {
    static const AccumulatedContactSolver empty;
    const auto* accumulated = dynamic_cast<const AccumulatedImpulseSolver*>(solver.get());
    return accumulated != nullptr ? accumulated->State() : empty;
}

const SoftContactSolver& PhysicsSystem::SoftSolver() const {
    static const SoftContactSolver empty;
    const auto* soft = dynamic_cast<const SoftStepSolver*>(solver.get());
    return soft != nullptr ? soft->State() : empty;
}

void PhysicsSystem::Update(float deltaTime) {
    if (!(deltaTime > 0.0f) || !std::isfinite(deltaTime) || !stages.stopReason.empty()) return;
    MatchSolverToSettings();
    StepContext ctx{settings};
    // The process keeps one pool per thread count (JobPool::Shared): worlds asking for the same count share it.
    ctx.jobs = &JobPool::Shared(settings.threads);
    ctx.dt = deltaTime;
    ctx.invDt = 1.0f / deltaTime;
    ctx.step = stepCount;
    stages.collisionsPending = false;  // set again by a solver that fills Collisions() on demand

    // Book order (docs/book-reference.md §3.4): collisions, forces, impulses, integrate, linear projection,
    // constraints. Spring forces are evaluated inside particle integration (erratum 5.2-20: a force over the step, not
    // a dt-free impulse after it), so every integrator sees them at its own intermediate states.
    // The volumes: the world's contact solver steps them with the shared stages (IContactSolver.h).
    if (!volumes.empty()) {
        solver->StepVolumes(stages, ctx);
        if (!stages.stopReason.empty()) return;  // over settings.maxPairs: the world stays as it is
    } else {
        stages.SkipStep();
    }
    for (Rigidbody* body : others) body->ApplyForces();
    for (Rigidbody* body : others) body->Update(deltaTime);
    if (!allParticles.empty()) IntegrateParticles(ctx);
    if (!constraints.empty() || !joints.empty()) SolveParticleConstraints(deltaTime);
    for (Rigidbody* body : others) body->SolveConstraints(constraints);
    ++stepCount;
}

namespace {

/// Particle check for AddRigidbody: finite position and velocity, finite mass >= 0 (0 = immovable).
bool ValidateParticle(const Particle& p, std::string* error) {
    char text[160];
    const vec3 x = p.GetPosition(), v = p.GetVelocity();
    const float mass = p.GetMass();
    if (!IsFinite(x)) {
        std::snprintf(text, sizeof text, "position = (%g, %g, %g): must be finite", static_cast<double>(x.x),
                      static_cast<double>(x.y), static_cast<double>(x.z));
    } else if (!IsFinite(v)) {
        std::snprintf(text, sizeof text, "velocity = (%g, %g, %g): must be finite", static_cast<double>(v.x),
                      static_cast<double>(v.y), static_cast<double>(v.z));
    } else if (!std::isfinite(mass) || mass < 0.0f) {
        std::snprintf(text, sizeof text, "mass = %g: must be finite and >= 0 (0 = immovable)",
                      static_cast<double>(mass));
    } else {
        return true;
    }
    *error = text;
    return false;
}

}  // namespace

bool PhysicsSystem::AddRigidbody(Rigidbody* body) {
    // Validate at the boundary (docs/STYLE.md): a degenerate body is refused with a message
    // naming the value instead of being simulated into NaN or through the ground.
    if (body == nullptr) {
        lastError = "AddRigidbody: refused a null body";
        return false;
    }
    std::string why;
    bool valid = true;
    const char* kind = "body";
    if (body->type == RigidbodyType::Particle) {
        kind = "particle";
        valid = ValidateParticle(*static_cast<const Particle*>(body), &why);
    } else if (body->HasVolume()) {
        kind = body->type == RigidbodyType::Sphere ? "sphere" : "box";
        valid = ValidateVolume(*static_cast<const RigidbodyVolume*>(body), &why);
    }
    if (!valid) {
        lastError = "AddRigidbody: refused ";
        lastError += kind;
        lastError += " (would have been body ";
        lastError += std::to_string(bodies.size());
        lastError += "): ";
        lastError += why;
        return false;
    }
    bodies.push_back(body);
    switch (body->type) {
        case RigidbodyType::Particle:
            particles.push_back(static_cast<Particle*>(body));
            // Free particles come first in allParticles: appending keeps that order while there is no cloth,
            // and keeps adding N particles O(N) instead of O(N^2).
            if (cloths.empty()) {
                allParticles.push_back(particles.back());
            } else {
                RebuildParticleList();
            }
            break;
        case RigidbodyType::Sphere:
        case RigidbodyType::Box:
            volumes.push_back(static_cast<RigidbodyVolume*>(body));
            break;
        case RigidbodyType::Base:
            if (auto* joint = dynamic_cast<DistanceJoint*>(body)) {
                joints.push_back(joint);
            } else {
                others.push_back(body);
            }
            break;
    }
    return true;
}

void PhysicsSystem::AddCloth(Cloth* cloth) {
    if (cloth == nullptr) return;
    cloths.push_back(cloth);
    RebuildParticleList();
}

void PhysicsSystem::AddSpring(const Spring& spring) { springs.push_back(spring); }
void PhysicsSystem::AddConstraint(const OBB& constraint) { constraints.push_back(constraint); }

void PhysicsSystem::ClearRigidbodys() {
    bodies.clear();
    particles.clear();
    volumes.clear();
    joints.clear();
    tensionPlan = TensionPlan();
    tensionPlanFor = static_cast<std::size_t>(-1);
    others.clear();
    stages.Reset();  // a new world may run again
    solver->Clear();
    RebuildParticleList();
}
void PhysicsSystem::ClearConstraints() { constraints.clear(); }
void PhysicsSystem::ClearSprings() { springs.clear(); }
void PhysicsSystem::ClearCloths() {
    cloths.clear();
    RebuildParticleList();
}

void PhysicsSystem::RebuildParticleList() {
    allParticles.clear();
    allParticles.insert(allParticles.end(), particles.begin(), particles.end());
    for (Cloth* cloth : cloths)
        for (Particle& p : cloth->verts) allParticles.push_back(&p);
}
