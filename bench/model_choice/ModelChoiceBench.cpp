// psb-model-choice-bench: `model: auto` against the sweep (docs/model-choice-validation.md). Each reference problem
// runs as its scene file (scenes/reference/) with auto at budgets of 1e-1, 1e-2 and 1e-3 in the problem's own error
// unit, and side by side with the cheapest setting of the full sweep (docs/sweep/results.csv) that meets the same
// budget, the book's model at 0.03 s and the most accurate setting of the sweep, all through the same FileScene path.
// Timings are reported, never asserted: the exit code is 0 unless something could not run (2 bad usage, 3 a run or
// file failed). --check runs each scene at settings the sweep ran and compares the errors with the sweep's own.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "Demos/Scenes/AutoModel.h"
#include "Demos/Scenes/FileScene.h"
#include "Demos/Scenes/SceneFile.h"
#include "Physics/WorldCopy.h"
#include "Platform/Files/AtomicFile.h"
#include "bench/model_choice/ReferenceProblems.h"
#include "bench/model_choice/Runs.h"
#include "bench/model_choice/SweepRows.h"
#include "bench/sweep/Sweep.h"

using namespace modelchoice;

namespace {

constexpr const char* kUsage =
    "usage: psb-model-choice-bench [--problem NAME]... [--budgets LIST] [--quick] [--check] [--out FILE.md]\n"
    "                              [--csv FILE.csv] [--scenes DIR] [--results FILE] [--explain] [--list]\n"
    "Runs `model: auto` on the sweep's reference problems (scenes/reference/*.json) at error budgets in each\n"
    "problem's unit and compares it with the cheapest sweep setting meeting the same budget, the book's model\n"
    "at 0.03 s and the most accurate sweep setting (docs/model-choice-validation.md).\n"
    "  --problem NAME  only this problem (repeatable; --list names them)\n"
    "  --budgets LIST  comma-separated budgets (default 0.1,0.01,0.001)\n"
    "  --quick         the CTest's small grid: the fast problems at 0.1,0.01, one run each, no book or most\n"
    "                  accurate columns\n"
    "  --check         run each scene at settings the sweep also ran and compare its error with the sweep's own\n"
    "                  run (linked) and with results.csv; exit 1 on a mismatch\n"
    "  --out FILE      write the markdown report (tables, criteria) to FILE\n"
    "  --csv FILE      write auto's points: problem,budget,...,error,cpu_per_sim_s (for the sweep figures)\n"
    "  --scenes DIR    the reference scene files (default: the source tree's scenes/reference)\n"
    "  --results FILE  the full sweep (default: the source tree's docs/sweep/results.csv)\n"
    "  --explain       print auto's candidates (AutoModel::Explain) and its log for every case on stderr\n"
    "  --safety S      auto's safety factor (default 2: a candidate meets a budget when S x estimate <= budget),\n"
    "                  to measure what another factor buys in accuracy and costs\n"
    "  --cpu-limit S   the CPU seconds auto's choice may spend (default 1, as in the app; 0: no limit, so the\n"
    "                  choice does not depend on timing, as in the CTest)\n";

std::string Num(double v, int digits = 3) {
    if (std::isinf(v)) return "inf";
    char text[32];
    std::snprintf(text, sizeof text, "%.*g", digits, v);
    return text;
}

bool LoadScene(const std::string& dir, const ReferenceProblem& p, SceneDescription* d) {
    std::vector<std::string> errors;
    if (LoadSceneFile(dir + "/" + p.name + ".json", d, &errors)) return true;
    for (const std::string& e : errors) std::cerr << "psb-model-choice-bench: " << e << "\n";
    return false;
}

bool Write(const std::string& path, const std::string& text) {
    std::string error;
    if (WriteFileAtomic(path, std::vector<std::uint8_t>(text.begin(), text.end()), &error)) return true;
    std::cerr << "psb-model-choice-bench: " << error << "\n";
    return false;
}

// ---- --check: the scene files are the sweep's problems.

/// The settings each problem is checked at: the book's integrator or solver at a sweep step, and RK4 or the soft
/// solver, both at 0.01 s.
std::vector<SweepRow> CheckSettings(const ReferenceProblem& p) {
    std::vector<SweepRow> out;
    SweepRow r;
    r.problem = p.sweepProblem;
    r.param = p.sweepParam;
    r.dt = 0.01;
    const bool volumes = p.name.rfind("bounce-sphere", 0) == 0 || p.name == "incline" || p.name.rfind("stack", 0) == 0;
    const bool rotation = p.name.rfind("rotation", 0) == 0;
    if (rotation) {
        r.integrator = r.solver = "-";
        out.push_back(r);
    } else if (volumes) {
        r.integrator = "-";
        r.solver = "book";
        r.iterations = 5;
        r.projection = 1;
        out.push_back(r);
        r.solver = "soft";
        r.iterations = r.projection = -1;
        r.softSubsteps = 4;
        out.push_back(r);
    } else {
        r.solver = "-";
        r.integrator = "euler";
        out.push_back(r);
        if (p.name != "cloth") {  // the cloth's converged reference is the costly part: one setting
            r.integrator = "rk4";
            out.push_back(r);
        }
    }
    return out;
}

int Check(const std::vector<const ReferenceProblem*>& problems, const std::string& scenes,
          const std::vector<SweepRow>& rows) {
    std::printf(
        "| problem | setting | sweep (run now) | results.csv | scene file | relative difference |\n"
        "|---|---|---|---|---|---|\n");
    int bad = 0;
    for (const ReferenceProblem* p : problems) {
        SceneDescription d;
        if (!LoadScene(scenes, *p, &d)) return 3;
        const sweep::Problem* sp = nullptr;
        for (const sweep::Problem& q : sweep::AllProblems())
            if (q.name == p->sweepProblem) sp = &q;
        if (sp == nullptr) return 3;
        const double seconds = p->checkSeconds > 0.0 ? p->checkSeconds : double(d.duration);
        for (const SweepRow& setting : CheckSettings(*p)) {
            const std::vector<sweep::Settings> grid = sp->grid(false);
            auto s =
                std::find_if(grid.begin(), grid.end(), [&](const sweep::Settings& g) { return setting.Matches(g); });
            if (s == grid.end()) {
                std::cerr << "psb-model-choice-bench: " << p->name << ": " << setting.Describe()
                          << " not in the grid\n";
                return 3;
            }
            const double swept = sp->run(*s).error;
            Assignments a = setting.ToAssignments();
            a.pop_back();  // dt: RunSweepStyle sets it
            auto diff = [&](double e) { return e == swept ? 0.0 : std::fabs(e - swept) / std::fabs(swept); };
            const RunResult file = RunSweepStyle(d, *p, a, setting.dt, seconds);
            if (!file.ok) {
                std::cerr << "psb-model-choice-bench: " << p->name << ": " << file.message << "\n";
                return 3;
            }
            std::string csv = "not in results.csv";
            for (const SweepRow& r : rows)
                if (r.problem == setting.problem && r.param == setting.param && r.Describe() == setting.Describe())
                    csv = Num(r.error, 6);
            const bool identical = diff(file.error) <= 1e-9;
            bad += identical ? 0 : 1;
            std::printf("| %s | %s | %s | %s | %s | %s%s |\n", p->name.c_str(), setting.Describe().c_str(),
                        Num(swept, 9).c_str(), csv.c_str(), Num(file.error, 9).c_str(),
                        Num(diff(file.error), 2).c_str(), identical ? "" : " MISMATCH");
        }
    }
    return bad == 0 ? 0 : 1;
}

// ---- the validation.

struct Case {
    const ReferenceProblem* problem = nullptr;
    double budget = 0.0;
    double autoBound = 0.0;
    RunResult autoRun;
    const SweepRow* cheapest = nullptr;
    RunResult cheapestRun;
    /// The cheapest sweep setting meeting the budget over auto's safety factor: what auto would choose among the
    /// sweep's settings if its estimates were exact and free (nullptr where none does, or in --quick).
    const SweepRow* margin = nullptr;
    RunResult marginRun;
    double own = NAN;  ///< OwnQuantity of auto's run
    bool Ran() const { return autoRun.ok && !autoRun.refused; }
    bool Within() const { return Ran() ? autoRun.error <= budget : cheapest == nullptr; }
    bool Under3x() const { return !Ran() || autoRun.error <= 3.0 * budget; }
    double CostRatio() const {
        return Ran() && cheapest != nullptr && cheapestRun.cpuPerSimSecond > 0.0
                   ? autoRun.cpuPerSimSecond / cheapestRun.cpuPerSimSecond
                   : NAN;
    }
    /// The margin setting's CPU over the cheapest's: what the safety factor alone costs.
    double MarginRatio() const {
        return cheapest != nullptr && margin != nullptr && cheapestRun.cpuPerSimSecond > 0.0
                   ? marginRun.cpuPerSimSecond / cheapestRun.cpuPerSimSecond
                   : NAN;
    }
};

/// Auto's own quantity at the end of the run (its budget's: the largest body distance, m, or |E - E_ref| / |E0|)
/// against the most accurate sweep setting's run, which stands for the exact run; NAN when either did not run or
/// they ended at different times.
double OwnQuantity(const RunResult& run, const RunResult& reference, BudgetQuantity quantity) {
    if (run.refused || !run.ok || reference.endPositions.empty() || !std::isfinite(run.error) ||
        std::fabs(run.simSeconds - reference.simSeconds) > 1e-9 ||
        run.endPositions.size() != reference.endPositions.size())
        return NAN;
    if (quantity == BudgetQuantity::Energy)
        return std::fabs(run.endEnergy - reference.endEnergy) / std::fabs(reference.startEnergy);
    double worst = 0.0;
    for (std::size_t i = 0; i + 2 < run.endPositions.size(); i += 3) {
        const double dx = run.endPositions[i] - reference.endPositions[i],
                     dy = run.endPositions[i + 1] - reference.endPositions[i + 1],
                     dz = run.endPositions[i + 2] - reference.endPositions[i + 2];
        worst = std::fmax(worst, std::sqrt(dx * dx + dy * dy + dz * dz));
    }
    return worst;
}

struct ProblemRuns {
    const ReferenceProblem* problem;
    RunResult book, accurate;
    const SweepRow* accurateRow = nullptr;
    double probeCpuSeconds = 0.0;  ///< one probe's build: a WorldCopy of the host's world
};

/// CPU s of what auto does before a probe runs a step: copy the host's world (Physics/WorldCopy.h, what
/// Physics/ModelChoice/Probes.cpp's probes are). The fastest of five batches of 200.
double ProbeBuildCpuSeconds(const SceneDescription& d) {
    FileScene host(d);
    double best = INFINITY;
    for (int batch = 0; batch < 5; ++batch) {
        const double start = sweep::CpuNow();
        for (int i = 0; i < 200; ++i) {
            const WorldCopy probe(host.System());
            if (probe.System().Bodies().size() != host.System().Bodies().size()) std::abort();  // keeps the copy
        }
        best = std::min(best, (sweep::CpuNow() - start) / 200.0);
    }
    return best;
}

std::string Verdict(const Case& c) {
    if (!c.autoRun.ok) return "failed: " + c.autoRun.message;
    if (c.autoRun.refused)
        return c.cheapest == nullptr ? "refused; the sweep has none either" : "refused; the sweep has one";
    std::string v = c.autoRun.error <= c.budget         ? "within"
                    : c.autoRun.error <= 3.0 * c.budget ? "over (< 3x)"
                                                        : "OVER 3x";
    if (c.cheapest == nullptr) v += "; the sweep has none";
    return v;
}

/// The markdown report. `safety` is the factor auto ran with (its margin settings meet the budget over it).
std::string Report(const std::vector<Case>& cases, const std::vector<ProblemRuns>& perProblem, bool quick,
                   double safety, const std::string& command) {
    std::ostringstream md;
    char date[64];
    const std::time_t now = std::time(nullptr);
    std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    md << "Made by `" << command << "` on " << date << ".\n\n";
    md << "| problem | budget | auto budget | auto's model | error | error / budget | verdict | CPU s per s | "
          "auto's overhead, CPU s | cheapest in the sweep | its error here | its CPU s per s | cost auto / cheapest | "
          "auto's quantity at the end: estimated, measured |\n";
    md << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Case& c : cases) {
        const ReferenceProblem& p = *c.problem;
        std::string model = c.Ran() ? c.autoRun.chosen : std::string("refused");
        if (c.Ran() && c.autoRun.switches > 0)
            model += " -> " + c.autoRun.model + " (" + std::to_string(c.autoRun.switches) + " log lines)";
        md << "| " << p.name << " | " << Num(c.budget) << " | " << Num(c.autoBound) << " " << ToString(p.quantity)
           << " | " << model << " | " << (c.Ran() ? Num(c.autoRun.error) : "-") << " | "
           << (c.Ran() ? Num(c.autoRun.error / c.budget) : "-") << " | " << Verdict(c) << " | "
           << (c.Ran() ? Num(c.autoRun.cpuPerSimSecond) : "-") << " | " << Num(c.autoRun.overheadCpuSeconds) << " | "
           << (c.cheapest ? c.cheapest->Describe() : "none") << " | " << (c.cheapest ? Num(c.cheapestRun.error) : "-")
           << " | " << (c.cheapest ? Num(c.cheapestRun.cpuPerSimSecond) : "-") << " | "
           << (std::isnan(c.CostRatio()) ? "-" : Num(c.CostRatio(), 2)) << " | "
           << (c.Ran() ? Num(c.autoRun.estimate) : "-") << ", " << (std::isnan(c.own) ? "-" : Num(c.own)) << " |\n";
    }
    int ran = 0, within = 0, under3 = 0, costed = 0, cheapEnough = 0, refusedRight = 0, refusedWrong = 0;
    for (const Case& c : cases) {
        within += c.Within() ? 1 : 0;
        under3 += c.Under3x() ? 1 : 0;
        if (c.Ran()) ++ran;
        if (c.autoRun.refused) (c.cheapest == nullptr ? refusedRight : refusedWrong)++;
        if (!std::isnan(c.CostRatio())) {
            ++costed;
            cheapEnough += c.CostRatio() <= 2.0 ? 1 : 0;
        }
    }
    const int n = int(cases.size());
    md << "\n**Criteria** (" << n << " cases; a refusal counts as within budget when the sweep has no setting "
       << "meeting it either):\n\n";
    md << "- within budget: " << within << " / " << n << " = " << Num(100.0 * within / std::max(n, 1), 3)
       << " % (criterion >= 90 %: " << (within >= 0.9 * n ? "met" : "NOT met") << ")\n";
    md << "- never above 3x the budget: " << under3 << " / " << n << " (" << (under3 == n ? "met" : "NOT met") << ")\n";
    md << "- cost at most 2x the cheapest sweep setting meeting the budget: " << cheapEnough << " / " << costed
       << " cases where both ran (" << (cheapEnough == costed ? "met" : "NOT met") << ")\n";
    md << "- refused: " << refusedRight << " with no sweep setting meeting the budget either, " << refusedWrong
       << " where the sweep has one\n";
    if (!quick) {
        // The same cases with a fixed model: the book's at 0.03 s and the sweep's most accurate, against auto.
        int bookWithin = 0, accurateWithin = 0;
        std::vector<double> accurateOverAuto;
        for (const Case& c : cases)
            for (const ProblemRuns& r : perProblem)
                if (r.problem == c.problem) {
                    bookWithin += r.book.error <= c.budget ? 1 : 0;
                    accurateWithin += r.accurateRow && r.accurate.error <= c.budget ? 1 : 0;
                    if (c.Ran() && r.accurateRow && c.autoRun.cpuPerSimSecond > 0.0)
                        accurateOverAuto.push_back(r.accurate.cpuPerSimSecond / c.autoRun.cpuPerSimSecond);
                }
        std::sort(accurateOverAuto.begin(), accurateOverAuto.end());
        md << "- the book's model at 0.03 s is within budget in " << bookWithin << " / " << n
           << " cases; the most accurate sweep setting in " << accurateWithin << " / " << n;
        if (!accurateOverAuto.empty())
            md << ", at a median " << Num(accurateOverAuto[accurateOverAuto.size() / 2], 2)
               << " times auto's CPU where auto ran (from " << Num(accurateOverAuto.front(), 2) << " to "
               << Num(accurateOverAuto.back(), 2) << ")";
        md << "\n";
        int margined = 0, marginUnder2 = 0, autoOverMarginUnder2 = 0;
        for (const Case& c : cases)
            if (!std::isnan(c.MarginRatio()) && !std::isnan(c.CostRatio())) {
                ++margined;
                marginUnder2 += c.MarginRatio() <= 2.0 ? 1 : 0;
                autoOverMarginUnder2 += c.CostRatio() / c.MarginRatio() <= 2.0 ? 1 : 0;
            }
        md << "- the safety factor's share: the cheapest sweep setting meeting the budget over " << Num(safety)
           << " (auto's safety factor; what auto would run, among the sweep's settings, if its estimates were exact "
              "and cost nothing) is within 2x of the cheapest meeting the budget in "
           << marginUnder2 << " / " << margined << " cases where auto ran; auto is within 2x of that setting in "
           << autoOverMarginUnder2 << " / " << margined << "\n";
        md << "\n**The same problems with fixed models** (the book's model at the host step 0.03 s; the most accurate "
              "setting of the sweep):\n\n";
        md << "| problem | book's model at 0.03 s: error | CPU s per s | most accurate in the sweep | its error | "
              "CPU s per s | one probe's build, CPU s |\n|---|---|---|---|---|---|---|\n";
        for (const ProblemRuns& r : perProblem)
            md << "| " << r.problem->name << " | " << Num(r.book.error) << " | " << Num(r.book.cpuPerSimSecond) << " | "
               << (r.accurateRow ? r.accurateRow->Describe() : "none") << " | " << Num(r.accurate.error) << " | "
               << Num(r.accurate.cpuPerSimSecond) << " | " << Num(r.probeCpuSeconds) << " |\n";
        md << "\n**The safety factor's share of the cost** (the cheapest sweep setting meeting the budget over "
           << Num(safety)
           << ", run side by side like the others; \"over the cheapest\": its CPU over the cheapest "
              "setting meeting the budget, under 1 where the sweep's own timings, which pick both, ranked them the "
              "other way; "
              "\"auto over it\": auto's CPU, calibration included, over its CPU):\n\n";
        md << "| problem | budget | cheapest meeting the budget / " << Num(safety)
           << " | its error here | its CPU s per s | over the cheapest | auto over it "
              "|\n|---|---|---|---|---|---|---|\n";
        for (const Case& c : cases) {
            if (c.cheapest == nullptr) continue;
            const double ratio = c.MarginRatio();
            const double autoOver = c.CostRatio() / ratio;
            md << "| " << c.problem->name << " | " << Num(c.budget) << " | "
               << (c.margin ? c.margin->Describe() : "none") << " | " << (c.margin ? Num(c.marginRun.error) : "-")
               << " | " << (c.margin ? Num(c.marginRun.cpuPerSimSecond) : "-") << " | "
               << (std::isnan(ratio) ? "-" : Num(ratio, 2)) << " | " << (std::isnan(autoOver) ? "-" : Num(autoOver, 2))
               << " |\n";
        }
    }
    return md.str();
}

