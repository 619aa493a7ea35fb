#pragma once
// ContactSolver::Accumulated's state and solve (ContactSolverSettings.h lists the three solvers; ImpulseSolvers.h
// puts this one behind IContactSolver). docs/soft-solver.md has the design notes and the measured figures.

#include <cstddef>
#include <string>
#include <vector>

#include "Math/matrices.h"
#include "Math/vectors.h"
#include "Physics/ContactSolverSettings.h"

class RigidbodyVolume;
struct CollisionPair;
struct StepContext;

/// The Accumulated solver's state: last step's contacts and impulses per colliding pair (the arbiter). Pairs are
/// keyed by the bodies' indices in PhysicsSystem::Volumes() (and the body addresses, compared for equality only,
/// so a changed body list never inherits impulses); contacts are matched by proximity. Storage is reused from step
/// to step (two buffers swapped), so the steady state allocates nothing.
class AccumulatedContactSolver {
public:
    /// Solves the velocities of `volumes` for pairs[0..count), which must be sorted by (indexA, indexB) as
    /// VolumeStages::FindCollisions writes them, over one volume substep of ctx.h seconds (the Baumgarte bias)
    /// with ctx.settings' solverIterations, penetrationSlop and accumulated. Impulses are carried over only from
    /// the substep just before (ctx.substepSerial is one more than at the last Solve), not from an older one.
    void Solve(const std::vector<RigidbodyVolume*>& volumes, const CollisionPair* pairs, std::size_t count,
               const StepContext& ctx);
    /// Forgets every kept contact (the next Solve starts cold).
    void Clear();

    /// Pairs solved in the last Solve.
    std::size_t ArbiterCount() const { return arbiters.size(); }
    /// Contacts solved in the last Solve, and how many of them were warm-started from a matched contact.
    std::size_t ContactCount() const { return contacts.size(); }
    std::size_t WarmStartedCount() const { return warmStarted; }
    /// Accumulated normal impulse (N s) summed over every contact of the last Solve.
    float TotalNormalImpulse() const;

    struct Contact {
        vec3 point;                   // world, at the start of the step (for matching)
        vec3 rA, rB;                  // from the body centres, world
        float massN, massT1, massT2;  // 1 / effective inverse mass along n, t1, t2
        float bias;                   // target separating speed along n (restitution or Baumgarte), m/s
        float jn, jt1, jt2;           // accumulated impulses, N s
    };
    struct Arbiter {
        int indexA, indexB;
        const RigidbodyVolume* a;  // identity check only, never ordered
        const RigidbodyVolume* b;
        vec3 n, t1, t2;            // normal from a to b, tangent basis
        float mu;                  // sqrt(muA * muB)
        std::size_t first, count;  // contacts[first, first + count)
    };

private:
    /// Per-body inverse masses and world inverse inertias of `volumes`; this step's buffers become last step's
    /// (forgotten unless carryOver).
    void BeginPrepare(const std::vector<RigidbodyVolume*>& volumes, bool carryOver);
    /// Warm start of contact c (its point set) from the nearest unclaimed contact of `old` (last step's arbiter of
    /// the same pair) within sqrt(matchSq) m, in arb's basis; false (c untouched) when there is none.
    bool Inherit(const Arbiter& old, const Arbiter& arb, float matchSq, float warmStartFactor, Contact* c);
    void Prepare(const std::vector<RigidbodyVolume*>& volumes, const CollisionPair* pairs, std::size_t count, float dt,
                 float slop, bool carryOver, const AccumulatedSolverSettings& settings);

    std::vector<Arbiter> arbiters, previousArbiters;
    std::vector<Contact> contacts, previousContacts;
    std::vector<float> invMass;                 // per volume index, this step
    std::vector<mat3> invInertia;               // per volume index: world R^T I^-1 R, this step
    std::vector<unsigned char> matchedScratch;  // per previous contact of one pair
    std::size_t warmStarted = 0;
    long long lastSubstep = -2;  // ctx.substepSerial of the last Solve
};
