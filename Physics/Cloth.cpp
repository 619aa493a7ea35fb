// STUB (issue 6 replaces this file).
#include "Cloth.h"

void Cloth::Initialize(int, float, const vec3&) {}
void Cloth::SetStructuralSprings(float, float) {}
void Cloth::SetShearSprings(float, float) {}
void Cloth::SetBendSprings(float, float) {}
void Cloth::SetParticleMass(float) {}
void Cloth::SetParticleFriction(float) {}
