#pragma once
// Islands and sleep for rigid volumes (WorldSettings::sleep, docs/sleep.md). An island is a set of dynamic volumes
// linked by this step's contact pairs (static bodies link nothing). A body is slow while |v| < linearSpeed and
// |w| < angularSpeed, and still while it stays within linearSpeed * timeToSleep of where its sleep time started and
// turned less than angularSpeed * timeToSleep from there (a stack swaying in place: its speed peaks above the
// thresholds while it goes nowhere); its sleep time grows by dt while slow or still and restarts otherwise (the
// window then starts again from the body's present pose). When every body of an island has been slow or still for
// timeToSleep, the island sleeps: velocities zeroed, no forces, no integration, and no pair is tested
// unless one of its bodies is awake and dynamic. A sleeping island wakes as a whole on a contact with an awake
// dynamic body, on a velocity change or impulse through the body's API (RigidbodyVolume::WakeUp), on a changed
// property (mass, friction, restitution, size, position, orientation, velocity, gravity, torque: compared with a
// snapshot taken when it fell asleep), and every island wakes when the volume list changes.
//
// A step with sleep on, for any solver:
//   islands.BeginStep(volumes, settings.sleep)      wake checks; true while sleep is in use
//   find pairs, skipping pairs where !IsActive(a) && !IsActive(b) (ActiveMask() for a broadphase)
//   islands.WakeTouched(pairs, count)              > 0: islands woke, find the pairs again (their inner pairs)
//   forces, solve, integrate only bodies with IsAwake(i) (static bodies are awake: they run as without sleep)
//   islands.Update(volumes, pairs, count, dt, settings.sleep)   once per step, with the step's touching pairs
// Pairs are any type with int members indexA and indexB (indices into `volumes`), e.g. CollisionPair.
// With sleep off and nothing asleep, BeginStep returns false and touches nothing.

#include <cstddef>
#include <utility>
#include <vector>

#include "Math/quaternion.h"
#include "Math/vectors.h"
#include "Physics/SleepSettings.h"

class RigidbodyVolume;

class Islands {
public:
    /// Call at the start of every step. With settings.enabled false it wakes anything still asleep (once) and
    /// returns false: the caller then runs its step exactly as without sleep. Otherwise it wakes every island on a
    /// changed volume list (count or any pointer) and every sleeping island of which a body was woken through its
    /// API or had a property changed since it fell asleep, refreshes the active mask and returns true.
    bool BeginStep(const std::vector<RigidbodyVolume*>& volumes, const SleepSettings& settings);

    /// True for a dynamic (mass > 0), awake volume: the only bodies that move this step. Valid after BeginStep
    /// returned true; index into the volumes given to it.
    bool IsActive(int index) const { return active[static_cast<std::size_t>(index)] != 0; }
    /// True unless the volume's island sleeps (static volumes are awake). Index as IsActive.
    bool IsAwake(int index) const { return next[static_cast<std::size_t>(index)] < 0; }
    /// IsActive per volume index, 1 or 0 (for a broadphase); valid after BeginStep returned true.
    const unsigned char* ActiveMask() const { return active.data(); }

    /// Wakes the island of every sleeping dynamic volume that touches an active one in pairs[0..count). Returns
    /// the number of islands woken: when > 0 the caller finds its pairs again, so that the woken bodies' own
    /// contacts (skipped while they slept) are in the step.
    template <class Pair>
    int WakeTouched(const Pair* pairs, std::size_t count) {
        int woken = 0;
        for (std::size_t k = 0; k < count; ++k) woken += WakeTouchedPair(pairs[k].indexA, pairs[k].indexB);
        return woken;
    }

    /// WakeTouched for (indexA, indexB) pairs as a broadphase writes them.
    int WakeTouched(const std::pair<int, int>* pairs, std::size_t count) {
        int woken = 0;
        for (std::size_t k = 0; k < count; ++k) woken += WakeTouchedPair(pairs[k].first, pairs[k].second);
        return woken;
    }

    /// Once per step, after integration: advances every active body's sleep time by dt while it is slow or still (else
    /// restarts it), builds
    /// islands by union-find over the pairs of two active bodies in pairs[0..count) and puts to sleep every island
    /// whose bodies have all been slow for settings.timeToSleep (and for at least this step, so timeToSleep <= 0
    /// puts an island to sleep at the first step all its bodies are slow, never a moving one).
    template <class Pair>
    void Update(const std::vector<RigidbodyVolume*>& volumes, const Pair* pairs, std::size_t count, float dt,
                const SleepSettings& settings) {
        BeginIslands(volumes, dt, settings);
        for (std::size_t k = 0; k < count; ++k) Link(pairs[k].indexA, pairs[k].indexB);
        EndIslands(volumes, settings);
    }

    /// Update for a step path that hands its touching pairs one by one: BeginUpdate, Link per pair, EndUpdate.
    void BeginUpdate(const std::vector<RigidbodyVolume*>& volumes, float dt, const SleepSettings& settings) {
        BeginIslands(volumes, dt, settings);
    }
    void LinkPair(int a, int b) { Link(a, b); }
    void EndUpdate(const std::vector<RigidbodyVolume*>& volumes, const SleepSettings& settings) {
        EndIslands(volumes, settings);
    }

    /// Wakes the island of volume `index` (nothing for an awake or static one). Sleep times of its bodies restart.
    void WakeIsland(int index);
    /// Wakes every sleeping island (the volumes of the last BeginStep must still exist).
    void WakeAll();

    /// Volumes asleep now; islands (of active bodies) found by the last Update, and how many of them fell asleep.
    std::size_t SleepingCount() const { return sleepingCount; }
    std::size_t IslandCount() const { return islandCount; }
    std::size_t IslandsPutToSleep() const { return islandsSlept; }

private:
    /// Property snapshot of a sleeping body, compared bit for bit at each BeginStep.
    struct Snapshot {
        vec3 position, velocity, angVel, torques, gravity, boxSize;
        quat orientation;
        float mass = 0, cor = 0, friction = 0, radius = 0;
    };
    static Snapshot Take(const RigidbodyVolume& body);
    static bool Same(const Snapshot& a, const Snapshot& b);

    /// Everything awake with sleep time 0 for `volumes` (the current list); the kept list is forgotten.
    void Reset(const std::vector<RigidbodyVolume*>& volumes);
    int WakeTouchedPair(int a, int b);
    void BeginIslands(const std::vector<RigidbodyVolume*>& volumes, float dt, const SleepSettings& settings);
    void Link(int a, int b);
    void EndIslands(const std::vector<RigidbodyVolume*>& volumes, const SleepSettings& settings);
    int Find(int i);

    std::vector<RigidbodyVolume*> known;  // the volume list of the last BeginStep, by index
    std::vector<unsigned char> active;    // 1: dynamic and awake
    std::vector<int> next;                // -1 awake; else the next body of its sleeping island (a circular list)
    std::vector<int> parent;              // union-find over active bodies, this Update only
    std::vector<float> islandTime;        // per root: the smallest sleep time of its island
    std::vector<Snapshot> snapshots;      // per sleeping body
    struct Pose {
        vec3 position;
        quat orientation;
    };
    std::vector<Pose> windowStart;  // per active body: its pose when its sleep time last started from 0
    std::size_t sleepingCount = 0;
    std::size_t islandCount = 0;
    std::size_t islandsSlept = 0;
    bool inUse = false;  // state exists (sleep was on at the last BeginStep)
};
