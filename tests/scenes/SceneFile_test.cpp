// Scene files (docs/scenes.md): every error kind is reported with the file, the JSON path and the bad value; a valid
// file is read field by field; FileScene builds only what the file names.
#include "Demos/Scenes/SceneFile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "Demos/Scenes/FileScene.h"
#include "Demos/Scenes/ModelRequest.h"
#include "Demos/Scenes/Parameters.h"
#include "Demos/Scenes/SceneExport.h"
#include "Physics/ModelChoice/ModelChoice.h"
#include "tests/support/Approx.h"

namespace {

/// Parses `text` as "t.json"; returns the problems (empty when it parsed).
std::vector<std::string> Problems(const std::string& text, SceneDescription* out = nullptr) {
    SceneDescription d;
    std::vector<std::string> errors;
    const bool ok = ParseSceneText(text, "t.json", out != nullptr ? out : &d, &errors);
    EXPECT_EQ(ok, errors.empty());
    return errors;
}

/// A minimal valid file with `bodies` spliced in as the bodies array and `extra` as further top-level members.
std::string File(const std::string& bodies, const std::string& extra = "") {
    return R"({"format": 1, "name": "t", "bodies": [)" + bodies + "]" + (extra.empty() ? "" : ", " + extra) + "}";
}

const char* kBox = R"({"id": "a", "type": "box", "position": [0, 1, 0]})";
const char* kP1 = R"({"id": "p", "type": "particle", "position": [0, 1, 0]})";
const char* kP2 = R"({"id": "q", "type": "particle", "position": [0, 2, 0]})";

/// True if exactly one problem was reported and it contains every piece.
::testing::AssertionResult OneProblem(const std::vector<std::string>& errors, std::vector<std::string> pieces) {
    if (errors.size() != 1) {
        std::string all;
        for (const auto& e : errors) all += "\n  " + e;
        return ::testing::AssertionFailure() << errors.size() << " problems:" << all;
    }
    for (const auto& piece : pieces) {
        if (errors[0].find(piece) == std::string::npos) {
            return ::testing::AssertionFailure() << "'" << errors[0] << "' lacks '" << piece << "'";
        }
    }
    return ::testing::AssertionSuccess();
}

}  // namespace

TEST(SceneFile, ReadsEveryField) {
    SceneDescription d;
    const std::string text = R"({"format": 1, "name": "All", "duration": 4.5,
      "world": {"gravity": [0, -5, 0], "step": 0.01, "integrator": "rk4", "contactSolver": "accumulated",
                "iterations": 12, "penetrationSlop": 0.02, "linearProjection": false, "projectionFraction": 0.3,
                "substeps": 4, "warmStartFactor": 0.5, "baumgarte": 0.2, "restitutionThreshold": 2,
                "jointModel": "tension"},
      "camera": {"target": [1, 2, 3], "rotation": [10, 20], "zoom": 15},
      "bodies": [{"id": "b", "type": "box", "position": [1, 2, 3], "halfExtents": [0.5, 1, 2], "euler": [0, 90, 0],
                  "velocity": [1, 0, 0], "angularVelocity": [0, 1, 0], "mass": 2, "restitution": 0.1,
                  "friction": 0.3, "velocityRetention": 1, "color": [1, 0, 0.5]},
                 {"id": "s", "type": "sphere", "position": [0, 5, 0], "radius": 0.25, "quaternion": [0, 0, 0, 2]},
                 {"id": "p", "type": "particle", "position": [0, 1, 0], "mass": 0},
                 {"id": "q", "type": "particle", "position": [0, 3, 0]}],
      "constraints": [{"position": [0, -1, 0], "halfExtents": [10, 1, 10], "euler": [5, 0, 0]}],
      "springs": [{"a": "p", "b": "q", "stiffness": 50, "damping": 1, "restLength": 2}],
      "joints": [{"a": "p", "b": "q", "length": 2}],
      "cloths": [{"gridSize": 4, "spacing": 0.5, "position": [0, 6, 0], "particleMass": 0.5,
                  "structural": {"stiffness": 100, "damping": 0.5}}]})";
    ASSERT_TRUE(Problems(text, &d).empty());
    EXPECT_EQ(d.name, "All");
    EXPECT_EQ(d.duration, 4.5f);
    EXPECT_TRUE(VecNear(d.world.gravity, vec3(0, -5, 0), 0.0f));
    EXPECT_EQ(d.world.step, 0.01f);
    EXPECT_EQ(d.world.integrator, Integrator::RK4);
    EXPECT_EQ(d.world.jointModel, JointModel::Tension);
    EXPECT_EQ(SceneWorld().jointModel, JointModel::Book) << "absent, the joints are the book's";
    EXPECT_EQ(d.world.contactSolver, ContactSolver::Accumulated);
    EXPECT_EQ(d.world.iterations, 12);
    EXPECT_FALSE(d.world.linearProjection);
    EXPECT_EQ(d.world.maxSubsteps, 4);
    EXPECT_EQ(d.world.baumgarte, 0.2f);
    EXPECT_EQ(d.camera.zoom, 15.0f);
    EXPECT_EQ(d.camera.rotation.y, 20.0f);
    ASSERT_EQ(d.bodies.size(), 4u);
    EXPECT_EQ(d.bodies[0].kind, SceneBodyKind::Box);
    EXPECT_TRUE(VecNear(d.bodies[0].halfExtents, vec3(0.5f, 1, 2), 0.0f));
    EXPECT_EQ(d.bodies[0].eulerDegrees.y, 90.0f);
    EXPECT_EQ(d.bodies[0].friction, 0.3f);
    EXPECT_TRUE(d.bodies[0].hasColor);
    EXPECT_EQ(d.bodies[1].kind, SceneBodyKind::Sphere);
    EXPECT_TRUE(d.bodies[1].hasQuaternion);
    EXPECT_EQ(d.bodies[1].orientation.w, 1.0f);  // normalised
    EXPECT_EQ(d.bodies[2].mass, 0.0f);
    EXPECT_EQ(d.bodies[2].restitution, 0.7f);  // particle default: the book's bounce
    ASSERT_EQ(d.springs.size(), 1u);
    EXPECT_EQ(d.springs[0].a, 2u);
    EXPECT_EQ(d.springs[0].b, 3u);
    EXPECT_EQ(d.joints[0].length, 2.0f);
    EXPECT_EQ(d.cloths[0].gridSize, 4);
    EXPECT_EQ(d.cloths[0].structuralStiffness, 100.0f);
}

