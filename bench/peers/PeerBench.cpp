// psb-peer-bench: one scene definition (Demos/Scenes/WorldBuilder.h, PeerBoxpile / PeerPyramid / PeerTower) built
// in Bullet (BulletWorld.h) and in this engine (RigidWorld), run alternately in one process, timed per step, and
// measured for quality with one engine-independent probe. Prints one line of key=value pairs, and with --csv writes
// one row per engine for a docs generator. docs/peers.md has the method, the scenes and the figures.
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "Demos/Scenes/WorldBuilder.h"
#include "Physics/Broadphase.h"
#include "Physics/ContactSolver.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/RigidbodyVolume.h"
#include "bench/peers/BulletWorld.h"

namespace {

constexpr float kDt = 1.0f / 60.0f;
/// Steps at the end of a run over which the deepest penetration is taken (one second at 60 Hz).
constexpr int kPenetrationWindow = 60;

const char kUsage[] =
    "Usage: psb-peer-bench SCENE N [--solver book|accumulated|soft] [--steps S] [--warmup W] [--repeat R]\n"
    "                      [--sleep] [--csv FILE] [--threads T] [--trace FILE]\n"
    "  SCENE N      boxpile N (cubes, 1..100000), pyramid N (base, 1..300) or tower N (height, 1..1000)\n"
    "  --solver S   this engine's contact solver (default accumulated; 10 iterations for accumulated)\n"
    "  --steps S    steps per run at 1/60 s (default 600)\n"
    "  --warmup W   first steps left out of the timing median (default 60, < S)\n"
    "  --repeat R   rounds, each running both engines, Bullet first in odd rounds (default 3)\n"
    "  --sleep      both engines sleep at their defaults (Bullet's deactivation; this engine's islands,\n"
    "               docs/sleep.md); without it neither sleeps\n"
    "  --csv FILE   also write FILE (replaced atomically): header scene,bodies,sleep,threads,engine,\n"
    "               cpu_ms_per_step,ratio_to_bullet,max_displacement_m,stands and one row per engine\n"
    "  --threads T  also run this engine on T threads (1..256) in every round, beside its one-thread run, and\n"
    "               print threads, psb_threads_ms (wall), speedup (psb_ms / psb_threads_ms) and same_state\n"
    "               (1 when both runs end in the same bits); this engine otherwise runs on one thread\n"
    "  --trace FILE also write FILE: header engine,round,step,cpu_us,awake and one row per step of every run\n"
    "               (awake: dynamic bodies not asleep after the step; the ground is not counted)\n"
    "Builds the scene in Bullet and in this engine from one definition and prints one line of key=value pairs:\n"
    "scene, n, solver, sleep (on|off); bullet_ms, psb_ms, ratio (psb / bullet): medians of wall ms per step after the "
    "warm-up,\n"
    "median over rounds; bullet_cpu_ms, psb_cpu_ms, cpu_ratio: the same from this thread's CPU time; each\n"
    "engine's quality: pen (deepest penetration over the last 60 steps, m, measured with this engine's box\n"
    "manifolds on both engines' poses), and ke (final kinetic energy, J) and below (bodies with centre below\n"
    "y = 0) for boxpile, disp (largest |p_end - p_start|, m) for pyramid and tower, drift (top box's x-z\n"
    "distance from its start, m) for tower; steps, warmup, repeat. docs/peers.md has the method.\n";

struct Options {
    std::string scene;
    int n = 0;
    ContactSolver solver = ContactSolver::Accumulated;
    int steps = 600;
    int warmup = 60;
    int repeat = 3;
    bool sleep = false;  // both engines at their default sleeping (--sleep)
    std::string csv;     // --csv FILE, empty: none
    int threads = 0;     // 0: no threaded run
    std::string trace;   // --trace FILE, empty: none
};

/// --trace: one row per step of every run (engine, round, step, CPU microseconds, awake dynamic bodies), for
/// finding where a run spends its time and when each engine's bodies fall asleep.
struct Trace {
    std::FILE* file = nullptr;
    int round = 0;
    void Row(const char* engine, int step, double cpuMs, std::size_t awake) const {
        if (file != nullptr) std::fprintf(file, "%s,%d,%d,%.3f,%zu\n", engine, round, step, 1e3 * cpuMs, awake);
    }
};

/// Quality figures of one run, computed the same way for both engines (Probe).
struct Quality {
    float penetration = 0.0f;  // m
    float kineticEnergy = 0.0f;
    int below = 0;
    float displacement = 0.0f;  // m
    float drift = 0.0f;         // m
};

/// This engine's copy of a scene, fed with either engine's poses: the metrics never depend on which engine
/// produced the state. Penetration is this engine's manifold depth (FindCollisionFeatures) on every pair whose
/// AABBs overlap (Broadphase's sweep).
class Probe {
public:
    explicit Probe(const std::vector<BodySpec>& specs) : bodies(MakeBodies(specs)) {
        start.reserve(bodies.size());
        pointers.reserve(bodies.size());
        for (RigidbodyVolume& b : bodies) {
            start.push_back(b.position);
            pointers.push_back(&b);
        }
    }

