// psb-rigid-bench: rigid-body scenes at 60 Hz with both contact solvers (ContactSolver.h): the book's
// (ImpulseIteration 5, its default) and the Accumulated sequential-impulse solver (10 passes, warm start 1.0,
// no Baumgarte bias), plus each at the other's pass count where it is cheap. Every row: projection 0.45, slack
// 0.01, damping 0.98 per step, restitution 0.5, friction 0.6.
// Usage: psb-rigid-bench [quick] [solver=book|accumulated]
// Scenes (defined once in Demos/Scenes/WorldBuilder.h, BoxpileScene etc.; unit cube = half extent 1, 1 kg):
//   boxpile N  N unit cubes in columns of 10 (2.2 m apart vertically, 2.5 m grid) dropped on a static ground
//   pyramid B  a 2-D pyramid of unit cubes with base B, resting (0.01 m gaps in x)
//   tower H    one column of H unit cubes, resting
//   bounce e   unit sphere, bottom 10 m above the ground, cor e (ground cor 1, so e = min = e)
// Figures: ms/step (wall clock, this machine), max penetration (deepest manifold depth in the last second), final
// kinetic energy (linear + angular, J), max displacement of any body from its start (m).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "Demos/Scenes/WorldBuilder.h"
#include "Physics/ContactSolver.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/RigidbodyVolume.h"

namespace {

constexpr float kDt = 1.0f / 60.0f;

struct Result {
    double msPerStep = 0;
    float maxPenetration = 0, finalKE = 0, maxDisplacement = 0;
    int steps = 0;
};

/// Which contact solver and how many passes a row uses.
struct SolverSetup {
    ContactSolver solver;
    int iterations;
};

Result Run(RigidWorld& w, int steps, const SolverSetup& setup) {
    PhysicsSystem& system = w.system;
    system.settings.contactSolver = setup.solver;
    system.settings.solverIterations = setup.iterations;
    Result r;
    r.steps = steps;
    const auto t0 = std::chrono::steady_clock::now();
    for (int i = 0; i < steps; ++i) {
        system.Update(kDt);
        if (i >= steps - 60)
            for (std::size_t k = 0; k < system.CollisionCount(); ++k)
                r.maxPenetration = std::fmax(r.maxPenetration, system.Collisions()[k].manifold.depth);
    }
    const auto t1 = std::chrono::steady_clock::now();
    r.msPerStep = std::chrono::duration<double, std::milli>(t1 - t0).count() / steps;
    r.finalKE = w.KineticEnergy();
    r.maxDisplacement = w.MaxDisplacement();
    return r;
}

void Print(const char* name, int size, const SolverSetup& setup, const Result& r) {
    std::printf("| %-8s | %5d | %-11s | %2d | %5d | %9.3f | %8.4f | %10.4g | %8.3f |\n", name, size,
                ToString(setup.solver), setup.iterations, r.steps, r.msPerStep, r.maxPenetration, r.finalKE,
                r.maxDisplacement);
    std::fflush(stdout);
}

/// Apex heights (bottom of the sphere above the ground) of the first bounces.
void Bounce(float e, float damping, const SolverSetup& setup) {
    RigidWorld w(BounceScene(e, damping));
    PhysicsSystem& system = w.system;
    system.settings.contactSolver = setup.solver;
    system.settings.solverIterations = setup.iterations;
    const float h0 = 10.0f;
    std::vector<float> apex;
    float prevVy = 0, maxPen = 0;
    const auto t0 = std::chrono::steady_clock::now();
    const int steps = 600;
    for (int i = 0; i < steps && apex.size() < 3; ++i) {
        system.Update(kDt);
        const RigidbodyVolume& b = w.Body(1);
        if (prevVy > 0 && b.velocity.y <= 0) apex.push_back(b.position.y - 1.0f);
        prevVy = b.velocity.y;
        for (std::size_t k = 0; k < system.CollisionCount(); ++k)
            maxPen = std::fmax(maxPen, system.Collisions()[k].manifold.depth);
    }
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count() / steps;
    std::printf("| %s | %d | %.2f | %.2f | %.4f | %.4f |", ToString(setup.solver), setup.iterations, e, damping, ms,
                maxPen);
    for (std::size_t n = 0; n < 3; ++n) {
        const float expect = std::pow(e, 2.0f * (n + 1)) * h0;
        if (n < apex.size())
            std::printf(" %.3f / %.3f |", apex[n], expect);
        else
            std::printf(" - / %.3f |", expect);
    }
    std::printf("\n");
    std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
    bool quick = false;
    bool only = false;
    ContactSolver onlySolver = ContactSolver::Book;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "quick") {
            quick = true;
        } else if (arg.rfind("solver=", 0) == 0 && ParseContactSolver(arg.substr(7), &onlySolver)) {
            only = true;
        } else {
            std::fprintf(stderr, "psb-rigid-bench: unknown argument '%s' (quick, solver=%s)\n", arg.c_str(),
                         ContactSolverIds().c_str());
            return 2;
        }
    }
    std::printf(
        "Settings: LinearProjectionPercent 0.45, PenetrationSlack 0.01, damping 0.98/step, cor 0.5, friction 0.6, "
        "dt 1/60 s; accumulated: warm start 1.0, Baumgarte 0, restitution above 1 m/s\n\n");
    std::printf("| scene    |  size | solver      | it | steps |  ms/step  | max pen. | final KE J | max disp |\n");
    std::printf("|----------|-------|-------------|----|-------|-----------|----------|------------|----------|\n");
    // Each solver at its own setting (book 5, the book's default; accumulated 10), and for the cheap scenes
    // also at the other's pass count, so cost and quality compare at equal passes.
    const SolverSetup main[] = {{ContactSolver::Book, 5}, {ContactSolver::Accumulated, 10}};
    const SolverSetup all[] = {{ContactSolver::Book, 5},
                               {ContactSolver::Book, 10},
                               {ContactSolver::Accumulated, 5},
                               {ContactSolver::Accumulated, 10}};
    auto wanted = [&](const SolverSetup& setup) { return !only || setup.solver == onlySolver; };
    const int pileSizes[] = {100, 1000, 4000};
    for (int n : pileSizes) {
        if (quick && n > 100) break;
        for (const SolverSetup& setup : main) {
            if (!wanted(setup)) continue;
            RigidWorld w(BoxpileScene(n));
            Print("boxpile", n, setup, Run(w, 600, setup));
        }
    }
    for (int b : {10, 20})
        for (const SolverSetup& setup : all) {
            if (!wanted(setup)) continue;
            RigidWorld w(PyramidScene(b));
            Print("pyramid", b, setup, Run(w, 600, setup));
        }
    for (int h : {10, 20})
        for (const SolverSetup& setup : all) {
            if (!wanted(setup)) continue;
            RigidWorld w(TowerScene(h));
            Print("tower", h, setup, Run(w, 600, setup));
        }
    std::printf(
        "\n| solver | it | e | damping | ms/step | max pen. | apex 1 (got / e^2 h0) | apex 2 (got / e^4 h0) | apex 3 "
        "(got / e^6 h0) "
        "|\n");
    std::printf("|---|---|---|---|---|---|---|---|---|\n");
    for (const SolverSetup& setup : main) {
        if (!wanted(setup)) continue;
        for (float e : {0.5f, 0.8f})
            for (float d : {0.98f, 1.0f}) Bounce(e, d, setup);
    }
    return 0;
}