TEST(SceneFile, SyntaxErrorHasLineAndColumn) {
    const auto e = Problems("{\"format\": 1,\n  \"name\": \"x\",\n  \"bodies\": [,]\n}");
    EXPECT_TRUE(OneProblem(e, {"t.json:3:14:", "syntax error"}));
}

TEST(SceneFile, LineAndColumnCountsFromOne) {
    int line = 0, column = 0;
    LineAndColumn("ab\ncd", 4, &line, &column);
    EXPECT_EQ(line, 2);
    EXPECT_EQ(column, 2);
    LineAndColumn("ab", 99, &line, &column);
    EXPECT_EQ(line, 1);
    EXPECT_EQ(column, 3);
}

TEST(SceneFile, WrongTypesNameThePathAndValue) {
    EXPECT_TRUE(OneProblem(Problems(File(R"({"id": "a", "type": "box", "position": [0, 1, 0], "mass": "2"})")),
                           {"t.json: bodies[0].mass: must be a number", "(got \"2\")"}));
    EXPECT_TRUE(OneProblem(Problems(File(R"({"id": "a", "type": "box", "position": [0, "y", 0]})")),
                           {"bodies[0].position[1]: must be a number"}));
    EXPECT_TRUE(OneProblem(Problems(File(R"({"id": "a", "type": "box", "position": [0, 1]})")),
                           {"bodies[0].position: must be an array of 3 numbers", "[0,1]"}));
    EXPECT_TRUE(OneProblem(Problems(File(kBox, R"("world": {"linearProjection": 1})")),
                           {"world.linearProjection: must be true or false"}));
    EXPECT_TRUE(OneProblem(Problems(File(kBox, R"("world": {"iterations": 2.5})")),
                           {"world.iterations: must be an integer", "2.5"}));
    EXPECT_TRUE(OneProblem(Problems("[1, 2]"), {"t.json: (top level): must be an object"}));
    EXPECT_TRUE(OneProblem(Problems(File(kBox, R"("springs": {})")), {"springs: must be an array"}));
}

TEST(SceneFile, MissingRequiredFields) {
    EXPECT_TRUE(OneProblem(Problems(R"({"name": "t"})"), {"format: is required"}));
    EXPECT_TRUE(OneProblem(Problems(R"({"format": 1})"), {"name: is required"}));
    EXPECT_TRUE(OneProblem(Problems(File(R"({"id": "a", "position": [0, 1, 0]})")), {"bodies[0].type: is required"}));
    EXPECT_TRUE(OneProblem(Problems(File(R"({"type": "box", "position": [0, 1, 0]})")), {"bodies[0].id: is required"}));
    EXPECT_TRUE(OneProblem(Problems(File(R"({"id": "a", "type": "box"})")), {"bodies[0].position: is required"}));
    EXPECT_TRUE(
        OneProblem(Problems(File(std::string(kP1) + "," + kP2, R"("springs": [{"a": "p", "b": "q", "stiffness": 1}])")),
                   {"springs[0].restLength: is required"}));
}

TEST(SceneFile, NonFiniteNumbers) {
    // JSON has no NaN literal: it is a syntax error with its position.
    EXPECT_TRUE(OneProblem(Problems(File(R"({"id": "a", "type": "box", "position": [0, NaN, 0]})")),
                           {"t.json:1:", "syntax error"}));
    // Out of double range is refused by the parser (with its place); out of float range becomes infinite when
    // stored.
    EXPECT_TRUE(OneProblem(Problems("{\"format\": 1,\n \"name\": \"t\", \"duration\": 1e999}"),
                           {"t.json:2:27: number is not finite: '1e999'"}));
    EXPECT_TRUE(OneProblem(Problems(File(R"({"id": "a", "type": "box", "position": [0, 3.5e38, 0]})")),
                           {"bodies[0].position[1]: must be finite", "3.5e+38"}));
    EXPECT_TRUE(OneProblem(Problems(File(R"({"id": "a", "type": "box", "position": [0, 1, 0], "mass": 1e39})")),
                           {"bodies[0].mass: must be finite", "1e+39"}));
}

TEST(SceneFile, ZeroOrNegativeSizesAndMasses) {
    EXPECT_TRUE(OneProblem(Problems(File(R"({"id": "a", "type": "box", "position": [0, 1, 0], "mass": -1})")),
                           {"bodies[0].mass: must be 0 or in [1e-06, 1e+09]", "-1"}));
    EXPECT_TRUE(
        OneProblem(Problems(File(R"({"id": "a", "type": "box", "position": [0, 1, 0], "halfExtents": [1, 0, 1]})")),
                   {"bodies[0].halfExtents[1]: must be > 0"}));
    EXPECT_TRUE(OneProblem(Problems(File(R"({"id": "a", "type": "sphere", "position": [0, 1, 0], "radius": -2})")),
                           {"bodies[0].radius: must be > 0", "-2"}));
    EXPECT_TRUE(OneProblem(Problems(File(kBox, R"("cloths": [{"gridSize": 5, "spacing": 0, "position": [0, 0, 0]}])")),
                           {"cloths[0].spacing: must be > 0"}));
    EXPECT_TRUE(OneProblem(Problems(File(kBox, R"("camera": {"zoom": 0})")), {"camera.zoom: must be > 0"}));
    EXPECT_TRUE(OneProblem(Problems(File(kBox, R"("duration": -1)")), {"duration: must be in [0.001, 3600]"}));
}

TEST(SceneFile, OutOfRangeValuesAndNames) {
    EXPECT_TRUE(OneProblem(Problems(File(R"({"id": "a", "type": "box", "position": [0, 1, 0], "restitution": 1.5})")),
                           {"bodies[0].restitution: must be in [0, 1]"}));
    EXPECT_TRUE(OneProblem(Problems(File(R"({"id": "a", "type": "cone", "position": [0, 1, 0]})")),
                           {"bodies[0].type: must be particle, sphere or box", "\"cone\""}));
    EXPECT_TRUE(OneProblem(Problems(File(kBox, R"("world": {"integrator": "leapfrog"})")),
                           {"world.integrator: is not an integrator", "rk4", "\"leapfrog\""}));
    EXPECT_TRUE(OneProblem(Problems(File(kBox, R"("world": {"particleContact": "bounce"})")),
                           {"world.particleContact: is not a particle contact", "reflect", "\"bounce\""}));
    EXPECT_TRUE(OneProblem(Problems(File(kBox, R"("world": {"contactSolver": "pgs"})")),
                           {"world.contactSolver: is not a contact solver"}));
    EXPECT_TRUE(OneProblem(Problems(File(kBox, R"("world": {"jointModel": "rigid"})")),
                           {"world.jointModel: is not a joint model", "book, tension", "\"rigid\""}));
    EXPECT_TRUE(OneProblem(Problems(File(kBox, R"("world": {"volumePositions": "verlet"})")),
                           {"world.volumePositions: is not a volume position update", "euler, average", "\"verlet\""}));
    EXPECT_TRUE(
        OneProblem(Problems(File(kBox, R"("world": {"iterations": 0})")), {"world.iterations: must be in [1, 1000]"}));
    EXPECT_TRUE(OneProblem(Problems(R"({"format": 2, "name": "t"})"), {"format: is not a version this build reads"}));
    EXPECT_TRUE(
        OneProblem(Problems(File(R"({"id": "a", "type": "box", "position": [0, 1, 0], "quaternion": [0, 0, 0, 0]})")),
                   {"bodies[0].quaternion: must have a non-zero length"}));
}

