#pragma once
// Blow-up detection for particle, spring and cloth systems: after each step, Check() looks for a
// non-finite position or velocity, a particle faster than a limit, or mechanical energy that has grown far
// beyond what the start state holds. The first failure is frozen in a report naming the step and the body,
// so a stiff setting is reported instead of rendered as garbage. It only reads the PhysicsSystem.

#include <string>

class PhysicsSystem;

/// Limits for StabilityMonitor. The defaults never trigger in the book's scenes (tests/scenes).
struct StabilitySettings {
    float maxSpeed = 1000.0f;        ///< m/s; any particle faster than this is a blow-up
    float maxEnergyGrowth = 10.0f;   ///< runaway when E - E0 > maxEnergyGrowth * energy scale
    float energyScalePerKg = 10.0f;  ///< J/kg added to the scale per unit particle mass (~ g * 1 m)
};

enum class InstabilityCause { None, NonFinite, Speed, Energy };

/// What went wrong first. body indexes Particles() for kind "particle", cloth->verts for "cloth-particle".
struct StabilityReport {
    InstabilityCause cause = InstabilityCause::None;
    long long step = 0;     ///< PhysicsSystem::StepCount() when detected (1 = after the first step)
    const char* kind = "";  ///< "particle" or "cloth-particle"
    int body = -1;          ///< index of the offending particle
    int cloth = -1;         ///< index in Cloths() for a cloth particle, else -1
    double value = 0.0;     ///< the offending speed (m/s) or energy gain (J); NaN/inf for NonFinite
    std::string message;    ///< one line naming all of the above
};

class StabilityMonitor {
public:
    explicit StabilityMonitor(const StabilitySettings& settings = {});

    /// Records the reference energy of the current state and clears any report.
    void Start(const PhysicsSystem& system);
    /// Checks the current state; returns false once unstable (the first report is kept; later calls are cheap).
    bool Check(const PhysicsSystem& system);
    bool Stable() const { return report.cause == InstabilityCause::None; }
    const StabilityReport& Report() const { return report; }
    double StartEnergy() const { return startEnergy; }

    /// Kinetic + gravitational (-m g.p, each particle's own gravity) + spring elastic energy in J, summed in
    /// double over free and cloth particles and over system and cloth springs. Joints store no energy.
    static double MechanicalEnergy(const PhysicsSystem& system);

private:
    StabilitySettings settings;
    StabilityReport report;
    double startEnergy = 0.0;
    double energyScale = 0.0;
};

/// Name of a cause: "none", "non-finite", "speed", "energy".
const char* ToString(InstabilityCause cause);
