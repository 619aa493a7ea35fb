#include "PhysicsSystem.h"

#include <cmath>

#include "Cloth.h"
#include "DistanceJoint.h"
#include "Particle.h"
#include "RigidbodyVolume.h"
#include "Spring.h"

PhysicsSystem::PhysicsSystem() = default;
PhysicsSystem::~PhysicsSystem() = default;

void PhysicsSystem::Update(float deltaTime) {
    if (!(deltaTime > 0.0f) || !std::isfinite(deltaTime)) return;
    const bool hasVolumes = !volumes.empty();

    // Book order (book.md 3.4): collisions, forces, impulses, integrate, linear projection, constraints.
    // Spring forces are evaluated inside particle integration (erratum 5.2-20: a force over the step, not
    // a dt-free impulse after it), so every integrator sees them at its own intermediate states.
    if (hasVolumes) {
        FindCollisions();
        ApplyVolumeForces(deltaTime);
        if (resultCount > 0) ApplyImpulses();
        IntegrateVolumes(deltaTime);
        if (DoLinearProjection && resultCount > 0) ApplyLinearProjection();
    } else {
        resultCount = 0;
    }
    for (Rigidbody* body : others) body->ApplyForces();
    for (Rigidbody* body : others) body->Update(deltaTime);
    if (!allParticles.empty()) IntegrateParticles(deltaTime);
    if (!constraints.empty() || !joints.empty()) SolveParticleConstraints();
    for (Rigidbody* body : others) body->SolveConstraints(constraints);
    ++stepCount;
}

void PhysicsSystem::AddRigidbody(Rigidbody* body) {
    if (body == nullptr) return;
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
