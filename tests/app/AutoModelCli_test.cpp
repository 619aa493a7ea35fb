// `model: auto` through the executable (docs/model-choice.md, docs/app.md "Error budget"): the demos and scene
// files choose their model before the run, the chosen model is the one that runs, --state gains the running
// estimate, --explain-model prints the candidates, and bad or impossible budgets exit 2 with nothing written.
// Runs are short (30 frames = 0.5 s), so the calibration stays small.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/app/SandboxRun.h"

namespace {

std::vector<std::string> Lines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) lines.push_back(line);
    return lines;
}

std::vector<std::string> Fields(const std::string& line) {
    std::vector<std::string> fields;
    std::istringstream in(line);
    std::string field;
    while (std::getline(in, field, ',')) fields.push_back(field);
    return fields;
}

/// The CSV without its last column (the error_estimate of an auto run), header included.
std::string WithoutLastColumn(const std::string& csv) {
    std::string out;
    for (const std::string& line : Lines(csv)) out += line.substr(0, line.rfind(',')) + "\n";
    return out;
}

/// The value of `key` in a --params listing ("  dt = 0.015  [number ...]  help"), "" when absent.
std::string ParamValue(const std::string& params, const std::string& key) {
    for (const std::string& line : Lines(params)) {
        const std::string head = "  " + key + " = ";
        if (line.rfind(head, 0) != 0) continue;
        const std::size_t end = line.find("  ", head.size());
        return line.substr(head.size(), end == std::string::npos ? std::string::npos : end - head.size());
    }
    return "";
}

/// The header and the rows whose time (second column) is at most `seconds`.
std::string Before(const std::string& csv, double seconds) {
    std::string out;
    for (const std::string& line : Lines(csv)) {
        const std::vector<std::string> f = Fields(line);
        if (out.empty() || (f.size() > 1 && std::strtod(f[1].c_str(), nullptr) <= seconds)) out += line + "\n";
    }
    return out;
}

/// Checks a state CSV of an auto run: the error_estimate column on the header and every row, each finite and > 0.
void ExpectEstimateColumn(const std::string& csv, std::size_t bodies, int frames) {
    const std::vector<std::string> lines = Lines(csv);
    ASSERT_EQ(lines.size(), 1 + bodies * std::size_t(frames)) << csv.substr(0, 400);
    EXPECT_EQ(lines[0], "frame,time,body,kind,x,y,z,vx,vy,vz,error_estimate");
    for (std::size_t i = 1; i < lines.size(); ++i) {
        const std::vector<std::string> f = Fields(lines[i]);
        ASSERT_EQ(f.size(), 11u) << lines[i];
        const double estimate = std::strtod(f[10].c_str(), nullptr);
        EXPECT_TRUE(std::isfinite(estimate) && estimate > 0.0) << "row " << i << ": " << lines[i];
    }
}

const char* kSpringScene = R"({"format": 1, "name": "Spring", "duration": 0.5, "model": "auto",
  "budget": {"quantity": "position", "bound": 0.01},
  "bodies": [{"id": "anchor", "type": "particle", "position": [0, 3, 0], "mass": 0},
             {"id": "bob", "type": "particle", "position": [1, 3, 0]}],
  "springs": [{"a": "anchor", "b": "bob", "stiffness": 20, "damping": 0.2, "restLength": 1}]})";

}  // namespace

TEST(AutoModelCli, DemosRunWithTheEstimateInTheStateCsv) {
    const std::string dir = ScratchDir("auto_model_state");
    // springs: two particles; ch15: the ground and two boxes.
    for (const auto& [demo, bodies] : std::vector<std::pair<std::string, std::size_t>>{{"springs", 2}, {"ch15", 3}}) {
        const std::string csv = dir + "/" + demo + ".csv";
        const SandboxResult r = RunSandboxExe({"--demo", demo, "--set", "model=auto", "--set", "error-budget=0.2",
                                               "--frames", "30", "--no-ui", "--state", csv});
        ASSERT_EQ(r.exitCode, 0) << demo << ": " << r.err;
        ExpectEstimateColumn(ReadText(csv), bodies, 30);
        // The summary names the auto model (its line follows the run's summary).
        EXPECT_NE(r.err.find(demo + ": "), std::string::npos) << r.err;
    }
}

