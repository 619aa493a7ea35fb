#pragma once
// The book's fixed step and the conversion of a per-step factor to another step (WorldSettings.h uses them for its
// defaults; particles and volumes for their velocity retention).

#include <cmath>

/// The book's fixed step, s (GetFixedFPS()/1000, docs/book-reference.md §1.2). The per-step factors the book
/// defines (a particle's velocity retention 0.95) are defined at this step.
constexpr float kBookStep = 0.03f;

/// Per-step factor for a step of dt seconds from a factor defined per step of referenceStep seconds: the same
/// per-second rate, factor^(dt / referenceStep). Exactly `factor` when dt == referenceStep (the book's path
/// stays bit-identical) or when referenceStep <= 0 (applied per step at every dt).
inline float FactorOverStep(float factor, float referenceStep, float dt) {
    if (!(referenceStep > 0.0f) || dt == referenceStep) return factor;
    return std::pow(factor, dt / referenceStep);
}
