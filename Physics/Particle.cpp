// STUB (issue 4 replaces this file).
#include "Particle.h"

Particle::Particle() : Rigidbody(RigidbodyType::Particle) {}
void Particle::ApplyForces() { forces = gravity * mass; }
void Particle::Update(float) {}
void Particle::SolveConstraints(const std::vector<OBB>&) {}
void Particle::SetPosition(const vec3& pos) { position = oldPosition = pos; }
void Particle::AddImpulse(const vec3& impulse) { velocity += impulse; }
float Particle::InvMass() const { return mass == 0.0f ? 0.0f : 1.0f / mass; }
