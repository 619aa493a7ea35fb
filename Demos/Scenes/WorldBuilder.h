#pragma once
// One builder for rigid-volume worlds, shared by the tests, the benchmarks and the sweep. A scene is defined as a
// plain list of BodySpec (shape, pose, size, mass, surface), so the same definition can be built in this engine
// (MakeBody, RigidWorld) or in another one; the benchmark scenes (BoxpileScene, PyramidScene, TowerScene,
// BounceScene) are defined here once. GL-free.

#include <vector>

#include "Physics/PhysicsSystem.h"
#include "Physics/RigidbodyVolume.h"

/// One rigid body of a scene definition. Defaults are RigidbodyVolume's (the book's): a unit-half-extent box of
/// 1 kg, friction 0.6, restitution 0.5, velocity retention 0.98 per 0.03 s.
struct BodySpec {
    RigidbodyType shape = RigidbodyType::Box;  ///< Box or Sphere
    vec3 position;                             ///< centre, world, m
    vec3 halfExtents{1.0f, 1.0f, 1.0f};        ///< box half extents along its local axes, m (boxes only)
    float radius = 1.0f;                       ///< m (spheres only)
    /// Orientation as the book's Euler angles (x pitch, y yaw, z roll), rad; all zero = identity.
    vec3 eulerRadians;
    vec3 velocity;             ///< initial linear velocity, world, m/s
    vec3 angularVelocity;      ///< initial angular velocity, world, rad/s
    float mass = 1.0f;         ///< kg; 0 = static
    float friction = 0.6f;     ///< Coulomb coefficient; pairs combine as sqrt(muA * muB)
    float restitution = 0.5f;  ///< coefficient of restitution (RigidbodyVolume::cor); pairs use the smaller
    /// Fraction of velocity kept per 0.03 s (RigidbodyVolume::velocityRetention, the book's damping); 1 = undamped.
    float velocityRetention = 0.98f;
    /// This engine's velocity threshold (RigidbodyVolume::velocityEpsilon), m/s and rad/s; 0 = none.
    float velocityEpsilon = 0.001f;
};

/// A box spec at `position` with half extents `halfExtents` (m) and `mass` (kg, 0 = static); other fields default.
BodySpec BoxSpec(const vec3& position, const vec3& halfExtents = vec3(1.0f, 1.0f, 1.0f), float mass = 1.0f);
/// A sphere spec at `position` with `radius` (m) and `mass` (kg, 0 = static); other fields default.
BodySpec SphereSpec(const vec3& position, float radius = 1.0f, float mass = 1.0f);
/// A static box with half extents `halfExtents` whose top face is the plane y = topY, centred on x = z = 0.
BodySpec GroundSpec(const vec3& halfExtents, float topY = 0.0f);

/// `spec` with no damping: velocity retention 1 and no velocity threshold (problems with exact answers).
BodySpec UndampedSpec(BodySpec spec);

/// A static, undamped slab (12 x 1 x 4 m, centred on the origin) tilted by `theta` (rad) about z, with friction `mu`
/// and restitution 0; its top face's normal and down-slope direction in world space (unit). The incline of the sweep
/// and of the contact problems.
struct TiltedSlab {
    BodySpec spec;
    vec3 normal;    ///< the top face's outward normal (its centre is at normal * 0.5 m)
    vec3 downhill;  ///< along the face, pointing down the slope
};
TiltedSlab MakeTiltedSlab(double theta, double mu);

/// A body built from `spec`, collision volumes synced. The spec is not validated (PhysicsSystem::AddRigidbody
/// refuses a degenerate body with a message).
RigidbodyVolume MakeBody(const BodySpec& spec);
/// One body per spec, in order (for callers that keep their own list; RigidWorld also adds them to a system).
std::vector<RigidbodyVolume> MakeBodies(const std::vector<BodySpec>& specs);
/// A box body at `position` with half extents `halfExtents` and `mass` (0 = static), volumes synced.
RigidbodyVolume MakeBox(const vec3& position, const vec3& halfExtents = vec3(1.0f, 1.0f, 1.0f), float mass = 1.0f);
/// A sphere body at `position` with `radius` and `mass` (0 = static), volumes synced.
RigidbodyVolume MakeSphere(const vec3& position, float radius = 1.0f, float mass = 1.0f);
/// A static box with half extents `halfExtents` whose top face is y = topY.
RigidbodyVolume MakeGround(const vec3& halfExtents, float topY = 0.0f);

// ---- Stacks. Each copies `cube` (shape, size, mass, surface; position and orientation are replaced), centred on
// x = z = 0 above the plane y = 0; h is cube.halfExtents. Tower and Pyramid rest face on face from y = 0 up.

