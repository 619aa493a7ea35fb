// One dt for every demo (docs/app.md, "Steps"): `--dt S` and `--set dt=S` are the same setting. Each of the nine
// demos runs at its default step and at 0.02 s given both ways: the two 0.02 s runs write byte-identical --state
// CSVs, the host runs a different number of physics steps than at the default, and every demo that simulates bodies
// writes a different state (before, springs, ch16 and joints ignored --dt and wrote the default CSV).
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "tests/app/SandboxRun.h"

namespace {

struct DtRun {
    std::string csv;  ///< the --state file's text
    long long steps = -1;
};

/// The step count of the run's summary line ("..., 0.500 simulated s, 24 steps, ...").
long long SummarySteps(const std::string& err) {
    const std::size_t at = err.find(" steps, wall");
    if (at == std::string::npos) return -1;
    const std::size_t start = err.rfind(", ", at);
    return start == std::string::npos ? -1 : std::atoll(err.c_str() + start + 2);
}

DtRun RunAt(const std::string& id, const std::vector<std::string>& step, const std::string& path) {
    std::vector<std::string> args = {"--demo", id, "--frames", "30", "--no-ui", "--state", path};
    args.insert(args.end(), step.begin(), step.end());
    const SandboxResult r = RunSandboxExe(args);
    EXPECT_EQ(r.exitCode, 0) << id << ": " << r.err;
    return {ReadText(path), SummarySteps(r.err)};
}

}  // namespace

TEST(OneDt, DtAndSetDtAreOneSettingThatChangesEveryDemosPhysics) {
    const std::vector<std::string> ids = ListDemoIds();
    ASSERT_EQ(ids.size(), 9u);
    const std::string dir = ScratchDir("one_dt");
    for (const std::string& id : ids) {
        const DtRun base = RunAt(id, {}, dir + "/" + id + "-default.csv");
        const DtRun dt = RunAt(id, {"--dt", "0.02"}, dir + "/" + id + "-dt.csv");
        const DtRun set = RunAt(id, {"--set", "dt=0.02"}, dir + "/" + id + "-set.csv");
        ASSERT_GT(base.steps, 0) << id;
        EXPECT_EQ(dt.csv, set.csv) << id << ": --dt 0.02 and --set dt=0.02 differ";
        EXPECT_EQ(dt.steps, set.steps) << id;
        EXPECT_NE(dt.steps, base.steps) << id << ": --dt 0.02 ran the default step";
        const bool hasBodies = base.csv.find('\n') + 1 < base.csv.size();  // more than the header
        if (hasBodies) {
            EXPECT_NE(dt.csv, base.csv) << id << ": --dt 0.02 wrote the default state";
        }
    }
}

// The step keeps --dt's exactness through a demo's own dt: 1/60 is run as 1/60 (no rounding note) on springs too.
TEST(OneDt, AFractionStaysExactOnADemoWithItsOwnDt) {
    for (const char* flag : {"--dt", "--set"}) {
        const std::vector<std::string> step = flag == std::string("--dt")
                                                  ? std::vector<std::string>{"--dt", "1/60"}
                                                  : std::vector<std::string>{"--set", "dt=1/60"};
        std::vector<std::string> args = {"--demo", "springs", "--frames", "3", "--no-ui"};
        args.insert(args.end(), step.begin(), step.end());
        const SandboxResult r = RunSandboxExe(args);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(r.err.find("rounded"), std::string::npos) << flag << ": " << r.err;
        EXPECT_EQ(SummarySteps(r.err), 3) << flag << ": " << r.err;  // 3 frames of 1/60 s: one step each
    }
}
