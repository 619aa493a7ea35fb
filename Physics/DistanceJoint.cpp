#include "Physics/DistanceJoint.h"

#include "Physics/EnumIds.h"

namespace {
constexpr EnumId<JointModel> kJointModelIds[] = {{JointModel::Book, "book"}, {JointModel::Tension, "tension"}};
// Below this separation (m) the pair has no axis to correct along (erratum 5.2-6).
constexpr float kMinAxisLength = 1e-6f;
}  // namespace

const char* ToString(JointModel model) { return IdOf(kJointModelIds, model); }

bool ParseJointModel(const std::string& text, JointModel* out) { return ParseId(kJointModelIds, text, out); }

std::string JointModelIds() { return JoinIds(kJointModelIds); }

void DistanceJoint::Initialize(Particle* _p1, Particle* _p2, float len) {
    p1 = _p1;
    p2 = _p2;
    length = len;
}

void DistanceJoint::SolveConstraints(const std::vector<OBB>& constraints) {
    if (p1 == nullptr || p2 == nullptr) return;
    const float w1 = p1->InvMass(), w2 = p2->InvMass();
    const float w = w1 + w2;
    if (w <= 0.0f) return;  // two immovable ends: nothing can move
    const vec3 delta = p2->GetPosition() - p1->GetPosition();
    const float distance = Magnitude(delta);
    // erratum 5.2-6: the book divides by the distance unguarded; coincident particles gave NaN positions.
    if (distance > kMinAxisLength) {
        // Position projection (PBD distance constraint, Mueller et al. 2007): dx_i = -+ w_i / (w1 + w2) * error * n.
        // The book (docs/book-reference.md §3.8) uses 1/2 for both ends whatever the masses; for equal masses w1 / w =
        // 1/2 exactly, so this is the book's correction bit for bit. SetPosition also resets oldPosition, so the
        // following constraint pass sees a zero-length travelled segment (as the book).
        const float correction = (distance - length) / distance;
        const float share1 = w1 / w, share2 = w2 / w;
        p1->SetPosition(p1->GetPosition() + delta * (share1 * correction));
        p2->SetPosition(p2->GetPosition() - delta * (share2 * correction));
        // Velocity along the joint: the book keeps it, so a bob keeps the radial speed gravity adds each step and
        // falls while its position is projected. Remove the relative velocity along the axis with the same weights
        // (the impulse of a rigid rod); tangential velocity and momentum are kept and kinetic energy can only drop.
        const vec3 axis = delta * (1.0f / distance);
        const vec3 v1 = p1->GetVelocity(), v2 = p2->GetVelocity();
        const float closing = Dot(v2 - v1, axis);
        p1->SetVelocity(v1 + axis * (share1 * closing));
        p2->SetVelocity(v2 - axis * (share2 * closing));
    }
    p1->SolveConstraints(constraints);
    p2->SolveConstraints(constraints);
}
