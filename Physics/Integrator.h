#pragma once
// Particle integrators, chosen at run time per PhysicsSystem (not by #define as in the book).
// Every integrator keeps Particle::velocity in m/s at the particle's position and applies the particle's velocity
// retention (the book's per-step "friction"), converted to the step in use, as a factor f on the carried velocity,
// so that f = 1 gives the pure method; docs/ch14.md has the table and the details.

#include <cstddef>
#include <string>

#include "Math/vectors.h"

class Particle;

enum class Integrator {
    ExplicitEuler,      ///< x += v dt; v += a dt. 1st order, gains energy, 1 force evaluation per step.
    SemiImplicitEuler,  ///< v += a dt; x += v dt. The book's shipped EULER_INTEGRATION. 1st order, symplectic.
    VelocityVerlet,     ///< The book's "accurate Euler". 2nd order, exact under constant force, 2 evaluations.
    PositionVerlet,     ///< The book's Verlet: x' = x + (x - x_old) + a dt^2. 2nd order, symplectic, 1 evaluation.
    RK4,                ///< Classical Runge-Kutta. 4th order, not symplectic, 4 force evaluations per step.
};

/// Stable id used on the command line and in CSV files: "explicit-euler", "euler", "velocity-verlet",
/// "verlet", "rk4".
const char* ToString(Integrator integrator);
/// Parses an id from ToString; false (output untouched) for anything else.
bool ParseIntegrator(const std::string& text, Integrator* out);
/// Comma-separated list of every valid id, for error messages.
std::string IntegratorIds();
/// Every integrator, in enum order (for tables, benchmarks and the demo's choice list).
constexpr Integrator kAllIntegrators[] = {Integrator::ExplicitEuler, Integrator::SemiImplicitEuler,
                                          Integrator::VelocityVerlet, Integrator::PositionVerlet, Integrator::RK4};
/// Force evaluations per step (the dominant cost when springs are present).
int ForceEvaluations(Integrator integrator);

/// Per-particle scratch of the integrators (start-of-step state, previous acceleration, RK4 sums).
/// Owned by the caller and reused from step to step, so a step allocates nothing.
struct IntegratorScratch {
    vec3 x0, v0, a0, sumX, sumV;
};

/// Must set `forces` (N) of every particle being integrated from its current position and velocity.
using ForceEvaluator = void (*)(void* context);

/// Advances particles[0..count) together by dt seconds with `method`; scratch must hold `count` entries.
/// Each particle's velocityRetention is defined per step of retentionStep seconds (WorldSettings::
/// particleRetentionStep) and applied as FactorOverStep(retention, retentionStep, dt): the book's factor itself
/// at its step, the same fraction per second at any other.
/// `evaluate(context)` is called once per force evaluation (1, 2 or 4 times, ForceEvaluations) with every
/// particle set to the stage's state, so coupled position- and velocity-dependent forces (springs) are
/// re-evaluated at intermediate states. Afterwards oldPosition = start-of-step position (the segment the
/// constraint solver tests) and velocity is in m/s. Mass 0 means no acceleration (InvMass 0). dt <= 0 or
/// count 0 does nothing.
void IntegrateParticleStates(Integrator method, Particle* const* particles, std::size_t count,
                             IntegratorScratch* scratch, float dt, float retentionStep, ForceEvaluator evaluate,
                             void* context);
