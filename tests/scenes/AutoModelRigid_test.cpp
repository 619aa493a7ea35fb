// The auto model on rigid-body problems (docs/model-choice.md): whole runs shared between candidates give the
// same figures at less work, and a world of several volumes that starts in free flight gets a calibration span over
// its first contact.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "Demos/Scenes/AutoModel.h"
#include "Demos/Scenes/FileScene.h"
#include "Demos/Scenes/SceneFile.h"
#include "Physics/ModelChoice/ModelChoice.h"

namespace {

constexpr double kHostStep = 1.0 / 60.0;  // s, the app's frame

AutoModelRequest Budget(double bound) {
    AutoModelRequest r;
    r.model = 1;
    r.bound = static_cast<float>(bound);
    return r;
}

/// No timing in tests: the choice's CPU limit is off.
ChoiceSettings Untimed() {
    ChoiceSettings s;
    s.cpuLimit = std::numeric_limits<double>::infinity();
    return s;
}

SceneBody Ground(float friction) {
    SceneBody g;
    g.id = "ground";
    g.kind = SceneBodyKind::Box;
    g.position = vec3(0, -0.5f, 0);
    g.halfExtents = vec3(20, 0.5f, 20);
    g.mass = 0.0f;
    g.friction = friction;
    g.restitution = 0.0f;
    return g;
}

SceneBody Box(const std::string& id, const vec3& position, const vec3& half, const vec3& velocity = vec3()) {
    SceneBody b;
    b.id = id;
    b.kind = SceneBodyKind::Box;
    b.position = position;
    b.halfExtents = half;
    b.velocity = velocity;
    b.friction = 0.5f;
    b.restitution = 0.0f;
    b.velocityRetention = 1.0f;
    b.velocityEpsilon = 0.0f;
    return b;
}

/// One auto choice on `d` over `seconds`, with `tuning`.
AutoModel Chosen(const SceneDescription& d, double seconds, double bound, const ChoiceSettings& tuning, bool* met) {
    FileScene scene(d);
    ParameterSet params;
    scene.AddParameters(&params);
    AutoModel autoModel;
    std::string error;
    *met = autoModel.Choose(&params, scene.System(), kHostStep, seconds, Budget(bound), &error, tuning);
    return autoModel;
}

// A box sliding to a stop (one volume: every candidate is measured over the whole run). The soft solver refines a
// candidate by doubling its substeps, so "4 substeps" runs as its own candidate, as the refinement of "2 substeps"
// and as the third probe of "1 substep": shared, each model runs once, and every estimate, note and the choice are
// the ones the side-by-side probes give.
TEST(AutoModelRigid, WholeRunsSharedBetweenCandidatesGiveTheSameFiguresForLessWork) {
    SceneDescription d;
    d.bodies.push_back(Ground(0.5f));
    d.bodies.push_back(Box("box", vec3(0, 0.1f, 0), vec3(0.3f, 0.1f, 0.2f), vec3(2.0f, 0, 0.5f)));
    ChoiceSettings apart = Untimed();
    apart.shareWholeRuns = false;
    bool metShared = false, metApart = false;
    const AutoModel shared = Chosen(d, 0.7, 1e-3, Untimed(), &metShared);
    const AutoModel separate = Chosen(d, 0.7, 1e-3, apart, &metApart);
    ASSERT_EQ(metShared, metApart);
    const ModelChoiceResult& a = shared.Choice();
    const ModelChoiceResult& b = separate.Choice();
    ASSERT_EQ(a.candidates.size(), b.candidates.size());
    EXPECT_EQ(a.chosen, b.chosen);
    int whole = 0;
    for (std::size_t i = 0; i < a.candidates.size(); ++i) {
        const CandidateEstimate& x = a.candidates[i];
        const CandidateEstimate& y = b.candidates[i];
        ASSERT_EQ(x.evaluated, y.evaluated) << x.model.Describe(false, true);
        EXPECT_EQ(x.estimate, y.estimate) << x.model.Describe(false, true);
        EXPECT_EQ(x.note, y.note) << x.model.Describe(false, true);
        EXPECT_EQ(x.unreliable, y.unreliable) << x.model.Describe(false, true);
        whole += x.evaluated && x.wholeRun ? 1 : 0;
    }
    EXPECT_GT(whole, 10) << "the choice measured whole runs";
    EXPECT_LT(a.calibrationWork, 0.9 * b.calibrationWork) << "shared whole runs are run once";
}

// 2 x 2 boxes dropped flat 0.5 m (they land after 0.32 s): the start span, 0.2 s, sees only their fall. The pilot
// finds the first contact and the calibration gets a span from a snapshot taken before it, when nothing touched.
TEST(AutoModelRigid, AWorldOfVolumesInFreeFlightGetsASpanOverItsFirstContact) {
    SceneDescription d;
    d.bodies.push_back(Ground(0.5f));
    for (int i = 0; i < 4; ++i) {
        const vec3 at(static_cast<float>(i / 2) * 0.8f - 0.4f, 0.7f, static_cast<float>(i % 2) * 0.8f - 0.4f);
        d.bodies.push_back(Box("b" + std::to_string(i), at, vec3(0.2f, 0.2f, 0.2f)));
    }
    bool met = false;
    const AutoModel chosen = Chosen(d, 1.0, 1e-2, Untimed(), &met);
    const ModelChoiceResult& c = chosen.Choice();
    ASSERT_EQ(c.eventTimes.size(), 1u);
    const double landing = std::sqrt(2.0 * 0.5 / 9.82);
    EXPECT_GE(c.eventTimes[0], c.spanSeconds) << "where the start span ends or after";
    EXPECT_LT(c.eventTimes[0], landing) << "before the boxes touch the ground";
    int spans = 0;
    for (const CandidateEstimate& e : c.candidates) spans += e.evaluated && e.segments.size() == 2 ? 1 : 0;
    EXPECT_GT(spans, 0) << "candidates estimated over both spans";

    // Boxes resting on the ground from the start: no onset to find.
    SceneDescription resting;
    resting.bodies.push_back(Ground(0.5f));
    resting.bodies.push_back(Box("a", vec3(0, 0.2f, 0), vec3(0.2f, 0.2f, 0.2f)));
    resting.bodies.push_back(Box("b", vec3(1, 0.2f, 0), vec3(0.2f, 0.2f, 0.2f)));
    EXPECT_TRUE(Chosen(resting, 1.0, 1e-2, Untimed(), &met).Choice().eventTimes.empty());
}

// Two boxes sliding at 3 m/s: at dt 0.1 s a box travels past the substep bound, so the book and accumulated solvers
// split the step into travel-bound substeps, and dt 0.05 s takes half as many of the same length. The candidate and
// its refinement then run the same substeps: their difference is 0, which is no estimate (a 4 x 4 grid of such boxes
// chose the book solver at dt 0.1 s on that 0 and ended 2,100 times its budget off). Such a candidate gets no
// estimate, and the choice goes on to candidates whose refinement does refine.
TEST(AutoModelRigid, ACandidateWhoseRefinementTakesTheSameSubstepsGetsNoEstimate) {
    SceneDescription d;
    d.bodies.push_back(Ground(0.7f));
    d.bodies.push_back(Box("a", vec3(-2, 0.1f, 0), vec3(0.3f, 0.1f, 0.2f), vec3(3.0f, 0, 0)));
    d.bodies.push_back(Box("b", vec3(2, 0.1f, 3), vec3(0.2f, 0.1f, 0.3f), vec3(0, 0, -3.0f)));
    bool met = false;
    const AutoModel chosen = Chosen(d, 0.6, 1e-2, Untimed(), &met);
    const ModelChoiceResult& c = chosen.Choice();
    int travelBound = 0;
    for (const CandidateEstimate& e : c.candidates) {
        if (!e.evaluated || e.model.solver == ContactSolver::Soft || e.model.step != 0.1) continue;
        ++travelBound;
        EXPECT_TRUE(std::isinf(e.estimate)) << e.model.Describe(false, true) << ": " << e.estimate;
        EXPECT_NE(e.note.find("no more volume substeps"), std::string::npos) << e.note;
    }
    EXPECT_GT(travelBound, 0) << "book or accumulated candidates at dt 0.1 s were estimated";
    ASSERT_TRUE(met);
    ASSERT_GE(c.chosen, 0);
    EXPECT_GT(c.candidates[static_cast<std::size_t>(c.chosen)].estimate, 0.0) << "chosen on a real difference";
}

}  // namespace
