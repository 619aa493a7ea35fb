// psb-manifold-bench: ns per box-box manifold, CollideBoxes (ContactManifold.h, margin 0.02 m) against the book's
// FindCollisionFeatures (one reused CollisionManifold), on the same pose sets, alternating in one process so both
// see the same machine load; thread CPU time, so time descheduled on a shared machine is not counted. Usage:
// psb-manifold-bench [rounds] Pose sets (seeded):
//   resting   unit cubes on a ground box: resting face down, slid and turned a little, sunk up to 1 cm
//   stacked   unit cube on unit cube, face on face, offsets and turns as above
//   random    random sizes and orientations pushed from touching to 5 cm deep (the test's poses)
//   near      the random set held 0-1 cm apart (only the solver manifold's speculative points)
// Prints per set: ns/call for each, the ratio book / solver, and the mean point counts.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

#include "Math/Random.h"
#include "Physics/Geometry/ContactManifold.h"
#include "Physics/Geometry/Geometry3D.h"
#include "tests/support/BoxPoses.h"

namespace {

struct Pair {
    OBB a, b;
};

std::vector<Pair> Resting(MsvcRand& rng, int n, bool stacked) {
    std::vector<Pair> pairs;
    const OBB ground =
        stacked ? OBB(vec3(0, -0.5f, 0), vec3(0.5f, 0.5f, 0.5f)) : OBB(vec3(0, -0.5f, 0), vec3(50, 0.5f, 50));
    for (int i = 0; i < n; ++i) {
        const vec3 c(rng.Range(-0.1f, 0.1f), 0.5f - rng.Range(0.0f, 0.01f), rng.Range(-0.1f, 0.1f));
        const mat3 o = Rotation3x3(rng.Range(-0.5f, 0.5f), rng.Range(-10, 10), rng.Range(-0.5f, 0.5f));
        pairs.push_back({ground, OBB(c, vec3(0.5f, 0.5f, 0.5f), o)});
    }
    return pairs;
}

std::vector<Pair> Random(MsvcRand& rng, int n, float pushMin, float pushMax) {
    std::vector<Pair> pairs;
    for (int i = 0; i < n; ++i) {
        const TouchingBoxes pose = RandomTouchingBoxes(rng);
        pairs.push_back({pose.a, pose.B(rng.Range(pushMin, pushMax))});
    }
    return pairs;
}

/// This thread's CPU time in ns: time spent descheduled by other processes on a shared machine is not counted.
double ThreadNs() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) * 1e9 + static_cast<double>(t.tv_nsec);
}

double NsSolver(const std::vector<Pair>& pairs, int reps, double* points) {
    ContactManifold m;
    long total = 0;
    const double t0 = ThreadNs();
    for (int r = 0; r < reps; ++r)
        for (const Pair& p : pairs) {
            CollideBoxes(p.a, p.b, 0.02f, &m);
            total += m.pointCount;
        }
    const double ns = ThreadNs() - t0;
    *points = static_cast<double>(total) / (static_cast<double>(reps) * pairs.size());
    return ns / (static_cast<double>(reps) * pairs.size());
}

double NsBook(const std::vector<Pair>& pairs, int reps, double* points) {
    CollisionManifold m;
    long total = 0;
    const double t0 = ThreadNs();
    for (int r = 0; r < reps; ++r)
        for (const Pair& p : pairs) {
            FindCollisionFeatures(p.a, p.b, &m);
            total += static_cast<long>(m.contacts.size());
        }
    const double ns = ThreadNs() - t0;
    *points = static_cast<double>(total) / (static_cast<double>(reps) * pairs.size());
    return ns / (static_cast<double>(reps) * pairs.size());
}

double Median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    const int rounds = argc > 1 ? std::max(1, std::atoi(argv[1])) : 7;
    const bool solverOnly = argc > 2 && std::string(argv[2]) == "solver-only";
    MsvcRand rng(2024);
    struct Set {
        const char* name;
        std::vector<Pair> pairs;
    };
    const Set sets[] = {{"resting", Resting(rng, 1000, false)},
                        {"stacked", Resting(rng, 1000, true)},
                        {"random", Random(rng, 1000, 0.0f, 0.05f)},
                        {"near", Random(rng, 1000, -0.01f, 0.0f)}};
    std::printf("%-8s %12s %12s %8s %14s %14s\n", "set", "book ns", "solver ns", "ratio", "book points",
                "solver points");
    for (const Set& s : sets) {
        std::vector<double> book, solver;
        double bookPoints = 0, solverPoints = 0;
        for (int r = 0; r < rounds; ++r) {
            book.push_back(solverOnly ? 0.0 : NsBook(s.pairs, 20, &bookPoints));
            solver.push_back(NsSolver(s.pairs, 20, &solverPoints));
        }
        const double b = Median(book), m = Median(solver);
        std::printf("%-8s %12.1f %12.1f %8.2f %14.2f %14.2f\n", s.name, b, m, b / m, bookPoints, solverPoints);
    }
    return 0;
}
