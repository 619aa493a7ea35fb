// JointModel::Tension: the distance joint's constraint force inside the particle force evaluation (docs/ch16.md,
// "A joint that keeps the integrator's order").
#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>
#include <vector>

#include "Physics/DistanceJoint.h"

namespace {

// Below this separation (m) the pair has no axis to pull along (as DistanceJoint.cpp, erratum 5.2-6).
constexpr double kMinTensionAxis = 1e-6;
// A Cholesky pivot below this fraction of its diagonal: the group's joints are dependent (or degenerate); it gets no
// tension this evaluation and is left to the projection.
constexpr double kMinPivot = 1e-9;

inline bool Movable(const Particle* p) { return p != nullptr && p->InvMass() > 0.0f; }

/// +1 when p is j's second end, -1 when its first, 0 otherwise: the sign of j's force lambda d on p.
inline double Side(const DistanceJoint& j, const Particle* p) { return j.p2 == p ? 1.0 : (j.p1 == p ? -1.0 : 0.0); }

inline double Dot3(const vec3& a, const vec3& b) { return double(a.x) * b.x + double(a.y) * b.y + double(a.z) * b.z; }

/// The group's system A lambda = b (row-major A, n x n, in `a`; b in `b`): A_jk = sum over the movable particles p
/// both joints hold of side_j(p) side_k(p) w_p d_j.d_k, b_j = -(|u_j|^2 + d_j.(a2 - a1)) from the current forces.
/// False when a joint has no particles, no movable end or coincident ends (the group then gets no tension).
bool BuildSystem(DistanceJoint* const* joints, std::size_t n, double* a, double* b) {
    for (std::size_t j = 0; j < n; ++j) {
        const DistanceJoint& J = *joints[j];
        if (J.p1 == nullptr || J.p2 == nullptr) return false;
        const vec3 d = J.p2->GetPosition() - J.p1->GetPosition();
        if (!(Dot3(d, d) > kMinTensionAxis * kMinTensionAxis)) return false;
        const vec3 u = J.p2->GetVelocity() - J.p1->GetVelocity();
        const vec3 da = J.p2->GetForces() * J.p2->InvMass() - J.p1->GetForces() * J.p1->InvMass();
        b[j] = -(Dot3(u, u) + Dot3(d, da));
        for (std::size_t k = 0; k < n; ++k) {
            const DistanceJoint& K = *joints[k];
            const vec3 dk = K.p2->GetPosition() - K.p1->GetPosition();
            double coupling = 0.0;
            for (const Particle* p : {J.p1, J.p2})
                if (Movable(p)) coupling += Side(J, p) * Side(K, p) * p->InvMass();
            a[j * n + k] = coupling * Dot3(d, dk);
        }
        if (!(a[j * n + j] > 0.0)) return false;
    }
    return true;
}

/// Solves A x = b in place (x in b) by Cholesky; false when a pivot is below kMinPivot of its diagonal.
bool SolveCholesky(double* a, double* b, std::size_t n) {
    for (std::size_t j = 0; j < n; ++j) {
        double pivot = a[j * n + j];
        for (std::size_t k = 0; k < j; ++k) pivot -= a[j * n + k] * a[j * n + k];
        if (!(pivot > kMinPivot * a[j * n + j])) return false;
        const double l = std::sqrt(pivot);
        a[j * n + j] = l;
        for (std::size_t i = j + 1; i < n; ++i) {
            double s = a[i * n + j];
            for (std::size_t k = 0; k < j; ++k) s -= a[i * n + k] * a[j * n + k];
            a[i * n + j] = s / l;
        }
    }
    for (std::size_t i = 0; i < n; ++i) {  // L y = b
        for (std::size_t k = 0; k < i; ++k) b[i] -= a[i * n + k] * b[k];
        b[i] /= a[i * n + i];
    }
    for (std::size_t i = n; i-- > 0;) {  // L^T x = y
        for (std::size_t k = i + 1; k < n; ++k) b[i] -= a[k * n + i] * b[k];
        b[i] /= a[i * n + i];
    }
    return true;
}

}  // namespace

void AddJointTensions(TensionPlan* plan) {
    std::size_t begin = 0;
    for (const std::size_t end : plan->groupEnds) {
        const std::size_t n = end - begin;
        if (plan->scratch.size() < n * n + n) plan->scratch.resize(n * n + n);
        double* a = plan->scratch.data();
        double* b = a + n * n;
        DistanceJoint* const* group = plan->joints.data() + begin;
        if (BuildSystem(group, n, a, b) && SolveCholesky(a, b, n)) {
            // lambda d on p2, -lambda d on p1; a mass-0 end gets nothing.
            for (std::size_t j = 0; j < n; ++j) {
                const DistanceJoint& J = *group[j];
                const vec3 f = (J.p2->GetPosition() - J.p1->GetPosition()) * float(b[j]);
                if (Movable(J.p1)) J.p1->AddForce(f * -1.0f);
                if (Movable(J.p2)) J.p2->AddForce(f);
            }
        }
        begin = end;
    }
}

bool TensionKeepsOrder(Integrator integrator) {
    return integrator == Integrator::VelocityVerlet || integrator == Integrator::RK4;
}

TensionPlan PlanTensions(const std::vector<DistanceJoint*>& joints) {
    // Union-find over joints: two joints holding the same movable particle are in one group.
    std::vector<std::size_t> parent(joints.size());
    std::iota(parent.begin(), parent.end(), std::size_t(0));
    auto root = [&parent](std::size_t i) {
        while (parent[i] != i) i = parent[i] = parent[parent[i]];
        return i;
    };
    std::vector<std::pair<const Particle*, std::size_t>> ends;
    for (std::size_t i = 0; i < joints.size(); ++i)
        for (const Particle* p : {joints[i]->p1, joints[i]->p2})
            if (Movable(p)) ends.emplace_back(p, i);
    std::sort(ends.begin(), ends.end());
    for (std::size_t e = 1; e < ends.size(); ++e)
        if (ends[e].first == ends[e - 1].first) parent[root(ends[e].second)] = root(ends[e - 1].second);
    // Groups in the order of their first joint, each joint in list order: the same plan whatever the addresses.
    TensionPlan plan;
    std::vector<std::vector<std::size_t>> members(joints.size());
    for (std::size_t i = 0; i < joints.size(); ++i) members[root(i)].push_back(i);
    for (std::size_t i = 0; i < joints.size(); ++i) {
        std::vector<std::size_t>& group = members[root(i)];
        if (group.empty() || group.size() > kMaxTensionGroup) continue;
        for (std::size_t k : group) plan.joints.push_back(joints[k]);
        plan.groupEnds.push_back(plan.joints.size());
        group.clear();  // placed
    }
    return plan;
}
