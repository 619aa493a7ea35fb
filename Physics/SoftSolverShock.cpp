// ContactSolver::Soft, shock propagation for large mass ratios (docs/soft-solver.md, "Mass ratios"). A light body under
// a heavy one couples its two contacts so that each Gauss-Seidel pass moves the heavy body by light / (heavy + light)
// of what it should: at 1000:1 the passes of a step cannot hold the load and the heavy body sinks through. In
// blocks whose moving bodies' masses differ by soft.shockMassRatio or more, each substep's biased passes are
// followed by one pass (and each relax pass by another) that walks the contacts bottom up (by distance from a static
// body in the contact graph) and treats the lower body of each as immovable: the upper one alone is given the normal
// speed the contact asks for. Then the loads are summed top down (what each body carries for the ones above it),
// and a friction sweep, bottom up again, gives each upper body its lower body's sideways velocity within the cone of
// that load. The pass changes velocities only; adding its impulses to the contacts' (tried) made the next warm
// start push the light body down by the heavy one's weight at once, and every scene blew up.
#include <algorithm>
#include <cmath>
#include <limits>

#include "Physics/RigidbodyVolume.h"
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
    BuildShockLayers();
    BuildShockPoints();
}

void SoftContactSolver::BuildShockLayers() {
    const std::size_t n = state.size();
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
}

void SoftContactSolver::BuildShockPoints() {
    // Where the solve keeps each contact's impulses (the contact, or its lane of a batch): the friction sweep
    // bounds itself by the load they carry and counts the friction they gave.
    rowSlots.resize(contacts.size());
    for (std::size_t k = 0; k < contacts.size(); ++k)
        rowSlots[k] = {&contacts[k].support, &contacts[k].tangent1.impulse, &contacts[k].tangent2.impulse};
    for (WideBatch& batch : batches)
        for (int lane = 0; lane < 4; ++lane) {
            if (batch.pair[lane] < 0) continue;
            const Pair& pair = pairs[static_cast<std::size_t>(batch.pair[lane])];
            for (std::size_t k = 0; k < pair.count; ++k) {
                WidePoint& w = batch.points[k];
                rowSlots[pair.first + k] = {reinterpret_cast<float*>(&w.support) + lane,
                                            reinterpret_cast<float*>(&w.tangent1.impulse) + lane,
                                            reinterpret_cast<float*>(&w.tangent2.impulse) + lane};
            }
        }
    carried.assign(state.size(), 0.0f);
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
        const bool rolls = pair.bodyA->type == RigidbodyType::Sphere || pair.bodyB->type == RigidbodyType::Sphere;
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
            p.rLxN = Cross(p.rL, nUL);
            p.friction = pair.friction;
            p.rows = rowSlots[k];
            p.t1 = bUpper ? pair.t1 : -pair.t1;  // the solve's tangent impulses push b along t, a against it
            p.t2 = bUpper ? pair.t2 : -pair.t2;
            p.rolls = rolls;
            p.upper = upper;
            p.lower = lower;
            p.layer = std::min(la, lb);
            p.block = static_cast<std::size_t>(block);
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
    // How many pairs each body rests on (what leans on it is shared among them).
    shockDown.assign(state.size(), 0);
    for (std::size_t k = 0; k < shockPoints.size(); ++k)
        if (k == 0 || shockPoints[k].upper != shockPoints[k - 1].upper ||
            shockPoints[k].lower != shockPoints[k - 1].lower)
            ++shockDown[static_cast<std::size_t>(shockPoints[k].upper)];
    const std::size_t blockCount = graph.Blocks().size();
    shockBlockStart.assign(blockCount + 1, 0);
    for (const ShockPoint& p : shockPoints) ++shockBlockStart[p.block + 1];
    for (std::size_t b = 0; b < blockCount; ++b) shockBlockStart[b + 1] += shockBlockStart[b];
}

std::size_t SoftContactSolver::ShockGroupEnd(std::size_t first, std::size_t end) const {
    std::size_t last = first + 1;
    while (last < end && last - first < kMaxShockPoints && shockPoints[last].upper == shockPoints[first].upper &&
           shockPoints[last].lower == shockPoints[first].lower)
        ++last;
    return last;
}

