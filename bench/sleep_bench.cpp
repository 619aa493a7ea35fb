// psb-sleep-bench: what a settled boxpile costs asleep against the same state awake (docs/sleep.md).
// Usage: psb-sleep-bench [N] [rounds] [solver]   (N cubes, default 4000; rounds of timing, default 5; contact
// solver id, default accumulated)
// Scene: BoxpileScene(N) (Demos/Scenes/WorldBuilder.h), the solver (accumulated: 10 passes; soft: its defaults), 60 Hz.
// World A runs with WorldSettings::sleep on until every cube sleeps (or 1800 steps). World B is built from the same
// definition, given A's positions and orientations (velocities zero) and runs with sleep off: the same settled state,
// awake. B is warmed up for 30 steps (warm-start contacts). Then blocks of 20 steps alternate A, B, A, B ... in this
// one process, so both see the same machine load; printed: the median ms per step of each and their ratio, one
// key=value line.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "Demos/Scenes/WorldBuilder.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/RigidbodyVolume.h"

namespace {

constexpr float kDt = 1.0f / 60.0f;

ContactSolver g_solver = ContactSolver::Accumulated;

void Setup(PhysicsSystem& system, bool sleep) {
    system.settings.contactSolver = g_solver;
    system.settings.solverIterations = 10;
    system.settings.sleep.enabled = sleep;
}

/// ms per step over `steps` steps of w.
double Time(RigidWorld& w, int steps) {
    const auto t0 = std::chrono::steady_clock::now();
    for (int i = 0; i < steps; ++i) w.system.Update(kDt);
    const auto t1 = std::chrono::steady_clock::now();
    return std::chrono::duration<double, std::milli>(t1 - t0).count() / steps;
}

double Median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    const int n = argc > 1 ? std::atoi(argv[1]) : 4000;
    const int rounds = argc > 2 ? std::atoi(argv[2]) : 5;
    if (n <= 0 || rounds <= 0 || (argc > 3 && !ParseContactSolver(argv[3], &g_solver))) {
        std::fprintf(stderr, "usage: psb-sleep-bench [N > 0] [rounds > 0] [solver: %s]\n", ContactSolverIds().c_str());
        return 2;
    }
    const std::vector<BodySpec> specs = BoxpileScene(n);
    RigidWorld asleep(specs);
    Setup(asleep.system, true);
    int settle = 0;
    const auto s0 = std::chrono::steady_clock::now();
    while (asleep.system.SleepIslands().SleepingCount() < static_cast<std::size_t>(n) && settle < 1800) {
        asleep.system.Update(kDt);
        ++settle;
    }
    const double settleSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - s0).count();

    RigidWorld awake(specs);
    Setup(awake.system, false);
    for (std::size_t i = 0; i < specs.size(); ++i) {
        RigidbodyVolume& b = awake.Body(i);
        b.position = asleep.Body(i).position;
        b.orientation = asleep.Body(i).orientation;
        b.velocity = vec3();
        b.angVel = vec3();
        b.SynchCollisionVolumes();
    }
    Time(awake, 30);

    std::vector<double> msAsleep, msAwake;
    for (int r = 0; r < rounds; ++r) {
        msAsleep.push_back(Time(asleep, 20));
        msAwake.push_back(Time(awake, 20));
    }
    const double a = Median(msAsleep), b = Median(msAwake);
    // The soft step's own pairs, speculative ones included (Collisions() lists only the touching ones).
    auto pairs = [](const PhysicsSystem& system) {
        return system.settings.contactSolver == ContactSolver::Soft ? system.SoftSolver().PairCount()
                                                                    : system.CollisionCount();
    };
    std::printf(
        "scene=boxpile n=%d solver=%s settle_steps=%d settle_s=%.1f sleeping=%zu "
        "asleep_ms=%.3f awake_ms=%.3f ratio=%.4f pairs_asleep=%zu pairs_awake=%zu\n",
        n, ToString(g_solver), settle, settleSeconds, asleep.system.SleepIslands().SleepingCount(), a, b, a / b,
        pairs(asleep.system), pairs(awake.system));
    return 0;
}