TEST(SceneFile, UnknownKeysAreErrors) {
    EXPECT_TRUE(OneProblem(Problems(File(R"({"id": "a", "type": "box", "position": [0, 1, 0], "mas": 2})")),
                           {"bodies[0].mas: unknown key"}));
    EXPECT_TRUE(OneProblem(Problems(File(kBox, R"("wrold": {})")), {"t.json: wrold: unknown key"}));
    EXPECT_TRUE(OneProblem(Problems(File(kBox, R"("world": {"gravty": [0, 0, 0]})")), {"world.gravty: unknown key"}));
    // A field of another kind of body is named as such, not silently ignored.
    EXPECT_TRUE(OneProblem(Problems(File(R"({"id": "p", "type": "particle", "position": [0, 1, 0], "friction": 0.5})")),
                           {"bodies[0].friction: is not a particle field"}));
    EXPECT_TRUE(
        OneProblem(Problems(File(R"({"id": "p", "type": "particle", "position": [0, 1, 0], "velocityEpsilon": 0})")),
                   {"bodies[0].velocityEpsilon: is not a particle field"}));
    EXPECT_TRUE(
        OneProblem(Problems(File(R"({"id": "a", "type": "box", "position": [0, 1, 0], "velocityEpsilon": -1})")),
                   {"bodies[0].velocityEpsilon: must be >= 0"}));
    EXPECT_TRUE(
        OneProblem(Problems(File(R"({"id": "s", "type": "sphere", "position": [0, 1, 0], "halfExtents": [1, 1, 1]})")),
                   {"bodies[0].halfExtents: is a box field"}));
    EXPECT_TRUE(
        OneProblem(Problems(File(kBox, R"("world": {"soft": {"hertz": 30}})")), {"world.soft.hertz: unknown key"}));
    EXPECT_TRUE(
        OneProblem(Problems(File(kBox, R"("world": {"sleep": {"time": 1}})")), {"world.sleep.time: unknown key"}));
}

// world.soft: every field of SoftSolverSettings, range-checked in the ranges of `--set soft-...`.
TEST(SceneFile, ReadsTheSoftSolversSettings) {
    SceneDescription d;
    ASSERT_TRUE(Problems(File(kBox, R"("world": {"contactSolver": "soft", "soft": {
                                   "substeps": 8, "iterations": 2, "relaxIterations": 0, "contactHertz": 60,
                                   "contactDampingRatio": 5, "maxPushoutSpeed": 1.5, "speculativeMargin": 0.04,
                                   "linearSlop": 0.001, "restitutionThreshold": 0.5, "warmStartFactor": 0.8}})"),
                         &d)
                    .empty());
    EXPECT_EQ(d.world.contactSolver, ContactSolver::Soft);
    const SoftSolverSettings& s = d.world.soft;
    EXPECT_EQ(s.substeps, 8);
    EXPECT_EQ(s.iterations, 2);
    EXPECT_EQ(s.relaxIterations, 0);
    EXPECT_EQ(s.contactHertz, 60.0f);
    EXPECT_EQ(s.contactDampingRatio, 5.0f);
    EXPECT_EQ(s.maxPushoutSpeed, 1.5f);
    EXPECT_EQ(s.speculativeMargin, 0.04f);
    EXPECT_EQ(s.linearSlop, 0.001f);
    EXPECT_EQ(s.restitutionThreshold, 0.5f);
    EXPECT_EQ(s.warmStartFactor, 0.8f);
    // Absent fields keep the engine's defaults.
    ASSERT_TRUE(Problems(File(kBox, R"("world": {"soft": {"substeps": 2}})"), &d).empty());
    EXPECT_EQ(d.world.soft.substeps, 2);
    EXPECT_EQ(d.world.soft.contactHertz, SoftSolverSettings().contactHertz);
    EXPECT_EQ(d.world.contactSolver, ContactSolver::Book);
}

TEST(SceneFile, SoftSettingsOutOfRangeNameThePathAndValue) {
    const struct {
        const char* soft;
        const char* message;
    } cases[] = {
        {R"({"substeps": 0})", "world.soft.substeps: must be in [1, 64] (got 0)"},
        {R"({"substeps": 65})", "world.soft.substeps: must be in [1, 64] (got 65)"},
        {R"({"substeps": 2.5})", "world.soft.substeps: must be an integer (got 2.5)"},
        {R"({"iterations": 0})", "world.soft.iterations: must be in [1, 100] (got 0)"},
        {R"({"relaxIterations": -1})", "world.soft.relaxIterations: must be in [0, 100] (got -1)"},
        {R"({"contactHertz": 0})", "world.soft.contactHertz: must be in [0.1, 1000] (got 0)"},
        {R"({"contactHertz": 1e6})", "world.soft.contactHertz: must be in [0.1, 1000] (got 1000000.0)"},
        {R"({"contactHertz": "30"})", "world.soft.contactHertz: must be a number (got \"30\")"},
        {R"({"contactHertz": 1e39})", "world.soft.contactHertz: must be finite"},
        {R"({"contactDampingRatio": -1})", "world.soft.contactDampingRatio: must be in [0, 100] (got -1)"},
        {R"({"maxPushoutSpeed": 101})", "world.soft.maxPushoutSpeed: must be in [0, 100] (got 101)"},
        {R"({"speculativeMargin": -0.1})", "world.soft.speculativeMargin: must be >= 0 (got -0.1)"},
        {R"({"linearSlop": -1})", "world.soft.linearSlop: must be >= 0"},
        {R"({"restitutionThreshold": -1})", "world.soft.restitutionThreshold: must be >= 0"},
        {R"({"warmStartFactor": 1.5})", "world.soft.warmStartFactor: must be in [0, 1] (got 1.5)"},
        {R"(4)", "world.soft: must be an object (got 4)"},
    };
    for (const auto& c : cases) {
        SceneDescription d;
        const auto e = Problems(File(kBox, std::string(R"("world": {"soft": )") + c.soft + "}"), &d);
        EXPECT_TRUE(OneProblem(e, {"t.json: ", c.message})) << c.soft;
    }
    // The bounds themselves are in range (compared as the stored float).
    EXPECT_TRUE(Problems(File(kBox, R"("world": {"soft": {"contactHertz": 0.1, "substeps": 64}})")).empty());
    EXPECT_TRUE(Problems(File(kBox, R"("world": {"soft": {"contactHertz": 1000, "maxPushoutSpeed": 0}})")).empty());
}

