// STUB (issue 5 replaces this file): rigid-volume stages of PhysicsSystem.
#include "PhysicsSystem.h"
#include "RigidbodyVolume.h"

void PhysicsSystem::FindCollisions() { resultCount = 0; }
void PhysicsSystem::ApplyVolumeForces() {}
void PhysicsSystem::ApplyImpulses() {}
void PhysicsSystem::IntegrateVolumes(float) {}
void PhysicsSystem::ApplyLinearProjection() {}
