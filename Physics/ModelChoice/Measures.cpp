// The quantities a budget bounds, measured on a world (docs/model-choice.md, "The budget"): body positions, the
// mechanical energy, the joints' constraint error.
#include <algorithm>
#include <cmath>

#include "Physics/Cloth.h"
#include "Physics/DistanceJoint.h"
#include "Physics/ModelChoice/ModelChoice.h"
#include "Physics/Particle.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/RigidbodyVolume.h"
#include "Physics/StabilityMonitor.h"

void WorldPositions(const PhysicsSystem& world, std::vector<double>* out) {
    out->clear();
    auto add = [out](const vec3& x) {
        out->push_back(x.x);
        out->push_back(x.y);
        out->push_back(x.z);
    };
    for (const Rigidbody* body : world.Bodies()) {
        if (body->type == RigidbodyType::Particle) {
            add(static_cast<const Particle*>(body)->GetPosition());
        } else if (body->type == RigidbodyType::Box || body->type == RigidbodyType::Sphere) {
            add(static_cast<const RigidbodyVolume*>(body)->position);
        }
    }
    for (const Cloth* cloth : world.Cloths()) {
        for (const Particle& p : cloth->verts) add(p.GetPosition());
    }
}

double WorldEnergy(const PhysicsSystem& world) {
    double energy = StabilityMonitor::MechanicalEnergy(world);
    for (const RigidbodyVolume* v : world.Volumes()) {
        if (!(v->mass > 0.0f)) continue;
        const double m = v->mass;
        const vec3& u = v->velocity;
        energy += 0.5 * m * (double(u.x) * u.x + double(u.y) * u.y + double(u.z) * u.z);
        const vec3 iw = MultiplyVector(v->angVel, v->InertiaTensor());
        energy += 0.5 * (double(iw.x) * v->angVel.x + double(iw.y) * v->angVel.y + double(iw.z) * v->angVel.z);
        const vec3& g = v->gravity;
        energy -= m * (double(g.x) * v->position.x + double(g.y) * v->position.y + double(g.z) * v->position.z);
    }
    return energy;
}

double WorldConstraintError(const PhysicsSystem& world) {
    double worst = 0.0;
    for (const DistanceJoint* j : world.Joints()) {
        if (!j->p1 || !j->p2) continue;
        const vec3 d = j->p2->GetPosition() - j->p1->GetPosition();
        const double length = std::sqrt(double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z);
        worst = std::max(worst, std::fabs(length - j->length));
    }
    return worst;
}
