#pragma once
// Hooke spring with damping between two particles (docs/book-reference.md §3.6). The book's sign convention stays:
// k runs from -5 to 0 and a negative k attracts. Damping acts along the spring axis (erratum 5.2-20).
//
// Units: here k is a force constant (N/m, |k| is the physical stiffness) and b a damping coefficient
// (N s/m); the force is added to the particles' `forces` and integrated over the step. The book applied
// its k and b as velocity changes per 0.03 s step; FromBookSpringConstant converts its numbers
// (docs/ERRATA.md, Chapter 16).

class Particle;

/// The book's fixed step (erratum 5.2-16): its spring constants are velocity changes per step of this length.
constexpr float kBookSpringStep = 0.03f;
/// A book k or b (velocity change per 0.03 s step per unit stretch/speed) as a force constant that gives the
/// same change per step at the book's step: value / 0.03. Independent of the step actually used.
inline float FromBookSpringConstant(float bookValue) { return bookValue / kBookSpringStep; }

class Spring {
public:
    Particle* p1 = nullptr;
    Particle* p2 = nullptr;
    float k = -1.0f;  ///< stiffness in N/m, book convention (negative attracts)
    float restingLength = 1.0f;
    float b = 0.0f;  ///< damping along the axis in N s/m; b >= 0 dissipates

    Spring(float k, float b, float len);
    void SetParticles(Particle* _p1, Particle* _p2);
    Particle* GetP1() const { return p1; }
    Particle* GetP2() const { return p2; }
    void SetConstants(float _k, float _b);
    /// Adds the spring force to both particles' `forces` (N), to be integrated over the step; dt is unused
    /// (kept for the book's signature). Coincident particles get no force (no axis; erratum 5.2-6).
    void ApplyForce(float dt);
    /// Elastic energy 0.5*|k|*(length - rest)^2 in J; 0 without both particles.
    float PotentialEnergy() const;
};
