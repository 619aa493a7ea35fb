#include "Physics/Broadphase.h"

#include <algorithm>
#include <cmath>

#include "Physics/RigidbodyVolume.h"

void VolumeBounds(const RigidbodyVolume& body, vec3* outMin, vec3* outMax) {
    vec3 extent;
    if (body.type == RigidbodyType::Sphere) {
        const float r = body.sphere.radius;
        extent = vec3(r, r, r);
        *outMin = body.sphere.position - extent;
        *outMax = body.sphere.position + extent;
        return;
    }
    if (body.type == RigidbodyType::Box) {
        // Half extent along world axis i: sum over local axes k of |axis_k[i]| * size_k.
        const mat3& R = body.box.orientation;
        for (int i = 0; i < 3; ++i)
            extent[i] = std::fabs(R[0][i]) * body.box.size.x + std::fabs(R[1][i]) * body.box.size.y +
                        std::fabs(R[2][i]) * body.box.size.z;
        *outMin = body.box.position - extent;
        *outMax = body.box.position + extent;
        return;
    }
    *outMin = body.position;
    *outMax = body.position;
}

void Broadphase::FindPairs(const std::vector<RigidbodyVolume*>& volumes, std::vector<std::pair<int, int>>* pairs,
                           const unsigned char* active, float margin, float sweepTime) {
    pairs->clear();
    const int n = static_cast<int>(volumes.size());

    // Keep the previous order when the body set is unchanged; otherwise start from insertion order.
    if (static_cast<int>(entries.size()) != n) {
        entries.resize(n);
        for (int i = 0; i < n; ++i) entries[i].index = i;
    }
    for (Entry& e : entries) {
        const RigidbodyVolume& body = *volumes[e.index];
        VolumeBounds(body, &e.min, &e.max);
        if (margin > 0.0f || sweepTime > 0.0f) {
            const float grow = margin + std::sqrt(MagnitudeSq(body.velocity)) * sweepTime;
            e.min -= vec3(grow, grow, grow);
            e.max += vec3(grow, grow, grow);
        }
        e.dynamic = active != nullptr ? active[e.index] != 0 : body.mass > 0.0f;
    }
    // Insertion sort on min.x (ties by index, so the order is a pure function of the bounds): O(n) when the
    // bodies barely moved since the last step.
    for (int i = 1; i < n; ++i) {
        const Entry key = entries[i];
        int j = i - 1;
        while (j >= 0 &&
               (entries[j].min.x > key.min.x || (entries[j].min.x == key.min.x && entries[j].index > key.index))) {
            entries[j + 1] = entries[j];
            --j;
        }
        entries[j + 1] = key;
    }
    // Sweep: only bodies whose x intervals overlap are compared on y and z. A body that does not move is paired
    // only with moving ones, so its sweep jumps from one moving body to the next (nextMoving): static and sleeping
    // bodies cost O(n) in all, not a pass over their x neighbours.
    nextMoving.resize(static_cast<std::size_t>(n) + 1);
    nextMoving[static_cast<std::size_t>(n)] = n;
    for (int k = n - 1; k >= 0; --k)
        nextMoving[static_cast<std::size_t>(k)] = entries[k].dynamic ? k : nextMoving[static_cast<std::size_t>(k) + 1];
    for (int i = 0; i < n; ++i) {
        const Entry& a = entries[i];
        auto step = [&](int k) { return a.dynamic ? k + 1 : nextMoving[static_cast<std::size_t>(k) + 1]; };
        for (int k = step(i); k < n && entries[k].min.x <= a.max.x; k = step(k)) {
            const Entry& b = entries[k];
            if (a.max.y < b.min.y || b.max.y < a.min.y || a.max.z < b.min.z || b.max.z < a.min.z) continue;
            pairs->emplace_back(std::min(a.index, b.index), std::max(a.index, b.index));
        }
    }
    std::sort(pairs->begin(), pairs->end());
}