    /// Body i takes the pose and velocities `s` (world) and syncs its collision volumes.
    void Set(std::size_t i, const BodyState& s) {
        RigidbodyVolume& b = bodies[i];
        b.position = s.position;
        b.orientation = s.orientation;
        b.velocity = s.velocity;
        b.angVel = s.angularVelocity;
        b.SynchCollisionVolumes();
    }

    /// Deepest penetration over every touching pair of the current poses, m (0 when nothing touches).
    float DeepestPenetration() {
        broadphase.FindPairs(pointers, &pairs);
        float deepest = 0.0f;
        for (const std::pair<int, int>& p : pairs) {
            FindCollisionFeatures(bodies[static_cast<std::size_t>(p.first)], bodies[static_cast<std::size_t>(p.second)],
                                  &manifold);
            if (manifold.colliding && std::isfinite(manifold.depth)) deepest = std::fmax(deepest, manifold.depth);
        }
        return deepest;
    }

    /// The run's quality from the bodies' current states (set from the last step) and the deepest
    /// `penetration` (m) seen over the window.
    Quality Final(float penetration) const {
        Quality q;
        q.penetration = penetration;
        for (std::size_t i = 0; i < bodies.size(); ++i) {
            const RigidbodyVolume& b = bodies[i];
            if (!(b.mass > 0.0f)) continue;
            q.kineticEnergy += 0.5f * b.mass * MagnitudeSq(b.velocity) +
                               0.5f * Dot(b.angVel, MultiplyVector(b.angVel, b.InertiaTensor()));
            if (b.position.y < 0.0f) ++q.below;
            q.displacement = std::fmax(q.displacement, Magnitude(b.position - start[i]));
        }
        const vec3 d = bodies.back().position - start.back();  // the top of a tower is its last body
        q.drift = std::sqrt(d.x * d.x + d.z * d.z);
        return q;
    }

private:
    std::vector<RigidbodyVolume> bodies;
    std::vector<RigidbodyVolume*> pointers;
    std::vector<vec3> start;
    Broadphase broadphase;
    std::vector<std::pair<int, int>> pairs;
    CollisionManifold manifold;
};

/// This engine with the bench's settings: the chosen contact solver, 10 iterations for Accumulated (the book's
/// 5 otherwise), sleeping off or at its defaults (docs/sleep.md), on `threads` threads; damping off comes from the
/// specs.
class PsbEngine {
public:
    PsbEngine(const std::vector<BodySpec>& specs, ContactSolver solver, bool sleep, int threads) : world(specs) {
        WorldSettings& s = world.system.settings;
        s.threads = threads;
        s.contactSolver = solver;
        if (solver == ContactSolver::Accumulated) s.solverIterations = 10;
        s.sleep = SleepSettings();
        s.sleep.enabled = sleep;
    }
    void Step() { world.system.Update(kDt); }
    std::size_t BodyCount() const { return world.Bodies().size(); }
    static const char* Name() { return "psb"; }
    std::size_t AwakeCount() const {
        std::size_t awake = 0;
        for (const RigidbodyVolume& b : world.Bodies())
            if (b.mass > 0.0f && !b.IsSleeping()) ++awake;
        return awake;
    }
    BodyState State(std::size_t i) const {
        const RigidbodyVolume& b = world.Body(i);
        return BodyState{b.position, b.orientation, b.velocity, b.angVel};
    }
    /// Empty unless the world refused a body.
    const std::string& Error() const { return world.system.LastError(); }

private:
    RigidWorld world;
};

/// Bullet with the bench's settings: 10 solver iterations, split impulse, one internal step per frame, bodies kept
/// awake or Bullet's default deactivation.
class BulletEngine {
public:
    BulletEngine(const std::vector<BodySpec>& specs, bool sleep) : world(specs, 10, sleep) {}
    void Step() { world.Step(kDt); }
    std::size_t BodyCount() const { return world.BodyCount(); }
    static const char* Name() { return "bullet"; }
    std::size_t AwakeCount() const { return world.AwakeCount(); }
    BodyState State(std::size_t i) const { return world.State(i); }

private:
    BulletWorld world;
};

double Median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    const std::size_t mid = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(mid), v.end());
    const double upper = v[mid];
    if (v.size() % 2 == 1) return upper;
    return 0.5 * (upper + *std::max_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(mid)));
}