/// `height` cubes in one column: cube k (0 = bottom) at (0, h.y + 2 h.y k, 0).
std::vector<BodySpec> Tower(int height, const BodySpec& cube);
/// A 2-D pyramid in the x-y plane with `base` cubes in the bottom row: row r holds base - r cubes, cube k of it at
/// x = (k - (base - r - 1) / 2) (2 h.x + gap), y = h.y + 2 h.y r, z = 0; rows bottom to top, k left to right.
std::vector<BodySpec> Pyramid(int base, const BodySpec& cube, float gap);
/// `count` cubes dropped in columns of 10 on a square grid of side s = ceil(sqrt(ceil(count / 10))) columns, 2.5 m
/// apart: cube i is in column c = i / 10 at (x, z) = ((c mod s - (s - 1) / 2) 2.5, (c / s - (s - 1) / 2) 2.5),
/// level k = i mod 10 at y = 1.5 + 2.2 k (fixed numbers: 0.5 m and 0.2 m gaps for cubes of half extent 1).
std::vector<BodySpec> Boxpile(int count, const BodySpec& cube);
/// The determinism scene: `count` unit-half-extent cubes of 1 kg dropped in a leaning, tilted column, cube i at
/// (0.1 i, 1 + 2.2 i, 0.05 i) with Euler angles (0.1 i, 0.2, 0.05) rad, so they fall onto each other and tumble.
std::vector<BodySpec> TiltedColumn(int count);
/// `ground` first (index 0), then `bodies` in order: the layout every scene below uses.
std::vector<BodySpec> WithGround(const BodySpec& ground, const std::vector<BodySpec>& bodies);

// ---- The rigid benchmark's scenes (psb-rigid-bench, docs/ch15.md): default cubes (half extent 1, 1 kg, friction
// 0.6, restitution 0.5) on a static ground slab whose top is y = 0, ground at index 0.

/// Boxpile(count) of default cubes on a ground of half width 1.25 s + 5 (s columns per side, see Boxpile).
std::vector<BodySpec> BoxpileScene(int count);
/// Pyramid(base) of default cubes with 0.01 m gaps on a ground of half width base + 5.
std::vector<BodySpec> PyramidScene(int base);
/// Tower(height) of default cubes on a ground of half width 10.
std::vector<BodySpec> TowerScene(int height);
/// A default sphere (radius 1, 1 kg) whose bottom is 10 m above a ground of half width 10, restitution e and
/// velocity retention `retention` per 0.03 s; the ground's restitution is 1, so the pair uses e.
std::vector<BodySpec> BounceScene(float e, float retention);

// ---- The peer benchmark's scenes (psb-peer-bench, docs/peers.md): one definition that this engine and the
// peer engine both build from. Cubes of half extent 0.5 m, 1 kg, friction 0.6, restitution 0 and no damping
// (velocityRetention 1, velocityEpsilon 0) on a static ground box of half extents (50, 0.5, 50) centred at
// (0, -0.5, 0) (top at y = 0), ground at index 0.

/// The peer scenes' cube: half extent 0.5 m, 1 kg, friction 0.6, restitution 0, undamped; at the origin.
BodySpec PeerCube();
/// The peer scenes' ground: a static box of half extents (50, 0.5, 50) centred at (0, -0.5, 0), friction 0.6,
/// restitution 0.
BodySpec PeerGround();
/// `count` PeerCubes in layers on a g x g grid, g = ceil(sqrt(count / 10)): cube i has c = i mod g^2,
/// l = floor(i / g^2), cx = c mod g, cz = floor(c / g), centre x = (cx - (g - 1) / 2) 1.5 + 0.1 sin(1.7 i),
/// z = (cz - (g - 1) / 2) 1.5 + 0.1 cos(2.3 i), y = 1 + 1.5 l, rotated 0.2 sin(0.9 i) rad about +Y (right-handed:
/// its local x axis at (cos a, 0, -sin a)). The ground first.
std::vector<BodySpec> PeerBoxpile(int count);
/// A 2-D pyramid of PeerCubes with `base` in the bottom row: row r holds base - r cubes, cube k of it at
/// x = (k - (base - r - 1) / 2) 1.05, y = 0.5 + r, z = 0 (0.05 m gaps). The ground first.
std::vector<BodySpec> PeerPyramid(int base);
/// `height` PeerCubes in one column, cube i at (0, 0.5 + i, 0). The ground first.
std::vector<BodySpec> PeerTower(int height);

/// Bodies built from a scene definition and the PhysicsSystem they are added to. The bodies are built once, in
/// spec order, and never move in memory (the system holds pointers to them); the system keeps its defaults, so
/// set solver settings on `system` before stepping.
class RigidWorld {
public:
    /// Builds one body per spec and adds each to the system (a degenerate body is refused there: see
    /// system.LastError()).
    explicit RigidWorld(const std::vector<BodySpec>& specs);
    RigidWorld(const RigidWorld&) = delete;
    RigidWorld& operator=(const RigidWorld&) = delete;

    /// The bodies in spec order; the list is fixed, a body's fields may be changed through Body(i).
    const std::vector<RigidbodyVolume>& Bodies() const { return bodies; }
    RigidbodyVolume& Body(std::size_t i) { return bodies[i]; }
    const RigidbodyVolume& Body(std::size_t i) const { return bodies[i]; }
    /// Each body's position when built, world, m.
    const std::vector<vec3>& StartPositions() const { return start; }
    /// Largest distance of any dynamic body (mass > 0) from its start, m; 0 if there is none.
    float MaxDisplacement() const;
    /// Linear plus rotational kinetic energy of the dynamic bodies, J.
    float KineticEnergy() const;

private:
    std::vector<RigidbodyVolume> bodies;  // declared before `system`, which holds pointers to them
    std::vector<vec3> start;

public:
    PhysicsSystem system;
};