// world.sleep: true, false, or an object of SleepSettings (sleep on unless it says enabled: false).
TEST(SceneFile, ReadsSleepAsABoolOrAnObject) {
    SceneDescription d;
    ASSERT_TRUE(Problems(File(kBox), &d).empty());
    EXPECT_FALSE(d.world.sleep.enabled);
    ASSERT_TRUE(Problems(File(kBox, R"("world": {"sleep": true})"), &d).empty());
    EXPECT_TRUE(d.world.sleep.enabled);
    EXPECT_EQ(d.world.sleep.timeToSleep, SleepSettings().timeToSleep);
    ASSERT_TRUE(Problems(File(kBox, R"("world": {"sleep": false})"), &d).empty());
    EXPECT_FALSE(d.world.sleep.enabled);
    ASSERT_TRUE(Problems(File(kBox, R"("world": {"sleep": {"timeToSleep": 1, "linearSpeed": 0.1,
                                                             "angularSpeed": 0.2}})"),
                         &d)
                    .empty());
    EXPECT_TRUE(d.world.sleep.enabled);
    EXPECT_EQ(d.world.sleep.timeToSleep, 1.0f);
    EXPECT_EQ(d.world.sleep.linearSpeed, 0.1f);
    EXPECT_EQ(d.world.sleep.angularSpeed, 0.2f);
    ASSERT_TRUE(Problems(File(kBox, R"("world": {"sleep": {"enabled": false, "timeToSleep": 2}})"), &d).empty());
    EXPECT_FALSE(d.world.sleep.enabled);
    EXPECT_EQ(d.world.sleep.timeToSleep, 2.0f);

    EXPECT_TRUE(OneProblem(Problems(File(kBox, R"("world": {"sleep": 1})")),
                           {"world.sleep: must be true, false or an object (got 1)"}));
    EXPECT_TRUE(OneProblem(Problems(File(kBox, R"("world": {"sleep": {"timeToSleep": -1}})")),
                           {"world.sleep.timeToSleep: must be >= 0 (got -1)"}));
    EXPECT_TRUE(OneProblem(Problems(File(kBox, R"("world": {"sleep": {"enabled": "yes"}})")),
                           {"world.sleep.enabled: must be true or false"}));
    EXPECT_TRUE(OneProblem(Problems(File(kBox, R"("world": {"sleep": {"linearSpeed": "fast"}})")),
                           {"world.sleep.linearSpeed: must be a number"}));
}

// A key given twice in one object would silently take the last value; it is refused at the second one, with its
// line and column, its object's path and the key.
TEST(SceneFile, DuplicateKeysAreRefusedWithTheirPlace) {
    EXPECT_TRUE(OneProblem(Problems("{\"format\": 1, \"name\": \"a\",\n  \"name\": \"b\"}"),
                           {"t.json:2:3: name: duplicate key \"name\""}));
    EXPECT_TRUE(
        OneProblem(Problems(File(kBox, "\"world\": {\"iterations\": 5,\n \"gravity\": [0, 0, 0], \"iterations\": 9}")),
                   {"t.json:2:24: world.iterations: duplicate key \"iterations\""}));
    EXPECT_TRUE(OneProblem(
        Problems(
            File(std::string(kBox) + R"(, {"id": "b", "type": "box", "mass": 1, "position": [0, 3, 0], "mass": 2})")),
        {"bodies[1].mass: duplicate key \"mass\""}));
    EXPECT_TRUE(OneProblem(Problems(File(kBox, R"("world": {"soft": {"substeps": 2, "substeps": 4}})")),
                           {"world.soft.substeps: duplicate key"}));
    // The same key in different objects, and in one object of each array element, is fine.
    EXPECT_TRUE(Problems(File(std::string(kBox) + R"(, {"id": "b", "type": "box", "position": [0, 3, 0]})",
                              R"("world": {"soft": {"iterations": 2}, "iterations": 3})"))
                    .empty());
}

TEST(SceneFile, DanglingAndDuplicateIds) {
    EXPECT_TRUE(OneProblem(Problems(File(std::string(kBox) + "," + kBox)),
                           {"bodies[1].id: duplicates the id of bodies[0]", "\"a\""}));
    EXPECT_TRUE(OneProblem(Problems(File(kP1, R"("joints": [{"a": "p", "b": "nobody", "length": 1}])")),
                           {"joints[0].b: names no body", "\"nobody\""}));
    EXPECT_TRUE(OneProblem(Problems(File(std::string(kP1) + "," + kBox,
                                         R"("springs": [{"a": "p", "b": "a", "stiffness": 1, "restLength": 1}])")),
                           {"springs[0].b: must name a particle"}));
    EXPECT_TRUE(OneProblem(Problems(File(kP1, R"("joints": [{"a": "p", "b": "p", "length": 1}])")),
                           {"joints[0].b: must differ from a"}));
}

TEST(SceneFile, CountsOverLimits) {
    std::string many;
    for (std::size_t i = 0; i <= SceneLimits::kMaxConstraints; ++i) {
        many += std::string(i ? "," : "") + R"({"position": [0, 0, 0], "halfExtents": [1, 1, 1]})";
    }
    EXPECT_TRUE(OneProblem(Problems(File(kBox, "\"constraints\": [" + many + "]")),
                           {"constraints: has more than the limit of 1000 entries", "1001"}));
    EXPECT_TRUE(
        OneProblem(Problems(File(kBox, R"("cloths": [{"gridSize": 101, "spacing": 1, "position": [0, 0, 0]}])")),
                   {"cloths[0].gridSize: must be in [3, 100]"}));
    const std::string huge(SceneLimits::kMaxFileBytes + 1, ' ');
    EXPECT_TRUE(OneProblem(Problems(huge), {"t.json: (top level): is larger than the limit of 4194304 bytes"}));
}

