#pragma once
// The test ground and a bitwise state snapshot shared by the rigid-body test files; bodies and scenes come from
// the one world builder, Demos/Scenes/WorldBuilder.h (MakeBox, MakeSphere, Tower, Pyramid), and a test's world is
// tests/support/TestWorld.h.

#include <vector>

#include "Demos/Scenes/WorldBuilder.h"
#include "Physics/RigidbodyVolume.h"

/// The test ground: a static slab 40 x 1 x 40 m whose top face is y = 0.
inline BodySpec GroundSlabSpec() { return GroundSpec(vec3(20.0f, 0.5f, 20.0f)); }
/// GroundSlabSpec() built.
inline RigidbodyVolume MakeGroundSlab() { return MakeBody(GroundSlabSpec()); }

/// Position, velocity, angular velocity and orientation of every body as raw bytes, for bitwise comparison; any
/// container of RigidbodyVolume.
template <class Bodies>
std::vector<unsigned char> Snapshot(const Bodies& bodies) {
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
