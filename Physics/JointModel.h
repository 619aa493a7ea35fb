#pragma once
// The distance joint setting (WorldSettings::jointModel); DistanceJoint.cpp implements its ids and
// DistanceJointTension.cpp the tension (docs/ch16.md, "A joint that keeps the integrator's order").

#include <string>

/// How distance joints hold their particles (WorldSettings::jointModel).
enum class JointModel {
    /// The book's: particles move unconstrained for the step, then DistanceJoint projects them back onto the rest
    /// length. Every integrator is then first order on a jointed particle: the tension that bends its path is missing
    /// from the force evaluation, and each projection drops kinetic energy of about v^2 (v dt / L)^2.
    Book,
    /// The joint's tension is part of every force evaluation (every RK4 stage and both velocity-Verlet evaluations),
    /// computed from that stage's positions and velocities, so each integrator keeps its own order; the book's
    /// projection still follows the step and only removes the integrator's own drift.
    Tension,
};
/// "book" or "tension".
const char* ToString(JointModel model);
/// Parses an id from ToString; false (output untouched) for anything else.
bool ParseJointModel(const std::string& text, JointModel* out);
/// Comma-separated list of every valid id, for error messages.
std::string JointModelIds();
