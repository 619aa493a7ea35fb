#pragma once
// The rigid volumes' position update (WorldSettings::volumePositions); RigidbodyVolume.cpp implements its ids
// (docs/ch15.md, "A position update exact for constant acceleration").

#include <string>

/// How a rigid volume's position follows its linear velocity over a (sub)step of h (WorldSettings::volumePositions).
enum class VolumePositions {
    /// The book's semi-implicit Euler: x += v_end h, with v_end the velocity after forces and contact impulses.
    /// First order: a body under constant acceleration a is off by a h t / 2 after t seconds.
    Euler,
    /// x += (v_start + v_end) h / 2, v_start the velocity the (sub)step began with: exact for constant acceleration
    /// (free fall, a steady slide), O(h^2) per step where the acceleration jumps (an impact, a stop), so second order
    /// overall. A body at rest stays put. Orientation is advanced as with Euler.
    Average,
};
/// "euler" or "average".
const char* ToString(VolumePositions mode);
/// Parses an id from ToString; false (output untouched) for anything else.
bool ParseVolumePositions(const std::string& text, VolumePositions* out);
/// Comma-separated list of every valid id, for error messages.
std::string VolumePositionsIds();
