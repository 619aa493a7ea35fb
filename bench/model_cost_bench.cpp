// Model only what the scene requires, measured. Each demo scene's step is timed as built, and
// again with an unused subsystem present: an empty cloth registered, a static volume far away (the volume
// stage then runs), or the sweep-and-prune broadphase forced on for a two-box scene. If PhysicsSystem's stages
// really run only over the kinds present, each pair of numbers is equal within noise, except where the added
// part does real work (the forced broadphase), which shows what that part costs.
#include <benchmark/benchmark.h>

#include "Demos/Scenes/Ch14Scene.h"
#include "Demos/Scenes/Ch15Scene.h"
#include "Demos/Scenes/Ch16Scene.h"
#include "Demos/Scenes/FileScene.h"
#include "Demos/Scenes/SceneFile.h"
#include "Demos/Scenes/WorldBuilder.h"
#include "Physics/Cloth.h"
#include "Physics/RigidbodyVolume.h"

namespace {

/// What is added to a scene that does not need it.
enum Extra { kNone = 0, kEmptyCloth = 1, kFarVolume = 2, kForcedBroadphase = 3 };

const char* ExtraName(int extra) {
    switch (extra) {
        case kEmptyCloth:
            return "+empty cloth";
        case kFarVolume:
            return "+static volume far away";
        case kForcedBroadphase:
            return "+broadphase forced on";
        default:
            return "as built";
    }
}

/// Adds `extra` to a system; the objects live in *holder (outliving the system's use of them).
struct Extras {
    Cloth cloth;  // never initialised: no particles, no springs
    RigidbodyVolume far = MakeBox(vec3(1000.0f, 1000.0f, 1000.0f), vec3(1.0f, 1.0f, 1.0f), 0.0f);  // static
    void Add(int extra, PhysicsSystem& system) {
        if (extra == kEmptyCloth) system.AddCloth(&cloth);
        if (extra == kFarVolume) system.AddRigidbody(&far);
        if (extra == kForcedBroadphase) system.settings.broadphaseMinVolumes = 0;
    }
};

void BM_Ch14Step(benchmark::State& state) {
    Ch14Scene scene;  // 50 particles, semi-implicit Euler, 0.03 s (the book's demo)
    Extras extras;
    extras.Add(int(state.range(0)), scene.System());
    for (int i = 0; i < 100; ++i) scene.Step(scene.Params().dt);  // past the spawn transient
    for (auto _ : state) scene.Step(scene.Params().dt);
    state.SetLabel(ExtraName(int(state.range(0))));
}

void BM_Ch15Step(benchmark::State& state) {
    Ch15Scene scene;  // two boxes on a ground slab, 8 iterations, projection on
    Extras extras;
    extras.Add(int(state.range(0)), scene.System());
    for (int i = 0; i < 120; ++i) scene.Step(1.0f / 60.0f);  // settled
    for (auto _ : state) scene.Step(1.0f / 60.0f);
    state.SetLabel(ExtraName(int(state.range(0))));
}

void BM_Ch16Step(benchmark::State& state) {
    Ch16Scene scene;  // 15 x 15 cloth, semi-implicit Euler, 0.03 s
    Extras extras;
    extras.Add(int(state.range(0)), scene.System());
    for (auto _ : state) {
        state.PauseTiming();
        if (scene.System().StepCount() >= 200) {  // keep timing the same 200-step window
            scene.Reset(scene.Params());
            extras.Add(int(state.range(0)), scene.System());
        }
        state.ResumeTiming();
        scene.Step(scene.Params().dt);
    }
    state.SetLabel(ExtraName(int(state.range(0))));
}

}  // namespace

/// A shipped scene file (scenes/NAME.json) as FileScene builds it: only what the file names is in the world.
void SceneFileStep(benchmark::State& state, const char* name) {
    SceneDescription description;
    std::vector<std::string> errors;
    if (!LoadSceneFile(std::string(PSB_SOURCE_DIR) + "/scenes/" + name + ".json", &description, &errors)) {
        state.SkipWithError(errors.front().c_str());
        return;
    }
    FileScene scene(description);
    Extras extras;
    extras.Add(int(state.range(0)), scene.System());
    for (int i = 0; i < 100; ++i) scene.Step(0.03f);
    for (auto _ : state) scene.Step(0.03f);
    state.SetLabel(std::string(name) + ".json " + ExtraName(int(state.range(0))));
}
void BM_SceneFileCh14Step(benchmark::State& state) { SceneFileStep(state, "ch14"); }
void BM_SceneFileCh16Step(benchmark::State& state) { SceneFileStep(state, "ch16"); }

BENCHMARK(BM_SceneFileCh14Step)->Arg(kNone)->Arg(kEmptyCloth)->Arg(kFarVolume);
BENCHMARK(BM_SceneFileCh16Step)->Arg(kNone)->Arg(kFarVolume);
BENCHMARK(BM_Ch14Step)->Arg(kNone)->Arg(kEmptyCloth)->Arg(kFarVolume);
BENCHMARK(BM_Ch15Step)->Arg(kNone)->Arg(kEmptyCloth)->Arg(kForcedBroadphase);
BENCHMARK(BM_Ch16Step)->Arg(kNone)->Arg(kFarVolume);

BENCHMARK_MAIN();
