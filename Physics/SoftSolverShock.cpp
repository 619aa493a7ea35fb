// ContactSolver::Soft, shock propagation for large mass ratios (docs/ch15.md, "Mass ratios"). A light body under a
// heavy one couples its two contacts so that each Gauss-Seidel pass moves the heavy body by light / (heavy + light)
// of what it should: at 1000:1 the passes of a step cannot hold the load and the heavy body sinks through. In
// blocks whose moving bodies' masses differ by soft.shockMassRatio or more, each substep's biased passes are
// followed by one pass (and each relax pass by another) that walks the contacts bottom up (by distance from a static
// body in the contact graph) and treats the lower body of each as immovable: the upper one alone is given the normal
// speed the contact asks for, and friction within the load that carries. The pass changes velocities only; adding its
// impulses to the contacts' (tried) made the next warm start push the light body down by the heavy one's weight at
// once, and every scene blew up.
#include <algorithm>
#include <cmath>
#include <limits>

#include "Physics/SoftSolver.h"
#include "Physics/WorldSettings.h"

namespace {

/// v M in the row-vector convention, M stored as three rows of four floats.
inline vec3 MulRows(const vec3& v, const float (*m)[4]) {
    return {v.x * m[0][0] + v.y * m[1][0] + v.z * m[2][0], v.x * m[0][1] + v.y * m[1][1] + v.z * m[2][1],
            v.x * m[0][2] + v.y * m[1][2] + v.z * m[2][2]};
}

/// Shock passes over a pair's points: its corners are solved one after another, and the turn one corner's
/// correction gives changes the others' speeds (as in the restitution passes).
constexpr int kShockPasses = 4;
/// Points of one pair in a shock pass (a solver manifold has at most four).
constexpr std::size_t kMaxShockPoints = 4;

/// r turned by a body's rotation since the step began (row-vector form, as UpdatePairSeparations).
inline vec3 Turned(const SoftContactSolver::BodyState& body, const vec3& r) {
    return vec3(body.dR[0][0], body.dR[0][1], body.dR[0][2]) * r.x +
           vec3(body.dR[1][0], body.dR[1][1], body.dR[1][2]) * r.y +
           vec3(body.dR[2][0], body.dR[2][1], body.dR[2][2]) * r.z;
}

}  // namespace

