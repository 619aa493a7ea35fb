// STUB (issue 5 replaces this file).
#include "RigidbodyVolume.h"

void RigidbodyVolume::ApplyForces() {}
void RigidbodyVolume::Update(float) {}
void RigidbodyVolume::SynchCollisionVolumes() {}
float RigidbodyVolume::InvMass() const { return mass == 0.0f ? 0.0f : 1.0f / mass; }
mat3 RigidbodyVolume::InvTensor() const { return mat3(); }
void RigidbodyVolume::AddLinearImpulse(const vec3& impulse) { velocity += impulse; }
void RigidbodyVolume::AddRotationalImpulse(const vec3&, const vec3&) {}
void RigidbodyVolume::SetEulerOrientation(const vec3&) {}