/// A CSV cell: commas become semicolons ("verlet; dt 0.1 s").
std::string NoCommas(std::string text) {
    std::replace(text.begin(), text.end(), ',', ';');
    return text;
}

std::string Csv(const std::vector<Case>& cases) {
    std::ostringstream csv;
    csv << "problem,sweep_problem,param,budget,quantity,auto_bound,refused,model,error,cpu_per_sim_s,"
           "overhead_cpu_s,switches,cheapest,cheapest_error,cheapest_cpu_per_sim_s,cost_ratio,own_quantity,margin,"
           "margin_error,margin_cpu_per_sim_s\n";
    for (const Case& c : cases) {
        const ReferenceProblem& p = *c.problem;
        csv << p.name << "," << p.sweepProblem << "," << p.sweepParam << "," << Num(c.budget, 6) << ","
            << ToString(p.quantity) << "," << Num(c.autoBound, 6) << "," << (c.autoRun.refused ? 1 : 0) << ","
            << NoCommas(c.Ran() ? c.autoRun.model : "refused") << "," << (c.Ran() ? Num(c.autoRun.error, 6) : "-")
            << "," << Num(c.autoRun.cpuPerSimSecond, 6) << "," << Num(c.autoRun.overheadCpuSeconds, 6) << ","
            << c.autoRun.switches << "," << (c.cheapest ? c.cheapest->Describe() : "-") << ","
            << (c.cheapest ? Num(c.cheapestRun.error, 6) : "-") << ","
            << (c.cheapest ? Num(c.cheapestRun.cpuPerSimSecond, 6) : "-") << ","
            << (std::isnan(c.CostRatio()) ? "-" : Num(c.CostRatio(), 4)) << ","
            << (std::isnan(c.own) ? "-" : Num(c.own, 6)) << "," << (c.margin ? c.margin->Describe() : "-") << ","
            << (c.margin ? Num(c.marginRun.error, 6) : "-") << ","
            << (c.margin ? Num(c.marginRun.cpuPerSimSecond, 6) : "-") << "\n";
    }
    return csv.str();
}