void SoftContactSolver::BuildShock(const StepContext& ctx) {
    shockPoints.clear();
    shockBlockStart.clear();
    const float ratio = ctx.settings.soft.shockMassRatio;
    if (!(ratio > 0.0f) || pairs.empty()) return;
    const std::vector<Block>& blocks = graph.Blocks();
    const std::vector<int>& blockBodies = graph.BlockBodies();
    // Which blocks reach the ratio (largest over smallest dynamic mass), and each moving body's block.
    const std::size_t n = state.size();
    bodyBlock.assign(n, -1);
    blockShocks.assign(blocks.size(), 0);
    bool any = false;
    for (std::size_t b = 0; b < blocks.size(); ++b) {
        float lightest = std::numeric_limits<float>::infinity(), heaviest = 0.0f;
        for (std::size_t k = blocks[b].bodyBegin; k < blocks[b].bodyEnd; ++k) {
            const std::size_t i = static_cast<std::size_t>(blockBodies[k]);
            bodyBlock[i] = static_cast<int>(b);
            const float mass = 1.0f / sim[i].invMass;
            lightest = std::min(lightest, mass);
            heaviest = std::max(heaviest, mass);
        }
        blockShocks[b] = heaviest >= ratio * lightest ? 1 : 0;
        any = any || blockShocks[b] != 0;
    }
    if (!any) return;

    // Layers: breadth first from the static (and sleeping) bodies over every pair. Adjacency in pair order.
    adjacencyStart.assign(n + 1, 0);
    for (const Pair& pair : pairs) {
        ++adjacencyStart[static_cast<std::size_t>(pair.a) + 1];
        ++adjacencyStart[static_cast<std::size_t>(pair.b) + 1];
    }
    for (std::size_t i = 0; i < n; ++i) adjacencyStart[i + 1] += adjacencyStart[i];
    adjacency.resize(static_cast<std::size_t>(adjacencyStart[n]));
    layerQueue.assign(adjacencyStart.begin(), adjacencyStart.end() - 1);  // fill cursors
    for (const Pair& pair : pairs) {
        adjacency[static_cast<std::size_t>(layerQueue[static_cast<std::size_t>(pair.a)]++)] = pair.b;
        adjacency[static_cast<std::size_t>(layerQueue[static_cast<std::size_t>(pair.b)]++)] = pair.a;
    }
    const int unreached = std::numeric_limits<int>::max();
    bodyLayer.assign(n, unreached);
    layerQueue.clear();
    for (std::size_t i = 0; i < n; ++i)
        if (!sim[i].dynamic) {
            bodyLayer[i] = 0;
            layerQueue.push_back(static_cast<int>(i));
        }
    for (std::size_t head = 0; head < layerQueue.size(); ++head) {
        const std::size_t i = static_cast<std::size_t>(layerQueue[head]);
        for (int k = adjacencyStart[i]; k < adjacencyStart[i + 1]; ++k) {
            const std::size_t j = static_cast<std::size_t>(adjacency[static_cast<std::size_t>(k)]);
            if (bodyLayer[j] != unreached) continue;
            bodyLayer[j] = bodyLayer[i] + 1;
            layerQueue.push_back(static_cast<int>(j));
        }
    }

    // Points of the pairs with a lower and an upper body, in shocked blocks.
    for (const Pair& pair : pairs) {
        const int la = bodyLayer[static_cast<std::size_t>(pair.a)], lb = bodyLayer[static_cast<std::size_t>(pair.b)];
        if (la == lb) continue;  // side by side, or both unreached: no order between them
        const bool bUpper = lb > la;
        const int upper = bUpper ? pair.b : pair.a, lower = bUpper ? pair.a : pair.b;
        const int block = bodyBlock[static_cast<std::size_t>(upper)];
        if (block < 0 || blockShocks[static_cast<std::size_t>(block)] == 0) continue;
        const BodySim& U = sim[static_cast<std::size_t>(upper)];
        const vec3 nUL = bUpper ? pair.n : -pair.n;
        for (std::size_t k = pair.first; k < pair.first + pair.count; ++k) {
            const Contact& c = contacts[k];
            ShockPoint p;
            p.n = nUL;
            p.rU = bUpper ? c.rB : c.rA;
            p.rL = bUpper ? c.rA : c.rB;
            p.rUxN = Cross(p.rU, nUL);
            p.iUrUxN = MulRows(p.rUxN, U.invI);
            const float kU = U.invMass + Dot(p.rUxN, p.iUrUxN);
            p.mass = kU > 0.0f ? 1.0f / kU : 0.0f;
            p.base = c.separation - Dot(p.rU - p.rL, nUL);
            p.upper = upper;
            p.lower = lower;
            p.layer = std::min(la, lb);
            p.block = static_cast<std::size_t>(block);
            p.t1 = pair.t1;
            p.t2 = pair.t2;
            p.rUxT1 = Cross(p.rU, pair.t1);
            p.rUxT2 = Cross(p.rU, pair.t2);
            p.iUrUxT1 = MulRows(p.rUxT1, U.invI);
            p.iUrUxT2 = MulRows(p.rUxT2, U.invI);
            const float k1 = U.invMass + Dot(p.rUxT1, p.iUrUxT1), k2 = U.invMass + Dot(p.rUxT2, p.iUrUxT2);
            p.massT1 = k1 > 0.0f ? 1.0f / k1 : 0.0f;
            p.massT2 = k2 > 0.0f ? 1.0f / k2 : 0.0f;
            p.friction = pair.friction;
            p.rLxN = Cross(p.rL, nUL);
            p.rLxT1 = Cross(p.rL, pair.t1);
            p.rLxT2 = Cross(p.rL, pair.t2);
            p.sequence = shockPoints.size();
            shockPoints.push_back(p);
        }
    }
    // By block, then bottom up, then in pair order (std::sort allocates nothing; the sequence makes keys unique).
    std::sort(shockPoints.begin(), shockPoints.end(), [](const ShockPoint& l, const ShockPoint& r) {
        if (l.block != r.block) return l.block < r.block;
        if (l.layer != r.layer) return l.layer < r.layer;
        return l.sequence < r.sequence;
    });
    shockBlockStart.assign(blocks.size() + 1, 0);
    for (const ShockPoint& p : shockPoints) ++shockBlockStart[p.block + 1];
    for (std::size_t b = 0; b < blocks.size(); ++b) shockBlockStart[b + 1] += shockBlockStart[b];
}

