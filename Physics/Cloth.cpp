#include "Physics/Cloth.h"

namespace {
// Book defaults (docs/book-reference.md §3.7).
constexpr float kDefaultK = -1.0f;
constexpr float kDefaultB = 0.0f;
constexpr float kParticleMass = 1.0f;
constexpr float kParticleBounce = 0.0f;
constexpr float kParticleRetention = 0.9f;  // velocity kept per book step (the book's particle "friction")

Spring MakeSpring(Particle* a, Particle* b) {
    Spring s(kDefaultK, kDefaultB, Magnitude(b->GetPosition() - a->GetPosition()));
    s.SetParticles(a, b);
    return s;
}

void SetAll(std::vector<Spring>& springs, float k, float b) {
    for (Spring& s : springs) s.SetConstants(k, b);
}
}  // namespace

void Cloth::Initialize(int gridSize, float distance, const vec3& position) {
    // erratum 5.2-21: the book resized verts before clamping the size, so N < 3 wrote out of bounds.
    const int n = gridSize < 3 ? 3 : gridSize;
    clothSize = static_cast<float>(n);
    structural.clear();
    shear.clear();
    bend.clear();
    verts.clear();
    verts.resize(static_cast<size_t>(n) * n);  // never resized again: springs hold pointers into it
    const float halfSize = static_cast<float>(n - 1) * 0.5f;

    for (int z = 0; z < n; ++z) {
        for (int x = 0; x < n; ++x) {
            Particle& p = verts[z * n + x];
            // erratum 5.2-21: the book computed (x + position.x - half)*distance, scaling the offset.
            p.SetPosition(vec3((static_cast<float>(x) - halfSize) * distance + position.x, position.y,
                               (static_cast<float>(z) - halfSize) * distance + position.z));
            p.SetVelocity(vec3());
            p.SetMass(kParticleMass);
            p.SetBounce(kParticleBounce);
            p.SetVelocityRetention(kParticleRetention);
        }
    }
    auto at = [&](int x, int z) { return &verts[z * n + x]; };

    // Rest length of every spring = the pair's initial distance (docs/book-reference.md §3.7), same pair order as the
    // book.
    structural.reserve(2 * n * (n - 1));
    for (int x = 0; x < n; ++x)
        for (int z = 0; z < n - 1; ++z) structural.push_back(MakeSpring(at(x, z), at(x, z + 1)));
    for (int x = 0; x < n - 1; ++x)
        for (int z = 0; z < n; ++z) structural.push_back(MakeSpring(at(x, z), at(x + 1, z)));

    shear.reserve(2 * (n - 1) * (n - 1));
    for (int x = 0; x < n - 1; ++x)
        for (int z = 0; z < n - 1; ++z) shear.push_back(MakeSpring(at(x, z), at(x + 1, z + 1)));
    for (int x = 1; x < n; ++x)
        for (int z = 0; z < n - 1; ++z) shear.push_back(MakeSpring(at(x, z), at(x - 1, z + 1)));

    bend.reserve(2 * n * (n - 2));
    for (int x = 0; x < n; ++x)
        for (int z = 0; z < n - 2; ++z) bend.push_back(MakeSpring(at(x, z), at(x, z + 2)));
    for (int x = 0; x < n - 2; ++x)
        for (int z = 0; z < n; ++z) bend.push_back(MakeSpring(at(x, z), at(x + 2, z)));
}

void Cloth::SetStructuralSprings(float k, float b) { SetAll(structural, k, b); }
void Cloth::SetShearSprings(float k, float b) { SetAll(shear, k, b); }
void Cloth::SetBendSprings(float k, float b) { SetAll(bend, k, b); }

void Cloth::SetParticleMass(float mass) {
    for (Particle& p : verts) p.SetMass(mass);
}

void Cloth::SetParticleVelocityRetention(float retention) {
    for (Particle& p : verts) p.SetVelocityRetention(retention);
}
