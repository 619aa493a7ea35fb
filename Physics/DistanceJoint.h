#pragma once
// Holds two particles at a rest length (docs/book-reference.md §3.8), then re-solves their constraints. The book moves
// both ends by half of the error and leaves their velocities alone; here the correction is weighted by inverse mass and
// the relative velocity along the joint is removed, as position-based dynamics does (docs/ERRATA.md, Chapter 16,
// "DistanceJoint without mass or velocity").

#include <cstddef>
#include <vector>

#include "Physics/Integrator.h"
#include "Physics/JointModel.h"
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

/// The joints JointModel::Tension pulls, in groups coupled through shared movable particles (PlanTensions).
struct TensionPlan {
    std::vector<DistanceJoint*> joints;  ///< group after group, each group's joints in list order
    std::vector<std::size_t> groupEnds;  ///< one past each group's last joint in `joints`
    std::vector<double> scratch;         ///< the largest group's linear system, grown only
};
/// Most joints in one coupled group (a chain of 64 links); a larger group is left to the book's projection alone.
constexpr std::size_t kMaxTensionGroup = 64;
/// Groups `joints`: two joints holding the same movable (mass > 0) particle are in one group; mass-0 particles (pivots)
/// couple nothing. Groups come in the order of their first joint; groups above kMaxTensionGroup joints are left out.
TensionPlan PlanTensions(const std::vector<DistanceJoint*>& joints);
/// JointModel::Tension: adds every planned joint's tension to its particles' `forces` (N), computed from their current
/// positions, velocities and forces (gravity and springs already in), so that no |p2 - p1|^2 has a second derivative
/// (docs/ch16.md, "A joint that keeps the integrator's order"). One joint alone: lambda = -(|u|^2 + d.(a2 - a1)) /
/// ((w1 + w2) |d|^2), lambda d on p2 and -lambda d on p1. A coupled group (a chain) solves its joints' tensions
/// together (Cholesky, in double). Mass-0 ends get no force. A group with a joint without particles, with coincident
/// ends or with dependent joints gets no tension in that evaluation.
void AddJointTensions(TensionPlan* plan);
/// Whether JointModel::Tension pulls under `integrator`: velocity Verlet and RK4, whose order it keeps. The first-order
/// integrators keep the book's joint: with the tension, each explicit step adds (v^2 / L)^2 dt^2 to the squared
/// speed, so a fast pendulum gains energy until it blows up (150 degrees, 0.01 s: within 60 s), and position Verlet's
/// history is restarted by the projection every step anyway (docs/ch16.md).
bool TensionKeepsOrder(Integrator integrator);
