// psb-cloth-bench: CH16 cloth (book settings: spacing 0.2, k_book = -3 -> 100 N/m, friction 0.9, posts) at
// N = 15, 30, 60, 120.
//   1. ms per PhysicsSystem::Update for each integrator at the book's dt = 0.03 (monitor not timed);
//   2. the largest stable dt for each integrator: geometric bisection over [dtMin, dtMax]; a run is stable when
//      the StabilityMonitor (finite, speed <= 1000 m/s, energy gain <= 10 x scale) passes for kSimTime seconds.
// Usage: psb-cloth-bench [--quick]   (--quick: N up to 60, fewer bisection steps)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "Demos/Scenes/Ch16Scene.h"

namespace {

constexpr double kSimTime = 3.0;  // s of simulated time per stability trial (fall 0.8 s, impact, hang)
constexpr float kDtMin = 0.001f, kDtMax = 0.2f;

Ch16Params Params(int n, Integrator integrator, float dt) {
    Ch16Params p;
    p.particlesPerSide = n;
    p.integrator = integrator;
    p.dt = dt;
    return p;
}

double MsPerStep(int n, Integrator integrator, double budgetSeconds) {
    Ch16Scene scene(Params(n, integrator, 0.03f));
    for (int i = 0; i < 5; ++i) scene.System().Update(0.03f);
    using Clock = std::chrono::steady_clock;
    int steps = 0;
    const auto start = Clock::now();
    double elapsed = 0.0;
    while (elapsed < budgetSeconds || steps < 5) {
        scene.System().Update(0.03f);
        ++steps;
        elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    }
    return 1000.0 * elapsed / steps;
}

bool StableAt(int n, Integrator integrator, float dt) {
    Ch16Scene scene(Params(n, integrator, dt));
    const int steps = static_cast<int>(std::ceil(kSimTime / dt));
    for (int i = 0; i < steps; ++i)
        if (!scene.Step(scene.Params().dt)) return false;
    return true;
}

/// Largest dt in [kDtMin, kDtMax] found stable (geometric bisection, kDtMin assumed stable and not run: it
/// is the costliest trial); 0 if no trial was stable.
float LargestStableDt(int n, Integrator integrator, int iterations) {
    if (StableAt(n, integrator, kDtMax)) return kDtMax;
    float lo = kDtMin, hi = kDtMax;
    bool found = false;
    for (int i = 0; i < iterations; ++i) {
        const float mid = std::sqrt(lo * hi);
        const bool stable = StableAt(n, integrator, mid);
        found = found || stable;
        (stable ? lo : hi) = mid;
    }
    return found ? lo : 0.0f;
}

}  // namespace

int main(int argc, char** argv) {
    const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
    std::vector<int> sizes = {15, 30, 60, 120};
    if (quick) sizes.pop_back();
    const int iterations = quick ? 5 : 7;

    std::printf("## ms per step (dt = 0.03, k_book = -3)\n\n| N | particles | springs |");
    for (Integrator in : kAllIntegrators) std::printf(" %s |", ToString(in));
    std::printf("\n|---|---|---|");
    for (size_t i = 0; i < std::size(kAllIntegrators); ++i) std::printf("---|");
    std::printf("\n");
    for (int n : sizes) {
        const Ch16Scene probe(Params(n, Integrator::SemiImplicitEuler, 0.03f));
        const Cloth& c = probe.GetCloth();
        std::printf("| %d | %zu | %zu |", n, c.verts.size(), c.structural.size() + c.shear.size() + c.bend.size());
        for (Integrator in : kAllIntegrators) std::printf(" %.3f |", MsPerStep(n, in, quick ? 0.1 : 0.25));
        std::printf("\n");
        std::fflush(stdout);
    }

    std::printf("\n## largest stable dt in s (%.0f s simulated, bisection in [%.3f, %.3f], %d halvings)\n\n| N |",
                kSimTime, kDtMin, kDtMax, iterations);
    for (Integrator in : kAllIntegrators) std::printf(" %s |", ToString(in));
    std::printf("\n|---|");
    for (size_t i = 0; i < std::size(kAllIntegrators); ++i) std::printf("---|");
    std::printf("\n");
    for (int n : sizes) {
        std::printf("| %d |", n);
        for (Integrator in : kAllIntegrators) {
            std::printf(" %.4f |", LargestStableDt(n, in, iterations));
            std::fflush(stdout);
        }
        std::printf("\n");
    }
    return 0;
}