/// CPU time this thread has used, ms. On a busy machine a step's wall time includes the time it waited for a
/// core, and a long step is preempted more often than a short one, so wall medians favour the faster engine; the
/// CPU-time medians are printed beside them (docs/peers.md, "Timing").
double ThreadCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

struct RunResult {
    double msPerStep = 0.0;     // wall clock: median over the steps after the warm-up
    double cpuMsPerStep = 0.0;  // this thread's CPU time: median over the same steps
    Quality quality;
    std::vector<BodyState> end;  // every body's state after the last step
};

/// One full run of `engine`: every step timed on its own; after each of the last kPenetrationWindow steps (not
/// timed) the probe takes the poses and measures penetration.
template <typename Engine>
RunResult Run(Engine& engine, Probe& probe, const Options& o, const Trace& trace) {
    std::vector<double> ms(static_cast<std::size_t>(o.steps)), cpuMs(ms.size());
    float penetration = 0.0f;
    const std::size_t count = engine.BodyCount();
    for (int s = 0; s < o.steps; ++s) {
        const double c0 = ThreadCpuMs();  // outside the wall-clock interval: its system call is not timed
        const auto t0 = std::chrono::steady_clock::now();
        engine.Step();
        const auto t1 = std::chrono::steady_clock::now();
        const double c1 = ThreadCpuMs();
        ms[static_cast<std::size_t>(s)] = std::chrono::duration<double, std::milli>(t1 - t0).count();
        cpuMs[static_cast<std::size_t>(s)] = c1 - c0;
        if (trace.file != nullptr) trace.Row(Engine::Name(), s, c1 - c0, engine.AwakeCount());
        if (s >= o.steps - kPenetrationWindow) {
            for (std::size_t i = 0; i < count; ++i) probe.Set(i, engine.State(i));
            penetration = std::fmax(penetration, probe.DeepestPenetration());
        }
    }
    RunResult r;
    r.msPerStep = Median(std::vector<double>(ms.begin() + o.warmup, ms.end()));
    r.cpuMsPerStep = Median(std::vector<double>(cpuMs.begin() + o.warmup, cpuMs.end()));
    r.quality = probe.Final(penetration);
    for (std::size_t i = 0; i < count; ++i) r.end.push_back(engine.State(i));
    return r;
}

