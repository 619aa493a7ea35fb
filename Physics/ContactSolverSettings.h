#pragma once
// The contact solver setting of a world (WorldSettings::contactSolver) and each solver's own settings. Plain data: the
// scene format, the parameter table and WorldSettings read it without knowing the solvers. The solvers themselves
// are behind IContactSolver.h (Book and Accumulated: ImpulseSolvers.h; Soft: SoftSolver.h).
//
//   Book         the book's per-contact impulses (ApplyImpulse: j / contact count, each contact solved on its own,
//                nothing kept between steps; erratum 5.2-15). The default: every book demo behaves as printed.
//   Accumulated  sequential impulses with an arbiter (the "proper arbiter system" the book's README lists as
//                future work, docs/book-reference.md §6): each colliding pair keeps its contacts across steps; per
//                contact a normal and two tangent impulses are accumulated over the solverIterations passes and the
//                running totals are clamped (normal >= 0, friction inside the Coulomb cone mu*jn), not the
//                increments; impulses are warm-started from the previous step's matched contacts. Stacks stand.
//   Soft         a soft step (SoftSolver.h): contacts found once per step with feature ids and a speculative
//                margin, then per substep: integrate velocities, warm start, biased soft solve, integrate
//                positions, relax without bias; restitution once at the end of the step.
// docs/soft-solver.md has the design notes and the measured figures.

#include <string>

enum class ContactSolver {
    Book,         ///< per-contact impulses divided by the contact count, no memory (the book's solver)
    Accumulated,  ///< sequential impulses, accumulated and clamped, warm-started from persistent contacts
    Soft,         ///< substepped soft-constraint solver (soft step), feature-id contacts, relax pass
};

/// Stable id used on the command line and in CSV files: "book", "accumulated", "soft".
const char* ToString(ContactSolver solver);
/// Parses an id from ToString; false (output untouched) for anything else.
bool ParseContactSolver(const std::string& text, ContactSolver* out);
/// Comma-separated list of every valid id, for error messages.
std::string ContactSolverIds();
/// Every solver, in enum order.
constexpr ContactSolver kAllContactSolvers[] = {ContactSolver::Book, ContactSolver::Accumulated, ContactSolver::Soft};

/// Settings of ContactSolver::Soft (WorldSettings::soft). Its friction and restitution combine as the book's do.
struct SoftSolverSettings {
    /// Substeps per step, count (each: integrate velocities, warm start, solve, integrate positions, relax). 6 and
    /// 90 Hz at damping ratio 1, not Box2D's 4, 30 Hz and 10: a tower of 20 cubes and a 100 kg cube on a 1 kg one
    /// need contacts that stiff, and the cap below needs 6 substeps for them (docs/soft-solver.md, "What is measured",
    /// why the defaults).
    int substeps = 6;
    /// Biased solve passes per substep, count (Box2D's soft step: 1).
    int iterations = 1;
    /// Relax passes (no bias) per substep, count (Box2D's soft step: 1).
    int relaxIterations = 1;
    /// Hz: stiffness of the contact constraint; capped at a quarter of the substep rate.
    float contactHertz = 90.0f;
    /// Damping ratio of the contact spring, dimensionless (1 critical; larger is stiffer to push-out overshoot).
    float contactDampingRatio = 1.0f;
    /// m/s: the fastest a penetrating contact is pushed apart by the position bias.
    float maxPushoutSpeed = 3.0f;
    /// m: contacts are created while the surfaces are within this distance (speculative contacts).
    float speculativeMargin = 0.02f;
    /// m: penetration allowed before the bias pushes. 0 (the default): a soft contact needs no slop to rest
    /// without jitter, it settles at about g / (2 pi contactHertz)^2 per unit of load over effective mass (0.03 mm
    /// for one box at 90 Hz), and a slop would add its own depth at every contact of a stack.
    float linearSlop = 0.0f;
    /// m/s: restitution only for a closing speed above this.
    float restitutionThreshold = 1.0f;
    /// Fraction (0..1) of last step's matched impulse applied as the warm start.
    float warmStartFactor = 1.0f;
    /// m: a box pair whose relative pose has moved no point of the second box more than this since its manifold was
    /// made reuses that manifold, re-expressed at the present poses, instead of colliding again (docs/soft-solver.md,
    /// "Manifold reuse"); 0 collides every pair every step.
    float manifoldReuseDistance = 0.001f;
    /// Shock propagation (docs/soft-solver.md, "Mass ratios") in every solver block whose moving bodies' masses differ
    /// by at least this factor (largest / smallest); 0 turns it off. Gauss-Seidel passes converge at a rate of heavy /
    /// (heavy + light) per pass through a light body under a heavy one, so below this ratio the passes hold the load
    /// and the shock pass is not run (nor paid for).
    float shockMassRatio = 10.0f;
};

/// Settings of the Accumulated solver (WorldSettings::accumulated). Iterations and slop are WorldSettings'
/// solverIterations and penetrationSlop; linear projection still runs after integration when
/// WorldSettings::linearProjection is on.
struct AccumulatedSolverSettings {
    /// Fraction (0..1) of last step's matched impulse applied before the first pass (0 = no warm start).
    float warmStartFactor = 1.0f;
    /// Baumgarte factor (dimensionless, per step): a contact deeper than the slop gets a target separating speed
    /// of baumgarte * (depth - slop) / dt. 0 leaves position error to linear projection alone.
    float baumgarte = 0.0f;
    /// Restitution is applied only when the closing speed exceeds this (m/s); slower contacts are inelastic, so
    /// resting bodies do not bounce on gravity's g*dt.
    float restitutionThreshold = 1.0f;
    /// A new contact inherits the impulse of last step's nearest contact of the same pair within this distance
    /// (m, world space); a contact without one starts from zero.
    float matchDistance = 0.05f;
};
