// The pilot's helpers (docs/model-choice.md, "Spans"): a point's speed between two frames, and where a world of
// several volumes that starts in free flight first makes contact, so a calibration span can cover it.
#include <cmath>
#include <memory>

#include "Physics/ModelChoice/Internals.h"
#include "Physics/PhysicsSystem.h"

namespace model_choice {

double FastestPoint(const std::vector<double>& now, const std::vector<double>& before, double h) {
    double speed = 0.0;
    for (std::size_t i = 0; i + 2 < now.size() && before.size() == now.size(); i += 3) {
        const double d[3] = {now[i] - before[i], now[i + 1] - before[i + 1], now[i + 2] - before[i + 2]};
        speed = std::max(speed, std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) / h);
    }
    return speed;
}

void AccountPilot(double cpuSeconds, double work, ModelChoiceResult* result, ChoiceClock* clock) {
    result->pilotCpuSeconds += cpuSeconds;
    result->calibrationWork += work;
    result->calibrationCpuSeconds += cpuSeconds;
    clock->Add(cpuSeconds, work);
}

ContactOnset FindContactOnset(const ProbeFactory& factory, const CandidateSpace& space, const ChoiceSettings& settings,
                              double span, ModelChoiceResult* result, ChoiceClock* clock) {
    ContactOnset out;
    const double T = settings.runSeconds;
    const double h = space.base.step;
    if (!(h > 0.0) || space.volumeCount < 2.0) return out;  // one volume: measured over the whole run
    const double start = ProcessCpuSeconds();
    clock->StartPiece();
    clock->Candidate(0.0, "the pilot run of the scene's own model, to its first contact");
    std::unique_ptr<ModelProbe> pilot = factory();
    pilot->Apply(space.base);
    // Contact-free snapshots every half span: the newest and the one before it.
    ProbeFactory last = factory, previous;
    double lastTime = 0.0, previousTime = -1.0;
    const double interval = span / 2.0;
    long long n = 0;
    double onset = -1.0;
    while (static_cast<double>(n + 1) * h <= T * (1.0 + 1e-12)) {
        if (!pilot->AdvanceTo(static_cast<double>(n + 1) * h)) break;  // blew up: no span from it
        ++n;
        if (pilot->World().CollisionCount() > 0) {
            onset = static_cast<double>(n) * h;
            break;
        }
        if (clock->Poll(start, PredictedWork(space.base, space) * static_cast<double>(n) * h)) break;
        if (static_cast<double>(n) * h >= lastTime + interval - 1e-9) {
            previous = std::move(last);
            previousTime = lastTime;
            last = pilot->Snapshot();
            lastTime = static_cast<double>(n) * h;
        }
    }
    AccountPilot(ProcessCpuSeconds() - start, PredictedWork(space.base, space) * static_cast<double>(n) * h, result,
                 clock);
    // The start span covers an onset within it; one past it gets a span from the newest contact-free snapshot at
    // least a quarter span before it (a speculative contact may carry solver state just before a touch), which
    // then covers the first half span or more after the touch.
    if (!(onset > span)) return out;
    const bool older = lastTime > onset - 0.25 * span && previousTime > 0.0;
    out.from = older ? previous : last;
    out.start = older ? previousTime : lastTime;
    if (!(out.start > 0.0)) return ContactOnset{};
    result->eventTimes.push_back(out.start);
    return out;
}

}  // namespace model_choice
