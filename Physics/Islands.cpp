#include "Physics/Islands.h"

#include <algorithm>
#include <cmath>

#include "Physics/RigidbodyVolume.h"

namespace {

bool SameVec(const vec3& a, const vec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

/// sin^2 of half the angle turned from orientation a to b (unit quaternions): 1 - (a . b)^2.
float TurnSinSq(const quat& a, const quat& b) {
    const float d = a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w;
    return 1.0f - d * d;
}

}  // namespace

Islands::Snapshot Islands::Take(const RigidbodyVolume& body) {
    Snapshot s;
    s.position = body.position;
    s.velocity = body.velocity;
    s.angVel = body.angVel;
    s.torques = body.torques;
    s.gravity = body.gravity;
    s.boxSize = body.box.size;
    s.orientation = body.orientation;
    s.mass = body.mass;
    s.cor = body.cor;
    s.friction = body.friction;
    s.radius = body.sphere.radius;
    return s;
}

bool Islands::Same(const Snapshot& a, const Snapshot& b) {
    return SameVec(a.position, b.position) && SameVec(a.velocity, b.velocity) && SameVec(a.angVel, b.angVel) &&
           SameVec(a.torques, b.torques) && SameVec(a.gravity, b.gravity) && SameVec(a.boxSize, b.boxSize) &&
           a.orientation.x == b.orientation.x && a.orientation.y == b.orientation.y &&
           a.orientation.z == b.orientation.z && a.orientation.w == b.orientation.w && a.mass == b.mass &&
           a.cor == b.cor && a.friction == b.friction && a.radius == b.radius;
}

bool Islands::BeginStep(const std::vector<RigidbodyVolume*>& volumes, const SleepSettings& settings) {
    if (!settings.enabled) {
        if (inUse) Reset(volumes);  // sleep turned off: everything awake, state forgotten
        inUse = false;
        return false;
    }
    const std::size_t n = volumes.size();
    // A changed volume list (added, removed or reordered bodies) wakes everything: indices no longer name the same
    // bodies, and a new body may rest on a sleeping one. The old list's bodies may be gone, so only the current
    // ones are touched.
    bool sameList = inUse && known.size() == n;
    for (std::size_t i = 0; sameList && i < n; ++i) sameList = known[i] == volumes[i];
    if (!sameList) {
        Reset(volumes);
        known = volumes;
        active.assign(n, 0);
        next.assign(n, -1);
        parent.assign(n, 0);
        islandTime.assign(n, 0.0f);
        snapshots.assign(n, Snapshot());
        windowStart.assign(n, Pose());
    }
    inUse = true;

    // A sleeping body woken through its API (WakeUp clears `sleeping`) or changed from outside wakes its island.
    if (sleepingCount > 0) {
        for (std::size_t i = 0; i < n; ++i) {
            if (next[i] < 0) continue;
            const RigidbodyVolume& body = *volumes[i];
            if (!body.sleeping || !Same(snapshots[i], Take(body))) WakeIsland(static_cast<int>(i));
        }
    }
    for (std::size_t i = 0; i < n; ++i) active[i] = next[i] < 0 && volumes[i]->mass > 0.0f ? 1 : 0;
    return true;
}

void Islands::WakeIsland(int index) {
    if (index < 0 || static_cast<std::size_t>(index) >= next.size() || next[static_cast<std::size_t>(index)] < 0)
        return;
    // Walk the island's circular list once, unlinking as it goes.
    int i = index;
    do {
        const std::size_t k = static_cast<std::size_t>(i);
        const int following = next[k];
        next[k] = -1;
        RigidbodyVolume& body = *known[k];
        body.sleeping = false;
        body.sleepTime = 0.0f;
        active[k] = body.mass > 0.0f ? 1 : 0;
        --sleepingCount;
        i = following;
    } while (i != index);
}

void Islands::WakeAll() {
    for (std::size_t i = 0; i < next.size(); ++i) WakeIsland(static_cast<int>(i));
}

void Islands::Reset(const std::vector<RigidbodyVolume*>& volumes) {
    for (RigidbodyVolume* body : volumes) {
        body->sleeping = false;
        body->sleepTime = 0.0f;
    }
    known.clear();
    std::fill(next.begin(), next.end(), -1);
    sleepingCount = 0;
    islandCount = 0;
    islandsSlept = 0;
}

int Islands::WakeTouchedPair(int a, int b) {
    const std::size_t ka = static_cast<std::size_t>(a), kb = static_cast<std::size_t>(b);
    if (active[ka] && next[kb] >= 0) {
        WakeIsland(b);
        return 1;
    }
    if (active[kb] && next[ka] >= 0) {
        WakeIsland(a);
        return 1;
    }
    return 0;
}

void Islands::BeginIslands(const std::vector<RigidbodyVolume*>& volumes, float dt, const SleepSettings& settings) {
    const float linearSq = settings.linearSpeed * settings.linearSpeed;
    const float angularSq = settings.angularSpeed * settings.angularSpeed;
    // The ball a still body stays in over its window: what a body at the sleep speeds would cover in timeToSleep.
    const float reach = std::max(settings.timeToSleep, 0.0f);
    const float radius = settings.linearSpeed * reach;
    const float halfTurn = std::sin(std::min(0.5f * settings.angularSpeed * reach, 1.5f));
    const float radiusSq = radius * radius, halfTurnSq = halfTurn * halfTurn;
    for (std::size_t i = 0; i < volumes.size(); ++i) {
        parent[i] = static_cast<int>(i);
        if (!active[i]) continue;
        RigidbodyVolume& body = *volumes[i];
        Pose& start = windowStart[i];
        if (body.sleepTime == 0.0f) start = Pose{body.position, body.orientation};  // a window starts here
        const bool slow = MagnitudeSq(body.velocity) < linearSq && MagnitudeSq(body.angVel) < angularSq;
        const bool still = body.sleepTime > 0.0f && MagnitudeSq(body.position - start.position) < radiusSq &&
                           TurnSinSq(start.orientation, body.orientation) < halfTurnSq;
        body.sleepTime = slow || still ? body.sleepTime + dt : 0.0f;
    }
}

int Islands::Find(int i) {
    // Path halving: every visited node skips to its grandparent.
    while (parent[static_cast<std::size_t>(i)] != i) {
        const std::size_t k = static_cast<std::size_t>(i);
        parent[k] = parent[static_cast<std::size_t>(parent[k])];
        i = parent[k];
    }
    return i;
}

void Islands::Link(int a, int b) {
    if (!active[static_cast<std::size_t>(a)] || !active[static_cast<std::size_t>(b)]) return;  // static: no link
    const int ra = Find(a), rb = Find(b);
    if (ra == rb) return;
    // The smaller index is the root: islands depend only on the pairs, not on the order they come in.
    if (ra < rb) {
        parent[static_cast<std::size_t>(rb)] = ra;
    } else {
        parent[static_cast<std::size_t>(ra)] = rb;
    }
}

void Islands::EndIslands(const std::vector<RigidbodyVolume*>& volumes, const SleepSettings& settings) {
    const std::size_t n = volumes.size();
    // Each island's smallest sleep time, kept at its root (the smallest index, so it comes first in index order).
    islandCount = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (!active[i]) continue;
        const std::size_t root = static_cast<std::size_t>(Find(static_cast<int>(i)));
        if (root == i) {
            ++islandCount;
            islandTime[i] = volumes[i]->sleepTime;
        } else {
            islandTime[root] = std::min(islandTime[root], volumes[i]->sleepTime);
        }
    }
    // Islands slow for timeToSleep fall asleep: velocities zeroed, members linked into a circular list at the root.
    islandsSlept = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (!active[i]) continue;
        const std::size_t root = static_cast<std::size_t>(Find(static_cast<int>(i)));
        // Every body slow for at least one step (a sleep time of 0 means fast now, even with timeToSleep <= 0).
        if (!(islandTime[root] > 0.0f && islandTime[root] >= settings.timeToSleep)) continue;
        RigidbodyVolume& body = *volumes[i];
        body.velocity = vec3();
        body.angVel = vec3();
        body.sleeping = true;
        snapshots[i] = Take(body);
        active[i] = 0;
        if (root == i) {
            next[i] = static_cast<int>(i);
            ++islandsSlept;
        } else {
            next[i] = next[root];
            next[root] = static_cast<int>(i);
        }
        ++sleepingCount;
    }
}
