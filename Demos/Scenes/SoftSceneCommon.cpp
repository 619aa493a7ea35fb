#include "Demos/Scenes/SoftSceneCommon.h"

#include <iterator>
#include <sstream>

std::vector<std::string> IntegratorChoices() {
    std::vector<std::string> ids;
    std::istringstream in(IntegratorIds());
    std::string id;
    while (std::getline(in, id, ',')) {
        const size_t first = id.find_first_not_of(' ');
        const size_t last = id.find_last_not_of(' ');
        if (first != std::string::npos) ids.push_back(id.substr(first, last - first + 1));
    }
    return ids;
}

int IntegratorIndex(Integrator integrator) {
    const std::vector<std::string> ids = IntegratorChoices();
    for (size_t i = 0; i < ids.size(); ++i)
        if (ids[i] == ToString(integrator)) return static_cast<int>(i);
    return 0;
}

Integrator IntegratorAt(int index) {
    const std::vector<std::string> ids = IntegratorChoices();
    Integrator result = Integrator::SemiImplicitEuler;
    if (index >= 0 && index < static_cast<int>(ids.size())) ParseIntegrator(ids[index], &result);
    return result;
}

void AddStepParameters(ParameterSet* set, int* integratorIndex, float* dt, const std::function<void()>& onChange) {
    set->AddChoice("integrator", integratorIndex, IntegratorChoices(),
                   "particle integrator for springs, cloth and joints (book: euler)", onChange);
    // No rebuild: the scene holds nothing that depends on its step, and a rebuild would draw new spawns from a
    // generator the book never reseeds (joints).
    set->AddFloat("dt", dt, kMinSceneDt, kMaxSceneDt, "physics step in s (book: 0.03); the host runs whole steps of it")
        .Step();
}

void AddParticleContactParameter(ParameterSet* set, int* index, const std::function<void()>& apply) {
    std::vector<std::string> ids;
    for (ParticleContact c : kAllParticleContacts) ids.emplace_back(ToString(c));
    set->AddChoice("particle-contact", index, ids,
                   "how particles meet boxes: book (put 3 mm off the surface: resting particles keep hopping at any "
                   "step), skin (the same 3 mm, converges as the step shrinks) or reflect (the true surface, the "
                   "bounce timed inside the step: second order)",
                   apply);
}

ParticleContact ParticleContactAt(int index) {
    return index >= 0 && index < static_cast<int>(std::size(kAllParticleContacts)) ? kAllParticleContacts[index]
                                                                                   : ParticleContact::Book;
}

int ParticleContactIndex(ParticleContact contact) {
    for (std::size_t i = 0; i < std::size(kAllParticleContacts); ++i)
        if (kAllParticleContacts[i] == contact) return static_cast<int>(i);
    return 0;
}

void AddJointModelParameter(ParameterSet* set, int* index, const std::function<void()>& apply) {
    set->AddChoice("joint-model", index, {ToString(JointModel::Book), ToString(JointModel::Tension)},
                   "how distance joints hold their particles: book (projected back after the step: first order for "
                   "every integrator) or tension (the joint's force in every force evaluation: each integrator keeps "
                   "its order)",
                   apply);
}

JointModel JointModelAt(int index) { return index == 1 ? JointModel::Tension : JointModel::Book; }

void AddVolumePositionsParameter(ParameterSet* set, int* index, const std::function<void()>& apply) {
    set->AddChoice("volume-positions", index, {ToString(VolumePositions::Euler), ToString(VolumePositions::Average)},
                   "how rigid volumes' positions follow their velocity: euler (x += v h, the book's: first order) or "
                   "average (x += (v_start + v_end) h / 2: exact for constant acceleration)",
                   apply);
}

VolumePositions VolumePositionsAt(int index) { return index == 1 ? VolumePositions::Average : VolumePositions::Euler; }

void ClampAboveFloor(std::vector<Particle>* particles, float floorY) {
    for (Particle& particle : *particles) {
        const vec3 pos = particle.GetPosition();
        if (pos.y < floorY) particle.SetPosition(vec3(pos.x, floorY, pos.z));
    }
}
