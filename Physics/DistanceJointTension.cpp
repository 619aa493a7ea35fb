// JointModel::Tension: the distance joint's constraint force inside the particle force evaluation (docs/ch16.md,
// "A joint that keeps the integrator's order").
#include <algorithm>
#include <vector>

#include "Physics/DistanceJoint.h"

namespace {

// Below this separation (m) the pair has no axis to pull along (as DistanceJoint.cpp, erratum 5.2-6).
constexpr float kMinTensionAxis = 1e-6f;

inline float Dot3(const vec3& a, const vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

/// One joint's tension, the one that cancels the second derivative of |d|^2 given the particles' current forces,
/// added to them.
void ApplyTension(const DistanceJoint& joint) {
    Particle* p1 = joint.p1;
    Particle* p2 = joint.p2;
    if (p1 == nullptr || p2 == nullptr) return;
    const float w1 = p1->InvMass(), w2 = p2->InvMass();
    if (!(w1 + w2 > 0.0f)) return;
    const vec3 d = p2->GetPosition() - p1->GetPosition();
    const float dd = Dot3(d, d);
    if (!(dd > kMinTensionAxis * kMinTensionAxis)) return;
    // With d = x2 - x1, u = v2 - v1 and accelerations a_i = F_i w_i: (|d|^2)'' / 2 = |u|^2 + d.(a2 - a1). A force
    // lambda d on p2 and -lambda d on p1 adds lambda (w1 + w2) |d|^2 to it, so lambda = -r / ((w1 + w2) |d|^2).
    // lambda < 0 pulls the ends together (tension); > 0 pushes them apart (a rod in compression).
    const vec3 u = p2->GetVelocity() - p1->GetVelocity();
    const vec3 a1 = p1->GetForces() * w1, a2 = p2->GetForces() * w2;
    const float residual = Dot3(u, u) + Dot3(d, a2 - a1);
    const float lambda = -residual / ((w1 + w2) * dd);
    if (w1 > 0.0f) p1->AddForce(d * -lambda);
    if (w2 > 0.0f) p2->AddForce(d * lambda);
}

}  // namespace

void AddJointTensions(DistanceJoint* const* joints, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) ApplyTension(*joints[i]);
}

bool TensionKeepsOrder(Integrator integrator) {
    return integrator == Integrator::VelocityVerlet || integrator == Integrator::RK4;
}

std::vector<DistanceJoint*> TensionJoints(const std::vector<DistanceJoint*>& joints) {
    std::vector<const Particle*> ends;
    for (const DistanceJoint* j : joints)
        for (const Particle* p : {j->p1, j->p2})
            if (p != nullptr && p->InvMass() > 0.0f) ends.push_back(p);
    std::sort(ends.begin(), ends.end());
    auto shared = [&ends](const Particle* p) {
        if (p == nullptr || !(p->InvMass() > 0.0f)) return false;
        const auto range = std::equal_range(ends.begin(), ends.end(), p);
        return range.second - range.first > 1;
    };
    std::vector<DistanceJoint*> out;
    for (DistanceJoint* j : joints)
        if (!shared(j->p1) && !shared(j->p2)) out.push_back(j);
    return out;
}
