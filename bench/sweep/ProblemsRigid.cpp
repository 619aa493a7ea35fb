// Rigid-volume reference problems of psb-sweep: sphere bounce, torque-free rotation, box sliding down a rough
// incline, resting towers. Bodies here have damping (the book's per-step velocity factor) 1 and
// velocityEpsilon 0 unless said otherwise: a per-step factor changes the physics with dt, and the 0.001 m/s
// threshold is larger than g dt below dt = 1.02e-4 s, where it would keep a body released from rest from
// ever falling (docs/sweep.md).
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "Demos/Scenes/WorldBuilder.h"
#include "Physics/ContactSolver.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/RigidbodyVolume.h"
#include "bench/sweep/Sweep.h"

namespace sweep {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kG = 9.82;

long long StepsFor(double seconds, double dt) { return std::llround(seconds / dt); }

/// A body spec with the sweep's damping 1 and velocityEpsilon 0 (see the top of this file).
BodySpec Undamped(BodySpec spec) { return UndampedSpec(spec); }

/// Static ground slab 40 x 1 x 40 m, top face at y = 0.
BodySpec Ground() { return Undamped(GroundSpec(vec3(20.0f, 0.5f, 20.0f))); }

/// A world built from specs (WorldBuilder.h) with the solver settings of one run.
struct VolumeWorld : RigidWorld {
    VolumeWorld(const Settings& s, const std::vector<BodySpec>& specs) : RigidWorld(specs) {
        if (s.iterations >= 0) system.settings.solverIterations = s.iterations;
        if (s.projection >= 0) system.settings.linearProjection = s.projection != 0;
        if (s.solver >= 0) system.settings.contactSolver = ContactSolver(s.solver);
        system.settings.soft = s.soft;
    }
    /// One frame: `substeps` updates of dt / substeps.
    void Frame(const Settings& s) {
        const float h = float(s.dt / s.substeps);
        for (int k = 0; k < s.substeps; ++k) system.Update(h);
    }
    /// Finite, within `radius` of the start and slower than 1,000 m/s.
    bool Bounded(float radius) const {
        for (std::size_t i = 0; i < Bodies().size(); ++i) {
            const RigidbodyVolume& b = Body(i);
            if (!IsFinite(b.position) || !IsFinite(b.velocity) || !IsFinite(b.angVel) || !IsFinite(b.orientation))
                return false;
            if (Magnitude(b.position - StartPositions()[i]) > radius || Magnitude(b.velocity) > 1000.0f) return false;
        }
        return true;
    }
};

Settings Base(double dt, int iterations, int projection, double param = 0.0, int substeps = 1) {
    Settings s;
    s.dt = dt;
    s.iterations = iterations;
    s.projection = projection;
    s.param = param;
    s.substeps = substeps;
    return s;
}

/// The same settings with a contact solver chosen (PhysicsSystem::contactSolver).
Settings With(ContactSolver solver, Settings s) {
    s.solver = int(solver);
    return s;
}

/// The solvers whose knob is WorldSettings::solverIterations (and linear projection): the grids sweep those.
constexpr ContactSolver kIteratedSolvers[] = {ContactSolver::Book, ContactSolver::Accumulated};

/// The soft solver's points at one param: its own substep count is its knob (1, 2, 4, 8 per step; only 1 below a
/// 1 ms step, where a substep would be shorter than the finest step of the grid's other solvers), its passes
/// and softness at their defaults; the book's iterations and projection do not apply ("-").
void AddSoftPoints(std::vector<Settings>* g, bool quick, double param = 0.0) {
    for (int substeps : quick ? std::vector<int>{4} : std::vector<int>{1, 2, 4, 8})
        for (double dt : quick ? QuickStepSizes() : StepSizes()) {
            if (substeps > 1 && dt < 1e-3 && !quick) continue;
            Settings s = With(ContactSolver::Soft, Base(dt, -1, -1, param));
            s.soft.substeps = substeps;
            g->push_back(s);
        }
}

// ---- bounce-sphere: radius 0.5, dropped 5 m (bottom to ground), restitution e; first five apex heights.
Outcome RunBounceSphere(const Settings& s) {
    const double e = s.param, h0 = 5.0, r = 0.5;
    BodySpec ground = Ground();
    ground.restitution = 1.0f;  // the pair uses min(cor): the sphere's e
    BodySpec ball = Undamped(SphereSpec(vec3(0.0f, float(h0 + r), 0.0f), float(r), 1.0f));
    ball.restitution = float(e);
    VolumeWorld w(s, {ground, ball});
    const RigidbodyVolume& b = w.Body(1);

    Outcome o;
    ApexTracker apex{e, h0, 0.0};
    const long long maxFrames = StepsFor(15.0, s.dt);
    const double t0 = CpuNow();
    long long i = 0;
    while (i < maxFrames && !apex.Done()) {
        w.Frame(s);
        ++i;
        if (!w.Bounded(20.0f) || b.position.y < -1.0f) {
            o.stable = false;
            break;
        }
        apex.Sample(double(b.position.y) - r, b.velocity.y);
    }
    o.cpuSeconds = CpuNow() - t0;
    o.steps = i * s.substeps;
    o.simSeconds = double(i) * s.dt;
    if (!o.stable) {
        o.error = kInf;
        o.note = "left the ground slab";
    } else {
        o.error = apex.Error();
        if (!apex.Done()) o.note = "only " + std::to_string(apex.apexes) + " apexes";
    }
    return o;
}

// ---- rotation: a free 2 kg box with distinct moments spinning about a non-principal axis for 10 s.
struct Spin {
    vec3 L;
    double E;
};
Spin Measure(const RigidbodyVolume& b) {
    const vec3 L = MultiplyVector(b.angVel, b.InertiaTensor());
    return {L, 0.5 * double(Dot(b.angVel, L))};
}

Outcome RunRotation(const Settings& s, bool energy) {
    BodySpec spec = Undamped(BoxSpec(vec3(), vec3(0.2f, 0.5f, 1.0f), 2.0f));
    spec.angularVelocity = vec3(2.0f, 1.0f, 0.5f);  // rad/s, world frame; not along a principal axis
    VolumeWorld w(s, {spec});
    w.Body(0).gravity = vec3();
    const Spin s0 = Measure(w.Body(0));
    const long long n = StepsFor(10.0, s.dt);
    Outcome o;
    const double t0 = CpuNow();
    for (long long i = 0; i < n; ++i) w.Frame(s);
    o.cpuSeconds = CpuNow() - t0;
    o.steps = n * s.substeps;
    o.simSeconds = double(n) * s.dt;
    o.stable = w.Bounded(1.0f);
    const Spin s1 = Measure(w.Body(0));
    o.error = energy ? std::fabs(s1.E - s0.E) / s0.E : Magnitude(s1.L - s0.L) / Magnitude(s0.L);
    if (!o.stable) o.error = kInf;
    return o;
}

// ---- incline: a 0.5 m cube (1 kg) on a static slab tilted 30 deg, mu = 0.3 for both (pair sqrt(mu mu) = 0.3),
// restitution 0. Acceleration from the down-slope speed at 0.5 s and 1.5 s against g (sin - mu cos).
Outcome RunIncline(const Settings& s) {
    const double theta = 30.0 * M_PI / 180.0, mu = 0.3;
    const TiltedSlab incline = MakeTiltedSlab(theta, mu);
    const BodySpec& slab = incline.spec;
    const vec3 normal = incline.normal, downhill = incline.downhill;
    // Start resting on the face, 2 mm into it (inside PenetrationSlack) so the contact exists from step 1.
    BodySpec cube = Undamped(BoxSpec(normal * (0.5f + 0.25f - 0.002f), vec3(0.25f, 0.25f, 0.25f), 1.0f));
    cube.friction = float(mu);
    cube.restitution = 0.0f;
    cube.eulerRadians = slab.eulerRadians;
    VolumeWorld w(s, {slab, cube});
    const RigidbodyVolume& c = w.Body(1);

    const double reference = kG * (std::sin(theta) - mu * std::cos(theta));
    const long long n1 = StepsFor(0.5, s.dt), n2 = StepsFor(1.5, s.dt);
    Outcome o;
    double v1 = 0.0;
    const double t0 = CpuNow();
    long long i = 0;
    while (i < n2) {
        w.Frame(s);
        ++i;
        if (i == n1) v1 = Dot(c.velocity, downhill);
        if (!w.Bounded(10.0f)) {
            o.stable = false;
            break;
        }
    }
    o.cpuSeconds = CpuNow() - t0;
    o.steps = i * s.substeps;
    o.simSeconds = double(i) * s.dt;
    if (!o.stable) {
        o.error = kInf;
        return o;
    }
    const double a = (Dot(c.velocity, downhill) - v1) / (double(n2 - n1) * s.dt);
    o.error = std::fabs(a - reference) / reference;
    return o;
}

// ---- stacks: towers of unit cubes (half-size 0.5) placed touching on the ground; max drift after 10 s.
// The book's friction 0.6 and restitution 0.5 are kept. param = mass of the top box (the others 1 kg).
Outcome RunStack(const Settings& s, int height, double topMass, double seconds) {
    std::vector<BodySpec> tower = Tower(height, Undamped(BoxSpec(vec3(), vec3(0.5f, 0.5f, 0.5f), 1.0f)));
    if (!tower.empty()) tower.back().mass = float(topMass);
    VolumeWorld w(s, WithGround(Ground(), tower));
    const long long n = StepsFor(seconds, s.dt);
    Outcome o;
    const double t0 = CpuNow();
    long long i = 0;
    while (i < n) {
        w.Frame(s);
        ++i;
        if ((i & 63) == 0 && !w.Bounded(100.0f)) {
            o.stable = false;
            break;
        }
    }
    o.cpuSeconds = CpuNow() - t0;
    if (o.stable) o.stable = w.Bounded(100.0f);
    o.steps = i * s.substeps;
    o.simSeconds = double(i) * s.dt;
    o.error = o.stable ? double(w.MaxDisplacement()) : kInf;
    return o;
}

std::vector<Settings> StackGrid(bool quick) {
    std::vector<Settings> g;
    const std::vector<int> iterations = quick ? std::vector<int>{5} : std::vector<int>{1, 5, 20};
    for (ContactSolver solver : kIteratedSolvers)
        for (int it : iterations)
            for (int proj : {1, 0})
                for (double dt : quick ? QuickStepSizes() : StepSizes()) g.push_back(With(solver, Base(dt, it, proj)));
    // Four substeps per frame at 5 iterations: the same cost and accuracy as a 4x smaller dt here, because
    // PhysicsSystem has no per-frame work; shown once to make that visible.
    if (!quick)
        for (double dt : StepSizes())
            if (dt >= 2e-3) g.push_back(With(ContactSolver::Book, Base(dt, 5, 1, 0.0, 4)));
    AddSoftPoints(&g, quick);
    return g;
}

}  // namespace

