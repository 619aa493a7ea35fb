#pragma once
// Holds two particles at a rest length (docs/book-reference.md §3.8), then re-solves their constraints. The book moves
// both ends by half of the error and leaves their velocities alone; here the correction is weighted by inverse mass and
// the relative velocity along the joint is removed, as position-based dynamics does (docs/ERRATA.md, Chapter 16,
// "DistanceJoint without mass or velocity").

#include <vector>

#include "Physics/Particle.h"
#include "Physics/Rigidbody.h"

class DistanceJoint : public Rigidbody {
public:
    Particle* p1 = nullptr;
    Particle* p2 = nullptr;
    float length = 0.0f;  ///< rest length (m)

    DistanceJoint() = default;
    void Initialize(Particle* _p1, Particle* _p2, float len);
    /// Projects the pair onto the rest length along the axis p1 -> p2 (world space): each end moves by its share
    /// w_i / (w1 + w2) of the error, w = 1/mass (equal masses: half each, as the book). Then removes the relative
    /// velocity along the axis with the same weights (momentum kept, tangential velocity kept, kinetic energy never
    /// gained), and re-solves both particles against `constraints`. A mass-0 end never moves; with both ends of mass
    /// 0 (or without particles) the call does nothing. Coincident particles (no axis, erratum 5.2-6) are not moved
    /// but still re-solve their constraints.
    void SolveConstraints(const std::vector<OBB>& constraints) override;
};
