#pragma once
// Hooke spring with damping between two particles (book.md 3.6). The book's sign convention stays:
// k runs from -5 to 0 and a negative k attracts. Damping acts along the spring axis (erratum 5.2-20).

class Particle;

class Spring {
public:
    Particle* p1 = nullptr;
    Particle* p2 = nullptr;
    float k = -1.0f;  ///< stiffness, book convention (negative attracts)
    float restingLength = 1.0f;
    float b = 0.0f;  ///< damping along the axis

    Spring(float k, float b, float len);
    void SetParticles(Particle* _p1, Particle* _p2);
    Particle* GetP1() const { return p1; }
    Particle* GetP2() const { return p2; }
    void SetConstants(float _k, float _b);
    /// Adds the spring force to both particles' forces (to be integrated over the step).
    void ApplyForce(float dt);
};
