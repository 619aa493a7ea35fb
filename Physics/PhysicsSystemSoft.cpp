// STUB (issue 6 replaces this file): spring, cloth and joint stages of PhysicsSystem.
#include "Cloth.h"
#include "DistanceJoint.h"
#include "PhysicsSystem.h"
#include "Spring.h"

void PhysicsSystem::AccumulateSpringForces() {}
void PhysicsSystem::SolveJoints() {}
