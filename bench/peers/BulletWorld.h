#pragma once
// A scene definition (Demos/Scenes/WorldBuilder.h, BodySpec) built in Bullet, the peer engine of psb-peer-bench
// (docs/peers.md): a btDiscreteDynamicsWorld with the default collision configuration, dispatcher, dynamic-AABB-
// tree broadphase and sequential-impulse solver, split impulse on, every body kept awake (or Bullet's default
// deactivation), no damping. Bullet
// types stay in the .cpp.

#include <cstddef>
#include <memory>
#include <vector>

#include "Demos/Scenes/WorldBuilder.h"
#include "Math/quaternion.h"
#include "Math/vectors.h"

/// One body's pose and velocities, world frame, in this engine's types (either engine fills it).
struct BodyState {
    vec3 position;         ///< m
    quat orientation;      ///< body -> world
    vec3 velocity;         ///< m/s
    vec3 angularVelocity;  ///< rad/s
};

class BulletWorld {
public:
    /// One Bullet body per spec, in order: a box or sphere shape, the spec's pose and velocities, mass (0 =
    /// static), friction sqrt(mu) and restitution sqrt(e) (Bullet multiplies the two bodies' values, so a pair
    /// gets sqrt(muA muB) as this engine does; for restitution that equals min(eA, eB) only when eA = eB),
    /// damping 0, deactivation disabled unless `sleeping` (then Bullet's default deactivation: its own
    /// thresholds and time). The solver runs `iterations` passes with split impulse; gravity is this engine's
    /// (0, -9.82, 0).
    BulletWorld(const std::vector<BodySpec>& specs, int iterations, bool sleeping = false);
    ~BulletWorld();
    BulletWorld(const BulletWorld&) = delete;
    BulletWorld& operator=(const BulletWorld&) = delete;

    /// Exactly one internal Bullet step of dt seconds (stepSimulation(dt, 0): no substeps, no interpolation).
    void Step(float dt);
    std::size_t BodyCount() const;
    /// Dynamic bodies Bullet counts as active (not deactivated) after the last step.
    std::size_t AwakeCount() const;
    /// Body i's state after the last step (its world transform, not a motion-state interpolation).
    BodyState State(std::size_t i) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl;
};