void SoftContactSolver::ShockNormals(std::size_t first, std::size_t last, float invH, float biasRate, float maxPushout,
                                     float slop, bool relax) {
    BodyState& U = state[static_cast<std::size_t>(shockPoints[first].upper)];
    const BodyState& L = state[static_cast<std::size_t>(shockPoints[first].lower)];
    const float invU = sim[static_cast<std::size_t>(shockPoints[first].upper)].invMass;
    float least[kMaxShockPoints];        // per point: the slowest normal speed the contact allows, m/s
    float pushed[kMaxShockPoints] = {};  // per point: the normal impulse given so far, N s
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
            const float vn = Dot(U.v - L.v, p.n) + Dot(U.w, p.rUxN) - Dot(L.w, p.rLxN);
            if (vn >= least[k - first]) continue;
            const float j = p.mass * (least[k - first] - vn);
            pushed[k - first] += j;
            U.v = U.v + p.n * (invU * j);
            U.w = U.w + p.iUrUxN * j;
        }
    }
    // The biased pass starts the substep's load at each point; the relax pass adds to it.
    for (std::size_t k = first; k < last; ++k) {
        shockPoints[k].load = (relax ? shockPoints[k].load : 0.0f) + pushed[k - first];
        if (!relax) shockPoints[k].given = vec3();
    }
}

float SoftContactSolver::PairLoad(std::size_t first, std::size_t last) const {
    const std::size_t upper = static_cast<std::size_t>(shockPoints[first].upper);
    float load = carried[upper] / static_cast<float>(shockDown[upper]);
    for (std::size_t k = first; k < last; ++k) load += shockPoints[k].load + *shockPoints[k].rows.support;
    return load;
}

void SoftContactSolver::ShockFriction(std::size_t first, std::size_t last) {
    const ShockPoint& p = shockPoints[first];
    BodyState& U = state[static_cast<std::size_t>(p.upper)];
    const BodyState& L = state[static_cast<std::size_t>(p.lower)];
    const float invU = sim[static_cast<std::size_t>(p.upper)].invMass;
    if (!(invU > 0.0f)) return;
    // The sideways velocity of the centres, not of the points: the light body's rocking (its turn, and the heavy
    // body's) would otherwise be handed on to the heavy one as a slide, every substep (docs/soft-solver.md, "Mass
    // ratios"). A pair with a sphere keeps the turns, so that rolling is not braked.
    vec3 vt = U.v - L.v;
    if (p.rolls) vt = vt + Cross(U.w, p.rU) - Cross(L.w, p.rL);
    vt = vt - p.n * Dot(vt, p.n);
    // The cone: the load through the pair this substep (the shock passes' and the solve's normal impulses) and
    // what the bodies above lean on the upper one.
    const float load = PairLoad(first, last);
    // Coulomb on the pair's whole friction this substep: the solve's (its tangent impulses) and this sweep's.
    vec3 before = p.given;
    for (std::size_t k = first; k < last; ++k) {
        const ShockPoint& q = shockPoints[k];
        before = before + q.t1 * *q.rows.tangent1 + q.t2 * *q.rows.tangent2;
    }
    vec3 total = before - vt * (1.0f / invU);
    const float limit = p.friction * load, sq = Dot(total, total);
    if (sq > limit * limit) total = total * (limit > 0.0f ? limit / std::sqrt(sq) : 0.0f);
    const vec3 j = total - before;
    shockPoints[first].given = p.given + j;
    U.v = U.v + j * invU;
}

void SoftContactSolver::ShockPass(std::size_t block, float invH, float biasRate, float maxPushout, float slop,
                                  bool relax) {
    const std::size_t begin = shockBlockStart[block], end = shockBlockStart[block + 1];
    for (std::size_t first = begin; first < end;) {
        const std::size_t last = ShockGroupEnd(first, end);
        ShockNormals(first, last, invH, biasRate, maxPushout, slop, relax);
        first = last;
    }
    // Top down (points are sorted bottom up, and a body's pairs over it have higher layers than its pairs under
    // it): each body's load on what is under it, its pairs' loads and its share of what leans on it.
    // A body that does not move this step (the ground, a sleeper) may be under several blocks, which run on
    // different threads: its load is never read, so it is not written.
    auto moves = [this](int body) { return sim[static_cast<std::size_t>(body)].dynamic; };
    for (std::size_t k = begin; k < end; ++k) {
        carried[static_cast<std::size_t>(shockPoints[k].upper)] = 0.0f;
        if (moves(shockPoints[k].lower)) carried[static_cast<std::size_t>(shockPoints[k].lower)] = 0.0f;
    }
    for (std::size_t stop = end; stop > begin;) {
        std::size_t start = stop - 1;
        while (start > begin && shockPoints[start - 1].upper == shockPoints[stop - 1].upper &&
               shockPoints[start - 1].lower == shockPoints[stop - 1].lower)
            --start;
        const float load = PairLoad(start, stop);
        if (moves(shockPoints[start].lower)) carried[static_cast<std::size_t>(shockPoints[start].lower)] += load;
        stop = start;
    }
    for (std::size_t first = begin; first < end;) {
        const std::size_t last = ShockGroupEnd(first, end);
        ShockFriction(first, last);
        first = last;
    }
}
