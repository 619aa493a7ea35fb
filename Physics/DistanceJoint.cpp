// STUB (issue 6 replaces this file).
#include "DistanceJoint.h"

void DistanceJoint::Initialize(Particle* _p1, Particle* _p2, float len) { p1 = _p1; p2 = _p2; length = len; }
void DistanceJoint::SolveConstraints(const std::vector<OBB>&) {}