void AddRigidProblems(std::vector<Problem>* out) {
    out->push_back({"bounce-sphere",
                    "0.5 m sphere dropped 5 m onto a static box, restitution e (param); first five apexes vs "
                    "e^(2n) h0",
                    "max relative apex error", "e",
                    [](bool q) {
                        std::vector<Settings> g;
                        for (ContactSolver solver : kIteratedSolvers)
                            for (double e : {0.5, 0.9})
                                for (int proj : {1, 0})
                                    for (double dt : q ? QuickStepSizes() : StepSizes())
                                        g.push_back(With(solver, Base(dt, 5, proj, e)));
                        for (double e : {0.5, 0.9}) AddSoftPoints(&g, q, e);
                        return g;
                    },
                    RunBounceSphere});
    auto dtOnly = [](bool q) {
        std::vector<Settings> g;
        for (double dt : q ? QuickStepSizes() : StepSizes()) g.push_back(Base(dt, -1, -1));
        return g;
    };
    out->push_back({"rotation-momentum",
                    "free box (0.4 x 1 x 2 m, 2 kg) spun at (2,1,0.5) rad/s; angular momentum after 10 s",
                    "|L - L0| / |L0| after 10 s", "", dtOnly, [](const Settings& s) { return RunRotation(s, false); }});
    out->push_back({"rotation-energy", "the same free box; kinetic energy after 10 s", "|E - E0| / E0 after 10 s", "",
                    dtOnly, [](const Settings& s) { return RunRotation(s, true); }});
    out->push_back({"incline", "0.5 m cube on a 30 deg slab, mu 0.3; acceleration vs g (sin - mu cos) = 2.36 m/s^2",
                    "relative acceleration error", "",
                    [](bool q) {
                        std::vector<Settings> g;
                        for (ContactSolver solver : kIteratedSolvers)
                            for (int it : q ? std::vector<int>{5} : std::vector<int>{1, 5, 20})
                                for (int proj : {1, 0})
                                    for (double dt : q ? QuickStepSizes() : StepSizes())
                                        g.push_back(With(solver, Base(dt, it, proj)));
                        AddSoftPoints(&g, q);
                        return g;
                    },
                    RunIncline});
    out->push_back({"stack-5", "tower of 5 unit cubes on the ground, book friction/restitution; 10 s",
                    "max drift of any box after 10 s (m)", "", StackGrid,
                    [](const Settings& s) { return RunStack(s, 5, 1.0, 10.0); }});
    out->push_back({"stack-10", "tower of 10 unit cubes on the ground; 10 s", "max drift of any box after 10 s (m)", "",
                    StackGrid, [](const Settings& s) { return RunStack(s, 10, 1.0, 10.0); }});
    out->push_back({"stack-mass-ratio",
                    "tower of 5 unit cubes whose top box has mass ratio r (param) to the others; 5 s: stability map",
                    "max drift of any box after 5 s (m)", "mass_ratio",
                    [](bool q) {
                        std::vector<Settings> g;
                        const std::vector<double> ratios =
                            q ? std::vector<double>{1e-3, 1e3} : std::vector<double>{1e-3, 1e-2, 0.1, 1, 10, 100, 1e3};
                        for (ContactSolver solver : kIteratedSolvers)
                            for (int it : q ? std::vector<int>{5} : std::vector<int>{5, 20})
                                for (double r : ratios)
                                    for (double dt : q ? QuickStepSizes() : StepSizes())
                                        g.push_back(With(solver, Base(dt, it, 1, r)));
                        for (double r : ratios) AddSoftPoints(&g, q, r);
                        return g;
                    },
                    [](const Settings& s) { return RunStack(s, 5, s.param, 5.0); }});
}

}  // namespace sweep
