#pragma once
// Particle integrators, chosen at run time per PhysicsSystem (not by #define as in the book).

#include <string>

enum class Integrator {
    ExplicitEuler,      ///< x += v dt; v += a dt. 1st order, gains energy, 1 force evaluation per step.
    SemiImplicitEuler,  ///< v += a dt; x += v dt. The book's shipped EULER_INTEGRATION. 1st order, symplectic.
    VelocityVerlet,     ///< The book's "accurate Euler". 2nd order, exact under constant force.
    PositionVerlet,     ///< The book's Verlet: x' = x + (x - x_old) + a dt^2. 2nd order, symplectic.
    RK4,                ///< Classical Runge-Kutta. 4th order, not symplectic, 4 force evaluations per step.
};

/// Stable id used on the command line and in CSV files: "explicit-euler", "euler", "velocity-verlet",
/// "verlet", "rk4".
const char* ToString(Integrator integrator);
/// Parses an id from ToString; false (output untouched) for anything else.
bool ParseIntegrator(const std::string& text, Integrator* out);
/// Comma-separated list of every valid id, for error messages.
std::string IntegratorIds();
