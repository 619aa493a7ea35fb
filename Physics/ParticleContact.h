#pragma once
// The particle contact setting (WorldSettings::particleContact); Particle.cpp implements its ids.

#include <string>

/// How a particle meets an OBB constraint (WorldSettings::particleContact; docs/ch14.md "Contact that converges").
enum class ParticleContact {
    /// The book's: the segment is tested against the box and the particle put Particle::kContactOffset off the
    /// surface. Each hit lifts it by that offset with no energy taken for it, so a particle at rest keeps hopping
    /// (a limit cycle of about sqrt(2 g offset / (1 - e^2)) m/s) whatever the step: its error does not shrink.
    Book,
    /// The box is inflated by kContactOffset and the particle put on the inflated surface where it crossed it: the
    /// same resting height, no lift beyond the step's own travel, so it converges as the step shrinks.
    Skin,
    /// Opt-in: the box's true surface (no offset) is tested and the step's remainder after the impact reflected about
    /// the face hit, the velocity's normal part at the impact times -e, so the particle ends the step where an ideal
    /// bounce would. Exact for a constant acceleration over the step, second order otherwise.
    Reflect,
};
/// Every contact, in the order of the "particle-contact" parameter's choices.
constexpr ParticleContact kAllParticleContacts[] = {ParticleContact::Book, ParticleContact::Skin,
                                                    ParticleContact::Reflect};
/// "book", "skin" or "reflect".
const char* ToString(ParticleContact contact);
/// "book, skin, reflect": the ids for error messages.
std::string ParticleContactIds();
/// Parses an id from ToString; false (output untouched) for anything else.
bool ParseParticleContact(const std::string& text, ParticleContact* out);
