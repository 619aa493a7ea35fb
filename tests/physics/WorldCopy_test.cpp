// WorldCopy (Physics/WorldCopy.h): a copy of a world that owns its bodies, the model choice's probes.
#include "Physics/WorldCopy.h"

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "Physics/ModelChoice/ModelChoice.h"
#include "tests/support/TestWorld.h"

namespace {

bool SameBits(const vec3& a, const vec3& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// Every moving thing's position, in a fixed order: free particles, volumes, cloth particles.
std::vector<vec3> Positions(const PhysicsSystem& world) {
    std::vector<vec3> out;
    for (const Particle* p : world.Particles()) out.push_back(p->GetPosition());
    for (const RigidbodyVolume* v : world.Volumes()) out.push_back(v->position);
    for (const Cloth* c : world.Cloths())
        for (const Particle& p : c->verts) out.push_back(p.GetPosition());
    return out;
}

void ExpectSameBits(const std::vector<vec3>& a, const std::vector<vec3>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) EXPECT_TRUE(SameBits(a[i], b[i])) << "body " << i;
}

BodySpec StaticBox(const vec3& position, const vec3& halfExtents) {
    BodySpec spec;
    spec.position = position;
    spec.halfExtents = halfExtents;
    spec.mass = 0.0f;
    return spec;
}

/// One of every kind the copy handles: free particles on a spring and a joint, a cloth, a falling box on a static
/// one, and a tilted constraint the particles hit.
struct MixedWorld {
    Cloth cloth;
    DistanceJoint joint;
    TestWorld world;

    MixedWorld() {
        Particle& a = world.AddParticle();
        a.SetPosition(vec3(0.0f, 3.0f, 0.0f));
        Particle& b = world.AddParticle();
        b.SetPosition(vec3(1.0f, 3.5f, 0.2f));
        b.SetVelocity(vec3(0.5f, 0.0f, 0.0f));
        Particle& c = world.AddParticle();
        c.SetPosition(vec3(-1.0f, 2.5f, 0.0f));
        world.Add(StaticBox(vec3(5.0f, -1.0f, 0.0f), vec3(2.0f, 0.5f, 2.0f)));
        BodySpec falling;
        falling.position = vec3(5.0f, 1.0f, 0.0f);
        falling.eulerRadians = vec3(0.3f, 0.2f, 0.1f);
        world.Add(falling);
        world.Join();
        Spring spring(-40.0f, 0.5f, 1.0f);
        spring.SetParticles(&a, &b);
        world.system.AddSpring(spring);
        joint.Initialize(&a, &c, 1.2f);
        world.system.AddRigidbody(&joint);
        cloth.Initialize(3, 0.5f, vec3(0.0f, 4.0f, 3.0f));
        cloth.SetStructuralSprings(-200.0f, 1.0f);
        cloth.SetShearSprings(-100.0f, 1.0f);
        cloth.SetBendSprings(-50.0f, 1.0f);
        world.system.AddCloth(&cloth);
        world.system.AddConstraint(
            OBB(vec3(0.0f, 0.0f, 0.0f), vec3(3.0f, 0.5f, 3.0f), Rotation3x3(10.0f, 5.0f, 20.0f)));
        world.system.settings.integrator = Integrator::PositionVerlet;  // history in oldPosition and forces
    }
};

}  // namespace

TEST(WorldCopy, ACopyMadeMidRunStepsToTheSameBitsAsTheWorldItCopies) {
    MixedWorld m;
    m.world.Step(0.01f, 30);  // mid-run: the particles carry Verlet history, the box is falling
    WorldCopy copy(m.world.system);
    ExpectSameBits(Positions(copy.System()), Positions(m.world.system));
    for (int i = 0; i < 150; ++i) {
        m.world.system.Update(0.01f);
        copy.System().Update(0.01f);
    }
    ExpectSameBits(Positions(copy.System()), Positions(m.world.system));
}

TEST(WorldCopy, SteppingACopyLeavesTheWorldItCopiedAsItWas) {
    MixedWorld m;
    m.world.Step(0.01f, 10);
    const std::vector<vec3> before = Positions(m.world.system);
    WorldCopy copy(m.world.system);
    for (int i = 0; i < 100; ++i) copy.System().Update(0.01f);
    ExpectSameBits(Positions(m.world.system), before);
    // The copy's springs, joints and cloth springs point at the copy's own particles.
    const PhysicsSystem& c = copy.System();
    auto owned = [&c](const Particle* p) {
        for (const Particle* q : c.Particles())
            if (p == q) return true;
        for (const Cloth* cloth : c.Cloths())
            for (const Particle& q : cloth->verts)
                if (p == &q) return true;
        return false;
    };
    for (const Spring& s : c.Springs()) EXPECT_TRUE(owned(s.GetP1()) && owned(s.GetP2()));
    for (const DistanceJoint* j : c.Joints()) EXPECT_TRUE(owned(j->p1) && owned(j->p2));
    for (const Cloth* cloth : c.Cloths())
        for (const Spring& s : cloth->structural) EXPECT_TRUE(owned(s.GetP1()) && owned(s.GetP2()));
}

TEST(WorldCopy, AProbeRunsTheWorldAsItIsWithTheCandidateModel) {
    MixedWorld m;
    m.world.Step(0.01f, 20);
    ModelCandidate model;
    model.integrator = Integrator::PositionVerlet;
    model.step = 0.01;
    std::unique_ptr<ModelProbe> probe = ProbesOf(m.world.system)();
    probe->Apply(model);
    ASSERT_TRUE(probe->AdvanceTo(0.5));
    for (int i = 0; i < 50; ++i) m.world.system.Update(0.01f);
    ExpectSameBits(Positions(probe->World()), Positions(m.world.system));
    // A snapshot of the probe starts where the probe is.
    std::unique_ptr<ModelProbe> later = probe->Snapshot()();
    later->Apply(model);
    ExpectSameBits(Positions(later->World()), Positions(m.world.system));
}
