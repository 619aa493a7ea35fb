#pragma once
// Rigid-volume builders and a bitwise state snapshot shared by the rigid-body test files.

#include <vector>

#include "Physics/RigidbodyVolume.h"

/// A box body at `position` with half extents `halfSize` and `mass` (0 = static), volumes synced.
inline RigidbodyVolume MakeBox(const vec3& position, const vec3& halfSize = vec3(1, 1, 1), float mass = 1.0f) {
    RigidbodyVolume b(RigidbodyType::Box);
    b.position = position;
    b.box.size = halfSize;
    b.mass = mass;
    b.SynchCollisionVolumes();
    return b;
}

/// A sphere body at `position` with `radius` and `mass` (0 = static), volumes synced.
inline RigidbodyVolume MakeSphere(const vec3& position, float radius = 1.0f, float mass = 1.0f) {
    RigidbodyVolume s(RigidbodyType::Sphere);
    s.position = position;
    s.sphere.radius = radius;
    s.mass = mass;
    s.SynchCollisionVolumes();
    return s;
}

/// A static slab 40 x 1 x 40 m whose top face is y = 0.
inline RigidbodyVolume MakeGroundSlab() { return MakeBox(vec3(0, -0.5f, 0), vec3(20, 0.5f, 20), 0.0f); }

/// Position, velocity, angular velocity and orientation of every body as raw bytes, for bitwise comparison.
inline std::vector<unsigned char> Snapshot(const std::vector<RigidbodyVolume>& bodies) {
    std::vector<unsigned char> out;
    for (const RigidbodyVolume& b : bodies) {
        const float f[13] = {b.position.x,    b.position.y,    b.position.z,   b.velocity.x, b.velocity.y,
                             b.velocity.z,    b.angVel.x,      b.angVel.y,     b.angVel.z,   b.orientation.x,
                             b.orientation.y, b.orientation.z, b.orientation.w};
        const unsigned char* p = reinterpret_cast<const unsigned char*>(f);
        out.insert(out.end(), p, p + sizeof f);
    }
    return out;
}
