#include "Physics/Spring.h"

#include <cmath>

#include "Physics/Particle.h"

namespace {
// Below this separation (m) the spring axis is undefined (erratum 5.2-6).
constexpr float kMinAxisLength = 1e-6f;
}  // namespace

Spring::Spring(float _k, float _b, float len) : k(_k), restingLength(len), b(_b) {}

void Spring::SetParticles(Particle* _p1, Particle* _p2) {
    p1 = _p1;
    p2 = _p2;
}

void Spring::SetConstants(float _k, float _b) {
    k = _k;
    b = _b;
}

void Spring::ApplyForce(float /*dt*/) {
    if (p1 == nullptr || p2 == nullptr) return;
    const vec3 relPos = p2->GetPosition() - p1->GetPosition();
    const float length = Magnitude(relPos);
    // erratum 5.2-6: the book normalises relPos unguarded, giving NaN for coincident particles.
    if (!(length > kMinAxisLength)) return;
    const vec3 axis = relPos * (1.0f / length);  // from p1 to p2
    const vec3 relVel = p2->GetVelocity() - p1->GetVelocity();

    // Hooke with the book's sign (docs/book-reference.md §3.6): F = -k*x along the axis pulls p1 toward p2 when k < 0
    // and the spring is stretched. erratum 5.2-20: damping uses the velocity ALONG the axis (separation rate),
    // +b*dot(relVel, axis), so it opposes both approach and separation; the book's -b*|relVel| always
    // repelled. The result is a force (N) integrated over the step, not a dt-free velocity change.
    const float stretch = length - restingLength;
    const float separationRate = Dot(relVel, axis);
    const float magnitude = -k * stretch + b * separationRate;
    const vec3 force = axis * magnitude;
    p1->AddForce(force);
    p2->AddForce(force * -1.0f);
}

float Spring::PotentialEnergy() const {
    if (p1 == nullptr || p2 == nullptr) return 0.0f;
    const float stretch = Magnitude(p2->GetPosition() - p1->GetPosition()) - restingLength;
    return 0.5f * std::fabs(k) * stretch * stretch;
}
