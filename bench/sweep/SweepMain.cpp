// psb-sweep: runs the reference problems over their settings and writes one CSV row per run.
// Exit codes: 0 done, 2 bad command line, 3 the output file could not be written (the message names the path and
// the system error; the file is written whole through a temporary, never left cut mid-row: docs/sweep.md).
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "Physics/ContactSolver.h"
#include "Platform/Files/AtomicFile.h"
#include "Platform/Files/TempRegistry.h"
#include "bench/sweep/Sweep.h"

namespace {

constexpr const char* kUsage =
    "usage: psb-sweep [--problem NAME]... [--quick] [--dt LIST] [--shard I/N] [--runs LIST] [--out FILE] [--list]\n"
    "                 [--plan] [--help]\n"
    "Runs the reference problems of docs/sweep.md over their settings; one CSV row per run.\n"
    "  --problem NAME  run only this problem (repeatable; default: every problem --list does not mark\n"
    "                  'not in the default set')\n"
    "  --quick         a small grid per problem (CI)\n"
    "  --shard I/N     run only shard I of N (1 <= I <= N): runs are dealt to shards by estimated cost (steps\n"
    "                  x solver iterations), the same way in every process; the union of the N shards is the\n"
    "                  whole sweep, rows in the same order once concatenated and sorted by run\n"
    "  --dt LIST       comma-separated step sizes (s) replacing the default 1e-4 .. 0.1 grid, e.g. a demo's 0.03\n"
    "  --runs LIST     run only these run indices of the selected grid (comma-separated, e.g. 0,867,1203): the\n"
    "                  same runs, with the same numbers, as in a full run's CSV\n"
    "  --out FILE      write the CSV to FILE instead of stdout\n"
    "  --list          print the problems (name, error measured, swept parameter) and exit\n"
    "  --plan          print the selected grid without running it: per run its index and settings columns\n"
    "                  (the outcome columns empty), e.g. to find a committed row's run today\n"
    "  --help          this text\n"
    "Progress goes to stderr. Columns: run,problem,integrator,dt,substeps,iterations,projection,solver,param,\n"
    "error,cpu_per_sim_s,stable,steps,sim_s,note, then the soft solver's settings soft_substeps,soft_iterations,\n"
    "soft_relax_iterations,soft_contact_hertz,soft_contact_damping_ratio,soft_max_pushout_speed,\n"
    "soft_speculative_margin,soft_linear_slop,soft_restitution_threshold,soft_warm_start_factor ('-' = setting\n"
    "not used by the run; solver = the contact solver of volume problems, book, accumulated or soft; iterations\n"
    "and projection are the book and accumulated solvers' knobs, the soft columns the soft solver's; stable = 1\n"
    "when every sampled state stayed finite and bounded).\n";

constexpr const char* kHeader =
    "run,problem,integrator,dt,substeps,iterations,projection,solver,param,error,cpu_per_sim_s,stable,steps,sim_s,"
    "note,soft_substeps,soft_iterations,soft_relax_iterations,soft_contact_hertz,soft_contact_damping_ratio,"
    "soft_max_pushout_speed,soft_speculative_margin,soft_linear_slop,soft_restitution_threshold,"
    "soft_warm_start_factor\n";

/// A failed write of the CSV: the temporary is already removed; exit 3.
int WriteFailed(const std::string& message) {
    std::cerr << "psb-sweep: " << message << "\n";
    return 3;
}

int Fail(const std::string& message) {
    std::cerr << "psb-sweep: " << message << "\n" << kUsage;
    return 2;
}

std::string Number(double v) {
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

std::string CleanNote(std::string note) {
    for (char& c : note)
        if (c == ',' || c == '\n' || c == '"') c = ';';
    return note;
}

bool ParseShard(const std::string& text, int* index, int* count) {
    const std::size_t slash = text.find('/');
    if (slash == std::string::npos) return false;
    char* end = nullptr;
    const std::string a = text.substr(0, slash), b = text.substr(slash + 1);
    if (a.empty() || b.empty()) return false;
    const long i = std::strtol(a.c_str(), &end, 10);
    if (*end != '\0') return false;
    const long n = std::strtol(b.c_str(), &end, 10);
    if (*end != '\0') return false;
    if (n < 1 || i < 1 || i > n || n > 100000) return false;
    *index = int(i);
    *count = int(n);
    return true;
}

struct Arguments {
    std::vector<const sweep::Problem*> selected;
    bool quick = false, list = false, plan = false;
    int shardIndex = 1, shardCount = 1;
    std::string outPath;
    std::vector<long> runs;  ///< --runs: only these indices of the grid (sorted, unique); empty = all
};

int SetRuns(const std::string& text, Arguments* args) {
    std::stringstream list(text);
    std::string item;
    while (std::getline(list, item, ',')) {
        char* end = nullptr;
        errno = 0;
        const long index = std::strtol(item.c_str(), &end, 10);
        if (item.empty() || *end != '\0' || errno != 0 || index < 0)
            return Fail("bad --runs entry '" + item + "': expected run indices >= 0, comma-separated");
        args->runs.push_back(index);
    }
    if (args->runs.empty()) return Fail("--runs needs at least one run index");
    std::sort(args->runs.begin(), args->runs.end());
    args->runs.erase(std::unique(args->runs.begin(), args->runs.end()), args->runs.end());
    return -1;
}

int AddProblem(const std::string& name, Arguments* args) {
    const std::vector<sweep::Problem>& problems = sweep::AllProblems();
    const sweep::Problem* found = nullptr;
    for (const sweep::Problem& p : problems)
        if (p.name == name) found = &p;
    if (found == nullptr) {
        std::string names;
        for (const sweep::Problem& p : problems) names += (names.empty() ? "" : ", ") + p.name;
        return Fail("unknown problem '" + name + "'; valid: " + names);
    }
    if (std::find(args->selected.begin(), args->selected.end(), found) == args->selected.end())
        args->selected.push_back(found);
    return -1;
}

int SetStepSizes(const std::string& text) {
    std::vector<double> dts;
    std::stringstream list(text);
    std::string item;
    while (std::getline(list, item, ',')) {
        char* end = nullptr;
        const double dt = std::strtod(item.c_str(), &end);
        if (item.empty() || *end != '\0' || !(dt >= 1e-6 && dt <= 1.0))
            return Fail("bad --dt value '" + item + "': expected a number of seconds in [1e-6, 1]");
        dts.push_back(dt);
    }
    if (dts.empty()) return Fail("--dt needs at least one step size");
    sweep::OverrideStepSizes(dts);
    return -1;
}

/// Reads the command line into *args. Returns -1 to go on, else the exit code (--help: 0, bad input: 2).
int ParseArguments(int argc, char** argv, Arguments* args) {
    for (int a = 1; a < argc; ++a) {
        const std::string arg = argv[a];
        const bool hasValue = a + 1 < argc;
        const std::string v = hasValue ? argv[a + 1] : "";
        int code = -1;
        if (arg == "--help" || arg == "-h") {
            std::cout << kUsage;
            return 0;
        } else if (arg == "--list") {
            args->list = true;
        } else if (arg == "--plan") {
            args->plan = true;
        } else if (arg == "--quick") {
            args->quick = true;
        } else if (arg == "--problem") {
            code = hasValue ? AddProblem(v, args) : Fail("--problem needs a name");
        } else if (arg == "--shard") {
            if (!hasValue) return Fail("--shard needs I/N");
            if (!ParseShard(v, &args->shardIndex, &args->shardCount))
                return Fail("bad --shard '" + v + "': expected I/N with integers 1 <= I <= N");
        } else if (arg == "--dt") {
            code = hasValue ? SetStepSizes(v) : Fail("--dt needs a comma-separated list of step sizes");
        } else if (arg == "--runs") {
            code = hasValue ? SetRuns(v, args) : Fail("--runs needs a list of run indices");
        } else if (arg == "--out") {
            if (!hasValue || v.empty()) return Fail("--out needs a file name");
            args->outPath = v;
        } else {
            return Fail("unknown argument '" + arg + "'");
        }
        if (code >= 0) return code;
        if (arg == "--problem" || arg == "--shard" || arg == "--dt" || arg == "--runs" || arg == "--out") ++a;
    }
    return -1;
}

struct Run {
    const sweep::Problem* problem;
    sweep::Settings settings;
    long index;
    double weight;
};

// The whole selected grid in a fixed order (the run index). Shards: longest-processing-time-first dealing of
// an estimated cost, substeps / dt (steps per simulated second) x (1 + iterations / 4) (the solver passes;
// measured on the stacks: 1, 5, 20 iterations cost about 0.6 : 1 : 2.7). Every process computes the same
// deal, so the shards are disjoint and cover the grid; dealing every N-th run instead put all the 1e-4 s
// runs (each inner list has 10 step sizes) on the same shard.
std::vector<Run> ShardRuns(const Arguments& args) {
    std::vector<Run> all;
    for (const sweep::Problem* p : args.selected)
        for (const sweep::Settings& s : p->grid(args.quick)) {
            double iterations = s.iterations > 0 ? double(s.iterations) : 0.0;
            if (s.solver == int(ContactSolver::Soft))  // its passes: (solve + relax) per substep
                iterations = double(s.soft.substeps) * double(s.soft.iterations + s.soft.relaxIterations);
            all.push_back({p, s, long(all.size()), double(s.substeps) / s.dt * (1.0 + iterations / 4.0)});
        }
    std::vector<const Run*> order;
    for (const Run& r : all) order.push_back(&r);
    std::stable_sort(order.begin(), order.end(), [](const Run* a, const Run* b) { return a->weight > b->weight; });
    std::vector<double> load(std::size_t(args.shardCount), 0.0);
    std::vector<char> mine(all.size(), 0);
    for (const Run* r : order) {
        std::size_t least = 0;
        for (std::size_t k = 1; k < load.size(); ++k)
            if (load[k] < load[least]) least = k;
        load[least] += r->weight;
        mine[std::size_t(r->index)] = least == std::size_t(args.shardIndex - 1);
    }
    std::vector<Run> runs;
    for (const Run& r : all)
        if (mine[std::size_t(r.index)] &&
            (args.runs.empty() || std::binary_search(args.runs.begin(), args.runs.end(), r.index)))
            runs.push_back(r);
    return runs;
}

/// --runs names only indices of the selected grid; -1 if so, else exit 2 naming the first that is not.
int CheckRuns(const Arguments& args) {
    long size = 0;
    for (const sweep::Problem* p : args.selected) size += long(p->grid(args.quick).size());
    if (!args.runs.empty() && args.runs.back() >= size)
        return Fail("--runs " + std::to_string(args.runs.back()) + ": the selected grid has runs 0.." +
                    std::to_string(size - 1));
    return -1;
}

/// The settings columns before the outcome: run .. param.
std::string SettingsColumns(const Run& run) {
    const sweep::Settings& s = run.settings;
    std::ostringstream row;
    row << run.index << "," << run.problem->name << "," << (s.hasIntegrator ? ToString(s.integrator) : "-") << ","
        << Number(s.dt) << "," << s.substeps << ","
        << (s.iterations < 0 ? std::string("-") : std::to_string(s.iterations)) << ","
        << (s.projection < 0 ? std::string("-") : std::to_string(s.projection)) << ","
        << (s.solver < 0 ? "-" : ToString(ContactSolver(s.solver))) << ","
        << (run.problem->paramName.empty() ? std::string("-") : Number(s.param));
    return row.str();
}

/// The soft solver's settings columns after the note: its values for a soft run, '-' for any other.
std::string SoftColumns(const sweep::Settings& s) {
    if (s.solver != int(ContactSolver::Soft)) return ",-,-,-,-,-,-,-,-,-,-";
    const SoftSolverSettings& f = s.soft;
    std::ostringstream row;
    row << "," << f.substeps << "," << f.iterations << "," << f.relaxIterations << "," << Number(f.contactHertz) << ","
        << Number(f.contactDampingRatio) << "," << Number(f.maxPushoutSpeed) << "," << Number(f.speculativeMargin)
        << "," << Number(f.linearSlop) << "," << Number(f.restitutionThreshold) << "," << Number(f.warmStartFactor);
    return row.str();
}

std::string Row(const Run& run, const sweep::Outcome& o) {
    const double cost = o.simSeconds > 0.0 ? o.cpuSeconds / o.simSeconds : 0.0;
    std::ostringstream row;
    row << SettingsColumns(run) << "," << Number(o.error) << "," << Number(cost) << "," << (o.stable ? 1 : 0) << ","
        << o.steps << "," << Number(o.simSeconds) << "," << CleanNote(o.note) << SoftColumns(run.settings) << "\n";
    return row.str();
}

/// --plan: the CSV with the settings of every selected run and empty outcome columns; nothing runs.
int WritePlan(const std::vector<Run>& runs) {
    std::cout << kHeader;
    for (const Run& run : runs) std::cout << SettingsColumns(run) << ",,,,,," << SoftColumns(run.settings) << "\n";
    return std::cout.flush() ? 0 : WriteFailed("cannot write to standard output");
}

/// Runs every run and writes the CSV: to stdout, or with --out whole through a temporary beside the file,
/// opened before the first run so an unwritable path costs nothing. Exit 0, or 3 on a failed write.
int RunAndWrite(const std::vector<Run>& runs, const std::string& outPath) {
    AtomicFile file;
    std::string error;
    const auto emit = [&](const std::string& text) {
        if (outPath.empty()) return bool(std::cout << text << std::flush);
        return file.Write(text.data(), text.size(), &error);
    };
    if (!outPath.empty() && !file.Open(outPath, &error)) return WriteFailed(error);
    if (!emit(kHeader)) return WriteFailed(outPath.empty() ? "cannot write to standard output" : error);
    const double start = sweep::CpuNow();
    for (std::size_t r = 0; r < runs.size(); ++r) {
        const Run& run = runs[r];
        const sweep::Settings& s = run.settings;
        const sweep::Outcome o = run.problem->run(s);
        if (!emit(Row(run, o))) return WriteFailed(outPath.empty() ? "cannot write to standard output" : error);
        std::cerr << "[" << (r + 1) << "/" << runs.size() << "] " << run.problem->name << " "
                  << (s.hasIntegrator ? ToString(s.integrator) : "")
                  << (s.solver < 0 ? "" : ToString(ContactSolver(s.solver))) << " dt=" << Number(s.dt)
                  << (s.param != 0.0 ? " param=" + Number(s.param) : "") << " error=" << Number(o.error)
                  << (o.stable ? "" : " UNSTABLE") << "\n";
    }
    std::cerr << "psb-sweep: " << runs.size() << " runs in " << Number(sweep::CpuNow() - start) << " s CPU\n";
    if (!outPath.empty() && !file.Commit(&error)) return WriteFailed(error);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    InstallTemporaryCleanupOnSignals("psb-sweep");
    Arguments args;
    const int code = ParseArguments(argc, argv, &args);
    if (code >= 0) return code;
    if (args.list) {
        for (const sweep::Problem& p : sweep::AllProblems())
            std::cout << p.name << (p.inDefault ? "" : " (not in the default set)") << "\t" << p.errorUnit << "\t"
                      << (p.paramName.empty() ? "-" : p.paramName) << "\t" << p.description << "\n";
        return std::cout.flush() ? 0 : WriteFailed("cannot write to standard output");
    }
    if (args.selected.empty())
        for (const sweep::Problem& p : sweep::AllProblems())
            if (p.inDefault) args.selected.push_back(&p);
    if (const int bad = CheckRuns(args); bad >= 0) return bad;
    if (args.plan) return WritePlan(ShardRuns(args));
    return RunAndWrite(ShardRuns(args), args.outPath);
}
