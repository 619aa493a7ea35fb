// Particle reference problems of psb-sweep: projectile, particle bounce, spring-mass oscillators, pendulum on a
// distance joint. Every particle here has friction (the book's per-step velocity damping) 1: the references are
// undamped or damped by a dt-independent spring coefficient, and a per-step factor would change the physics
// with dt.
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "Physics/DistanceJoint.h"
#include "Physics/Particle.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/Spring.h"
#include "Physics/StabilityMonitor.h"
#include "bench/sweep/Sweep.h"

namespace sweep {
namespace {

constexpr double kG = 9.82;  // the book's gravity (Particle::gravity)
constexpr double kInf = std::numeric_limits<double>::infinity();

long long StepsFor(double seconds, double dt) { return std::llround(seconds / dt); }

/// Every integrator at every default (or quick) step size, param fixed.
std::vector<Settings> IntegratorGrid(bool quick, double param = 0.0) {
    std::vector<Settings> out;
    for (Integrator integrator : kAllIntegrators)
        for (double dt : quick ? QuickStepSizes() : StepSizes()) {
            Settings s;
            s.hasIntegrator = true;
            s.integrator = integrator;
            s.dt = dt;
            s.param = param;
            out.push_back(s);
        }
    return out;
}

bool Finite(const Particle& p) { return IsFinite(p.GetPosition()) && IsFinite(p.GetVelocity()); }

/// A particle with no per-step damping and the given mass, position and velocity.
void Setup(Particle* p, float mass, const vec3& position, const vec3& velocity) {
    p->SetMass(mass);
    p->SetVelocityRetention(1.0f);
    p->SetPosition(position);
    p->SetVelocity(velocity);
}

// ---- projectile: exact x0 + v0 t + g t^2 / 2 after 2 s.
Outcome RunProjectile(const Settings& s) {
    const vec3 x0(0.0f, 1.0f, 0.0f), v0(20.0f, 15.0f, 5.0f);
    const double T = 2.0;
    PhysicsSystem world;
    world.settings.integrator = s.integrator;
    Particle p;
    Setup(&p, 1.0f, x0, v0);
    world.AddRigidbody(&p);
    Outcome o;
    const long long n = StepsFor(T, s.dt);
    const double t0 = CpuNow();
    for (long long i = 0; i < n; ++i) world.Update(float(s.dt));
    o.cpuSeconds = CpuNow() - t0;
    o.steps = n;
    o.simSeconds = T;
    const double t = double(n) * s.dt;
    const double ex = x0.x + v0.x * t, ey = x0.y + v0.y * t - 0.5 * kG * t * t, ez = x0.z + v0.z * t;
    const vec3 x = p.GetPosition();
    o.error = std::sqrt((x.x - ex) * (x.x - ex) + (x.y - ey) * (x.y - ey) + (x.z - ez) * (x.z - ez));
    o.stable = Finite(p);
    return o;
}

// ---- bounce: particle dropped from h0 onto a box, restitution e; the first five apex heights.
Outcome RunBounceParticle(const Settings& s) {
    const double e = s.param, h0 = 5.0;
    PhysicsSystem world;
    world.settings.integrator = s.integrator;
    world.AddConstraint(OBB(vec3(0.0f, -1.0f, 0.0f), vec3(10.0f, 1.0f, 10.0f)));  // top face at y = 0
    Particle p;
    Setup(&p, 1.0f, vec3(0.0f, float(h0), 0.0f), vec3());
    p.SetBounce(float(e));
    world.AddRigidbody(&p);

    // Reference: the particle reaches y = 0 with speed sqrt(2 g h) and is put Particle::kContactOffset above
    // the surface with e times that speed, so h_n = c + e^2 h_(n-1): h_n = e^(2n) h0 + c (1 - e^(2n)) / (1 - e^2).
    // The offset term is the documented 3 mm placement; with c = 0 this is the textbook e^(2n) h0.
    ApexTracker apex{e, h0, Particle::kContactOffset};
    Outcome o;
    const long long maxSteps = StepsFor(15.0, s.dt);
    const double t0 = CpuNow();
    long long i = 0;
    for (; i < maxSteps && !apex.Done(); ++i) {
        world.Update(float(s.dt));
        const float y = p.GetPosition().y, vy = p.GetVelocity().y;
        if (!std::isfinite(y) || y < -1.0f || y > 2.0f * float(h0)) {
            o.stable = false;
            break;
        }
        apex.Sample(y, vy);
    }
    o.cpuSeconds = CpuNow() - t0;
    if (!o.stable) ++i;  // the step that failed was run
    o.steps = i;
    o.simSeconds = double(i) * s.dt;
    // A missing apex (the particle came to rest or never left the ground within 15 s) counts as 100 % error.
    o.error = apex.Error();
    if (!apex.Done()) o.note = "only " + std::to_string(apex.apexes) + " apexes";
    return o;
}

// ---- spring-mass: a 1 kg bob on a spring of stiffness K to an immovable anchor (mass 0), no gravity.
struct Oscillator {
    PhysicsSystem world;
    Particle anchor, bob;
    double K, b, omega, gamma, omegaD;  // stiffness, damping, natural, decay rate, damped frequency
    double amplitude = 0.1, rest = 1.0;

