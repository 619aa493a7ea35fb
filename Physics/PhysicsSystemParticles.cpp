// STUB (issue 4 replaces this file): particle stages of PhysicsSystem.
#include "Particle.h"
#include "PhysicsSystem.h"

void PhysicsSystem::IntegrateParticles(float) {}
void PhysicsSystem::AccumulateParticleForces() {}
void PhysicsSystem::SolveParticleConstraints() {}
