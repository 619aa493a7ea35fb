// Fuzz target: bytes -> the scene-file loader (Demos/Scenes/SceneFile.h). Checks that a refused input says why
// (text nested deeper than the limit: with the limit named, before parsing) and that an accepted one lies within
// the documented limits (docs/scenes.md, "Limits") with finite numbers and
// ids that resolve; small accepted scenes are built (FileScene) and stepped twice. docs/testing.md "Fuzzing".

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "Demos/Scenes/FileScene.h"
#include "Demos/Scenes/JsonNesting.h"
#include "Demos/Scenes/SceneFile.h"
#include "Physics/ModelChoice/ModelChoice.h"

namespace {

void Require(bool ok, const char* what) {
    if (ok) return;
    std::fprintf(stderr, "scene_fuzz: check failed: %s\n", what);
    std::abort();
}

bool Finite(const vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

void CheckAccepted(const SceneDescription& d) {
    Require(d.format == kSceneFormatVersion && !d.name.empty(), "format and name");
    Require(d.duration >= SceneLimits::kMinDuration && d.duration <= SceneLimits::kMaxDuration, "duration in range");
    Require(d.bodies.size() <= SceneLimits::kMaxBodies && d.constraints.size() <= SceneLimits::kMaxConstraints &&
                d.springs.size() <= SceneLimits::kMaxSprings && d.joints.size() <= SceneLimits::kMaxJoints &&
                d.cloths.size() <= SceneLimits::kMaxCloths,
            "counts within the limits");
    Require(Finite(d.world.gravity), "world finite");
    Require(d.world.step == 0.0f || (d.world.step >= SceneLimits::kMinStep && d.world.step <= SceneLimits::kMaxStep),
            "step 0 or in range");
    std::string budgetError;
    Require(!d.autoModel.Auto() || ValidateBudget(d.autoModel.Budget(), &budgetError), "an auto budget is valid");
    Require(d.autoModel.quantity >= 0 && d.autoModel.quantity <= 2, "a known budget quantity");
    for (const SceneBody& b : d.bodies) {
        Require(!b.id.empty() && Finite(b.position) && Finite(b.velocity) && Finite(b.angularVelocity), "body finite");
        Require(b.mass == 0.0f || (b.mass >= SceneLimits::kMinMass && b.mass <= SceneLimits::kMaxMass),
                "mass 0 or in range");
        Require(b.halfExtents.x > 0.0f && b.halfExtents.y > 0.0f && b.halfExtents.z > 0.0f && b.radius > 0.0f,
                "sizes > 0");
    }
    for (const SceneSpring& s : d.springs) {
        Require(s.a < d.bodies.size() && s.b < d.bodies.size() && s.a != s.b, "spring ends resolve");
        Require(d.bodies[s.a].kind == SceneBodyKind::Particle && d.bodies[s.b].kind == SceneBodyKind::Particle,
                "spring ends are particles");
    }
    for (const SceneJoint& j : d.joints) {
        Require(j.a < d.bodies.size() && j.b < d.bodies.size() && j.a != j.b, "joint ends resolve");
    }
    for (const SceneCloth& c : d.cloths) Require(c.gridSize >= 3 && c.gridSize <= SceneLimits::kMaxClothGrid, "grid");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    SceneDescription d;
    std::vector<std::string> errors;
    const bool ok = ParseSceneText(text, "fuzz.json", &d, &errors);
    Require(ok == errors.empty(), "refused exactly when a problem is reported");
    for (const std::string& e : errors) Require(e.rfind("fuzz.json", 0) == 0, "every problem names the file");
    // Nesting past the limit is refused up front, with the limit named (docs/scenes.md, "Limits").
    if (MeasureNesting(text, SceneLimits::kMaxNesting).over)
        Require(errors.size() == 1 && errors[0].find("over the limit of") != std::string::npos, "deep nesting refused");
    if (!ok) return 0;
    CheckAccepted(d);
    std::size_t particles = d.bodies.size();
    for (const SceneCloth& c : d.cloths) particles += std::size_t(c.gridSize) * std::size_t(c.gridSize);
    if (particles <= 200) {
        FileScene scene(d);
        scene.Step(0.03f);
        scene.Step(0.03f);
    }
    return 0;
}
