#include "Physics/WorldCopy.h"

#include <unordered_map>

namespace {

using ParticleMap = std::unordered_map<const Particle*, Particle*>;

/// `spring` with its ends moved to their copies (an end without one keeps its pointer: none in a valid world).
Spring Repointed(const Spring& spring, const ParticleMap& copies) {
    Spring out = spring;
    auto to = [&copies](Particle* p) {
        auto it = copies.find(p);
        return it == copies.end() ? p : it->second;
    };
    out.SetParticles(to(spring.GetP1()), to(spring.GetP2()));
    return out;
}

}  // namespace

WorldCopy::WorldCopy(const PhysicsSystem& world) : system(std::make_unique<PhysicsSystem>()) {
    system->settings = world.settings;
    particles.reserve(world.Particles().size());
    volumes.reserve(world.Volumes().size());
    joints.reserve(world.Joints().size());
    ParticleMap copies;
    // Cloths first, so the joints and springs below can find their particles' copies.
    for (const Cloth* cloth : world.Cloths()) {
        auto copy = std::make_unique<Cloth>();
        copy->verts = cloth->verts;
        copy->clothSize = cloth->clothSize;
        for (std::size_t i = 0; i < cloth->verts.size(); ++i) copies[&cloth->verts[i]] = &copy->verts[i];
        for (const Spring& s : cloth->structural) copy->structural.push_back(Repointed(s, copies));
        for (const Spring& s : cloth->shear) copy->shear.push_back(Repointed(s, copies));
        for (const Spring& s : cloth->bend) copy->bend.push_back(Repointed(s, copies));
        cloths.push_back(std::move(copy));
    }
    for (const Particle* p : world.Particles()) {
        particles.push_back(*p);
        copies[p] = &particles.back();
    }
    for (const RigidbodyVolume* v : world.Volumes()) {
        volumes.push_back(*v);
        volumes.back().WakeUp();  // the copy's islands start afresh
    }
    for (const DistanceJoint* j : world.Joints()) {
        joints.push_back(*j);
        DistanceJoint& copy = joints.back();
        if (auto it = copies.find(j->p1); it != copies.end()) copy.p1 = it->second;
        if (auto it = copies.find(j->p2); it != copies.end()) copy.p2 = it->second;
    }
    // Added in the world's insertion order.
    std::size_t particle = 0, volume = 0, joint = 0;
    for (const Rigidbody* body : world.Bodies()) {
        if (body->type == RigidbodyType::Particle) {
            system->AddRigidbody(&particles[particle++]);
        } else if (body->type == RigidbodyType::Sphere || body->type == RigidbodyType::Box) {
            system->AddRigidbody(&volumes[volume++]);
        } else if (joint < joints.size() && body == world.Joints()[joint]) {
            system->AddRigidbody(&joints[joint++]);
        }
    }
    for (const OBB& constraint : world.Constraints()) system->AddConstraint(constraint);
    for (const Spring& spring : world.Springs()) system->AddSpring(Repointed(spring, copies));
    for (const std::unique_ptr<Cloth>& cloth : cloths) system->AddCloth(cloth.get());
}
