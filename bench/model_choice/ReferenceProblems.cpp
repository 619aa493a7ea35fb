// The errors of the sweep's reference problems, measured on FileScene runs of scenes/reference/*.json. Each observer
// repeats its sweep problem's reference and error formula (bench/sweep/ProblemsParticle.cpp, ProblemsRigid.cpp,
// ProblemsCloth.cpp) on the scene's state; the check mode of psb-model-choice-bench runs both at the same setting
// and compares the numbers.
#include "bench/model_choice/ReferenceProblems.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include "bench/sweep/Sweep.h"

namespace modelchoice {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kG = 9.82;  // the sweep's references use the book's gravity in double precision

bool Finite(const Particle& p) { return IsFinite(p.GetPosition()) && IsFinite(p.GetVelocity()); }

bool FiniteVolume(const RigidbodyVolume& b) {
    return IsFinite(b.position) && IsFinite(b.velocity) && IsFinite(b.angVel) && IsFinite(b.orientation);
}

// ---- projectile: exact x0 + v0 t + g t^2 / 2 at the end.
class ProjectileError : public ErrorObserver {
public:
    void Start(const FileScene& scene) override {
        x0 = scene.Particles()[0].GetPosition();
        v0 = scene.Particles()[0].GetVelocity();
    }
    void AfterStep(const FileScene&, const StepTime&) override {}
    double Error(const FileScene& scene, double t) override {
        const Particle& p = scene.Particles()[0];
        if (!Finite(p)) return kInf;
        const double ex = x0.x + v0.x * t, ey = x0.y + v0.y * t - 0.5 * kG * t * t, ez = x0.z + v0.z * t;
        const vec3 x = p.GetPosition();
        return std::sqrt((x.x - ex) * (x.x - ex) + (x.y - ey) * (x.y - ey) + (x.z - ez) * (x.z - ez));
    }

private:
    vec3 x0, v0;
};

// ---- apex heights of a bounce: the first five against e^(2n) h0 (+ the particle's contact offset term).
class ApexError : public ErrorObserver {
public:
    /// `sphere`: volume 1 of radius r (its bottom is the height), else particle 0.
    ApexError(double restitution, double offset, bool sphere) : apex{restitution, kH0, offset}, sphere(sphere) {}
    void Start(const FileScene&) override {}
    void AfterStep(const FileScene& scene, const StepTime&) override {
        if (!stable || apex.Done()) return;
        double y = 0.0, vy = 0.0;
        if (sphere) {
            const RigidbodyVolume& b = scene.Volumes()[1];
            const auto& start = scene.Description().bodies;
            // The sweep's bounds: every body finite, within 20 m of its start, slower than 1,000 m/s; above y = -1.
            for (std::size_t i = 0; i < scene.Volumes().size(); ++i) {
                const RigidbodyVolume& v = scene.Volumes()[i];
                if (!FiniteVolume(v) || Magnitude(v.position - start[i].position) > 20.0f ||
                    Magnitude(v.velocity) > 1000.0f)
                    stable = false;
            }
            if (b.position.y < -1.0f) stable = false;
            y = double(b.position.y) - double(b.sphere.radius);
            vy = b.velocity.y;
        } else {
            const Particle& p = scene.Particles()[0];
            // The apexes' answer follows the run's contact (set before the first step, by auto too): the offset
            // contacts put the particle that far up at each impact, the reflect contact does not.
            apex.c = ContactOffsetOf(scene.System().settings.particleContact);
            const float py = p.GetPosition().y;
            if (!std::isfinite(py) || py < -1.0f || py > 2.0f * float(kH0)) stable = false;
            y = py;
            vy = p.GetVelocity().y;
        }
        if (stable) apex.Sample(y, vy);
    }
    double Error(const FileScene&, double) override {
        return stable ? apex.Error() : kInf;  // a missing apex is 100 % error, as in the sweep
    }

private:
    static constexpr double kH0 = 5.0;
    sweep::ApexTracker apex;
    bool sphere;
    bool stable = true;
};

// ---- oscillator: particle 1 on a spring of stiffness K, damping b, rest 1 m to the fixed particle 0; 1 kg.
struct OscillatorState {
    double K, b, gamma, omegaD, rest = 1.0;
    OscillatorState(double stiffness, double damping) : K(stiffness), b(damping) {
        gamma = 0.5 * b;
        omegaD = std::sqrt(K - gamma * gamma);
    }
    double U(const FileScene& s) const { return double(s.Particles()[1].GetPosition().x) - rest; }
    double V(const FileScene& s) const { return double(s.Particles()[1].GetVelocity().x); }
    double Energy(const FileScene& s) const { return 0.5 * V(s) * V(s) + 0.5 * K * U(s) * U(s); }
};

class PhaseError : public ErrorObserver {
public:
    PhaseError(double K, double b) : osc(K, b) {}
    void Start(const FileScene& scene) override { e0 = osc.Energy(scene); }
    void AfterStep(const FileScene&, const StepTime&) override {}
    double Error(const FileScene& scene, double t) override {
        if (!Finite(scene.Particles()[1]) || osc.Energy(scene) > 1e6 * e0) return kInf;
        // Released from rest: u = C e^(-gamma t) cos(omega_d t - phi), tan(phi) = gamma / omega_d.
        const double phase = std::atan2(-(osc.V(scene) + osc.gamma * osc.U(scene)) / osc.omegaD, osc.U(scene));
        const double expected = osc.omegaD * t - std::atan2(osc.gamma, osc.omegaD);
        return std::fabs(std::remainder(phase - expected, 2.0 * M_PI));
    }

private:
    OscillatorState osc;
    double e0 = 0.0;
};

class EnergyDrift : public ErrorObserver {
public:
    explicit EnergyDrift(double K) : osc(K, 0.0) {}
    void Start(const FileScene& scene) override { e0 = osc.Energy(scene); }
    void AfterStep(const FileScene&, const StepTime&) override {}
    double Error(const FileScene& scene, double) override {
        const double e = osc.Energy(scene);
        if (!Finite(scene.Particles()[1]) || e > 1e6 * e0) return kInf;
        return std::fabs(e - e0) / e0;
    }

private:
    OscillatorState osc;
    double e0 = 0.0;
};

// ---- pendulum: period from the zero crossings of the bob's x about the pivot, against the elliptic-integral period.
class PeriodError : public ErrorObserver {
public:
    explicit PeriodError(double theta0) : reference(sweep::PendulumPeriod(1.0, kG, theta0)) {}
    void Start(const FileScene& scene) override {
        pivot = scene.Particles()[0].GetPosition();
        prevX = scene.Particles()[1].GetPosition().x - pivot.x;
    }
    void AfterStep(const FileScene& scene, const StepTime& step) override {
        if (!stable) return;
        const Particle& bob = scene.Particles()[1];
        const vec3 x = bob.GetPosition();
        if (!Finite(bob) || Magnitude(x - pivot) > 10.0f ||
            Magnitude(scene.Particles()[0].GetPosition() - pivot) != 0.0f) {
            stable = false;
            return;
        }
        const double cx = x.x - pivot.x;
        if ((prevX > 0.0) != (cx > 0.0) && cx != prevX) crossings.push_back(step.At(prevX / (prevX - cx)));
        prevX = cx;
    }
    double Error(const FileScene&, double) override {
        if (!stable) return kInf;
        if (crossings.size() < 3) return 1.0;
        const double period = 2.0 * (crossings.back() - crossings.front()) / double(crossings.size() - 1);
        return std::fabs(period - reference) / reference;
    }

private:
    double reference;
    vec3 pivot;
    double prevX = 0.0;
    std::vector<double> crossings;
    bool stable = true;
};

// ---- free rotation of volume 0: |L - L0| / |L0| or |E - E0| / E0.
class RotationError : public ErrorObserver {
public:
    explicit RotationError(bool energy) : energy(energy) {}
    void Start(const FileScene& scene) override { Measure(scene.Volumes()[0], &l0, &e0); }
    void AfterStep(const FileScene&, const StepTime&) override {}
    double Error(const FileScene& scene, double) override {
        const RigidbodyVolume& b = scene.Volumes()[0];
        if (!FiniteVolume(b) || Magnitude(b.position - scene.Description().bodies[0].position) > 1.0f ||
            Magnitude(b.velocity) > 1000.0f)
            return kInf;
        vec3 l;
        double e = 0.0;
        Measure(b, &l, &e);
        return energy ? std::fabs(e - e0) / e0 : double(Magnitude(l - l0) / Magnitude(l0));
    }

private:
    static void Measure(const RigidbodyVolume& b, vec3* l, double* e) {
        *l = MultiplyVector(b.angVel, b.InertiaTensor());
        *e = 0.5 * double(Dot(b.angVel, *l));
    }
    bool energy;
    vec3 l0;
    double e0 = 0.0;
};

// ---- incline: down-slope acceleration of volume 1 between t = 0.5 s and the end (1.5 s) against g (sin - mu cos).
class AccelerationError : public ErrorObserver {
public:
    void Start(const FileScene& scene) override {
        const float* axes = scene.Volumes()[0].box.orientation.asArray;  // rows: local X, Y, Z in world space
        downhill = vec3(axes[0], axes[1], axes[2]);
        if (downhill.y > 0.0f) downhill = downhill * -1.0f;
    }
    void AfterStep(const FileScene& scene, const StepTime& step) override {
        for (std::size_t i = 0; i < scene.Volumes().size(); ++i) {
            const RigidbodyVolume& v = scene.Volumes()[i];
            if (!FiniteVolume(v) || Magnitude(v.position - scene.Description().bodies[i].position) > 10.0f ||
                Magnitude(v.velocity) > 1000.0f)
                stable = false;
        }
        if (!measured && step.After() >= 0.5 - 1e-9 * step.dt) {
            measured = true;
            t1 = step.After();
            v1 = Dot(scene.Volumes()[1].velocity, downhill);
        }
    }
    double Error(const FileScene& scene, double end) override {
        if (!stable || !measured || !(end > t1)) return kInf;
        const double theta = 30.0 * M_PI / 180.0, mu = 0.3;
        const double reference = kG * (std::sin(theta) - mu * std::cos(theta));
        const double a = (Dot(scene.Volumes()[1].velocity, downhill) - v1) / (end - t1);
        return std::fabs(a - reference) / reference;
    }

private:
    vec3 downhill;
    bool measured = false, stable = true;
    double t1 = 0.0, v1 = 0.0;
};

// ---- towers: the largest distance of any dynamic volume from its start.
class DriftError : public ErrorObserver {
public:
    void Start(const FileScene&) override {}
    void AfterStep(const FileScene&, const StepTime&) override {}
    double Error(const FileScene& scene, double) override {
        double worst = 0.0;
        for (std::size_t i = 0; i < scene.Volumes().size(); ++i) {
            const RigidbodyVolume& v = scene.Volumes()[i];
            const double d = Magnitude(v.position - scene.Description().bodies[i].position);
            if (!FiniteVolume(v) || d > 100.0 || Magnitude(v.velocity) > 1000.0f) return kInf;
            if (v.mass > 0.0f) worst = std::fmax(worst, d);
        }
        return worst;
    }
};

// ---- cloth: RMS particle distance to a converged run of the same scene (RK4 at 2.5e-5 s), computed once per end
// time (whole reference steps) per process.
class ClothError : public ErrorObserver {
public:
    void Start(const FileScene&) override {}
    void AfterStep(const FileScene&, const StepTime&) override {}
    double Error(const FileScene& scene, double end) override {
        const std::vector<Particle>& verts = scene.Cloths()[0]->verts;
        for (const Particle& p : verts)
            if (!Finite(p)) return kInf;
        const std::vector<vec3>& reference = Reference(scene.Description(), end);
        double sum = 0.0;
        for (std::size_t i = 0; i < verts.size(); ++i)
            sum += double(MagnitudeSq(verts[i].GetPosition() - reference[i]));
        return std::sqrt(sum / double(verts.size()));
    }

private:
    static const std::vector<vec3>& Reference(SceneDescription d, double end) {
        constexpr double kReferenceDt = 2.5e-5;  // the sweep's: a quarter of its smallest step
        static std::map<std::pair<std::string, long long>, std::vector<vec3>> cache;
        const long long n = std::llround(end / kReferenceDt);
        const auto key = std::make_pair(d.name, n);
        auto it = cache.find(key);
        if (it != cache.end()) return it->second;
        d.world.integrator = Integrator::RK4;
        FileScene converged(d);
        for (long long i = 0; i < n; ++i) converged.Step(float(kReferenceDt));
        std::vector<vec3>& out = cache[key];
        for (const Particle& p : converged.Cloths()[0]->verts) out.push_back(p.GetPosition());
        return out;
    }
};

/// m: the straight-line distance between the bottom and where a 1 m pendulum of amplitude theta0 is `delay` s
/// before or after passing it (the motion is symmetric in time about the bottom). RK4 at about 1e-5 s on
/// theta'' = -(g / L) sin theta, from theta = 0 at the bottom's angular speed sqrt(2 g / L (1 - cos theta0)).
double ChordFromBottom(double theta0, double delay) {
    const double w2 = kG;  // g / L, L = 1 m
    const int n = std::max(1, static_cast<int>(std::ceil(delay / 1e-5)));
    const double h = delay / n;
    double th = 0.0, om = std::sqrt(2.0 * w2 * (1.0 - std::cos(theta0)));
    auto acc = [w2](double a) { return -w2 * std::sin(a); };
    for (int i = 0; i < n; ++i) {
        const double k1x = om, k1v = acc(th);
        const double k2x = om + 0.5 * h * k1v, k2v = acc(th + 0.5 * h * k1x);
        const double k3x = om + 0.5 * h * k2v, k3v = acc(th + 0.5 * h * k2x);
        const double k4x = om + h * k3v, k4v = acc(th + h * k3x);
        th += h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
        om += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
    }
    return 2.0 * std::sin(std::fabs(th) / 2.0);  // 2 L sin(theta / 2)
}

template <class T, class... Args>
std::function<std::unique_ptr<ErrorObserver>()> Make(Args... args) {
    return [=] { return std::unique_ptr<ErrorObserver>(new T(args...)); };
}

std::vector<ReferenceProblem> Build() {
    using Q = BudgetQuantity;
    const double K = 4.0 * M_PI * M_PI, damping = 0.2 * M_PI;
    const double c = Particle::kContactOffset;
    std::vector<ReferenceProblem> out;
    out.push_back({"projectile", "projectile", "-", "position error after 2 s (m)", Q::Position, 1.0,
                   "position error itself (m)", false, Make<ProjectileError>()});
    for (double e : {0.5, 0.9}) {
        const std::string p = e == 0.5 ? "0.5" : "0.9";
        // An apex is its flight's energy: a relative error at the fifth is e^10 of the drop's energy. The file ends
        // in the fifth flight for e = 0.9; for e = 0.5 in the sixth, whose apex, with the contact offset that each
        // impact adds, is still about e^10 h0 (5.2 mm). The offset is the run's contact's (ApexError::AfterStep): c
        // for the book's and the skin, 0 for reflect.
        out.push_back({"bounce-particle-" + p, "bounce-particle", p, "max relative apex error", Q::Energy,
                       std::pow(e, 10),
                       "relative apex error x e^10 = " + std::to_string(std::pow(e, 10)).substr(0, 7) +
                           ": an apex is its flight's energy, the fifth e^10 of the drop's; measured at the end",
                       false, Make<ApexError>(e, c, false)});
    }
    // Phase error phi of an oscillation of amplitude A is a position error A phi at the end.
    out.push_back({"spring-phase", "spring-phase", "-", "phase error after 10 periods (rad)", Q::Position, 0.1,
                   "phase x amplitude 0.1 m", false, Make<PhaseError>(K, 0.0)});
    const double endAmplitude = 0.1 * std::exp(-0.5 * damping * 10.012523486435178);
    out.push_back({"spring-damped", "spring-damped", "-", "phase error after 10 damped periods (rad)", Q::Position,
                   endAmplitude, "phase x the amplitude left at the end, 0.1 e^(-gamma T) = 0.0043 m", false,
                   Make<PhaseError>(K, damping)});
    out.push_back({"spring-energy", "spring-energy", "-", "relative energy drift over 1000 periods", Q::Energy, 1.0,
                   "relative energy drift itself", false, Make<EnergyDrift>(K)});
    // A relative period error eps over the run's 5.25 periods is a delay of 5.25 T eps. The run ends a quarter period
    // after a turning point, at the bottom, so the bob is the straight-line distance from the bottom that the
    // pendulum covers in that delay away from where it should be. Up to a quarter period that distance grows with
    // the delay (to the turning point's chord, 2 L sin(theta0 / 2)); beyond, it shrinks again and the position at
    // the end no longer tells a larger period error from a smaller one, so the delay is capped there: a budget
    // beyond a quarter period asks auto for that quarter period.
    for (double deg : {5.0, 120.0}) {
        const double theta0 = deg * M_PI / 180.0;
        const double period = sweep::PendulumPeriod(1.0, kG, theta0);
        ReferenceProblem p{deg == 5.0 ? "pendulum-small" : "pendulum-large",
                           deg == 5.0 ? "pendulum-small" : "pendulum-large",
                           "-",
                           "relative period error",
                           Q::Position,
                           1.0,
                           "the bob's distance from the bottom a delay of 5.25 T eps away (capped at T / 4, the "
                           "turning point)",
                           false,
                           Make<PeriodError>(theta0)};
        p.bound = [theta0, period](double budget) {
            return ChordFromBottom(theta0, std::min(5.25 * period * budget, period / 4.0));
        };
        out.push_back(p);
    }
    for (double e : {0.5, 0.9}) {
        const std::string p = e == 0.5 ? "0.5" : "0.9";
        // Position, not energy as for the particle: the e = 0.5 file ends after the seventh impact, with e^14 of the
        // drop's energy (no contact offset keeps it up), and the soft and accumulated solvers drop the fifth impact
        // under their 1 m/s restitution threshold in a candidate and its refinement alike; with an energy budget
        // e = 0.5 at 0.1 runs the soft solver and loses its fifth apex (docs/model-choice-validation.md).
        const double h5 = std::pow(e, 10) * 5.0;
        out.push_back(
            {"bounce-sphere-" + p, "bounce-sphere", p, "max relative apex error", Q::Position, h5,
             "relative apex error x the fifth apex height e^10 h0 = " + std::to_string(h5).substr(0, 6) + " m", false,
             Make<ApexError>(e, 0.0, true)});
    }
    out.push_back({"rotation-momentum", "rotation-momentum", "-", "|L - L0| / |L0| after 10 s", Q::Energy, 1.0,
                   "relative energy drift (the box's centre does not move, so a position budget bounds nothing; "
                   "|dE|/E stands for |dL|/|L|, the other first integral)",
                   false, Make<RotationError>(false)});
    out.push_back({"rotation-energy", "rotation-energy", "-", "|E - E0| / E0 after 10 s", Q::Energy, 1.0,
                   "relative energy drift itself", false, Make<RotationError>(true)});
    const double a = kG * (std::sin(M_PI / 6.0) - 0.3 * std::cos(M_PI / 6.0));
    out.push_back({"incline", "incline", "-", "relative acceleration error", Q::Position, 0.5 * a * 1.5 * 1.5,
                   "relative acceleration error x the distance slid, a T^2 / 2 = 2.66 m", false,
                   Make<AccelerationError>()});
    out.push_back({"stack-5", "stack-5", "-", "max drift of any box after 10 s (m)", Q::Position, 1.0,
                   "drift is a position error (m)", false, Make<DriftError>()});
    out.push_back({"stack-10", "stack-10", "-", "max drift of any box after 10 s (m)", Q::Position, 1.0,
                   "drift is a position error (m)", false, Make<DriftError>()});
    out.push_back({"cloth", "cloth", "-3", "RMS particle distance to the converged run (m)", Q::Position, 1.0,
                   "the largest particle distance bounds the RMS distance (m)", false, Make<ClothError>()});
    // The CTest's small grid: cases auto meets today, across particles, springs, a pendulum, bounces, volumes and a
    // stack, so a change that stops it meeting them fails (the full bench reports the others). pendulum-small at
    // 1e-2 and bounce-particle-0.9 were above 3x their budgets before particle worlds were measured over the whole
    // run (spans missed the period error and the bounces).
    for (ReferenceProblem& p : out) {
        if (p.name.rfind("bounce", 0) == 0) p.checkSeconds = 15.0;
        p.fast = p.name == "projectile" || p.name == "spring-damped" || p.name == "spring-energy" ||
                 p.name == "rotation-energy" || p.name == "incline" || p.name == "bounce-sphere-0.9" ||
                 p.name == "stack-5" || p.name == "pendulum-small" || p.name == "bounce-particle-0.9";
    }
    return out;
}

}  // namespace

const std::vector<ReferenceProblem>& ReferenceProblems() {
    static const std::vector<ReferenceProblem> problems = Build();
    return problems;
}

const ReferenceProblem* FindReferenceProblem(const std::string& name) {
    for (const ReferenceProblem& p : ReferenceProblems())
        if (p.name == name) return &p;
    return nullptr;
}

}  // namespace modelchoice