// Nesting beyond SceneLimits::kMaxNesting is refused before parsing, with the depth, the limit and the place of
// the first bracket over it; brackets inside strings are not nesting.
TEST(SceneFile, NestingOverTheLimitIsRefusedWithItsDepth) {
    const auto nested = [](std::size_t arrays) {
        return R"({"format": 1, "name": "d", "extra": )" + std::string(arrays, '[') + std::string(arrays, ']') + "}";
    };
    const std::string deep = nested(20000);
    const std::size_t over = deep.find('[') + SceneLimits::kMaxNesting - 1;  // the object is level 1
    EXPECT_TRUE(OneProblem(Problems(deep), {"t.json:1:" + std::to_string(over + 1) +
                                            ": arrays and objects nest 20001 levels deep, over the limit of 64"}));
    // At the limit the file is parsed and checked as usual.
    EXPECT_TRUE(OneProblem(Problems(nested(SceneLimits::kMaxNesting - 1)), {"t.json: extra: unknown key"}));
    EXPECT_TRUE(OneProblem(Problems(nested(SceneLimits::kMaxNesting)), {"nest 65 levels deep"}));
    // Unbalanced text is measured as written.
    EXPECT_TRUE(OneProblem(Problems(std::string(100, '{')), {"t.json:1:65: arrays and objects nest 100 levels"}));
    // 70 brackets and braces in a string, with an escaped quote among them: one problem, the camera's unknown key.
    const std::string brackets = std::string(70, '[') + "\\\"" + std::string(70, '{');
    EXPECT_TRUE(OneProblem(Problems(File(kBox, R"("camera": {")" + brackets + R"(": 1})")),
                           {"camera." + brackets.substr(0, 10)}));
}

// Every number is stored as a float: one that would round to 0 or to a denormal is refused with the range, as is
// one beyond the float range. Masses, the duration and the step have ranges of their own, named in the message.
TEST(SceneFile, ValuesThatRoundToZeroOrOverflowAFloatAreRefusedWithTheRange) {
    const auto body = [](const std::string& field) {
        return File(R"({"id": "a", "type": "box", "position": [0, 1, 0], )" + field + "}");
    };
    for (const char* mass : {"5e-324", "1e-45", "1e-7", "1e38", "2e9"})
        EXPECT_TRUE(OneProblem(Problems(body(std::string(R"("mass": )") + mass)),
                               {"bodies[0].mass: must be 0 or in [1e-06, 1e+09]"}))
            << mass;
    SceneDescription d;
    ASSERT_TRUE(Problems(body(R"("mass": 1e-6)"), &d).empty());
    EXPECT_EQ(d.bodies[0].mass, 1e-6f);
    ASSERT_TRUE(Problems(body(R"("mass": 1e9)"), &d).empty());
    EXPECT_EQ(d.bodies[0].mass, 1e9f);
    ASSERT_TRUE(Problems(body(R"("mass": 0)"), &d).empty());
    EXPECT_EQ(d.bodies[0].mass, 0.0f);
    EXPECT_TRUE(OneProblem(
        Problems(
            File(kBox, R"("cloths": [{"gridSize": 5, "spacing": 1, "position": [0, 0, 0], "particleMass": 1e-45}])")),
        {"cloths[0].particleMass: must be in [1e-06, 1e+09]"}));
    for (const char* duration : {"1e-300", "0", "0.0009", "3601"})
        EXPECT_TRUE(OneProblem(Problems(File(kBox, std::string(R"("duration": )") + duration)),
                               {"duration: must be in [0.001, 3600]"}))
            << duration;
    // Any other field: below the smallest normal float, or beyond the largest.
    EXPECT_TRUE(OneProblem(Problems(body(R"("restitution": 1e-40)")),
                           {"bodies[0].restitution: is too small for a float: must be 0 or of magnitude at least"}));
    EXPECT_TRUE(OneProblem(Problems(body(R"("velocity": [0, 5e-324, 0])")),
                           {"bodies[0].velocity[1]: is too small for a float"}));
    EXPECT_TRUE(OneProblem(Problems(File(kBox, R"("camera": {"zoom": 1e-39})")), {"camera.zoom: is too small"}));
    EXPECT_TRUE(
        OneProblem(Problems(body(R"("friction": 1e39)")), {"bodies[0].friction: must be finite (a float: magnitude"}));
    ASSERT_TRUE(Problems(body(R"("velocity": [0, 1.2e-38, 0], "restitution": 0)"), &d).empty());
    EXPECT_EQ(d.bodies[0].velocity.y, 1.2e-38f);
}

// world.step follows --dt's rule (docs/app.md, "Steps"): 0 is the host's step, else in --dt's range; a step that is
// not a whole number of microseconds is rounded to the nearest one with a note, and one that rounds below the range
// (1e-9, 5e-7) is refused instead of becoming the host's.
TEST(SceneFile, WorldStepIsRoundedToMicrosecondsWithANoteOrRefused) {
    const auto parse = [](const std::string& step, SceneDescription* d, std::vector<std::string>* notes) {
        std::vector<std::string> errors;
        ParseSceneText(File(kBox, R"("world": {"step": )" + step + "}"), "t.json", d, &errors, notes);
        return errors;
    };
    SceneDescription d;
    std::vector<std::string> notes;
    EXPECT_TRUE(parse("0.0166666667", &d, &notes).empty());
    EXPECT_EQ(d.world.step, 0.016667f);
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_EQ(notes[0],
              "t.json: world.step: 0.0166666667 s rounded to 0.016667 s (a step is a whole number of "
              "microseconds; docs/app.md, \"Steps\")");
    notes.clear();
    for (const char* exact : {"0.01", "0.03", "0.0001", "1", "0"}) {
        EXPECT_TRUE(parse(exact, &d, &notes).empty()) << exact;
        EXPECT_EQ(d.world.step, static_cast<float>(std::atof(exact))) << exact;
    }
    EXPECT_TRUE(notes.empty());
    for (const char* bad : {"1e-9", "5e-7", "0.00009", "1.5", "-0.01"}) {
        const std::vector<std::string> errors = parse(bad, &d, &notes);
        EXPECT_TRUE(OneProblem(errors, {"t.json: world.step: must be 0 or in [0.0001, 1]"})) << bad;
    }
}

