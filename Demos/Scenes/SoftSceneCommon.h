#pragma once
// Pieces shared by the chapter 16 scenes (springs, ch16, joints): the integrator and step-size parameters.

#include <functional>
#include <string>
#include <vector>

#include "Demos/Scenes/Parameters.h"
#include "Physics/Integrator.h"
#include "Physics/JointModel.h"
#include "Physics/Particle.h"
#include "Physics/VolumePositions.h"

/// Integrator ids in IntegratorIds() order ("explicit-euler", "euler", ...): the "integrator" choice list.
std::vector<std::string> IntegratorChoices();
/// Index of an integrator in IntegratorChoices(); 0 if absent.
int IntegratorIndex(Integrator integrator);
/// The integrator at an index of IntegratorChoices(); the book's semi-implicit Euler if out of range.
Integrator IntegratorAt(int index);

/// Step-size range offered on the panel and by --set dt=..., in seconds.
constexpr float kMinSceneDt = 0.0005f;
constexpr float kMaxSceneDt = 0.1f;

/// Registers "integrator" (choice bound to *integratorIndex) and "dt" (s, bound to *dt) on *set. onChange runs
/// after --set integrator= (the scenes reset, as the book's widgets take effect on Reset); dt needs no reset: it
/// is the step the host runs (DemoBase::PhysicsStep).
void AddStepParameters(ParameterSet* set, int* integratorIndex, float* dt, const std::function<void()>& onChange);

/// Registers "particle-contact" (book|skin|reflect, bound to *index) on *set: how free and cloth particles meet their
/// boxes (ParticleContact, docs/ch14.md "Contact that converges"). `apply` puts the choice into the world at once.
void AddParticleContactParameter(ParameterSet* set, int* index, const std::function<void()>& apply);
/// The ParticleContact at an index of that choice (book for anything else).
ParticleContact ParticleContactAt(int index);
/// The index of `contact` in that choice (ParticleContactAt's inverse).
int ParticleContactIndex(ParticleContact contact);

/// Registers "joint-model" (book|tension, bound to *index) on *set: how distance joints hold their particles
/// (JointModel, docs/ch16.md "A joint that keeps the integrator's order"). `apply` puts the choice into the world.
void AddJointModelParameter(ParameterSet* set, int* index, const std::function<void()>& apply);
/// The JointModel at an index of that choice (book for anything else).
JointModel JointModelAt(int index);
/// Registers "volume-positions" (euler|average, bound to *index) on *set: how rigid volumes' positions follow their
/// velocity (VolumePositions, docs/ch15.md "A position update exact for constant acceleration").
void AddVolumePositionsParameter(ParameterSet* set, int* index, const std::function<void()>& apply);
/// The VolumePositions at an index of that choice (euler for anything else).
VolumePositions VolumePositionsAt(int index);

/// The "integrator" choice behind a chapter 16 scene's panel. The scene owns its params; this holds the rest.
/// Host time is not accumulated here: the host runs whole physics steps of the scene's dt (DemoBase::PhysicsStep).
class SoftSceneStepping {
public:
    /// Points the "integrator" choice at `integrator` (Reset(params)).
    void Select(Integrator integrator) { integratorIndex = IntegratorIndex(integrator); }
    /// The integrator the "integrator" choice names (Reset() from the panel values).
    Integrator Chosen() const { return IntegratorAt(integratorIndex); }
    /// AddStepParameters bound to this choice and to *dt.
    void AddParameters(ParameterSet* set, float* dt, const std::function<void()>& onChange) {
        AddStepParameters(set, &integratorIndex, dt, onChange);
    }
    /// The "particle-contact" choice (AddParticleContactParameter); `apply` puts Contact() into the scene's world.
    void AddContactParameter(ParameterSet* set, const std::function<void()>& apply) {
        AddParticleContactParameter(set, &contactIndex, apply);
    }
    ParticleContact Contact() const { return ParticleContactAt(contactIndex); }

private:
    int integratorIndex = 0;
    int contactIndex = 0;
};

/// Raises every particle below floorY to it (the book's Update clamp y >= -5 in springs and joints).
void ClampAboveFloor(std::vector<Particle>* particles, float floorY);
