#pragma once
// A copy of a world's state that owns its bodies (docs/model-choice.md, "Probes"): the world holds raw pointers to
// bodies it does not own, so a copy needs bodies of its own and a system that points at them. The model choice
// runs its probes on copies like this one, made here in the physics layer, never through a scene description.
//
// Copied: the settings; every particle, volume and distance joint (in the world's insertion order); the
// constraints; the springs and the cloths, their ends re-pointed at the copy's particles. Not copied: solver
// caches (the accumulated solver's warm start, the soft solver's contacts, sleep islands; the copy starts them
// afresh, and wakes every volume), the step count, and bodies of other Rigidbody kinds (none in the sandbox).

#include <memory>
#include <vector>

#include "Physics/Cloth.h"
#include "Physics/DistanceJoint.h"
#include "Physics/Particle.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/RigidbodyVolume.h"

class WorldCopy {
public:
    explicit WorldCopy(const PhysicsSystem& world);
    WorldCopy(const WorldCopy&) = delete;
    WorldCopy& operator=(const WorldCopy&) = delete;

    PhysicsSystem& System() { return *system; }
    const PhysicsSystem& System() const { return *system; }

private:
    std::unique_ptr<PhysicsSystem> system;
    std::vector<Particle> particles;       // never resized after construction: the system and springs point in
    std::vector<RigidbodyVolume> volumes;  // likewise
    std::vector<DistanceJoint> joints;     // likewise
    std::vector<std::unique_ptr<Cloth>> cloths;
};
