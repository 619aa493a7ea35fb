#pragma once
// Holds two particles at a rest length by moving both (book.md 3.8), then re-solves their constraints.

#include <vector>

#include "Particle.h"
#include "Rigidbody.h"

class DistanceJoint : public Rigidbody {
public:
    Particle* p1 = nullptr;
    Particle* p2 = nullptr;
    float length = 0.0f;

    DistanceJoint() = default;
    void Initialize(Particle* _p1, Particle* _p2, float len);
    /// Coincident particles leave the pair unchanged instead of dividing by zero (erratum 5.2-6).
    void SolveConstraints(const std::vector<OBB>& constraints) override;
};
