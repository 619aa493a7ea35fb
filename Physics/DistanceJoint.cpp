#include "DistanceJoint.h"

namespace {
// Below this separation (m) the pair has no axis to correct along (erratum 5.2-6).
constexpr float kMinAxisLength = 1e-6f;
}  // namespace

void DistanceJoint::Initialize(Particle* _p1, Particle* _p2, float len) {
    p1 = _p1;
    p2 = _p2;
    length = len;
}

void DistanceJoint::SolveConstraints(const std::vector<OBB>& constraints) {
    if (p1 == nullptr || p2 == nullptr) return;
    const vec3 delta = p2->GetPosition() - p1->GetPosition();
    const float distance = Magnitude(delta);
    // erratum 5.2-6: the book divides by the distance unguarded; coincident particles gave NaN positions.
    if (distance > kMinAxisLength) {
        // Book.md 3.8: move both ends half of the error each along the pair axis. SetPosition also resets
        // oldPosition, so the following constraint pass sees a zero-length travelled segment.
        const float correction = (distance - length) / distance;
        p1->SetPosition(p1->GetPosition() + delta * (0.5f * correction));
        p2->SetPosition(p2->GetPosition() - delta * (0.5f * correction));
    }
    p1->SolveConstraints(constraints);
    p2->SolveConstraints(constraints);
}
