// Chapter 16 stages of PhysicsSystem: spring and cloth forces, distance joints ("soft" is the contact solver).
#include "Physics/Cloth.h"
#include "Physics/DistanceJoint.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/Spring.h"

void PhysicsSystem::AccumulateSpringForces() {
    // Book order (docs/book-reference.md §3.4 step 6): system springs, then each cloth's structural, shear, bend
    // springs. The force is evaluated at the current (possibly intermediate) particle state; erratum 5.2-20.
    for (Spring& spring : springs) spring.ApplyForce(0.0f);
    for (Cloth* cloth : cloths) {
        for (Spring& spring : cloth->structural) spring.ApplyForce(0.0f);
        for (Spring& spring : cloth->shear) spring.ApplyForce(0.0f);
        for (Spring& spring : cloth->bend) spring.ApplyForce(0.0f);
    }
}

void PhysicsSystem::SolveJoints() {
    // Joints were added after their particles, so they run after the free particles' own constraint pass.
    for (DistanceJoint* joint : joints) joint->SolveConstraints(constraints);
}