    Oscillator(Integrator integrator, double stiffness, double damping) : K(stiffness), b(damping) {
        world.settings.integrator = integrator;
        Setup(&anchor, 0.0f, vec3(), vec3());
        Setup(&bob, 1.0f, vec3(float(rest + amplitude), 0.0f, 0.0f), vec3());
        bob.SetGravity(vec3());
        anchor.SetGravity(vec3());
        world.AddRigidbody(&anchor);
        world.AddRigidbody(&bob);
        Spring spring(-float(K), float(b), float(rest));  // book sign: negative k attracts
        spring.SetParticles(&anchor, &bob);
        world.AddSpring(spring);
        omega = std::sqrt(K);
        gamma = 0.5 * b;  // b / (2 m)
        omegaD = std::sqrt(omega * omega - gamma * gamma);
    }
    double U() const { return double(bob.GetPosition().x) - rest; }
    double V() const { return double(bob.GetVelocity().x); }
    double Energy() const { return 0.5 * V() * V() + 0.5 * K * U() * U(); }
    /// Phase of the (damped) oscillation: atan2(-(v + gamma u) / omega_d, u), equal to omega_d t exactly.
    double Phase() const { return std::atan2(-(V() + gamma * U()) / omegaD, U()); }
    bool Finite() const { return std::isfinite(U()) && std::isfinite(V()); }
};

double WrapAngle(double a) { return std::remainder(a, 2.0 * M_PI); }

/// Runs n steps, checking every `check` steps that the state is finite and its energy below `maxEnergy`.
Outcome StepOscillator(Oscillator& osc, const Settings& s, long long n, long long check, double maxEnergy) {
    Outcome o;
    const double t0 = CpuNow();
    long long i = 0;
    while (i < n) {
        const long long end = std::min(n, i + check);
        for (; i < end; ++i) osc.world.Update(float(s.dt));
        if (!osc.Finite() || osc.Energy() > maxEnergy) {
            o.stable = false;
            break;
        }
    }
    o.cpuSeconds = CpuNow() - t0;
    o.steps = i;
    o.simSeconds = double(i) * s.dt;
    return o;
}

Outcome RunSpringPhase(const Settings& s, double damping) {
    // K = 4 pi^2 N/m with 1 kg: a period of 1 s (undamped). Ten (damped) periods.
    Oscillator osc(s.integrator, 4.0 * M_PI * M_PI, damping);
    const double T = 10.0 * 2.0 * M_PI / osc.omegaD;
    const long long n = StepsFor(T, s.dt);
    Outcome o = StepOscillator(osc, s, n, std::max(1LL, n / 100), 1e6 * osc.Energy());
    // Released from rest: u = C e^(-gamma t) cos(omega_d t - phi) with tan(phi) = gamma / omega_d.
    const double expected = osc.omegaD * double(n) * s.dt - std::atan2(osc.gamma, osc.omegaD);
    o.error = o.stable ? std::fabs(WrapAngle(osc.Phase() - expected)) : kInf;
    return o;
}

Outcome RunSpringEnergy(const Settings& s) {
    // Undamped, period 1 s: relative energy change after 1,000 periods.
    Oscillator osc(s.integrator, 4.0 * M_PI * M_PI, 0.0);
    const double E0 = osc.Energy();
    const long long n = StepsFor(1000.0, s.dt);
    Outcome o = StepOscillator(osc, s, n, StepsFor(1.0, s.dt), 1e6 * E0);
    o.error = o.stable ? std::fabs(osc.Energy() - E0) / E0 : kInf;
    return o;
}

Outcome RunSpringStiffness(const Settings& s) {
    // Stiffness K = param N/m, undamped, 1 s: state error |(u, v/omega) - exact| / amplitude. Drives the
    // stability map; the StabilityMonitor decides "unstable" and its report goes in the note.
    Oscillator osc(s.integrator, s.param, 0.0);
    StabilityMonitor monitor;
    monitor.Start(osc.world);
    const long long n = StepsFor(1.0, s.dt);
    Outcome o;
    const double t0 = CpuNow();
    long long i = 0;
    while (i < n) {
        osc.world.Update(float(s.dt));
        ++i;
        if (!monitor.Check(osc.world)) break;
    }
    o.cpuSeconds = CpuNow() - t0;
    o.steps = i;
    o.simSeconds = double(i) * s.dt;
    o.stable = monitor.Stable();
    if (!o.stable) {
        o.note = monitor.Report().message;
        o.error = kInf;
        return o;
    }
    const double t = double(n) * s.dt;
    const double du = osc.U() - osc.amplitude * std::cos(osc.omega * t);
    const double dv = osc.V() / osc.omega + osc.amplitude * std::sin(osc.omega * t);
    o.error = std::sqrt(du * du + dv * dv) / osc.amplitude;
    return o;
}

// ---- pendulum: a 1 kg bob on a 1 m DistanceJoint to a pinned pivot, released from rest at theta0.
Outcome RunPendulum(const Settings& s, double theta0) {
    const double L = 1.0;
    const vec3 pivotAt(0.0f, 2.0f, 0.0f);
    PhysicsSystem world;
    world.settings.integrator = s.integrator;
    Particle pivot, bob;
    Setup(&pivot, 0.0f, pivotAt, vec3());  // mass 0: gravity cannot move it ...
    Setup(&bob, 1.0f, pivotAt + vec3(float(L * std::sin(theta0)), -float(L * std::cos(theta0)), 0.0f), vec3());
    world.AddRigidbody(&pivot);
    world.AddRigidbody(&bob);
    DistanceJoint joint;
    joint.Initialize(&pivot, &bob, float(L));
    world.AddRigidbody(&joint);

    const double Tref = PendulumPeriod(L, kG, theta0);
    const double T = 5.25 * Tref;  // five periods and a bit: ten zero crossings of x
    const long long n = StepsFor(T, s.dt);
    Outcome o;
    std::vector<double> crossings;
    double prevX = bob.GetPosition().x - pivotAt.x;
    const double t0 = CpuNow();
    long long i = 0;
    for (; i < n; ++i) {
        world.Update(float(s.dt));
        // ... nor the joint (inverse-mass weighting); a pivot that moved would make the reference meaningless.
        const vec3 x = bob.GetPosition();
        if (!Finite(bob) || Magnitude(x - pivotAt) > 10.0f || Magnitude(pivot.GetPosition() - pivotAt) != 0.0f) {
            o.stable = false;
            o.note = Magnitude(pivot.GetPosition() - pivotAt) != 0.0f ? "the mass-0 pivot moved" : "bob left";
            break;
        }
        const double cx = x.x - pivotAt.x;
        if ((prevX > 0.0) != (cx > 0.0) && cx != prevX) {
            const double frac = prevX / (prevX - cx);  // linear interpolation of the crossing time
            crossings.push_back((double(i) + frac) * s.dt);
        }
        prevX = cx;
    }
    o.cpuSeconds = CpuNow() - t0;
    if (!o.stable) ++i;  // the step that failed was run
    o.steps = i;
    o.simSeconds = double(i) * s.dt;
    if (!o.stable || crossings.size() < 3) {
        o.error = o.stable ? 1.0 : kInf;  // no measurable period: 100 % error
        if (o.stable) o.note = "fewer than 3 zero crossings";
        return o;
    }
    const double period = 2.0 * (crossings.back() - crossings.front()) / double(crossings.size() - 1);
    o.error = std::fabs(period - Tref) / Tref;
    return o;
}

}  // namespace

void AddParticleProblems(std::vector<Problem>* out) {
    out->push_back({"projectile", "particle thrown at (20,15,5) m/s, no damping; exact parabola after 2 s",
                    "position error after 2 s (m)", "", [](bool q) { return IntegratorGrid(q); }, RunProjectile});
    out->push_back({"bounce-particle",
                    "particle dropped 5 m onto a box, restitution e (param); first five apex heights vs e^(2n) h0 "
                    "(+ the 3 mm contact offset)",
                    "max relative apex error", "e",
                    [](bool q) {
                        std::vector<Settings> g = IntegratorGrid(q, 0.5);
                        for (Settings s : IntegratorGrid(q, 0.9)) g.push_back(s);
                        return g;
                    },
                    RunBounceParticle});
    out->push_back({"spring-phase", "undamped 1 kg / 39.5 N/m oscillator (T = 1 s); phase after 10 periods",
                    "phase error after 10 periods (rad)", "", [](bool q) { return IntegratorGrid(q); },
                    [](const Settings& s) { return RunSpringPhase(s, 0.0); }});
    out->push_back({"spring-damped", "damped oscillator, zeta = 0.05 (b = 0.628 N s/m); phase after 10 periods",
                    "phase error after 10 damped periods (rad)", "", [](bool q) { return IntegratorGrid(q); },
                    [](const Settings& s) { return RunSpringPhase(s, 0.2 * M_PI); }});
    out->push_back({"spring-energy", "undamped oscillator (T = 1 s); energy after 1,000 periods",
                    "relative energy drift over 1000 periods", "",
                    [](bool q) {
                        // 1,000 s of simulation: the quick grid keeps one point per integrator.
                        if (!q) return IntegratorGrid(false);
                        std::vector<Settings> g;
                        for (Settings s : IntegratorGrid(true))
                            if (s.dt == 0.01) g.push_back(s);
                        return g;
                    },
                    RunSpringEnergy});
    out->push_back({"spring-stiffness", "undamped 1 kg oscillator of stiffness K (param) for 1 s: stability map",
                    "state error / amplitude after 1 s", "stiffness_N_per_m",
                    [](bool q) {
                        std::vector<Settings> g;
                        const std::vector<double> ks =
                            q ? std::vector<double>{10.0, 1e4} : std::vector<double>{1, 10, 100, 1e3, 1e4, 1e5, 1e6};
                        for (double k : ks)
                            for (Settings s : IntegratorGrid(q, k)) g.push_back(s);
                        return g;
                    },
                    RunSpringStiffness});
    // DistanceJoint projects position and removes the axial velocity (PBD): the pendulum converges to the exact
    // period, first order in dt (the projection loses energy, most at large amplitude).
    out->push_back({"pendulum-small", "1 m pendulum on a DistanceJoint released at 5 deg; period vs 4 sqrt(L/g) K",
                    "relative period error", "", [](bool q) { return IntegratorGrid(q); },
                    [](const Settings& s) { return RunPendulum(s, 5.0 * M_PI / 180.0); }});
    out->push_back({"pendulum-large", "1 m pendulum on a DistanceJoint released at 120 deg; period vs elliptic K",
                    "relative period error", "", [](bool q) { return IntegratorGrid(q); },
                    [](const Settings& s) { return RunPendulum(s, 120.0 * M_PI / 180.0); }});
}

}  // namespace sweep