bool ParseInt(const char* text, int* out) {
    if (text == nullptr || *text == '\0') return false;
    char* end = nullptr;
    errno = 0;
    const long v = std::strtol(text, &end, 10);
    if (*end != '\0' || errno != 0 || v < -2147483647L || v > 2147483647L) return false;
    *out = static_cast<int>(v);
    return true;
}

int Usage(const char* message, const char* value) {
    std::fprintf(stderr, "psb-peer-bench: %s '%s'\n%s", message, value, kUsage);
    return 2;
}

/// 0 on success, else the exit code (2) after printing why.
int Parse(int argc, char** argv, Options* o, bool* help) {
    std::vector<const char*> positional;
    for (int i = 1; i < argc; ++i) {
        const char* arg = argv[i];
        if (std::strcmp(arg, "--help") == 0 || std::strcmp(arg, "-h") == 0) {
            *help = true;
            return 0;
        }
        if (std::strncmp(arg, "--", 2) != 0) {
            positional.push_back(arg);
            continue;
        }
        if (std::strcmp(arg, "--sleep") == 0) {
            o->sleep = true;
            continue;
        }
        if (i + 1 >= argc) return Usage("missing value after", arg);
        const char* value = argv[++i];
        if (std::strcmp(arg, "--solver") == 0) {
            if (!ParseContactSolver(value, &o->solver)) {
                std::fprintf(stderr, "psb-peer-bench: unknown --solver '%s' (one of %s)\n", value,
                             ContactSolverIds().c_str());
                return 2;
            }
        } else if (std::strcmp(arg, "--steps") == 0) {
            if (!ParseInt(value, &o->steps) || o->steps < 1 || o->steps > 1000000)
                return Usage("--steps must be an integer in 1..1000000, got", value);
        } else if (std::strcmp(arg, "--warmup") == 0) {
            if (!ParseInt(value, &o->warmup) || o->warmup < 0)
                return Usage("--warmup must be an integer >= 0, got", value);
        } else if (std::strcmp(arg, "--csv") == 0) {
            if (*value == '\0') return Usage("--csv needs a file name, got", value);
            o->csv = value;
        } else if (std::strcmp(arg, "--trace") == 0) {
            if (*value == '\0') return Usage("--trace needs a file name, got", value);
            o->trace = value;
        } else if (std::strcmp(arg, "--threads") == 0) {
            if (!ParseInt(value, &o->threads) || o->threads < 1 || o->threads > 256)
                return Usage("--threads must be an integer in 1..256, got", value);
        } else if (std::strcmp(arg, "--repeat") == 0) {
            if (!ParseInt(value, &o->repeat) || o->repeat < 1 || o->repeat > 1000)
                return Usage("--repeat must be an integer in 1..1000, got", value);
        } else {
            return Usage("unknown option", arg);
        }
    }
    if (positional.size() != 2) {
        std::fprintf(stderr, "psb-peer-bench: expected SCENE N, got %zu argument(s)\n%s", positional.size(), kUsage);
        return 2;
    }
    o->scene = positional[0];
    int limit = 0;
    if (o->scene == "boxpile") {
        limit = 100000;
    } else if (o->scene == "pyramid") {
        limit = 300;
    } else if (o->scene == "tower") {
        limit = 1000;
    } else {
        return Usage("unknown scene (boxpile, pyramid or tower)", positional[0]);
    }
    if (!ParseInt(positional[1], &o->n) || o->n < 1 || o->n > limit) {
        std::fprintf(stderr, "psb-peer-bench: N for %s must be an integer in 1..%d, got '%s'\n", o->scene.c_str(),
                     limit, positional[1]);
        return 2;
    }
    if (o->warmup >= o->steps) {
        std::fprintf(stderr, "psb-peer-bench: --warmup %d must be smaller than --steps %d\n", o->warmup, o->steps);
        return 2;
    }
    return 0;
}