TEST(SceneFile, ReportsEveryProblemNotJustTheFirst) {
    const auto e = Problems(File(R"({"id": "a", "type": "box", "position": [0, 1, 0], "mass": -1, "friction": -1},
                                   {"id": "a", "type": "box", "position": [0, 1, 0], "colour": [1, 1, 1]})"));
    EXPECT_EQ(e.size(), 4u);
}

TEST(SceneFile, LoadReportsUnreadableAndOversizedFiles) {
    SceneDescription d;
    std::vector<std::string> errors;
    EXPECT_FALSE(LoadSceneFile("/nonexistent/scene.json", &d, &errors));
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_NE(errors[0].find("/nonexistent/scene.json: cannot read"), std::string::npos);
    EXPECT_NE(errors[0].find("cannot read: No such file or directory"), std::string::npos) << errors[0];
    errors.clear();
    EXPECT_FALSE(LoadSceneFile("/tmp", &d, &errors));
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_NE(errors[0].find("/tmp: cannot read: not a regular file"), std::string::npos) << errors[0];

    const std::string path = ::testing::TempDir() + "psb_scenefile_test.json";
    {
        std::ofstream out(path);
        out << File(kBox);
    }
    errors.clear();
    EXPECT_TRUE(LoadSceneFile(path, &d, &errors));
    EXPECT_EQ(d.bodies.size(), 1u);
    std::remove(path.c_str());
}

TEST(FileScene, BuildsOnlyWhatTheFileNames) {
    SceneDescription d;
    ASSERT_TRUE(Problems(File(std::string(kP1) + "," + kP2), &d).empty());
    FileScene particlesOnly(d);
    EXPECT_EQ(particlesOnly.System().Particles().size(), 2u);
    EXPECT_TRUE(particlesOnly.System().Volumes().empty());
    EXPECT_TRUE(particlesOnly.System().Springs().empty());
    EXPECT_TRUE(particlesOnly.System().Cloths().empty());
    EXPECT_TRUE(particlesOnly.System().Joints().empty());
    EXPECT_TRUE(particlesOnly.System().Constraints().empty());

    ASSERT_TRUE(Problems(File(std::string(kBox) + "," + kP1 + "," + kP2,
                              R"("springs": [{"a": "p", "b": "q", "stiffness": 5, "restLength": 1}],
                                 "joints": [{"a": "p", "b": "q", "length": 1}],
                                 "constraints": [{"position": [0, -1, 0], "halfExtents": [5, 1, 5]}],
                                 "cloths": [{"gridSize": 3, "spacing": 1, "position": [0, 4, 0]}])"),
                         &d)
                    .empty());
    FileScene all(d);
    EXPECT_EQ(all.System().Volumes().size(), 1u);
    EXPECT_EQ(all.System().Particles().size(), 2u);
    EXPECT_EQ(all.System().Springs().size(), 1u);
    EXPECT_EQ(all.System().Joints().size(), 1u);
    EXPECT_EQ(all.System().Constraints().size(), 1u);
    ASSERT_EQ(all.System().Cloths().size(), 1u);
    EXPECT_EQ(all.System().Cloths()[0]->verts.size(), 9u);
    EXPECT_EQ(all.BodyIndex()[1].kind, SceneBodyKind::Particle);
    EXPECT_EQ(all.BodyIndex()[2].index, 1u);
}

TEST(FileScene, AppliesWorldSettingsAndBodyFields) {
    SceneDescription d;
    ASSERT_TRUE(Problems(File(R"({"id": "s", "type": "sphere", "position": [0, 5, 0], "radius": 0.5, "mass": 3,
                                   "quaternion": [0, 0.7071068, 0, 0.7071068], "friction": 0.2,
                                   "velocityEpsilon": 0},
                                  {"id": "p", "type": "particle", "position": [1, 2, 3], "restitution": 0.3})",
                              R"("world": {"gravity": [0, -2, 0], "iterations": 9, "integrator": "verlet",
                                           "contactSolver": "accumulated", "substeps": 3,
                                           "jointModel": "tension", "volumePositions": "average"})"),
                         &d)
                    .empty());
    FileScene scene(d);
    const WorldSettings& s = scene.System().settings;
    EXPECT_EQ(s.solverIterations, 9);
    EXPECT_EQ(s.integrator, Integrator::PositionVerlet);
    EXPECT_EQ(s.jointModel, JointModel::Tension);
    EXPECT_EQ(s.volumePositions, VolumePositions::Average);
    EXPECT_EQ(s.contactSolver, ContactSolver::Accumulated);
    EXPECT_EQ(s.maxVolumeSubsteps, 3);
    const RigidbodyVolume& v = scene.Volumes()[0];
    EXPECT_EQ(v.type, RigidbodyType::Sphere);
    EXPECT_EQ(v.sphere.radius, 0.5f);
    EXPECT_EQ(v.mass, 3.0f);
    EXPECT_EQ(v.friction, 0.2f);
    EXPECT_EQ(v.velocityEpsilon, 0.0f);
    EXPECT_EQ(scene.Volumes().size(), 1u);
    EXPECT_EQ(SceneBody().velocityEpsilon, RigidbodyVolume().velocityEpsilon) << "the format's default is the engine's";
    EXPECT_NEAR(v.orientation.y, 0.7071068f, 1e-6f);
    EXPECT_TRUE(VecNear(v.gravity, vec3(0, -2, 0), 0.0f));
    const Particle& p = scene.Particles()[0];
    EXPECT_TRUE(VecNear(p.GetPosition(), vec3(1, 2, 3), 0.0f));
    EXPECT_EQ(p.GetBounce(), 0.3f);
    EXPECT_TRUE(VecNear(p.GetGravity(), vec3(0, -2, 0), 0.0f));
}

// A file's soft settings and sleep reach the world; the "solver" choice offers soft and keeps it when another
// setting changes.
TEST(FileScene, AppliesSoftSettingsAndSleepAndOffersTheSoftSolver) {
    SceneDescription d;
    ASSERT_TRUE(Problems(File(kBox, R"("world": {"contactSolver": "soft", "soft": {"substeps": 6, "contactHertz": 45},
                                                 "sleep": {"timeToSleep": 0.25}})"),
                         &d)
                    .empty());
    FileScene scene(d);
    const WorldSettings& s = scene.System().settings;
    EXPECT_EQ(s.contactSolver, ContactSolver::Soft);
    EXPECT_EQ(s.soft.substeps, 6);
    EXPECT_EQ(s.soft.contactHertz, 45.0f);
    EXPECT_TRUE(s.sleep.enabled);
    EXPECT_EQ(s.sleep.timeToSleep, 0.25f);
    EXPECT_NE(scene.ModelSummary().find("soft solver, 6 substeps, 45 Hz"), std::string::npos) << scene.ModelSummary();

    ParameterSet set;
    scene.AddParameters(&set);
    std::string error;
    ASSERT_TRUE(set.Set("iterations", "7", &error)) << error;
    EXPECT_EQ(scene.System().settings.contactSolver, ContactSolver::Soft);  // not reset to the book's
    ASSERT_TRUE(set.Set("soft-substeps", "3", &error)) << error;
    EXPECT_EQ(scene.System().settings.soft.substeps, 3);
    ASSERT_TRUE(set.Set("solver", "book", &error)) << error;
    EXPECT_EQ(scene.System().settings.contactSolver, ContactSolver::Book);
    ASSERT_TRUE(set.Set("solver", "soft", &error)) << error;
    EXPECT_EQ(scene.System().settings.contactSolver, ContactSolver::Soft);
    ASSERT_TRUE(set.Set("sleep", "0", &error)) << error;
    EXPECT_FALSE(scene.Description().world.sleep.enabled);
    EXPECT_EQ(scene.Description().world.sleep.timeToSleep, 0.25f) << "only the on/off goes through the choice";
    scene.Reset();  // the settings are the description's, so a rebuild keeps them
    EXPECT_EQ(scene.System().settings.soft.substeps, 3);
    EXPECT_EQ(scene.System().settings.contactSolver, ContactSolver::Soft);
    EXPECT_FALSE(scene.System().settings.sleep.enabled);
    EXPECT_TRUE(scene.Step(1.0f / 60.0f));
    EXPECT_EQ(scene.System().Solver().Kind(), ContactSolver::Soft) << "the world steps with the chosen solver";
}

