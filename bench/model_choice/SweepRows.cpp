#include "bench/model_choice/SweepRows.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace modelchoice {
namespace {

std::vector<std::string> SplitCsv(const std::string& line) {
    std::vector<std::string> out;
    std::stringstream in(line);
    std::string cell;
    while (std::getline(in, cell, ',')) out.push_back(cell);
    if (!line.empty() && line.back() == ',') out.emplace_back();
    return out;
}

int IntOr(const std::string& text, int fallback) {
    return text == "-" || text.empty() ? fallback : std::atoi(text.c_str());
}

std::string Number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", v);
    return text;
}

}  // namespace

std::string SweepRow::Describe() const {
    std::string s;
    if (solver != "-") {
        s = solver + " solver dt=" + Number(dt);
        if (substeps > 1) s += " substeps=" + std::to_string(substeps);
        if (iterations >= 0) s += " iterations=" + std::to_string(iterations);
        if (projection >= 0) s += projection ? " projection=on" : " projection=off";
        if (softSubsteps >= 0) s += " soft-substeps=" + std::to_string(softSubsteps);
        return s;
    }
    return (integrator != "-" ? integrator : std::string("volumes")) + " dt=" + Number(dt);
}

Assignments SweepRow::ToAssignments() const {
    Assignments a;
    if (integrator != "-") a.emplace_back("integrator", integrator);
    if (solver != "-") a.emplace_back("solver", solver);
    if (iterations >= 0) a.emplace_back("iterations", std::to_string(iterations));
    if (projection >= 0) a.emplace_back("linear-projection", projection ? "1" : "0");
    if (softSubsteps >= 0) a.emplace_back("soft-substeps", std::to_string(softSubsteps));
    a.emplace_back("dt", Number(dt / double(substeps)));
    return a;
}

bool SweepRow::Matches(const sweep::Settings& s) const {
    if ((integrator != "-") != s.hasIntegrator) return false;
    if (s.hasIntegrator && integrator != ToString(s.integrator)) return false;
    if (std::fabs(s.dt - dt) > 1e-12 * dt || s.substeps != substeps) return false;
    if (s.iterations != iterations || s.projection != projection) return false;
    if ((solver != "-") != (s.solver >= 0)) return false;
    if (s.solver >= 0 && solver != ToString(ContactSolver(s.solver))) return false;
    if (solver == "soft" && s.soft.substeps != softSubsteps) return false;
    const std::string p = s.param == 0.0 ? "-" : Number(s.param);
    return p == param;
}

bool ReadSweepRows(const std::string& path, std::vector<SweepRow>* rows, std::string* error) {
    std::ifstream in(path);
    if (!in) {
        *error = path + ": cannot read";
        return false;
    }
    std::string line;
    std::getline(in, line);
    const std::vector<std::string> header = SplitCsv(line);
    auto column = [&](const char* name) {
        for (std::size_t i = 0; i < header.size(); ++i)
            if (header[i] == name) return int(i);
        return -1;
    };
    const int cProblem = column("problem"), cIntegrator = column("integrator"), cDt = column("dt"),
              cSubsteps = column("substeps"), cIterations = column("iterations"), cProjection = column("projection"),
              cSolver = column("solver"), cParam = column("param"), cError = column("error"),
              cCpu = column("cpu_per_sim_s"), cStable = column("stable"), cSoft = column("soft_substeps");
    if (cProblem < 0 || cDt < 0 || cError < 0 || cCpu < 0 || cStable < 0 || cSoft < 0) {
        *error = path + ": not a psb-sweep CSV (header " + line + ")";
        return false;
    }
    int number = 1;
    while (std::getline(in, line)) {
        ++number;
        const std::vector<std::string> c = SplitCsv(line);
        if (int(c.size()) <= cSoft) {
            *error = path + ":" + std::to_string(number) + ": too few columns";
            return false;
        }
        SweepRow r;
        r.problem = c[cProblem];
        r.param = c[cParam];
        r.integrator = c[cIntegrator];
        r.dt = std::atof(c[cDt].c_str());
        r.substeps = IntOr(c[cSubsteps], 1);
        r.iterations = IntOr(c[cIterations], -1);
        r.projection = IntOr(c[cProjection], -1);
        r.solver = c[cSolver];
        r.softSubsteps = r.solver == "soft" ? IntOr(c[cSoft], -1) : -1;
        r.error = c[cError] == "inf" ? HUGE_VAL : std::atof(c[cError].c_str());
        r.cpuPerSimSecond = std::atof(c[cCpu].c_str());
        r.stable = c[cStable] == "1" && std::isfinite(r.error);
        rows->push_back(r);
    }
    return true;
}

const SweepRow* CheapestMeeting(const std::vector<SweepRow>& rows, const std::string& problem, const std::string& param,
                                double budget) {
    const SweepRow* best = nullptr;
    for (const SweepRow& r : rows)
        if (r.problem == problem && r.param == param && r.stable && r.error <= budget &&
            (best == nullptr || r.cpuPerSimSecond < best->cpuPerSimSecond))
            best = &r;
    return best;
}

const SweepRow* MostAccurate(const std::vector<SweepRow>& rows, const std::string& problem, const std::string& param) {
    const SweepRow* best = nullptr;
    for (const SweepRow& r : rows)
        if (r.problem == problem && r.param == param && r.stable && (best == nullptr || r.error < best->error))
            best = &r;
    return best;
}

}  // namespace modelchoice
