#include "Demos/Scenes/FileScene.h"

#include <cmath>
#include <cstdio>
#include <iterator>

#include "Demos/Scenes/ContactSolverParameters.h"
#include "Demos/Scenes/SoftSceneCommon.h"
#include "Demos/Scenes/WorldBuilder.h"

namespace {

constexpr float kDegreesToRadians = 0.0174532925f;

BodySpec SpecOf(const SceneBody& body) {
    BodySpec spec;
    spec.shape = body.kind == SceneBodyKind::Sphere ? RigidbodyType::Sphere : RigidbodyType::Box;
    spec.position = body.position;
    spec.halfExtents = body.halfExtents;
    spec.radius = body.radius;
    if (!body.hasQuaternion) spec.eulerRadians = body.eulerDegrees * kDegreesToRadians;
    spec.velocity = body.velocity;
    spec.angularVelocity = body.angularVelocity;
    spec.mass = body.mass;
    spec.friction = body.friction;
    spec.restitution = body.restitution;
    spec.velocityRetention = body.velocityRetention;
    spec.velocityEpsilon = body.velocityEpsilon;
    return spec;
}

}  // namespace

FileScene::FileScene(const SceneDescription& d) : description(d) {
    for (std::size_t i = 0; i < std::size(kAllIntegrators); ++i) {
        if (kAllIntegrators[i] == d.world.integrator) integratorChoice = static_cast<int>(i);
    }
    contact.solver = ContactSolverIndex(d.world.contactSolver);
    contact.soft = d.world.soft;
    contact.sleep = d.world.sleep.enabled;
    Reset();
}

void FileScene::AddParameters(ParameterSet* set) {
    using Widget = ParameterSet::Widget;
    SceneWorld& w = description.world;
    auto apply = [this] {
        description.world.integrator = kAllIntegrators[integratorChoice];
        description.world.contactSolver = ContactSolverAt(contact.solver);
        description.world.soft = contact.soft;
        description.world.sleep.enabled = contact.sleep;
        ApplyWorldSettings();
    };
    std::vector<std::string> integrators;
    for (Integrator i : kAllIntegrators) integrators.emplace_back(ToString(i));
    set->AddChoice("integrator", &integratorChoice, integrators, "how particles are integrated", apply);
    contactChoice = ParticleContactIndex(w.particleContact);
    AddParticleContactParameter(set, &contactChoice, [this] {
        description.world.particleContact = ParticleContactAt(contactChoice);
        ApplyWorldSettings();
    });
    jointChoice = w.jointModel == JointModel::Tension ? 1 : 0;
    AddJointModelParameter(set, &jointChoice, [this] {
        description.world.jointModel = JointModelAt(jointChoice);
        ApplyWorldSettings();
    });
    positionsChoice = w.volumePositions == VolumePositions::Average ? 1 : 0;
    AddVolumePositionsParameter(set, &positionsChoice, [this] {
        description.world.volumePositions = VolumePositionsAt(positionsChoice);
        ApplyWorldSettings();
    });
    AddContactSolverParameters(
        set, &contact, "contact solver: the book's per-contact impulses, accumulated impulses or the soft step", apply);
    set->AddInt("iterations", &w.iterations, 1, SceneLimits::kMaxIterations, "contact solver passes per step", apply);
    set->AddFloat("slop", &w.penetrationSlop, 0.0f, 1.0f, "penetration left uncorrected (m)", apply);
    set->AddBool("linear-projection", &w.linearProjection, "positional correction after integration", apply);
    set->AddFloat("projection-fraction", &w.projectionFraction, 0.0f, 1.0f,
                  "fraction of the penetration beyond the slop removed per step", apply);
    set->AddFloat("dt", &w.step, 0.0f, 1.0f, "physics step (s); 0 = the host's (--dt)").Step();
    set->AddPanelText([this] { return ModelSummary(); });
    set->AddAction(
           "reset", [this] { Reset(); }, "rebuild the scene from the file")
        .OnPanel(Widget::Button("Reset"));
}

std::string FileScene::ModelSummary() const {
    const SceneWorld& w = description.world;
    char passes[64];
    if (w.contactSolver == ContactSolver::Soft) {  // its passes are its own (world.soft), not world.iterations
        std::snprintf(passes, sizeof passes, "%d substeps, %g Hz", w.soft.substeps,
                      static_cast<double>(w.soft.contactHertz));
    } else {
        std::snprintf(passes, sizeof passes, "%d iterations", w.iterations);
    }
    std::string row =
        std::string("Model: ") + ToString(w.integrator) + ", " + ToString(w.contactSolver) + " solver, " + passes;
    if (w.step > 0.0f) {
        char step[32];
        std::snprintf(step, sizeof step, ", dt %g s", static_cast<double>(w.step));
        row += step;
    }
    return row;
}

