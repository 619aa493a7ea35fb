// Chapter 14 stages of PhysicsSystem: particle forces, integration (Integrator.cpp) and constraint solving.
// A particle-only step touches each particle a fixed number of times and allocates nothing once the scratch
// arrays have grown to the particle and constraint counts.
#include "Physics/Cloth.h"
#include "Physics/DistanceJoint.h"
#include "Physics/Particle.h"
#include "Physics/PhysicsSystem.h"

void PhysicsSystem::AccumulateParticleForces() {
    // Gravity * mass (erratum 5.1-6), then springs (ch16) add to it, then the joints' tension from those forces
    // (JointModel::Tension; the book's joints act only after the step, in SolveParticleConstraints).
    for (Particle* p : allParticles) {
        const float m = p->mass;
        p->forces = vec3(p->gravity.x * m, p->gravity.y * m, p->gravity.z * m);
    }
    if (!springs.empty() || !cloths.empty()) AccumulateSpringForces();
    if (settings.jointModel == JointModel::Tension && TensionKeepsOrder(settings.integrator) &&
        !tensionPlan.joints.empty())
        AddJointTensions(&tensionPlan);
}

void PhysicsSystem::IntegrateParticles(const StepContext& ctx) {
    if (integratorScratch.size() < allParticles.size()) integratorScratch.resize(allParticles.size());
    // The joints tension pulls (PlanTensions), planned again only when the joint count changes.
    if (ctx.settings.jointModel == JointModel::Tension && tensionPlanFor != joints.size()) {
        tensionPlan = PlanTensions(joints);
        tensionPlanFor = joints.size();
    }
    ForceEvaluator evaluate = [](void* self) { static_cast<PhysicsSystem*>(self)->AccumulateParticleForces(); };
    IntegrateParticleStates(ctx.settings.integrator, allParticles.data(), allParticles.size(), integratorScratch.data(),
                            ctx.dt, ctx.settings.particleRetentionStep, evaluate, this);
}

void PhysicsSystem::SolveParticleConstraints(float dt) {
    if (!constraints.empty()) {
        if (preparedConstraints.size() != constraints.size()) preparedConstraints.resize(constraints.size());
        for (std::size_t i = 0; i < constraints.size(); ++i)
            preparedConstraints[i] = PrepareParticleConstraint(constraints[i], settings.particleContact);
        for (Particle* p : particles) p->SolveConstraints(preparedConstraints.data(), preparedConstraints.size(), dt);
    }
    // Joints move their particles and re-solve them against `constraints` themselves.
    if (!joints.empty()) SolveJoints();
    if (!constraints.empty())
        for (std::size_t i = particles.size(); i < allParticles.size(); ++i)
            allParticles[i]->SolveConstraints(preparedConstraints.data(), preparedConstraints.size(), dt);
}
