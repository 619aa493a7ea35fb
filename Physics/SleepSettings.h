#pragma once
// Settings of islands and sleep (WorldSettings::sleep; Islands.h, docs/sleep.md).

/// Islands and sleep for rigid volumes (WorldSettings::sleep). Off by default (the book has no sleep), in the
/// benchmarks and in the sweep.
struct SleepSettings {
    /// On: an island of touching dynamic volumes that all stay slower than the speeds below for timeToSleep
    /// sleeps (no integration, no pair tests among its bodies) until a new contact, an impulse or a changed
    /// property wakes it.
    bool enabled = false;
    /// s a body must stay slow (or still: within linearSpeed * timeToSleep and angularSpeed * timeToSleep of its pose
    /// at the start of that time, docs/sleep.md) before its island may sleep.
    float timeToSleep = 0.5f;
    /// m/s: a body is slow while its linear speed is below this.
    float linearSpeed = 0.05f;
    /// rad/s: ... and its angular speed below this (2 degrees per second).
    float angularSpeed = 0.035f;
};