void FileScene::ApplyWorldSettings() {
    const SceneWorld& w = description.world;
    WorldSettings& s = system->settings;
    s.integrator = w.integrator;
    s.particleContact = w.particleContact;
    s.jointModel = w.jointModel;
    s.contactSolver = w.contactSolver;
    s.volumePositions = w.volumePositions;
    s.solverIterations = w.iterations;
    s.penetrationSlop = w.penetrationSlop;
    s.linearProjection = w.linearProjection;
    s.projectionFraction = w.projectionFraction;
    s.maxVolumeSubsteps = w.maxSubsteps;
    s.accumulated.warmStartFactor = w.warmStartFactor;
    s.accumulated.baumgarte = w.baumgarte;
    s.accumulated.restitutionThreshold = w.restitutionThreshold;
    s.soft = w.soft;
    s.sleep = w.sleep;
}

void FileScene::Reset() {
    system = std::make_unique<PhysicsSystem>();
    ApplyWorldSettings();
    const vec3 gravity = description.world.gravity;

    std::size_t particleCount = 0;
    for (const SceneBody& body : description.bodies) particleCount += body.kind == SceneBodyKind::Particle ? 1 : 0;
    particles.assign(particleCount, Particle());
    volumes.clear();
    volumes.reserve(description.bodies.size() - particleCount);
    bodyIndex.clear();
    for (const SceneBody& body : description.bodies) {
        if (body.kind == SceneBodyKind::Particle) {
            const std::size_t i = bodyIndex.size() - volumes.size();
            Particle& p = particles[i];
            p.SetPosition(body.position);
            p.SetVelocity(body.velocity);
            p.SetMass(body.mass);
            p.SetBounce(body.restitution);
            p.SetVelocityRetention(body.velocityRetention);
            p.SetGravity(gravity);
            bodyIndex.push_back({body.kind, i});
        } else {
            bodyIndex.push_back({body.kind, volumes.size()});
            volumes.push_back(MakeBody(SpecOf(body)));
            RigidbodyVolume& v = volumes.back();
            v.gravity = gravity;
            if (body.hasQuaternion) {
                v.orientation = body.orientation;
                v.SynchCollisionVolumes();
            }
        }
    }
    // Added in file order, after every list has its final size (the system keeps pointers).
    for (const FileSceneBody& b : bodyIndex) {
        if (b.kind == SceneBodyKind::Particle) {
            system->AddRigidbody(&particles[b.index]);
        } else {
            system->AddRigidbody(&volumes[b.index]);
        }
    }
    for (const SceneConstraint& c : description.constraints) {
        const vec3& e = c.eulerDegrees;
        system->AddConstraint(OBB(c.position, c.halfExtents, Rotation3x3(e.x, e.y, e.z)));
    }
    for (const SceneSpring& s : description.springs) {
        // Spring's k follows the book's sign (negative pulls towards the rest length).
        Spring spring(-s.stiffness, s.damping, s.restLength);
        spring.SetParticles(&particles[bodyIndex[s.a].index], &particles[bodyIndex[s.b].index]);
        system->AddSpring(spring);
    }
    joints.assign(description.joints.size(), DistanceJoint());
    for (std::size_t i = 0; i < joints.size(); ++i) {
        const SceneJoint& j = description.joints[i];
        joints[i].Initialize(&particles[bodyIndex[j.a].index], &particles[bodyIndex[j.b].index], j.length);
        system->AddRigidbody(&joints[i]);
    }
    cloths.clear();
    for (const SceneCloth& c : description.cloths) {
        auto cloth = std::make_unique<Cloth>();
        cloth->Initialize(c.gridSize, c.spacing, c.position);
        cloth->SetStructuralSprings(-c.structuralStiffness, c.structuralDamping);
        cloth->SetBendSprings(-c.bendStiffness, c.bendDamping);  // the book's order: structural, bend, shear
        cloth->SetShearSprings(-c.shearStiffness, c.shearDamping);
        cloth->SetParticleMass(c.particleMass);
        cloth->SetParticleVelocityRetention(c.velocityRetention);
        for (Particle& p : cloth->verts) p.SetGravity(gravity);
        system->AddCloth(cloth.get());
        cloths.push_back(std::move(cloth));
    }
    monitor.Start(*system);
}

bool FileScene::Step(float dt) {
    if (!monitor.Stable() || !(dt > 0.0f) || !std::isfinite(dt)) return false;
    system->Update(dt);
    return system->StopReason().empty() && monitor.Check(*system);
}
