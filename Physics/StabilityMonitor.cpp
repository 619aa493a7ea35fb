#include "Physics/StabilityMonitor.h"

#include <cmath>
#include <sstream>

#include "Physics/Cloth.h"
#include "Physics/Particle.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/Spring.h"

namespace {

double Kinetic(const Particle& p) {
    const vec3 v = p.GetVelocity();
    return 0.5 * p.GetMass() * (double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z);
}

double Gravitational(const Particle& p) {
    const vec3 g = p.GetGravity();
    const vec3 x = p.GetPosition();
    return -double(p.GetMass()) * (double(g.x) * x.x + double(g.y) * x.y + double(g.z) * x.z);
}

// Calls f(particle, kind, index, clothIndex) for every particle in system order; stops when f returns false.
template <typename F>
void ForEachParticle(const PhysicsSystem& system, F f) {
    const auto& free = system.Particles();
    for (size_t i = 0; i < free.size(); ++i)
        if (!f(*free[i], "particle", static_cast<int>(i), -1)) return;
    const auto& cloths = system.Cloths();
    for (size_t c = 0; c < cloths.size(); ++c)
        for (size_t i = 0; i < cloths[c]->verts.size(); ++i)
            if (!f(cloths[c]->verts[i], "cloth-particle", static_cast<int>(i), static_cast<int>(c))) return;
}

}  // namespace

const char* ToString(InstabilityCause cause) {
    switch (cause) {
        case InstabilityCause::None:
            return "none";
        case InstabilityCause::NonFinite:
            return "non-finite";
        case InstabilityCause::Speed:
            return "speed";
        case InstabilityCause::Energy:
            return "energy";
    }
    return "?";
}

StabilityMonitor::StabilityMonitor(const StabilitySettings& s) : settings(s) {}

double StabilityMonitor::MechanicalEnergy(const PhysicsSystem& system) {
    double energy = 0.0;
    ForEachParticle(system, [&](const Particle& p, const char*, int, int) {
        energy += Kinetic(p) + Gravitational(p);
        return true;
    });
    for (const Spring& s : system.Springs()) energy += s.PotentialEnergy();
    for (const Cloth* cloth : system.Cloths()) {
        for (const Spring& s : cloth->structural) energy += s.PotentialEnergy();
        for (const Spring& s : cloth->shear) energy += s.PotentialEnergy();
        for (const Spring& s : cloth->bend) energy += s.PotentialEnergy();
    }
    return energy;
}

void StabilityMonitor::Start(const PhysicsSystem& system) {
    report = StabilityReport();
    startEnergy = MechanicalEnergy(system);
    // Scale of "a lot of energy" for this system: what it holds in motion and springs, plus a per-kg
    // allowance so a system starting at rest still has a meaningful bound.
    double scale = 1.0;
    ForEachParticle(system, [&](const Particle& p, const char*, int, int) {
        scale += Kinetic(p) + double(settings.energyScalePerKg) * p.GetMass();
        return true;
    });
    for (const Spring& s : system.Springs()) scale += s.PotentialEnergy();
    for (const Cloth* cloth : system.Cloths()) {
        for (const Spring& s : cloth->structural) scale += s.PotentialEnergy();
        for (const Spring& s : cloth->shear) scale += s.PotentialEnergy();
        for (const Spring& s : cloth->bend) scale += s.PotentialEnergy();
    }
    energyScale = scale;
}

bool StabilityMonitor::Check(const PhysicsSystem& system) {
    if (!Stable()) return false;
    const double maxSpeedSq = double(settings.maxSpeed) * settings.maxSpeed;
    double fastestSq = -1.0;
    const char* fastestKind = "";
    int fastest = -1, fastestCloth = -1;
    ForEachParticle(system, [&](const Particle& p, const char* kind, int index, int cloth) {
        const vec3 v = p.GetVelocity();
        if (!IsFinite(p.GetPosition()) || !IsFinite(v)) {
            report.cause = InstabilityCause::NonFinite;
            report.kind = kind;
            report.body = index;
            report.cloth = cloth;
            report.value = IsFinite(p.GetPosition()) ? double(MagnitudeSq(v)) : double(MagnitudeSq(p.GetPosition()));
            return false;
        }
        const double speedSq = double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z;
        if (speedSq > fastestSq) {
            fastestSq = speedSq;
            fastestKind = kind;
            fastest = index;
            fastestCloth = cloth;
        }
        return true;
    });
    if (report.cause == InstabilityCause::None && fastest >= 0) {
        if (fastestSq > maxSpeedSq) {
            report.cause = InstabilityCause::Speed;
            report.value = std::sqrt(fastestSq);
        } else {
            const double gain = MechanicalEnergy(system) - startEnergy;
            if (gain > double(settings.maxEnergyGrowth) * energyScale) {
                report.cause = InstabilityCause::Energy;
                report.value = gain;
            }
        }
        if (report.cause != InstabilityCause::None) {
            // The fastest particle carries the runaway: name it.
            report.kind = fastestKind;
            report.body = fastest;
            report.cloth = fastestCloth;
        }
    }
    if (report.cause == InstabilityCause::None) return true;
    report.step = system.StepCount();
    std::ostringstream s;
    s << "unstable (" << ToString(report.cause) << ") at step " << report.step << ": " << report.kind << " "
      << report.body;
    if (report.cloth >= 0) s << " of cloth " << report.cloth;
    if (report.cause == InstabilityCause::Speed) s << ", speed " << report.value << " m/s";
    if (report.cause == InstabilityCause::Energy)
        s << ", energy gain " << report.value << " J > " << settings.maxEnergyGrowth << " x " << energyScale << " J";
    if (report.cause == InstabilityCause::NonFinite) s << ", non-finite position or velocity";
    report.message = s.str();
    return false;
}
