// psb-contact-convergence: the contact problems of tests/support/ContactProblems.h at a grid of steps for every
// contact solver (and soft substep counts), one CSV row per run: problem,solver,dt,substeps,h,error_m,cpu_s.
// scripts/plot-contact-convergence.sh draws docs/sweep/contact-*.png from it (docs/soft-solver.md, "Convergence of the
// contact solvers").
//   psb-contact-convergence [--quick] [--problem NAME] [--solver ID] [--grid N] [--dt LIST] [--substeps LIST]
//                           [--min-h S]
// Soft runs whose substep h = dt / substeps is below --min-h (default 1.5e-5 s) are skipped: below about 15 us
// every solver's error grows again from single-precision rounding of v += a h and x += v h (docs/soft-solver.md).
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/ContactProblems.h"

namespace {

using namespace contact_problems;

double CpuNow() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

template <typename T>
bool ParseList(const char* text, std::vector<T>* out) {
    out->clear();
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ',')) {
        std::stringstream one(item);
        T v{};
        if (!(one >> v) || !one.eof() || !(v > T(0))) return false;
        out->push_back(v);
    }
    return !out->empty();
}

int Usage(const char* why, const char* value) {
    std::fprintf(stderr, "psb-contact-convergence: %s '%s'\n", why, value);
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<double> steps{4e-3, 2e-3, 1e-3, 5e-4, 2.5e-4, 1.25e-4};
    std::vector<int> substeps{1, 6, 16, 64};
    std::string onlyProblem, onlySolver;
    int grid = 15;
    double minH = 1.5e-5;
    for (int i = 1; i < argc; ++i) {
        const char* a = argv[i];
        const char* v = i + 1 < argc ? argv[i + 1] : "";
        if (std::strcmp(a, "--quick") == 0) {
            steps = {4e-3, 1e-3};
            substeps = {6};
            grid = 3;
        } else if (std::strcmp(a, "--problem") == 0 && ++i < argc) {
            onlyProblem = v;
        } else if (std::strcmp(a, "--solver") == 0 && ++i < argc) {
            ContactSolver s;
            if (!ParseContactSolver(v, &s)) return Usage("unknown solver", v);
            onlySolver = v;
        } else if (std::strcmp(a, "--grid") == 0 && ++i < argc) {
            grid = std::atoi(v);
            if (grid < 1 || grid > 40) return Usage("grid side must be 1..40, got", v);
        } else if (std::strcmp(a, "--dt") == 0 && ++i < argc) {
            if (!ParseList(v, &steps)) return Usage("bad step list", v);
        } else if (std::strcmp(a, "--min-h") == 0 && ++i < argc) {
            char* end = nullptr;
            minH = std::strtod(v, &end);
            if (end == v || *end != '\0' || !(minH >= 0.0)) return Usage("bad --min-h", v);
        } else if (std::strcmp(a, "--substeps") == 0 && ++i < argc) {
            if (!ParseList(v, &substeps)) return Usage("bad substep list", v);
        } else {
            return Usage("unknown argument", a);
        }
    }
    bool known = onlyProblem.empty();
    for (Problem p : kAllProblems) known = known || onlyProblem == Name(p);
    if (!known) return Usage("unknown problem", onlyProblem.c_str());

    std::printf("problem,solver,dt,substeps,h,error_m,cpu_s\n");
    for (Problem p : kAllProblems) {
        if (!onlyProblem.empty() && onlyProblem != Name(p)) continue;
        for (ContactSolver solver : kAllContactSolvers) {
            if (!onlySolver.empty() && onlySolver != ToString(solver)) continue;
            const bool soft = solver == ContactSolver::Soft;
            for (int n : soft ? substeps : std::vector<int>{1})
                for (double dt : steps) {
                    if (soft && dt / n < minH) continue;
                    Setting s;
                    s.solver = solver;
                    s.dt = dt;
                    s.substeps = n;
                    s.gridSide = grid;
                    const double t0 = CpuNow();
                    const double error = Error(p, s);
                    const double cpu = CpuNow() - t0;
                    std::printf("%s,%s,%g,%d,%g,%.6g,%.3f\n", Name(p), ToString(solver), dt, n, dt / n, error, cpu);
                    std::fflush(stdout);
                }
        }
    }
    return 0;
}
