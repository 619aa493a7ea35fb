// STUB (issue 6 replaces this file).
#include "Spring.h"

Spring::Spring(float _k, float _b, float len) : k(_k), restingLength(len), b(_b) {}
void Spring::SetParticles(Particle* _p1, Particle* _p2) { p1 = _p1; p2 = _p2; }
void Spring::SetConstants(float _k, float _b) { k = _k; b = _b; }
void Spring::ApplyForce(float) {}