TEST(FileScene, StepsUnderTheFilesGravity) {
    SceneDescription d;
    ASSERT_TRUE(Problems(File(kP1, R"("world": {"gravity": [0, -4, 0]})"), &d).empty());
    FileScene scene(d);
    for (int i = 0; i < 10; ++i) EXPECT_TRUE(scene.Step(0.03f));
    EXPECT_LT(scene.Particles()[0].GetVelocity().y, -0.5f);
    EXPECT_GT(scene.Particles()[0].GetVelocity().y, -4.0f * 0.3f - 1e-4f);
    EXPECT_FALSE(scene.Step(0.0f));
    scene.Reset();
    EXPECT_EQ(scene.Particles()[0].GetVelocity().y, 0.0f);
}

TEST(SceneExport, WrittenTextReadsBackToTheSameWorld) {
    SceneDescription d;
    ASSERT_TRUE(Problems(File(std::string(kBox) + "," + kP1 + "," + kP2 +
                                  R"(, {"id": "s", "type": "sphere", "position": [1, 2, 3], "radius": 0.3,
                                   "euler": [10, 20, 30], "velocity": [0.1, 0, 0], "friction": 0.25,
                                   "velocityEpsilon": 0})",
                              R"("springs": [{"a": "p", "b": "q", "stiffness": 5, "damping": 0.5, "restLength": 1.5}],
                                 "joints": [{"a": "p", "b": "q", "length": 1}],
                                 "constraints": [{"position": [0, -1, 0], "halfExtents": [5, 1, 5]}],
                                 "cloths": [{"gridSize": 4, "spacing": 0.3, "position": [0, 4, 0]}],
                                 "world": {"iterations": 7, "integrator": "rk4", "jointModel": "tension",
                                           "volumePositions": "average"})"),
                         &d)
                    .empty());
    FileScene original(d);
    std::vector<std::string> notes;
    const SceneDescription described = DescribeWorld(original.System(), "round trip", &notes);
    EXPECT_TRUE(notes.empty()) << notes.front();
    SceneDescription read;
    std::vector<std::string> errors;
    ASSERT_TRUE(ParseSceneText(WriteSceneText(described), "export.json", &read, &errors)) << errors.front();
    FileScene copy(read);
    EXPECT_EQ(copy.Volumes()[1].velocityEpsilon, 0.0f) << "a threshold other than the default is written";
    EXPECT_EQ(copy.Volumes()[0].velocityEpsilon, RigidbodyVolume().velocityEpsilon);
    EXPECT_EQ(copy.System().settings.solverIterations, 7);
    EXPECT_EQ(copy.System().settings.integrator, Integrator::RK4);
    EXPECT_EQ(copy.System().settings.jointModel, JointModel::Tension);
    EXPECT_EQ(copy.System().settings.volumePositions, VolumePositions::Average);
    ASSERT_EQ(copy.System().Bodies().size(), original.System().Bodies().size());
    ASSERT_EQ(copy.System().Springs().size(), 1u);
    EXPECT_EQ(copy.System().Springs()[0].b, 0.5f);
    EXPECT_EQ(copy.System().Joints().size(), 1u);
    ASSERT_EQ(copy.System().Cloths().size(), 1u);
    for (int step = 0; step < 30; ++step) {
        original.Step(0.03f);
        copy.Step(0.03f);
    }
    for (std::size_t i = 0; i < original.Volumes().size(); ++i) {
        EXPECT_TRUE(VecNear(original.Volumes()[i].position, copy.Volumes()[i].position, 0.0f)) << i;
    }
    for (std::size_t i = 0; i < original.Particles().size(); ++i) {
        EXPECT_TRUE(VecNear(original.Particles()[i].GetPosition(), copy.Particles()[i].GetPosition(), 0.0f)) << i;
    }
    const Cloth& a = *original.Cloths()[0];
    const Cloth& b = *copy.Cloths()[0];
    for (std::size_t i = 0; i < a.verts.size(); ++i) {
        EXPECT_TRUE(VecNear(a.verts[i].GetPosition(), b.verts[i].GetPosition(), 0.0f)) << i;
    }
}

// Soft settings and sleep are exported where they differ from the defaults, and read back to the same world.
TEST(SceneExport, WritesSoftAndSleepOnlyWhenTheyDifferFromTheDefaults) {
    SceneDescription d;
    ASSERT_TRUE(Problems(File(kBox), &d).empty());
    FileScene plain(d);
    std::vector<std::string> notes;
    const std::string plainText = WriteSceneText(DescribeWorld(plain.System(), "plain", &notes));
    EXPECT_EQ(plainText.find("\"soft\""), std::string::npos) << plainText;
    EXPECT_EQ(plainText.find("\"sleep\""), std::string::npos) << plainText;

    ASSERT_TRUE(Problems(File(kBox, R"("world": {"contactSolver": "soft", "soft": {"substeps": 8, "linearSlop": 0.002},
                                                 "sleep": true})"),
                         &d)
                    .empty());
    FileScene soft(d);
    const std::string text = WriteSceneText(DescribeWorld(soft.System(), "soft", &notes));
    EXPECT_NE(text.find("\"sleep\": true"), std::string::npos) << text;
    EXPECT_NE(text.find("\"substeps\": 8"), std::string::npos) << text;
    EXPECT_EQ(text.find("\"contactHertz\""), std::string::npos) << "a default was written: " << text;
    SceneDescription read;
    std::vector<std::string> errors;
    ASSERT_TRUE(ParseSceneText(text, "export.json", &read, &errors)) << errors.front();
    EXPECT_EQ(read.world.contactSolver, ContactSolver::Soft);
    EXPECT_EQ(read.world.soft.substeps, 8);
    EXPECT_EQ(read.world.soft.linearSlop, 0.002f);
    EXPECT_EQ(read.world.soft.contactHertz, SoftSolverSettings().contactHertz);
    EXPECT_TRUE(read.world.sleep.enabled);

    // Sleep thresholds of their own are written as the whole object.
    ASSERT_TRUE(Problems(File(kBox, R"("world": {"sleep": {"enabled": false, "angularSpeed": 0.5}})"), &d).empty());
    FileScene thresholds(d);
    const std::string text2 = WriteSceneText(DescribeWorld(thresholds.System(), "sleep", &notes));
    ASSERT_TRUE(ParseSceneText(text2, "export.json", &read, &errors)) << errors.front();
    EXPECT_FALSE(read.world.sleep.enabled);
    EXPECT_EQ(read.world.sleep.angularSpeed, 0.5f);
    EXPECT_EQ(read.world.sleep.timeToSleep, SleepSettings().timeToSleep);
}