TEST(AutoModelCli, EverySimulatedDemoTakesTheKeysAndTheScriptedOnesDoNot) {
    const std::vector<std::string> hosts = {"ch14", "ch15", "springs", "ch16", "joints", "linear-impulse", "momentum"};
    const std::string dir = ScratchDir("auto_model_hosts");
    for (const std::string& demo : hosts) {
        const SandboxResult params = RunSandboxExe({"--demo", demo, "--params"});
        ASSERT_EQ(params.exitCode, 0) << demo << ": " << params.err;
        EXPECT_EQ(ParamValue(params.out, "model"), "fixed") << demo;
        EXPECT_EQ(ParamValue(params.out, "budget"), "position") << demo;
        EXPECT_FALSE(ParamValue(params.out, "error-budget").empty()) << demo;
        // A loose budget (5 m over 0.5 s) is met on each, and the run carries the estimate. (At 1 m momentum's watch
        // finds the collision's estimate over the budget at its fixed 0.03 s step: exit 4.)
        const std::string csv = dir + "/" + demo + ".csv";
        const SandboxResult r = RunSandboxExe({"--demo", demo, "--set", "model=auto", "--set", "error-budget=5",
                                               "--frames", "30", "--no-ui", "--quiet", "--state", csv});
        ASSERT_EQ(r.exitCode, 0) << demo << ": " << r.err;
        EXPECT_EQ(Lines(ReadText(csv)).front(), "frame,time,body,kind,x,y,z,vx,vy,vz,error_estimate") << demo;
    }
    for (const std::string demo : {"raycast", "collision-features"}) {
        const SandboxResult r = RunSandboxExe({"--demo", demo, "--set", "model=auto"});
        EXPECT_EQ(r.exitCode, 2) << demo;
        EXPECT_NE(r.err.find("model"), std::string::npos) << r.err;
    }
}

TEST(AutoModelCli, TheOldToleranceKeyStillSetsTheErrorBudgetAndSaysItIsDeprecated) {
    // `--set tolerance=` was the error budget's key before `error-budget` (docs/model-choice.md): the same choice,
    // the same states, and one line on stderr naming the new key. (1 cm: at 0.5 s the particles have just bounced off
    // the ground, and a budget under twice the contact's 3 mm offset is refused: docs/model-choice.md "Impact timing".)
    const std::string dir = ScratchDir("auto_model_tolerance_alias");
    const SandboxResult old = RunSandboxExe({"--demo", "springs", "--set", "model=auto", "--set", "tolerance=0.01",
                                             "--frames", "30", "--no-ui", "--state", dir + "/old.csv"});
    ASSERT_EQ(old.exitCode, 0) << old.err;
    EXPECT_NE(old.err.find("'tolerance' is deprecated; use 'error-budget'"), std::string::npos) << old.err;
    const SandboxResult now = RunSandboxExe({"--demo", "springs", "--set", "model=auto", "--set", "error-budget=0.01",
                                             "--frames", "30", "--no-ui", "--state", dir + "/new.csv"});
    ASSERT_EQ(now.exitCode, 0) << now.err;
    EXPECT_EQ(now.err.find("deprecated"), std::string::npos) << now.err;
    EXPECT_EQ(ReadText(dir + "/old.csv"), ReadText(dir + "/new.csv"));
}