void SoftContactSolver::ShockPass(std::size_t block, float invH, float biasRate, float maxPushout, float slop) {
    const std::size_t begin = shockBlockStart[block], end = shockBlockStart[block + 1];
    std::size_t first = begin;
    while (first < end) {
        // The points of one pair (consecutive: same upper and lower body), at most kMaxShockPoints.
        std::size_t last = first + 1;
        while (last < end && last - first < kMaxShockPoints && shockPoints[last].upper == shockPoints[first].upper &&
               shockPoints[last].lower == shockPoints[first].lower)
            ++last;
        BodyState& U = state[static_cast<std::size_t>(shockPoints[first].upper)];
        const BodyState& L = state[static_cast<std::size_t>(shockPoints[first].lower)];
        const float invU = sim[static_cast<std::size_t>(shockPoints[first].upper)].invMass;
        float least[kMaxShockPoints];        // per point: the slowest normal speed the contact allows, m/s
        float pushed[kMaxShockPoints] = {};  // per point: the normal impulse given so far, N s (the friction cone)
        for (std::size_t k = first; k < last; ++k) {
            const ShockPoint& p = shockPoints[k];
            // The separation now, from both bodies' motion since the step began (UpdatePairSeparations). A gap may
            // close this substep and no more; a penetration is pushed out as the biased pass pushes a contact with
            // a static body.
            const float s = Dot(U.dp + Turned(U, p.rU) - L.dp - Turned(L, p.rL), p.n) + p.base;
            least[k - first] = s > 0.0f ? -s * invH : std::min(-biasRate * std::min(s + slop, 0.0f), maxPushout);
        }
        // What every point lacks alike is given as a push of the whole body along n (no turn): corner by corner it
        // would leave the turn of the first corners' corrections, the same way every substep, and the body would
        // rock. The passes then correct what differs between the points.
        float common = std::numeric_limits<float>::infinity();
        for (std::size_t k = first; k < last; ++k) {
            const ShockPoint& p = shockPoints[k];
            const float vn = Dot(U.v - L.v, p.n) + Dot(U.w, p.rUxN) - Dot(L.w, p.rLxN);
            common = std::min(common, std::max(least[k - first] - vn, 0.0f));
        }
        if (common > 0.0f && invU > 0.0f) {
            U.v = U.v + shockPoints[first].n * common;
            const float share = common / invU / static_cast<float>(last - first);
            for (std::size_t k = first; k < last; ++k) pushed[k - first] += share;
        }
        for (int pass = 0; pass < kShockPasses; ++pass) {
            for (std::size_t k = first; k < last; ++k) {
                const ShockPoint& p = shockPoints[k];
                // Friction first, inside the cone of the normal impulse this pass has given (the load it carries).
                const vec3 dv = U.v - L.v;
                const float vt1 = Dot(dv, p.t1) + Dot(U.w, p.rUxT1) - Dot(L.w, p.rLxT1);
                const float vt2 = Dot(dv, p.t2) + Dot(U.w, p.rUxT2) - Dot(L.w, p.rLxT2);
                float j1 = -p.massT1 * vt1, j2 = -p.massT2 * vt2;
                const float limit = p.friction * pushed[k - first];
                const float sq = j1 * j1 + j2 * j2;
                if (sq > limit * limit) {
                    const float scale = limit > 0.0f ? limit / std::sqrt(sq) : 0.0f;
                    j1 *= scale;
                    j2 *= scale;
                }
                U.v = U.v + (p.t1 * j1 + p.t2 * j2) * invU;
                U.w = U.w + p.iUrUxT1 * j1 + p.iUrUxT2 * j2;

                const float vn = Dot(U.v - L.v, p.n) + Dot(U.w, p.rUxN) - Dot(L.w, p.rLxN);
                if (vn >= least[k - first]) continue;
                const float j = p.mass * (least[k - first] - vn);
                pushed[k - first] += j;
                U.v = U.v + p.n * (invU * j);
                U.w = U.w + p.iUrUxN * j;
            }
        }
        first = last;
    }
}
