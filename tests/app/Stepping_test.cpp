// One stepping contract for every demo: the physics step (--set dt= for demos with a dt parameter, --dt for the
// others) changes accuracy, never the speed of simulated time. Each demo runs at the book's 0.03 s and at 0.01 s;
// the --state CSV's time column must be the physics time of the state it holds (the whole steps the strict
// accumulator handed out, and the run's time, frames * 1/60 s, on the last row), and the body that moved furthest
// must be where the coarse run has it, within the error a 0.03 s step allows.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "tests/app/SandboxRun.h"

namespace {

constexpr double kCoarseStep = 0.03;  // the book's step (the default)
constexpr double kFineStep = 0.01;
constexpr double kFrameTime = 1.0 / 60.0;  // the default --fps
constexpr double kGravity = 9.82;          // m/s^2, every demo's
constexpr int kFrames = 31;                // frame 30 is 0.5 s in: early enough that bodies mostly fly or fall

struct Row {
    int frame = 0;
    double time = 0.0;
    int body = 0;
    double x = 0, y = 0, z = 0, vx = 0, vy = 0, vz = 0;
};

std::vector<Row> ReadState(const std::string& path) {
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);  // header
    std::vector<Row> rows;
    while (std::getline(in, line)) {
        std::vector<std::string> f;
        std::stringstream ss(line);
        std::string cell;
        while (std::getline(ss, cell, ',')) f.push_back(cell);
        if (f.size() != 10) continue;
        Row r;
        r.frame = std::atoi(f[0].c_str());
        r.time = std::atof(f[1].c_str());
        r.body = std::atoi(f[2].c_str());
        r.x = std::atof(f[4].c_str());
        r.y = std::atof(f[5].c_str());
        r.z = std::atof(f[6].c_str());
        r.vx = std::atof(f[7].c_str());
        r.vy = std::atof(f[8].c_str());
        r.vz = std::atof(f[9].c_str());
        rows.push_back(r);
    }
    return rows;
}

/// The physics time of frame `frame`'s row at step `step` (0.03 or 0.01 s): in ticks of 1/300 s a frame is 5 and the
/// step 9 or 3; the strict accumulator runs n = ceil(owed / step) - 1 whole steps, and the last row lands on the
/// frames' time (docs/app.md "Time").
double PhysicsTimeOfRow(int frame, double step, bool last) {
    const long long owed = 5LL * (frame + 1);
    if (last) return double(owed) / 300.0;
    const long long stepTicks = step == kCoarseStep ? 9 : 3;
    return double((owed - 1) / stepTicks * stepTicks) / 300.0;
}

/// True if the demo has a `dt` parameter (--params lists "  dt = ...").
bool HasDtParameter(const std::string& id) {
    const SandboxResult r = RunSandboxExe({"--demo", id, "--params"});
    return r.exitCode == 0 && r.out.find("\n  dt = ") != std::string::npos;
}

/// Runs `id` for kFrames frames at `step` seconds and returns its state rows.
std::vector<Row> RunAtStep(const std::string& id, double step, const std::string& dir) {
    const std::string csv = dir + "/" + id + (step == kCoarseStep ? "-coarse" : "-fine") + ".csv";
    std::vector<std::string> args = {"--demo",  id,        "--frames", std::to_string(kFrames),
                                     "--no-ui", "--quiet", "--state",  csv};
    if (step != kCoarseStep) {
        std::ostringstream value;
        value << step;
        if (HasDtParameter(id)) {
            args.push_back("--set");
            args.push_back("dt=" + value.str());
        } else {
            args.push_back("--dt");
            args.push_back(value.str());
        }
    }
    const SandboxResult r = RunSandboxExe(args);
    EXPECT_EQ(r.exitCode, 0) << id << " at " << step << ": " << r.err;
    return ReadState(csv);
}

using ByBody = std::map<int, Row>;
ByBody Frame(const std::vector<Row>& rows, int frame) {
    ByBody out;
    for (const Row& r : rows)
        if (r.frame == frame) out[r.body] = r;
    return out;
}

