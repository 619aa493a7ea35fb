#include "Physics/PhysicsSystem.h"

#include <cmath>
#include <cstdio>

#include "Physics/Cloth.h"
#include "Physics/DistanceJoint.h"
#include "Physics/JobPool.h"
#include "Physics/Particle.h"
#include "Physics/RigidbodyVolume.h"
#include "Physics/Spring.h"

PhysicsSystem::PhysicsSystem() = default;
PhysicsSystem::~PhysicsSystem() = default;

void PhysicsSystem::Update(float deltaTime) {
    if (!(deltaTime > 0.0f) || !std::isfinite(deltaTime) || !stopReason.empty()) return;
    StepContext ctx{settings};
    // The process keeps one pool per thread count (JobPool::Shared): worlds asking for the same count share it.
    ctx.jobs = &JobPool::Shared(settings.threads);
    ctx.dt = deltaTime;
    ctx.invDt = 1.0f / deltaTime;
    ctx.step = stepCount;
    softCollisionsPending = false;  // set again by a soft step

    // Book order (docs/book-reference.md §3.4): collisions, forces, impulses, integrate, linear projection,
    // constraints. Spring forces are evaluated inside particle integration (erratum 5.2-20: a force over the step, not
    // a dt-free impulse after it), so every integrator sees them at its own intermediate states.
    // Volumes step in n equal substeps when one step would carry a volume through another (VolumeSubsteps);
    // n = 1 is the book's single step, with dt passed through unchanged.
    if (!volumes.empty() && settings.contactSolver == ContactSolver::Soft) {
        StepSoftVolumes(ctx);
        if (!stopReason.empty()) return;
    } else if (!volumes.empty()) {
        const int n = VolumeSubsteps(deltaTime);
        ctx.substepCount = n;
        ctx.h = n == 1 ? deltaTime : deltaTime / static_cast<float>(n);
        ctx.invH = 1.0f / ctx.h;
        lastVolumeSubsteps = n;
        // Islands and sleep (Islands.h): null while settings.sleep is off, and then nothing below changes.
        Islands* sleep = islands.BeginStep(volumes, settings.sleep) ? &islands : nullptr;
        for (int s = 0; s < n; ++s) {
            ctx.substep = s;
            ctx.substepSerial = volumeSubstepSerial;
            FindCollisions(ctx, sleep);
            if (!stopReason.empty()) return;  // over settings.maxPairs: the world stays as it is
            ApplyVolumeForces(ctx, sleep);
            if (resultCount > 0) ApplyImpulses(ctx);
            IntegrateVolumes(ctx, sleep);
            if (settings.linearProjection && resultCount > 0) ApplyLinearProjection(ctx);
            ++volumeSubstepSerial;
        }
        if (sleep != nullptr) islands.Update(volumes, results.data(), resultCount, deltaTime, settings.sleep);
    } else {
        resultCount = 0;
        lastVolumeSubsteps = 1;
        ++volumeSubstepSerial;
    }
    for (Rigidbody* body : others) body->ApplyForces();
    for (Rigidbody* body : others) body->Update(deltaTime);
    if (!allParticles.empty()) IntegrateParticles(ctx);
    if (!constraints.empty() || !joints.empty()) SolveParticleConstraints();
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
    others.clear();
    resultCount = 0;
    softCollisionsPending = false;
    softSolver.Clear();
    stopReason.clear();  // a new world may run again
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
