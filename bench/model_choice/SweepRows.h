#pragma once
// The committed sweep (docs/sweep/results.csv, written by psb-sweep): its rows as settings a scene file can be run
// with, and the picks the validation compares auto with (cheapest meeting a budget, most accurate).

#include <string>
#include <vector>

#include "bench/model_choice/Runs.h"
#include "bench/sweep/Sweep.h"

namespace modelchoice {

/// One row of results.csv: its settings as written ("-" = not used) and what it measured.
struct SweepRow {
    std::string problem, param;  ///< param as written ("-" when none)
    std::string integrator;      ///< id or "-"
    double dt = 0.0;             ///< s per frame
    int substeps = 1;            ///< frame substeps (the book solver's dt / substeps steps)
    int iterations = -1, projection = -1;
    std::string solver;  ///< "book", "accumulated", "soft" or "-"
    int softSubsteps = -1;
    double error = 0.0, cpuPerSimSecond = 0.0;
    bool stable = false;
    /// "rk4 dt=0.02", "soft solver dt=0.02 soft-substeps=4" (as docs/sweep/cheapest.md writes them).
    std::string Describe() const;
    /// The `--set` assignments of FileScene::AddParameters that run this row's model (dt = dt / substeps).
    Assignments ToAssignments() const;
    /// True when `s` (a point of the sweep problem's grid) is this row's setting.
    bool Matches(const sweep::Settings& s) const;
};

/// Reads results.csv; false with *error naming the file or line.
bool ReadSweepRows(const std::string& path, std::vector<SweepRow>* rows, std::string* error);

/// The stable row of `problem`/`param` with error <= budget and the least CPU per simulated second; nullptr if none.
const SweepRow* CheapestMeeting(const std::vector<SweepRow>& rows, const std::string& problem, const std::string& param,
                                double budget);
/// The stable row of `problem`/`param` with the smallest error; nullptr if none.
const SweepRow* MostAccurate(const std::vector<SweepRow>& rows, const std::string& problem, const std::string& param);

}  // namespace modelchoice