double Distance(const Row& a, const Row& b) {
    return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
}

}  // namespace

TEST(Stepping, EveryDemoKeepsSimulatedTimeAtTwoSteps) {
    const std::vector<std::string> ids = ListDemoIds();
    ASSERT_FALSE(ids.empty());
    const std::string dir = ScratchDir("stepping");
    int compared = 0;
    for (const std::string& id : ids) {
        const std::vector<Row> coarse = RunAtStep(id, kCoarseStep, dir);
        const std::vector<Row> fine = RunAtStep(id, kFineStep, dir);
        ASSERT_EQ(coarse.size(), fine.size()) << id;
        if (coarse.empty()) continue;  // raycast and collision-features simulate no bodies: nothing to time

        // The time column is the physics time of the row's state; both runs end at the same time, the frames'.
        for (std::size_t i = 0; i < coarse.size(); ++i) {
            const bool last = coarse[i].frame == kFrames - 1;
            ASSERT_NEAR(coarse[i].time, PhysicsTimeOfRow(coarse[i].frame, kCoarseStep, last), 1e-8)
                << id << " frame " << coarse[i].frame;
            ASSERT_NEAR(fine[i].time, PhysicsTimeOfRow(fine[i].frame, kFineStep, last), 1e-8)
                << id << " frame " << fine[i].frame;
            if (last) {
                ASSERT_NEAR(coarse[i].time, kFrames * kFrameTime, 1e-8) << id;
            }
        }

        // The body that moved furthest by the last frame (the falling or thrown one) is where the coarse run has
        // it, within what a 0.03 s step allows: the accumulator lags host time by up to one step (|v| dt) and
        // first-order integration is off by about g t dt. Slow motion (0.01 s steps at the pace of 0.03 s ones)
        // would leave it two thirds of the way behind.
        const int last = kFrames - 1;
        const ByBody start = Frame(coarse, 0), endCoarse = Frame(coarse, last), endFine = Frame(fine, last);
        int mover = -1;
        double travelled = 0.0;
        for (const auto& [body, row] : endCoarse) {
            const double d = Distance(row, start.at(body));
            if (d > travelled) travelled = d, mover = body;
        }
        ASSERT_GE(mover, 0) << id << ": nothing moved";
        const Row& a = endCoarse.at(mover);
        const Row& b = endFine.at(mover);
        const double speed = std::sqrt(a.vx * a.vx + a.vy * a.vy + a.vz * a.vz);
        const double t = a.time;
        const double tolerance = (speed + kGravity * t) * kCoarseStep;
        EXPECT_LT(Distance(a, b), tolerance)
            << id << " body " << mover << " at t = " << t << " s: (" << a.x << ", " << a.y << ", " << a.z
            << ") at 0.03 s steps, (" << b.x << ", " << b.y << ", " << b.z << ") at 0.01 s; travelled " << travelled;
        EXPECT_GT(travelled, 3.0 * tolerance) << id << ": the check must be able to tell slow motion apart";
        // The fine run really stepped 0.01 s: a step that was ignored would give the coarse run's numbers.
        EXPECT_GT(Distance(a, b), 0.0) << id << ": the 0.01 s run is identical to the 0.03 s run";
        std::printf("%s: body %d travelled %.3f m; the two steps differ by %.4f m (tolerance %.4f m)\n", id.c_str(),
                    mover, travelled, Distance(a, b), tolerance);
        ++compared;
    }
    EXPECT_GE(compared, 7) << "every demo with bodies must be compared";
}