/// A tower or pyramid "stands" while no cube has moved more than this from its start (a tenth of a cube's edge).
constexpr float kStandsDisplacement = 0.1f;
/// A boxpile "stands" (has settled in place) when no cube is below the ground and the final kinetic energy is at
/// most this per cube (a 1 kg cube at 0.14 m/s).
constexpr float kSettledEnergyPerBody = 0.01f;

bool Stands(const Options& o, const Quality& q) {
    if (o.scene == "boxpile") return q.below == 0 && q.kineticEnergy <= kSettledEnergyPerBody * static_cast<float>(o.n);
    return q.displacement <= kStandsDisplacement;
}

/// --csv: the file is written to a temporary name beside it, opened before the run (a bad path fails before any
/// time is spent), and renamed over FILE once complete, so a reader never sees half a file.
class CsvOutput {
public:
    /// False (with the reason on stderr) when the temporary file cannot be created.
    bool Open(const std::string& path) {
        target = path;
        temp = path + ".tmp." + std::to_string(static_cast<long>(getpid()));
        out.open(temp, std::ios::out | std::ios::trunc);
        if (!out) {
            std::fprintf(stderr, "psb-peer-bench: cannot write --csv '%s': %s\n", path.c_str(), std::strerror(errno));
            return false;
        }
        out << "scene,bodies,sleep,threads,engine,cpu_ms_per_step,ratio_to_bullet,max_displacement_m,stands\n";
        return true;
    }
    /// One engine's row; `bodies` counts the dynamic bodies (the ground left out).
    void Row(const Options& o, std::size_t bodies, const char* engine, double cpuMs, double ratio, const Quality& q) {
        char line[256];
        std::snprintf(line, sizeof line, "%s,%zu,%s,%d,%s,%.6g,%.6g,%.6g,%s\n", o.scene.c_str(), bodies,
                      o.sleep ? "on" : "off", 1, engine, cpuMs, ratio, static_cast<double>(q.displacement),
                      Stands(o, q) ? "yes" : "no");
        out << line;
    }
    /// Renames the complete file over the target; false (the temporary removed, the reason on stderr) on failure.
    bool Commit() {
        out.close();
        if (!out || std::rename(temp.c_str(), target.c_str()) != 0) {
            std::fprintf(stderr, "psb-peer-bench: cannot write --csv '%s': %s\n", target.c_str(), std::strerror(errno));
            std::remove(temp.c_str());
            return false;
        }
        return true;
    }
    /// Removes the temporary file when the run fails before Commit.
    void Abandon() {
        out.close();
        std::remove(temp.c_str());
    }

private:
    std::string target, temp;
    std::ofstream out;
};