// The error budget (docs/scenes.md, "Error budget"): "model" and "budget" read into SceneDescription::autoModel.
TEST(SceneFile, ReadsTheErrorBudget) {
    SceneDescription d;
    ASSERT_TRUE(Problems(File(kBox), &d).empty());
    EXPECT_FALSE(d.autoModel.Auto()) << "fixed is the default";

    ASSERT_TRUE(
        Problems(File(kBox, R"("model": "auto", "budget": {"quantity": "energy", "bound": 0.05})"), &d).empty());
    EXPECT_TRUE(d.autoModel.Auto());
    EXPECT_EQ(d.autoModel.quantity, static_cast<int>(BudgetQuantity::Energy));
    EXPECT_EQ(d.autoModel.bound, 0.05f);
    EXPECT_EQ(d.autoModel.Budget().quantity, BudgetQuantity::Energy);

    // The quantity defaults to position; "fixed" may keep a budget (for `--set model=auto`).
    ASSERT_TRUE(Problems(File(kBox, R"("model": "auto", "budget": {"bound": 0.002})"), &d).empty());
    EXPECT_EQ(d.autoModel.quantity, static_cast<int>(BudgetQuantity::Position));
    EXPECT_EQ(d.autoModel.bound, 0.002f);
    ASSERT_TRUE(
        Problems(File(kBox, R"("model": "fixed", "budget": {"quantity": "constraint", "bound": 0.1})"), &d).empty());
    EXPECT_FALSE(d.autoModel.Auto());
    EXPECT_EQ(d.autoModel.quantity, static_cast<int>(BudgetQuantity::Constraint));
    EXPECT_EQ(d.autoModel.bound, 0.1f);
}

TEST(SceneFile, RefusesABadErrorBudgetWithThePathAndValue) {
    EXPECT_TRUE(OneProblem(Problems(File(kBox, R"("model": "auto")")), {"t.json: budget: is required", "auto"}));
    EXPECT_TRUE(OneProblem(Problems(File(kBox, R"("model": "best", "budget": {"bound": 1})")),
                           {"t.json: model: must be \"fixed\" or \"auto\"", "(got \"best\")"}));
    EXPECT_TRUE(OneProblem(Problems(File(kBox, R"("model": "auto", "budget": {"bound": 0})")),
                           {"t.json: budget.bound: must be in [1e-09, 1e+06]", "(got 0)"}));
    EXPECT_TRUE(OneProblem(Problems(File(kBox, R"("model": "auto", "budget": {"bound": -0.01})")),
                           {"budget.bound: must be in [1e-09, 1e+06]", "(got -0.01)"}));
    EXPECT_TRUE(OneProblem(Problems(File(kBox, R"("model": "auto", "budget": {"bound": 1e39})")),
                           {"budget.bound: must be finite", "(got 1e+39)"}));
    EXPECT_TRUE(OneProblem(Problems(File(kBox, R"("model": "auto", "budget": {"bound": "tight"})")),
                           {"budget.bound: must be a number", "(got \"tight\")"}));
    EXPECT_TRUE(OneProblem(Problems(File(kBox, R"("model": "auto", "budget": {"quantity": "speed", "bound": 1})")),
                           {"budget.quantity: must be position, energy or constraint", "(got \"speed\")"}));
    EXPECT_TRUE(OneProblem(Problems(File(kBox, R"("model": "auto", "budget": {"quantity": "energy"})")),
                           {"budget.bound: is required"}));
    EXPECT_TRUE(OneProblem(Problems(File(kBox, R"("model": "auto", "budget": {"bound": 1, "safety": 2})")),
                           {"budget.safety: unknown key"}));
    EXPECT_TRUE(OneProblem(Problems(File(kBox, R"("model": "auto", "budget": 0.01)")),
                           {"budget: must be an object", "(got 0.01)"}));
    // A file and `--set error-budget=` take the same bounds.
    ParameterSet keys;
    AutoModelRequest request;
    AddAutoModelParameters(&keys, &request);
    const ParameterSet::Entry* tolerance = keys.Find("error-budget");
    ASSERT_NE(tolerance, nullptr);
    if (tolerance->max * 10.0 < 3e38) {  // a finite float above the key's range
        const std::string above = std::to_string(tolerance->max * 10.0);
        EXPECT_TRUE(OneProblem(Problems(File(kBox, R"("model": "auto", "budget": {"bound": )" + above + "}")),
                               {"budget.bound: must be in ["}));
    }
}

TEST(SceneExport, WritesTheErrorBudgetOnlyForAnAutoModel) {
    SceneDescription d;
    ASSERT_TRUE(Problems(File(kBox, R"("budget": {"quantity": "energy", "bound": 0.05})"), &d).empty());
    const std::string fixedText = WriteSceneText(d);
    EXPECT_EQ(fixedText.find("\"model\""), std::string::npos) << fixedText;
    EXPECT_EQ(fixedText.find("\"budget\""), std::string::npos) << fixedText;

    d.autoModel.model = 1;
    const std::string text = WriteSceneText(d);
    SceneDescription read;
    std::vector<std::string> errors;
    ASSERT_TRUE(ParseSceneText(text, "export.json", &read, &errors)) << errors.front() << "\n" << text;
    EXPECT_TRUE(read.autoModel.Auto());
    EXPECT_EQ(read.autoModel.quantity, static_cast<int>(BudgetQuantity::Energy));
    EXPECT_EQ(read.autoModel.bound, 0.05f);
}