TEST(AutoModelCli, TheChosenModelIsTheOneThatRuns) {
    // A budget the book's step does not meet (1 cm, over twice the contact offset the just-bounced particles fly
    // off by): the choice differs from the defaults. --params shows the values in
    // effect after the choice; a fixed run with exactly those values gives the auto run's states.
    const std::string dir = ScratchDir("auto_model_chosen");
    const std::vector<std::string> autoArgs = {
        "--demo", "springs", "--set", "model=auto", "--set", "error-budget=0.01", "--frames", "30", "--no-ui"};
    std::vector<std::string> params = autoArgs;
    params.push_back("--params");
    const SandboxResult listed = RunSandboxExe(params);
    ASSERT_EQ(listed.exitCode, 0) << listed.err;
    const std::string dt = ParamValue(listed.out, "dt"), integrator = ParamValue(listed.out, "integrator");
    ASSERT_FALSE(dt.empty()) << listed.out;
    ASSERT_FALSE(integrator.empty()) << listed.out;
    const SandboxResult defaults = RunSandboxExe({"--demo", "springs", "--params"});
    ASSERT_EQ(defaults.exitCode, 0) << defaults.err;
    EXPECT_TRUE(dt != ParamValue(defaults.out, "dt") || integrator != ParamValue(defaults.out, "integrator"))
        << "the chosen model is the book's: " << listed.out;

    // --explain-model marks the candidate whose settings --params showed.
    std::vector<std::string> explain = autoArgs;
    explain.push_back("--explain-model");
    const SandboxResult explained = RunSandboxExe(explain);
    ASSERT_EQ(explained.exitCode, 0) << explained.err;
    EXPECT_NE(explained.out.find(integrator), std::string::npos) << explained.out;

    std::vector<std::string> autoRun = autoArgs;
    autoRun.insert(autoRun.end(), {"--state", dir + "/auto.csv"});
    const SandboxResult a = RunSandboxExe(autoRun);
    ASSERT_EQ(a.exitCode, 0) << a.err;
    const SandboxResult fixed =
        RunSandboxExe({"--demo", "springs", "--set", "dt=" + dt, "--set", "integrator=" + integrator, "--frames", "30",
                       "--no-ui", "--state", dir + "/fixed.csv"});
    ASSERT_EQ(fixed.exitCode, 0) << fixed.err;
    const SandboxResult book =
        RunSandboxExe({"--demo", "springs", "--frames", "30", "--no-ui", "--state", dir + "/book.csv"});
    ASSERT_EQ(book.exitCode, 0) << book.err;
    // The live watch may refine the model during the run ("t = 0.17 s: ... switching from ... to ..."): until
    // then the auto run is the fixed run of the chosen model, state for state.
    double switchedAt = 1e9;
    const std::size_t at = a.err.find(": model auto: t = ");
    if (at != std::string::npos)
        switchedAt = std::strtod(a.err.c_str() + at + std::strlen(": model auto: t = "), nullptr);
    const std::string autoStates = Before(WithoutLastColumn(ReadText(dir + "/auto.csv")), switchedAt + 0.005);
    EXPECT_GE(Lines(autoStates).size(), 1u + 2u * 5u) << "the first check runs after a sixth of the run";
    EXPECT_EQ(autoStates, Before(ReadText(dir + "/fixed.csv"), switchedAt + 0.005)) << a.err;
    EXPECT_NE(autoStates, Before(ReadText(dir + "/book.csv"), switchedAt + 0.005));
    // A refined step takes effect in the host: more steps than the chosen step alone gives.
    if (at != std::string::npos && a.err.find(", dt ", at) != std::string::npos) {
        const std::size_t steps = a.err.rfind(" steps, wall");
        ASSERT_NE(steps, std::string::npos) << a.err;
        const std::size_t start = a.err.rfind(", ", steps) + 2;
        EXPECT_GT(std::atoi(a.err.c_str() + start), int(0.5 / std::atof(dt.c_str()))) << a.err;
    }
}

TEST(AutoModelCli, BadTolerancesExitTwoNamingTheValueWithNothingWritten) {
    const std::string dir = ScratchDir("auto_model_bad_tolerance");
    for (const char* value : {"0", "nan", "-1", "inf"}) {
        const SandboxResult r =
            RunSandboxExe({"--demo", "springs", "--set", "model=auto", "--set", std::string("error-budget=") + value,
                           "--frames", "30", "--out", dir + "/frames", "--state", dir + "/s.csv"});
        EXPECT_EQ(r.exitCode, 2) << value << ": " << r.err;
        EXPECT_NE(r.err.find(std::string("error-budget=") + value), std::string::npos) << r.err;
        EXPECT_TRUE(FilesIn(dir).empty()) << value;
    }
}

TEST(AutoModelCli, AnImpossibleBudgetIsRefusedUpFront) {
    const std::string dir = ScratchDir("auto_model_impossible");
    const SandboxResult r = RunSandboxExe({"--demo", "springs", "--set", "model=auto", "--set", "error-budget=1e-9",
                                           "--frames", "30", "--out", dir + "/frames", "--state", dir + "/s.csv"});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("1e-09"), std::string::npos) << "the message names the budget: " << r.err;
    EXPECT_NE(r.err.find("the budget over the safety factor"), std::string::npos) << r.err;
    EXPECT_TRUE(FilesIn(dir).empty());
    // --explain-model refuses it the same way.
    const SandboxResult explained = RunSandboxExe({"--demo", "springs", "--set", "model=auto", "--set",
                                                   "error-budget=1e-9", "--frames", "30", "--explain-model"});
    EXPECT_EQ(explained.exitCode, 2) << explained.err;
    EXPECT_NE(explained.err.find("the budget over the safety factor"), std::string::npos) << explained.err;
}

