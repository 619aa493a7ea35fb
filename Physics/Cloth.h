#pragma once
// N x N grid of particles joined by structural, shear and bend springs (docs/book-reference.md §3.7).

#include <vector>

#include "Physics/Particle.h"
#include "Physics/Spring.h"

class Cloth {
public:
    std::vector<Particle> verts;  ///< index z*N + x; never resized after Initialize (springs point in)
    std::vector<Spring> structural;
    std::vector<Spring> shear;
    std::vector<Spring> bend;
    float clothSize = 0.0f;

    Cloth() = default;
    Cloth(const Cloth&) = delete;
    Cloth& operator=(const Cloth&) = delete;

    /// gridSize clamped to >= 3 first (erratum 5.2-21); particle (x,z) at
    /// ((x - half)*distance + position.x, position.y, (z - half)*distance + position.z).
    void Initialize(int gridSize, float distance, const vec3& position);
    void SetStructuralSprings(float k, float b);
    void SetShearSprings(float k, float b);
    void SetBendSprings(float k, float b);
    void SetParticleMass(float mass);
    /// Particle::SetVelocityRetention on every particle (the book's SetParticleFriction; book cloth: 0.9).
    void SetParticleVelocityRetention(float retention);
    int GridSize() const { return static_cast<int>(clothSize); }
};