std::vector<double> ParseList(const std::string& text) {
    std::vector<double> out;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        char* end = nullptr;
        const double v = std::strtod(item.c_str(), &end);
        if (end == item.c_str() || *end != '\0' || !(v > 0.0) || !std::isfinite(v)) return {};
        out.push_back(v);
    }
    return out;
}

int Usage(const std::string& message) {
    std::cerr << "psb-model-choice-bench: " << message << "\n" << kUsage;
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    std::string scenes = std::string(PSB_SOURCE_DIR) + "/scenes/reference";
    std::string results = std::string(PSB_SOURCE_DIR) + "/docs/sweep/results.csv";
    std::string out, csvOut;
    std::vector<std::string> names;
    std::vector<double> budgets{0.1, 0.01, 0.001};
    bool quick = false, check = false, budgetsGiven = false, explain = false;
    ChoiceSettings tuning;  // auto's; --safety sets its safety factor
    std::string command = "psb-model-choice-bench";
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string { return i + 1 < argc ? argv[++i] : std::string(); };
        if (a == "--help") {
            std::cout << kUsage;
            return 0;
        } else if (a == "--list") {
            for (const ReferenceProblem& p : ReferenceProblems())
                std::cout << p.name << ": " << p.errorUnit << " -> " << ToString(p.quantity)
                          << " at 0.1: " << p.AutoBound(0.1) << "\n";
            return 0;
        } else if (a == "--problem") {
            names.push_back(value());
            if (FindReferenceProblem(names.back()) == nullptr) return Usage("unknown problem '" + names.back() + "'");
        } else if (a == "--budgets") {
            budgets = ParseList(value());
            budgetsGiven = true;
            if (budgets.empty()) return Usage("--budgets: a comma-separated list of finite positive numbers");
        } else if (a == "--quick") {
            quick = true;
        } else if (a == "--check") {
            check = true;
        } else if (a == "--explain") {
            explain = true;
        } else if (a == "--safety") {
            const std::vector<double> v = ParseList(value());
            if (v.size() != 1 || v[0] < 1.0) return Usage("--safety: one finite number of at least 1");
            tuning.safety = v[0];
        } else if (a == "--cpu-limit") {
            const std::string text = value();
            char* end = nullptr;
            const double v = std::strtod(text.c_str(), &end);
            if (end == text.c_str() || *end != '\0' || !(v >= 0.0) || !std::isfinite(v)) {
                return Usage("--cpu-limit: one finite number of at least 0 (got '" + text + "')");
            }
            tuning.cpuLimit = v > 0.0 ? v : std::numeric_limits<double>::infinity();
        } else if (a == "--out") {
            out = value();
        } else if (a == "--csv") {
            csvOut = value();
        } else if (a == "--scenes") {
            scenes = value();
        } else if (a == "--results") {
            results = value();
        } else {
            return Usage("unknown argument '" + a + "'");
        }
        if (a != "--scenes" && a != "--results" && a != "--out" && a != "--csv") command += " " + a;
        if (a == "--problem" || a == "--budgets" || a == "--safety" || a == "--cpu-limit")
            command += " " + std::string(argv[i]);
    }
    std::vector<const ReferenceProblem*> problems;
    for (const ReferenceProblem& p : ReferenceProblems())
        if (names.empty() ? (!quick || p.fast) : std::find(names.begin(), names.end(), p.name) != names.end())
            problems.push_back(&p);
    if (quick && !budgetsGiven) budgets = {0.1, 0.01};
    std::vector<SweepRow> rows;
    std::string error;
    if (!ReadSweepRows(results, &rows, &error)) {
        std::cerr << "psb-model-choice-bench: " << error << "\n";
        return 3;
    }
    if (check) return Check(problems, scenes, rows);

    const double minCpu = quick ? 0.0 : 0.05;
    const int repeats = quick ? 1 : 20;
    std::vector<Case> cases;
    std::vector<ProblemRuns> perProblem;
    for (const ReferenceProblem* p : problems) {
        SceneDescription d;
        if (!LoadScene(scenes, *p, &d)) return 3;
        if (!quick) {
            ProblemRuns r{p, {}, {}, MostAccurate(rows, p->sweepProblem, p->sweepParam)};
            r.book = RunScene(d, *p, {}, nullptr, minCpu, repeats);
            if (r.accurateRow) r.accurate = RunScene(d, *p, r.accurateRow->ToAssignments(), nullptr, minCpu, repeats);
            r.probeCpuSeconds = ProbeBuildCpuSeconds(d);
            std::fprintf(stderr, "%s: book %s, most accurate %s\n", p->name.c_str(), Num(r.book.error).c_str(),
                         Num(r.accurate.error).c_str());
            perProblem.push_back(r);
        }
        for (double budget : budgets) {
            Case c;
            c.problem = p;
            c.budget = budget;
            c.autoBound = p->AutoBound(budget);
            c.cheapest = CheapestMeeting(rows, p->sweepProblem, p->sweepParam, budget);
            AutoModelRequest request;
            request.model = 1;
            request.bound = float(c.autoBound);
            request.quantity = int(p->quantity);
            c.autoRun = RunScene(d, *p, {}, &request, minCpu, repeats, tuning);
            if (!c.autoRun.ok) {
                std::cerr << "psb-model-choice-bench: " << p->name << ": " << c.autoRun.message << "\n";
                return 3;
            }
            if (c.cheapest) c.cheapestRun = RunScene(d, *p, c.cheapest->ToAssignments(), nullptr, minCpu, repeats);
            if (c.cheapest && !quick) {
                c.margin = CheapestMeeting(rows, p->sweepProblem, p->sweepParam, budget / tuning.safety);
                if (c.margin == c.cheapest)
                    c.marginRun = c.cheapestRun;
                else if (c.margin)
                    c.marginRun = RunScene(d, *p, c.margin->ToAssignments(), nullptr, minCpu, repeats);
            }
            std::fprintf(stderr, "%s budget %g: auto %s, %lld steps to %g s, error %s (%s)%s\n", p->name.c_str(),
                         budget, c.autoRun.refused ? "refused" : c.autoRun.chosen.c_str(), c.autoRun.steps,
                         c.autoRun.simSeconds, Num(c.autoRun.error).c_str(), Verdict(c).c_str(),
                         c.autoRun.refused ? (": " + c.autoRun.message).c_str() : "");
            if (explain) {
                std::fprintf(stderr, "%s", c.autoRun.explain.c_str());
                for (const std::string& line : c.autoRun.log) std::fprintf(stderr, "  log: %s\n", line.c_str());
            }
            if (!perProblem.empty() && perProblem.back().problem == p)
                c.own = OwnQuantity(c.autoRun, perProblem.back().accurate, p->quantity);
            cases.push_back(std::move(c));
        }
    }
    const std::string report = Report(cases, perProblem, quick, tuning.safety, command);
    std::cout << report;
    if (!out.empty() && !Write(out, report)) return 3;
    if (!csvOut.empty() && !Write(csvOut, Csv(cases))) return 3;
    return 0;
}