TEST(Stepping, TheLastRowHoldsThePhysicsAtTheRunsTime) {
    // A projectile at 0.1 s steps for 1.5 s (90 frames): the book's strict accumulator alone would leave the
    // physics at 1.4 s, 1.26 m short of x(1.5) in this scene. Velocity Verlet is exact for a constant force, so the
    // last row must be the exact x(t), y(t) at its own time, and that time must be 1.5 s.
    const std::string dir = ScratchDir("stepping_last_row");
    const std::string scene = dir + "/projectile.json";
    std::ofstream(scene) << R"({"format": 1, "name": "projectile", "duration": 1.5,
        "world": {"step": 0.1, "integrator": "velocity-verlet"},
        "bodies": [{"id": "ball", "type": "particle", "position": [0, 1, 0], "velocity": [12.6, 9.5, 0],
                    "mass": 1, "velocityRetention": 1}]})";
    const std::string csv = dir + "/projectile.csv";
    const SandboxResult r = RunSandboxExe({"--scene", scene, "--no-ui", "--state", csv});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("1.500 simulated s, 15 steps"), std::string::npos) << r.err;
    const std::vector<Row> rows = ReadState(csv);
    ASSERT_EQ(rows.size(), 90u);
    const Row& last = rows.back();
    EXPECT_NEAR(last.time, 1.5, 1e-8);
    EXPECT_NEAR(last.x, 12.6 * last.time, 1e-4);
    EXPECT_NEAR(last.y, 1.0 + 9.5 * last.time - 0.5 * kGravity * last.time * last.time, 1e-4);
    // Every earlier row is where its own time says too (exact integrator: any lag would show as an offset).
    for (const Row& row : rows) EXPECT_NEAR(row.x, 12.6 * row.time, 1e-4) << "frame " << row.frame;
}

// One rule for a step given as --dt, --set dt= or a scene's world.step (docs/app.md, "Steps"): a step that is not a
// whole number of microseconds runs rounded to the nearest one, with a one-line note; one that rounds below the
// range is refused with exit 2 and the range, never run silently at the host's 0.03 s.
TEST(Stepping, OneRuleForDtSetDtAndWorldStep) {
    const std::string note = " s rounded to 0.016667 s (a step is a whole number of microseconds";
    const SandboxResult dt = RunSandboxExe({"--demo", "ch14", "--dt", "0.0166666667", "--frames", "2", "--quiet"});
    EXPECT_EQ(dt.exitCode, 0) << dt.err;
    EXPECT_NE(dt.err.find("--dt 0.0166666667: 0.0166666667" + note), std::string::npos) << dt.err;
    const SandboxResult set =
        RunSandboxExe({"--demo", "springs", "--set", "dt=0.0166666667", "--frames", "2", "--quiet"});
    EXPECT_EQ(set.exitCode, 0) << set.err;
    EXPECT_NE(set.err.find("--set dt=0.0166666667: 0.0166666667" + note), std::string::npos) << set.err;
    const SandboxResult exact = RunSandboxExe({"--demo", "ch14", "--dt", "1/60", "--frames", "2", "--quiet"});
    EXPECT_EQ(exact.exitCode, 0) << exact.err;
    EXPECT_EQ(exact.err, "");

    const std::string dir = ScratchDir("step_rule");
    const auto scene = [&](const std::string& step) {
        const std::string path = dir + "/s.json";
        std::ofstream(path) << R"({"format": 1, "name": "s", "duration": 0.1, "world": {"step": )" << step
                            << R"(}, "bodies": [{"id": "p", "type": "particle", "position": [0, 1, 0]}]})";
        return RunSandboxExe({"--scene", path, "--state", dir + "/s.csv", "--no-ui", "--quiet"});
    };
    for (const char* tiny : {"1e-9", "5e-7"}) {
        const SandboxResult r = scene(tiny);
        EXPECT_EQ(r.exitCode, 2) << tiny;
        const std::string shown = tiny == std::string("1e-9") ? "1e-09" : "5e-07";  // as nlohmann-json prints it
        EXPECT_NE(r.err.find("s.json: world.step: must be 0 or in [0.0001, 1] (got " + shown + ")"), std::string::npos)
            << r.err;
        EXPECT_FALSE(std::ifstream(dir + "/s.csv").good());
    }
    const SandboxResult rounded = scene("0.0166666667");
    EXPECT_EQ(rounded.exitCode, 0) << rounded.err;
    EXPECT_NE(rounded.err.find("s.json: world.step: 0.0166666667" + note), std::string::npos) << rounded.err;
}
