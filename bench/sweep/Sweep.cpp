// Problem registry and the shared references of psb-sweep.
#include "bench/sweep/Sweep.h"

#include <time.h>

#include <cmath>

namespace sweep {

const std::vector<Problem>& AllProblems() {
    static const std::vector<Problem> problems = [] {
        std::vector<Problem> out;
        AddParticleProblems(&out);
        AddRigidProblems(&out);
        AddClothProblems(&out);
        return out;
    }();
    return problems;
}

namespace {
std::vector<double> gOverride;  // --dt: replaces both lists for the whole run
}  // namespace

void OverrideStepSizes(const std::vector<double>& dts) { gOverride = dts; }

const std::vector<double>& StepSizes() {
    static const std::vector<double> dts{1e-4, 2e-4, 5e-4, 1e-3, 2e-3, 5e-3, 0.01, 0.02, 0.05, 0.1};
    return gOverride.empty() ? dts : gOverride;
}

const std::vector<double>& QuickStepSizes() {
    static const std::vector<double> dts{1e-3, 0.01, 0.05};
    return gOverride.empty() ? dts : gOverride;
}

double CpuNow() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

double EllipticK(double k) {
    // Gauss's arithmetic-geometric mean: K(k) = pi / (2 AGM(1, k')), k' = sqrt(1 - k^2). Converges
    // quadratically; 30 rounds are far more than double precision needs for k < 1.
    double a = 1.0, b = std::sqrt(1.0 - k * k);
    for (int i = 0; i < 30 && std::fabs(a - b) > 1e-16 * a; ++i) {
        const double an = 0.5 * (a + b);
        b = std::sqrt(a * b);
        a = an;
    }
    return M_PI / (2.0 * a);
}

double PendulumPeriod(double length, double g, double theta0) {
    return 4.0 * std::sqrt(length / g) * EllipticK(std::sin(0.5 * theta0));
}

void ApexTracker::Sample(double y, double vy) {
    if (vy > 0.0) {
        rising = true;
        peak = std::fmax(peak, y);
    } else if (rising) {
        rising = false;
        ++apexes;
        peak = std::fmax(peak, y);
        const double e2n = std::pow(e * e, apexes);
        const double ref = c != 0.0 ? e2n * h0 + c * (1.0 - e2n) / (1.0 - e * e) : e2n * h0;
        worst = std::fmax(worst, std::fabs(peak - ref) / ref);
        peak = -std::numeric_limits<double>::infinity();
    }
}

double ApexTracker::Error() const { return apexes < 5 ? std::fmax(worst, 1.0) : worst; }

}  // namespace sweep
