// Probes made by copying the world (Physics/WorldCopy.h): the chooser's own, with no call back into a scene.
#include <memory>
#include <utility>

#include "Physics/ModelChoice/ModelChoice.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/StabilityMonitor.h"
#include "Physics/WorldCopy.h"

namespace {

/// A copy of `source` run with one candidate; stops at a blow-up (the stability monitor, as a scene does) or
/// when the world stops (PhysicsSystem::StopReason).
class WorldProbe : public ModelProbe {
public:
    explicit WorldProbe(std::shared_ptr<const WorldCopy> from) : source(std::move(from)) {}

    void Apply(const ModelCandidate& model) override {
        copy = std::make_unique<WorldCopy>(source->System());
        WorldSettings& s = copy->System().settings;
        s.integrator = model.integrator;
        s.contactSolver = model.solver;
        s.solverIterations = model.iterations;
        s.soft.substeps = model.softSubsteps;
        step = model.step;
        steps = 0;
        updates = 0;
        monitor = StabilityMonitor();
        monitor.Start(copy->System());
    }

    bool AdvanceTo(double seconds) override {
        const float dt = static_cast<float>(step);
        PhysicsSystem& world = copy->System();
        while (static_cast<double>(steps + 1) * step <= seconds * (1.0 + 1e-12) + 1e-12) {
            if (!monitor.Stable() || !(dt > 0.0f)) return false;
            world.Update(dt);
            if (!world.StopReason().empty() || !monitor.Check(world)) return false;
            ++steps;
            updates += world.LastVolumeSubsteps();
        }
        return true;
    }

    const PhysicsSystem& World() const override { return copy ? copy->System() : source->System(); }

    ProbeFactory Snapshot() const override { return ProbesNow(World()); }

    long long VolumeUpdates() const override { return updates; }

private:
    std::shared_ptr<const WorldCopy> source;
    std::unique_ptr<WorldCopy> copy;
    StabilityMonitor monitor;
    double step = 0.03;
    long long steps = 0;
    long long updates = 0;
};

}  // namespace

ProbeFactory ProbesNow(const PhysicsSystem& world) {
    auto now = std::make_shared<const WorldCopy>(world);
    return [now]() -> std::unique_ptr<ModelProbe> { return std::make_unique<WorldProbe>(now); };
}

ProbeFactory ProbesOf(const PhysicsSystem& world) {
    auto source = std::make_shared<std::shared_ptr<const WorldCopy>>();
    const PhysicsSystem* at = &world;
    return [source, at]() -> std::unique_ptr<ModelProbe> {
        if (!*source) *source = std::make_shared<const WorldCopy>(*at);
        return std::make_unique<WorldProbe>(*source);
    };
}
