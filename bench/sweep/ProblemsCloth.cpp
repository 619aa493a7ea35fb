// Cloth reference problems of psb-sweep: the CH16 cloth (Ch16Scene: 15 x 15 particles 0.2 m apart dropped from
// 6 m onto four posts) after 2 s, against a converged run of the same scene with RK4 at a 4x smaller step than
// the sweep's smallest. Two changes from the demo, both because the demo's values are per-step, not per-second:
// particle friction (per-step velocity factor 0.9) is 1, and the springs get a small axial damping instead
// (book d = 0.02, b = 0.67 N s/m), so the problem converges as dt -> 0.
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "Demos/Scenes/Ch16Scene.h"
#include "bench/sweep/Sweep.h"

namespace sweep {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kSeconds = 2.0;
constexpr double kReferenceDt = 2.5e-5;  // a quarter of StepSizes().front()
constexpr float kBookDamping = 0.02f;

long long StepsFor(double seconds, double dt) { return std::llround(seconds / dt); }

Ch16Params ClothParams(Integrator integrator, double dt, double bookK) {
    Ch16Params p;
    p.integrator = integrator;
    p.dt = float(dt);
    p.springK = float(bookK);
    p.springDamping = kBookDamping;
    return p;
}

std::unique_ptr<Ch16Scene> MakeCloth(const Ch16Params& p) {
    auto scene = std::make_unique<Ch16Scene>(p);
    for (Cloth* c : scene->System().Cloths()) c->SetParticleVelocityRetention(1.0f);
    return scene;
}

std::vector<vec3> Positions(const Ch16Scene& scene) {
    std::vector<vec3> out;
    for (const Particle& p : scene.GetCloth().verts) out.push_back(p.GetPosition());
    return out;
}

/// Converged positions at `seconds` (2 s, or n dt for a step that does not divide 2 s) for a book stiffness,
/// computed once per process.
const std::vector<vec3>& Reference(double bookK, double seconds) {
    static std::map<std::pair<double, long long>, std::vector<vec3>> cache;
    const long long n = StepsFor(seconds, kReferenceDt);
    auto it = cache.find({bookK, n});
    if (it != cache.end()) return it->second;
    auto scene = MakeCloth(ClothParams(Integrator::RK4, kReferenceDt, bookK));
    for (long long i = 0; i < n; ++i) scene->Step(scene->Params().dt);
    return cache[{bookK, n}] = Positions(*scene);
}

double RmsDistance(const std::vector<vec3>& a, const std::vector<vec3>& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) sum += double(MagnitudeSq(a[i] - b[i]));
    return std::sqrt(sum / double(a.size()));
}

/// param = the book's k (velocity change per 0.03 s step per metre; -3 in the demo). The StabilityMonitor of
/// the scene decides "unstable"; its report goes in the note.
Outcome RunCloth(const Settings& s) {
    const long long n = StepsFor(kSeconds, s.dt);
    const std::vector<vec3>& reference = Reference(s.param, double(n) * s.dt);  // before the timer
    auto scene = MakeCloth(ClothParams(s.integrator, s.dt, s.param));
    Outcome o;
    const double t0 = CpuNow();
    long long i = 0;
    bool ok = true;
    while (i < n && ok) {
        ok = scene->Step(scene->Params().dt);
        ++i;
    }
    o.cpuSeconds = CpuNow() - t0;
    o.steps = i;
    o.simSeconds = double(i) * s.dt;
    o.stable = ok;
    if (!ok) {
        o.note = scene->Monitor().Report().message;
        o.error = kInf;
        return o;
    }
    o.error = RmsDistance(Positions(*scene), reference);
    return o;
}

std::vector<Settings> ClothGrid(bool quick, const std::vector<double>& ks) {
    std::vector<Settings> g;
    for (double k : ks)
        for (Integrator integrator : kAllIntegrators) {
            if (quick && integrator != Integrator::SemiImplicitEuler && integrator != Integrator::RK4) continue;
            for (double dt : quick ? std::vector<double>{0.01, 0.05} : StepSizes()) {
                Settings s;
                s.hasIntegrator = true;
                s.integrator = integrator;
                s.dt = dt;
                s.param = k;
                g.push_back(s);
            }
        }
    return g;
}

}  // namespace

void AddClothProblems(std::vector<Problem>* out) {
    out->push_back({"cloth",
                    "CH16 cloth (15x15, book k = -3 as param) after 2 s vs RK4 at dt 2.5e-5; friction 1, book d 0.02",
                    "RMS particle distance to the converged run (m)", "book_k",
                    [](bool q) { return ClothGrid(q, {-3.0}); }, RunCloth});
    out->push_back({"cloth-stiffness", "the CH16 cloth at book k = -1 .. -100 (param): stability map",
                    "RMS particle distance to the converged run (m)", "book_k",
                    [](bool q) {
                        if (q) return std::vector<Settings>{};
                        return ClothGrid(false, {-1.0, -10.0, -30.0, -100.0});
                    },
                    RunCloth});
}

}  // namespace sweep
