#pragma once
// Contact problems with exact answers, for the convergence tests (tests/physics/ContactConvergence_test.cpp) and
// the sweep that plots them (bench/contact_convergence.cpp, docs/soft-solver.md "Convergence of the contact solvers").
// Each runs one problem at one setting (solver, step, soft substeps) and returns its error against the exact rigid
// answer in metres. Bodies are undamped (velocity retention 1, no velocity threshold) so the exact answers hold at
// every step. GL-free.

#include <algorithm>
#include <cmath>
#include <vector>

#include "Demos/Scenes/WorldBuilder.h"
#include "Physics/ContactSolver.h"
#include "Physics/Particle.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/RigidbodyVolume.h"

namespace contact_problems {

constexpr double kG = 9.82;  // the book's gravity, m/s^2
constexpr double kPi = 3.14159265358979323846;

enum class Problem {
    BoxSlideStop,        ///< a box launched at 2 m/s on flat ground, mu 0.5: stops after v0^2 / (2 mu g)
    BoxInclineStick,     ///< a box on a 20 deg incline, mu 0.6 (> tan 20 deg): stays where it is
    BoxInclineSlide,     ///< a box on a 30 deg incline, mu 0.3: slides at g (sin - mu cos)
    SphereInclineRoll,   ///< a sphere on a 20 deg incline, mu 0.6 (> 2/7 tan): rolls at 5/7 g sin
    SphereInclineSlide,  ///< a sphere on a 20 deg incline, mu 0.1 (< 2/7 tan): slides at g (sin - mu cos)
    DropGrid,            ///< side x side separate cubes dropped flat 0.5 m: rest at their drop x, z, y = half extent
    BoxOnBox,            ///< a box resting on a box on the ground, 0.25 s: neither moves
    ParticleBounce,      ///< a particle dropped 1 m onto an OBB, e 0.5: the first three apex heights
};
constexpr Problem kAllProblems[] = {Problem::BoxSlideStop,      Problem::BoxInclineStick,    Problem::BoxInclineSlide,
                                    Problem::SphereInclineRoll, Problem::SphereInclineSlide, Problem::DropGrid,
                                    Problem::BoxOnBox,          Problem::ParticleBounce};

inline const char* Name(Problem p) {
    switch (p) {
        case Problem::BoxSlideStop:
            return "box-slide-stop";
        case Problem::BoxInclineStick:
            return "box-incline-stick";
        case Problem::BoxInclineSlide:
            return "box-incline-slide";
        case Problem::SphereInclineRoll:
            return "sphere-incline-roll";
        case Problem::SphereInclineSlide:
            return "sphere-incline-slide";
        case Problem::DropGrid:
            return "drop-grid";
        case Problem::BoxOnBox:
            return "box-on-box";
        case Problem::ParticleBounce:
            return "particle-bounce";
    }
    return "?";
}

/// One run's setting: the solver, the step (s) and, for the soft solver, its substeps per step (the other two
/// solvers ignore `substeps`: the engine splits their steps only for fast bodies, WorldSettings::maxVolumeSubsteps).
struct Setting {
    ContactSolver solver = ContactSolver::Book;
    double dt = 1e-3;
    int substeps = 6;
    int gridSide = 3;                                    ///< DropGrid: cubes per side
    VolumePositions positions = VolumePositions::Euler;  ///< the volumes' position update (VolumePositions.h)
};

/// An undamped spec (the exact answers have no damping).
inline BodySpec Undamped(BodySpec spec) { return UndampedSpec(spec); }

/// A rigid world at one setting, stepped for `seconds`.
struct World : RigidWorld {
    World(const Setting& s, const std::vector<BodySpec>& specs) : RigidWorld(specs) {
        system.settings.contactSolver = s.solver;
        system.settings.soft.substeps = s.substeps;
        system.settings.volumePositions = s.positions;
    }
    void Run(const Setting& s, double seconds) {
        const long long n = std::llround(seconds / s.dt);
        for (long long i = 0; i < n; ++i) system.Update(float(s.dt));
    }
};

inline double Distance(const vec3& a, double x, double y, double z) {
    const double dx = a.x - x, dy = a.y - y, dz = a.z - z;
    return std::sqrt(dx * dx + dy * dy + dz * dz);
}

/// Static ground slab 40 x 1 x 40 m, top face y = 0, restitution 0.
inline BodySpec Floor(float friction) {
    BodySpec g = Undamped(GroundSpec(vec3(20.0f, 0.5f, 20.0f)));
    g.friction = friction;
    g.restitution = 0.0f;
    return g;
}

inline double BoxSlideStop(const Setting& s) {
    const double h = 0.25, v0 = 2.0, mu = 0.5, T = 1.0;  // stops at 0.41 s
    BodySpec box = Undamped(BoxSpec(vec3(0.0f, float(h), 0.0f), vec3(float(h), float(h), float(h)), 1.0f));
    box.friction = float(mu);
    box.restitution = 0.0f;
    box.velocity = vec3(float(v0), 0.0f, 0.0f);
    World w(s, {Floor(float(mu)), box});
    w.Run(s, T);
    return Distance(w.Body(1).position, v0 * v0 / (2.0 * mu * kG), h, 0.0);
}

/// A body on a static slab tilted by theta about z, touching its top face at the slab's centre; after T seconds
/// 0.5 s later it should be a t^2 / 2 down the slope from there (a = 0: it stays).
inline double Incline(const Setting& s, bool sphere, double thetaDeg, double mu, double a) {
    const double theta = thetaDeg * kPi / 180.0, T = 0.5, r = 0.25;
    const TiltedSlab incline = MakeTiltedSlab(theta, mu);
    const BodySpec& slab = incline.spec;
    const vec3 normal = incline.normal, downhill = incline.downhill;
    const vec3 start = normal * float(0.5 + r);
    BodySpec body = Undamped(sphere ? SphereSpec(start, float(r), 1.0f) : BoxSpec(start, vec3(0.25f, 0.25f, 0.25f)));
    body.friction = float(mu);
    body.restitution = 0.0f;
    if (!sphere) body.eulerRadians = slab.eulerRadians;
    World w(s, {slab, body});
    w.Run(s, T);
    const double d = 0.5 * a * T * T;
    return Distance(w.Body(1).position, start.x + downhill.x * d, start.y + downhill.y * d, start.z + downhill.z * d);
}

inline double DropGrid(const Setting& s) {
    const double h = 0.25, drop = 0.5, spacing = 1.0, T = 1.0;
    const int n = s.gridSide;
    std::vector<BodySpec> specs{Floor(0.6f)};
    for (int i = 0; i < n; ++i)
        for (int k = 0; k < n; ++k) {
            const float x = float((i - 0.5 * (n - 1)) * spacing), z = float((k - 0.5 * (n - 1)) * spacing);
            BodySpec c = Undamped(BoxSpec(vec3(x, float(h + drop), z), vec3(float(h), float(h), float(h))));
            c.restitution = 0.0f;
            specs.push_back(c);
        }
    World w(s, specs);
    w.Run(s, T);
    double worst = 0.0;
    for (std::size_t i = 1; i < specs.size(); ++i) {
        const vec3 p0 = specs[i].position;
        worst = std::max(worst, Distance(w.Body(i).position, p0.x, h, p0.z));
    }
    return worst;
}

inline double BoxOnBox(const Setting& s) {
    BodySpec lower = Undamped(BoxSpec(vec3(0.0f, 0.5f, 0.0f), vec3(0.5f, 0.5f, 0.5f), 1.0f));
    BodySpec upper = Undamped(BoxSpec(vec3(0.0f, 1.25f, 0.0f), vec3(0.25f, 0.25f, 0.25f), 1.0f));
    lower.restitution = upper.restitution = 0.0f;
    World w(s, {Floor(0.6f), lower, upper});
    w.Run(s, 0.25);
    return std::max(Distance(w.Body(1).position, 0.0, 0.5, 0.0), Distance(w.Body(2).position, 0.0, 1.25, 0.0));
}

/// The particle path is the same under every contact solver (particles meet OBBs through Particle's own
/// constraint solve). Exact: the particle is put Particle::kContactOffset c above the face with e times its
/// speed, so h_n = e^2 h_(n-1) + c (the book's placement; docs/ch14.md).
inline double ParticleBounce(const Setting& s) {
    const double e = 0.5, h0 = 1.0, c = Particle::kContactOffset;
    PhysicsSystem world;
    world.settings.contactSolver = s.solver;
    world.AddConstraint(OBB(vec3(0.0f, -1.0f, 0.0f), vec3(10.0f, 1.0f, 10.0f)));  // top face at y = 0
    Particle p;
    p.SetMass(1.0f);
    p.SetVelocityRetention(1.0f);
    p.SetPosition(vec3(0.0f, float(h0), 0.0f));
    p.SetBounce(float(e));
    world.AddRigidbody(&p);
    double exact = h0, worst = 0.0, peak = -1.0;
    bool rising = false;
    int apexes = 0;
    const long long maxSteps = std::llround(5.0 / s.dt);
    for (long long i = 0; i < maxSteps && apexes < 3; ++i) {
        world.Update(float(s.dt));
        const double y = p.GetPosition().y, vy = p.GetVelocity().y;
        if (vy > 0.0) {
            rising = true;
            peak = std::max(peak, y);
        } else if (rising) {
            peak = std::max(peak, y);
            exact = e * e * exact + c;
            worst = std::max(worst, std::fabs(peak - exact));
            ++apexes;
            rising = false;
            peak = -1.0;
        }
    }
    return apexes == 3 ? worst : h0;  // a missing apex counts as the whole drop
}

/// The error (m) of `problem` at `s` against its exact rigid answer.
inline double Error(Problem problem, const Setting& s) {
    const double g20 = kG * std::sin(20.0 * kPi / 180.0);
    switch (problem) {
        case Problem::BoxSlideStop:
            return BoxSlideStop(s);
        case Problem::BoxInclineStick:
            return Incline(s, false, 20.0, 0.6, 0.0);
        case Problem::BoxInclineSlide:
            return Incline(s, false, 30.0, 0.3, kG * (std::sin(kPi / 6.0) - 0.3 * std::cos(kPi / 6.0)));
        case Problem::SphereInclineRoll:
            return Incline(s, true, 20.0, 0.6, 5.0 / 7.0 * g20);
        case Problem::SphereInclineSlide:
            return Incline(s, true, 20.0, 0.1, g20 - 0.1 * kG * std::cos(20.0 * kPi / 180.0));
        case Problem::DropGrid:
            return DropGrid(s);
        case Problem::BoxOnBox:
            return BoxOnBox(s);
        case Problem::ParticleBounce:
            return ParticleBounce(s);
    }
    return 0.0;
}

}  // namespace contact_problems