std::vector<BodySpec> Scene(const Options& o) {
    if (o.scene == "boxpile") return PeerBoxpile(o.n);
    if (o.scene == "pyramid") return PeerPyramid(o.n);
    return PeerTower(o.n);
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    bool help = false;
    if (const int code = Parse(argc, argv, &o, &help)) return code;
    if (help) {
        std::fputs(kUsage, stdout);
        return 0;
    }
    CsvOutput csv;
    if (!o.csv.empty() && !csv.Open(o.csv)) return 2;
    Trace trace;
    if (!o.trace.empty()) {
        trace.file = std::fopen(o.trace.c_str(), "w");
        if (trace.file == nullptr) {
            std::fprintf(stderr, "psb-peer-bench: cannot write --trace '%s': %s\n", o.trace.c_str(),
                         std::strerror(errno));
            if (!o.csv.empty()) csv.Abandon();
            return 2;
        }
        std::fputs("engine,round,step,cpu_us,awake\n", trace.file);
    }
    const std::vector<BodySpec> specs = Scene(o);
    Probe probe(specs);
    std::vector<double> bulletMs, psbMs, bulletCpuMs, psbCpuMs, threadedMs;
    RunResult bullet, psb, threaded;
    for (int round = 0; round < o.repeat; ++round) {
        trace.round = round;
        // Alternate which engine goes first, so neither always runs on a warmer (or busier) machine.
        for (int k = 0; k < 2; ++k) {
            if ((k == 0) == (round % 2 == 0)) {
                BulletEngine engine(specs, o.sleep);
                bullet = Run(engine, probe, o, trace);
                bulletMs.push_back(bullet.msPerStep);
                bulletCpuMs.push_back(bullet.cpuMsPerStep);
            } else {
                PsbEngine engine(specs, o.solver, o.sleep, 1);
                if (!engine.Error().empty()) {
                    if (!o.csv.empty()) csv.Abandon();
                    std::fprintf(stderr, "psb-peer-bench: the scene was refused: %s\n", engine.Error().c_str());
                    return 1;
                }
                psb = Run(engine, probe, o, trace);
                psbMs.push_back(psb.msPerStep);
                psbCpuMs.push_back(psb.cpuMsPerStep);
            }
        }
        if (o.threads > 0) {  // right after this round's one-thread run, on the same scene
            PsbEngine engine(specs, o.solver, o.sleep, o.threads);
            threaded = Run(engine, probe, o, Trace());
            threadedMs.push_back(threaded.msPerStep);
        }
    }
    if (trace.file != nullptr) std::fclose(trace.file);
    const double bMs = Median(bulletMs), pMs = Median(psbMs);
    const double bCpu = Median(bulletCpuMs), pCpu = Median(psbCpuMs);
    if (!o.csv.empty()) {
        const std::string engine = std::string("psb-") + ToString(o.solver);
        csv.Row(o, specs.size() - 1, engine.c_str(), pCpu, bCpu > 0.0 ? pCpu / bCpu : 0.0, psb.quality);
        csv.Row(o, specs.size() - 1, "bullet", bCpu, 1.0, bullet.quality);
        if (!csv.Commit()) return 1;
    }
    std::printf("scene=%s n=%d solver=%s sleep=%s bullet_ms=%.4g psb_ms=%.4g ratio=%.3f", o.scene.c_str(), o.n,
                ToString(o.solver), o.sleep ? "on" : "off", bMs, pMs, bMs > 0.0 ? pMs / bMs : 0.0);
    std::printf(" bullet_cpu_ms=%.4g psb_cpu_ms=%.4g cpu_ratio=%.3f", bCpu, pCpu, bCpu > 0.0 ? pCpu / bCpu : 0.0);
    const Quality& b = bullet.quality;
    const Quality& p = psb.quality;
    std::printf(" bullet_pen=%.4g psb_pen=%.4g", b.penetration, p.penetration);
    if (o.scene == "boxpile") {
        std::printf(" bullet_ke=%.4g psb_ke=%.4g bullet_below=%d psb_below=%d", b.kineticEnergy, p.kineticEnergy,
                    b.below, p.below);
    } else {
        std::printf(" bullet_disp=%.4g psb_disp=%.4g", b.displacement, p.displacement);
        if (o.scene == "tower") std::printf(" bullet_drift=%.4g psb_drift=%.4g", b.drift, p.drift);
    }
    if (o.threads > 0) {
        const double tMs = Median(threadedMs);
        bool same = psb.end.size() == threaded.end.size();
        for (std::size_t i = 0; same && i < psb.end.size(); ++i)
            same = std::memcmp(&psb.end[i], &threaded.end[i], sizeof(BodyState)) == 0;
        std::printf(" threads=%d psb_threads_ms=%.4g speedup=%.3f same_state=%d", o.threads, tMs,
                    tMs > 0.0 ? pMs / tMs : 0.0, same ? 1 : 0);
    }
    std::printf(" steps=%d warmup=%d repeat=%d\n", o.steps, o.warmup, o.repeat);
    return 0;
}