TEST(AutoModelCli, ExplainModelNeedsAnAutoModelAndRunsNothing) {
    const std::string dir = ScratchDir("auto_model_explain");
    const SandboxResult fixed = RunSandboxExe({"--demo", "springs", "--explain-model", "--out", dir + "/frames"});
    EXPECT_EQ(fixed.exitCode, 2) << fixed.err;
    EXPECT_NE(fixed.err.find("--set model=auto"), std::string::npos) << fixed.err;
    EXPECT_TRUE(fixed.out.empty()) << fixed.out;
    const SandboxResult explained =
        RunSandboxExe({"--demo", "ch15", "--set", "model=auto", "--set", "error-budget=0.2", "--frames", "30",
                       "--explain-model", "--out", dir + "/frames", "--state", dir + "/s.csv"});
    EXPECT_EQ(explained.exitCode, 0) << explained.err;
    EXPECT_FALSE(explained.out.empty());
    EXPECT_TRUE(FilesIn(dir).empty()) << "--explain-model ran the demo";
}

TEST(AutoModelCli, SceneFilesChooseTooAndExportKeepsTheBudget) {
    const std::string dir = ScratchDir("auto_model_scene");
    const std::string scene = dir + "/spring.json";
    std::ofstream(scene) << kSpringScene;
    const SandboxResult r = RunSandboxExe({"--scene", scene, "--no-ui", "--state", dir + "/s.csv"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ExpectEstimateColumn(ReadText(dir + "/s.csv"), 2, 30);
    // `--set model=fixed` runs the file's own model: the default CSV, no estimate column.
    const SandboxResult fixed =
        RunSandboxExe({"--scene", scene, "--set", "model=fixed", "--no-ui", "--state", dir + "/fixed.csv"});
    ASSERT_EQ(fixed.exitCode, 0) << fixed.err;
    EXPECT_EQ(Lines(ReadText(dir + "/fixed.csv")).front(), "frame,time,body,kind,x,y,z,vx,vy,vz");

    // A demo exported with model=auto writes its request, and the file runs with it.
    const std::string exported = dir + "/springs.json";
    const SandboxResult e = RunSandboxExe({"--demo", "springs", "--set", "model=auto", "--set", "error-budget=0.03",
                                           "--set", "budget=energy", "--export-scene", exported});
    ASSERT_EQ(e.exitCode, 0) << e.err;
    const std::string text = ReadText(exported);
    EXPECT_NE(text.find("\"model\": \"auto\""), std::string::npos) << text;
    EXPECT_NE(text.find("\"quantity\": \"energy\""), std::string::npos) << text;
    EXPECT_NE(text.find("\"bound\": 0.03"), std::string::npos) << text;
    const SandboxResult explained = RunSandboxExe({"--scene", exported, "--frames", "30", "--explain-model"});
    EXPECT_EQ(explained.exitCode, 0) << explained.err;
    EXPECT_FALSE(explained.out.empty());

    // A scene file whose bound is not positive stops at the file, exit 2, nothing written.
    const std::string bad = dir + "/bad.json";
    std::string badText = kSpringScene;
    badText.replace(badText.find("\"bound\": 0.01"), 13, "\"bound\": -1");
    std::ofstream(bad) << badText;
    const SandboxResult refused = RunSandboxExe({"--scene", bad, "--state", dir + "/bad.csv"});
    EXPECT_EQ(refused.exitCode, 2);
    EXPECT_NE(refused.err.find("bad.json: budget.bound: must be in [1e-09, 1e+06] (got -1)"), std::string::npos)
        << refused.err;
    EXPECT_FALSE(std::ifstream(dir + "/bad.csv").good());
}

TEST(AutoModelCli, ARunThatMissesItsBudgetExitsFourWithItsOutputsWhole) {
    // The tower of five at 0.1 m: the choice meets the budget on its calibration; the watch then finds the estimate
    // over it and keeps the model (a finer one would change little; AutoModel::MissedBudget). The run still writes
    // every row, landed on its time, then exits 4 naming the estimate, the budget and the frame.
    const std::string dir = ScratchDir("auto_model_missed");
    const std::string csv = dir + "/stack-5.csv";
    const std::string scene = std::string(PSB_SOURCE_DIR) + "/scenes/reference/stack-5.json";
    const SandboxResult r = RunSandboxExe(
        {"--scene", scene, "--set", "model=auto", "--set", "error-budget=0.1", "--no-ui", "--state", csv});
    EXPECT_EQ(r.exitCode, 4) << r.err;
    EXPECT_NE(r.err.find("missed its error budget"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("the budget 0.1 at frame "), std::string::npos) << r.err;
    const std::vector<std::string> rows = Lines(ReadText(csv));
    ASSERT_FALSE(rows.empty());
    EXPECT_EQ(rows.back().rfind("599,10,", 0), 0u) << rows.back();  // the last frame, landed on 10 s
    // The same run with a budget it meets exits 0: the code follows the watch, not the scene.
    const SandboxResult met =
        RunSandboxExe({"--scene", scene, "--set", "model=auto", "--set", "error-budget=2", "--no-ui", "--quiet"});
    EXPECT_EQ(met.exitCode, 0) << met.err;
}

namespace {

/// The largest distance between the two runs' last-frame rows (same bodies, same order), and both rows' times.
double LastFrameDistance(const std::string& a, const std::string& b, double* timeA, double* timeB) {
    auto lastRows = [](const std::string& csv) {
        std::vector<std::vector<double>> rows;
        std::vector<std::string> lines = Lines(ReadText(csv));
        const std::string lastFrame = lines.back().substr(0, lines.back().find(','));
        for (const std::string& line : lines) {
            if (line.rfind(lastFrame + ",", 0) != 0) continue;
            std::vector<double> cells;
            std::stringstream ss(line);
            std::string cell;
            while (std::getline(ss, cell, ',')) cells.push_back(std::atof(cell.c_str()));
            rows.push_back(cells);
        }
        return rows;
    };
    const auto ra = lastRows(a), rb = lastRows(b);
    EXPECT_EQ(ra.size(), rb.size());
    double worst = 0.0;
    for (std::size_t i = 0; i < std::min(ra.size(), rb.size()); ++i) {
        const double dx = ra[i][4] - rb[i][4], dy = ra[i][5] - rb[i][5], dz = ra[i][6] - rb[i][6];
        worst = std::max(worst, std::sqrt(dx * dx + dy * dy + dz * dz));
        *timeA = ra[i][1];
        *timeB = rb[i][1];
    }
    return worst;
}

}  // namespace

TEST(AutoModelCli, TheReadmesSpringsExamplesMeetTheirBudgetsAgainstAConvergedReference) {
    // README "Using it": 1 mm over 600 frames, and 1 cm over 300 frames. Each must run (exit 0) and its last row must
    // be within the budget of a converged reference: RK4 at 0.5 ms with the reflect contact auto runs (checked
    // converged by the same run at 1 ms: the two differ by under a tenth of the budget).
    const std::string dir = ScratchDir("auto_model_readme_springs");
    for (const auto& [tolerance, frames] :
         std::vector<std::pair<std::string, std::string>>{{"1e-3", "600"}, {"1e-2", "300"}}) {
        const std::string csv = dir + "/auto-" + frames + ".csv";
        const SandboxResult r =
            RunSandboxExe({"--demo", "springs", "--set", "model=auto", "--set", "error-budget=" + tolerance, "--frames",
                           frames, "--state", csv, "--no-ui", "--quiet"});
        ASSERT_EQ(r.exitCode, 0) << tolerance << ": " << r.err;
        std::string reference[2];
        const char* steps[2] = {"0.0005", "0.001"};
        for (int i = 0; i < 2; ++i) {
            reference[i] = dir + "/reference-" + frames + "-" + steps[i] + ".csv";
            const SandboxResult ref = RunSandboxExe(
                {"--demo", "springs", "--set", "integrator=rk4", "--set", "particle-contact=reflect", "--set",
                 std::string("dt=") + steps[i], "--frames", frames, "--state", reference[i], "--no-ui", "--quiet"});
            ASSERT_EQ(ref.exitCode, 0) << ref.err;
        }
        const double budget = std::atof(tolerance.c_str());
        double t0 = 0.0, t1 = 0.0;
        EXPECT_LT(LastFrameDistance(reference[0], reference[1], &t0, &t1), 0.1 * budget) << "reference not converged";
        const double error = LastFrameDistance(csv, reference[0], &t0, &t1);
        EXPECT_EQ(t0, t1) << "the auto run's last row and the reference's are at different times";
        EXPECT_LE(error, budget) << tolerance << " over " << frames << " frames";
    }
}
