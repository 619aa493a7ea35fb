// Particle state, the book's single-particle step, and constraint solving against immovable OBBs
// (docs/book-reference.md §3.2), with the book's failure modes fixed: see docs/ERRATA.md, Chapter 14.
#include "Physics/Particle.h"

#include <cfloat>
#include <cmath>

#include "Physics/EnumIds.h"
#include "Physics/StepFactor.h"

namespace {

inline float Dot3(const vec3& a, const vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

/// Where the segment travelled this step first meets a box, in world space.
struct SegmentHit {
    float t = FLT_MAX;  ///< fraction of the segment at the entry; -1 when the start was already inside
    vec3 point;         ///< on the box surface
    vec3 normal;        ///< outward unit face normal
};

/// The book's Linetest + Raycast from oldPosition fused into one slab clip in the box's frame: the segment
/// p0 -> p0 + delta against the solid box. Never normalises anything, so a zero-length segment (a particle at
/// rest, erratum 5.2-6) is just a point test. A start inside (or on) the box is pushed out through the
/// nearest face (t = -1). Returns false when the closed segment misses the box.
bool ClipSegment(const OBB& box, const vec3& p0, const vec3& delta, SegmentHit* out) {
    const vec3 rel(p0.x - box.position.x, p0.y - box.position.y, p0.z - box.position.z);
    const float* m = box.orientation.asArray;
    float tEnter = -FLT_MAX, tExit = FLT_MAX;
    int enterAxis = -1;
    float enterSign = 1.0f;
    bool inside = true;
    float s[3];
    for (int i = 0; i < 3; ++i) {
        const vec3 axis(m[3 * i], m[3 * i + 1], m[3 * i + 2]);
        const float e = std::fabs(box.size[i]);
        s[i] = Dot3(rel, axis);
        const float d = Dot3(delta, axis);
        if (std::fabs(s[i]) > e) inside = false;
        // Parallel to this slab (or no motion): the start's offset alone decides.
        if (std::fabs(d) < 1e-20f) {
            if (std::fabs(s[i]) > e) return false;
            continue;
        }
        const float inv = 1.0f / d;
        float tNear = (-e - s[i]) * inv, tFar = (e - s[i]) * inv;
        if (tNear > tFar) {
            const float tmp = tNear;
            tNear = tFar;
            tFar = tmp;
        }
        if (tNear > tEnter) {
            tEnter = tNear;
            enterAxis = i;
            enterSign = d > 0.0f ? -1.0f : 1.0f;  // the face met first faces against the travel
        }
        if (tFar < tExit) tExit = tFar;
    }
    if (inside) {
        // Nearest face of the start point (smallest distance to a face plane).
        int best = 0;
        float bestGap = FLT_MAX;
        for (int i = 0; i < 3; ++i) {
            const float gap = std::fabs(box.size[i]) - std::fabs(s[i]);
            if (gap < bestGap) {
                bestGap = gap;
                best = i;
            }
        }
        const vec3 axis(m[3 * best], m[3 * best + 1], m[3 * best + 2]);
        const float sign = s[best] < 0.0f ? -1.0f : 1.0f;
        const float push = sign * std::fabs(box.size[best]) - s[best];
        out->t = -1.0f;
        out->normal = vec3(axis.x * sign, axis.y * sign, axis.z * sign);
        out->point = vec3(p0.x + axis.x * push, p0.y + axis.y * push, p0.z + axis.z * push);
        return true;
    }
    if (enterAxis < 0 || !(tEnter <= tExit) || !(tEnter >= 0.0f) || !(tEnter <= 1.0f)) return false;
    const vec3 axis(m[3 * enterAxis], m[3 * enterAxis + 1], m[3 * enterAxis + 2]);
    out->t = tEnter;
    out->normal = vec3(axis.x * enterSign, axis.y * enterSign, axis.z * enterSign);
    out->point = vec3(p0.x + delta.x * tEnter, p0.y + delta.y * tEnter, p0.z + delta.z * tEnter);
    return true;
}

inline float Min(float a, float b) { return a < b ? a : b; }
inline float Max(float a, float b) { return a > b ? a : b; }

/// True when the segment's AABB and the constraint's AABB are disjoint (plain compares: no libm calls).
inline bool SegmentMissesBounds(const vec3& a, const vec3& b, const ParticleConstraint& c) {
    return Max(a.x, b.x) < c.boundsMin.x || Min(a.x, b.x) > c.boundsMax.x || Max(a.y, b.y) < c.boundsMin.y ||
           Min(a.y, b.y) > c.boundsMax.y || Max(a.z, b.z) < c.boundsMin.z || Min(a.z, b.z) > c.boundsMax.z;
}

/// The ideal bounces that follow an impact inside one step under a constant normal acceleration `an` (< 0: back
/// towards the face): the particle leaves the face at normal speed `u` (> 0) with `left` s of the step to go, and
/// each return within it is another impact that keeps e of the speed. Writes the normal distance and velocity at
/// the step's end. When the rest of the train (sum of 2 u e^k / |an|) ends within the step, or after 64 impacts,
/// the particle is at rest on the face: the train's limit.
void BounceTrain(float u, float left, float an, float e, float* d, float* v) {
    for (int impact = 0; impact < 64 && an < 0.0f && u > 0.0f; ++impact) {
        const float flight = -2.0f * u / an;
        if (flight >= left) break;
        left -= flight;
        u *= e;
        if (e < 1.0f && -2.0f * u / (an * (1.0f - e)) <= left) u = 0.0f;
    }
    if (!(u > 0.0f) || (an < 0.0f && -2.0f * u / an < left)) {
        *d = 0.0f;
        *v = 0.0f;
        return;
    }
    *d = Max(u * left + 0.5f * an * left * left, 0.0f);
    *v = u + an * left;
}

}  // namespace

namespace {
constexpr EnumId<ParticleContact> kContactIds[] = {
    {ParticleContact::Book, "book"}, {ParticleContact::Skin, "skin"}, {ParticleContact::Reflect, "reflect"}};
}  // namespace

const char* ToString(ParticleContact contact) { return IdOf(kContactIds, contact); }

bool ParseParticleContact(const std::string& text, ParticleContact* out) { return ParseId(kContactIds, text, out); }

std::string ParticleContactIds() { return JoinIds(kContactIds); }

ParticleConstraint PrepareParticleConstraint(const OBB& box, ParticleContact contact) {
    ParticleConstraint c;
    c.box = box;
    if (contact == ParticleContact::Skin) {
        // The surface a particle rests on is kContactOffset out, as in the book, but it is the surface tested, so a
        // hit moves the particle back only along the step it took (docs/ch14.md "Contact that converges").
        const float skin = Particle::kContactOffset;
        c.box.size = vec3(std::fabs(box.size.x) + skin, std::fabs(box.size.y) + skin, std::fabs(box.size.z) + skin);
        c.placement = 0.0f;
    }
    if (contact == ParticleContact::Reflect) {
        c.placement = 0.0f;
        c.reflect = true;
    }
    const float* m = c.box.orientation.asArray;
    for (int w = 0; w < 3; ++w) {
        // World half-extent along axis w: sum over local axes of |axis_i[w]| * size_i.
        float extent = 0.0f;
        for (int i = 0; i < 3; ++i) extent += std::fabs(m[3 * i + w]) * std::fabs(c.box.size[i]);
        c.boundsMin[w] = c.box.position[w] - extent;
        c.boundsMax[w] = c.box.position[w] + extent;
    }
    return c;
}

float ContactOffsetOf(ParticleContact contact) {
    return contact == ParticleContact::Reflect ? 0.0f : Particle::kContactOffset;
}

Particle::Particle() : Rigidbody(RigidbodyType::Particle) {}

void Particle::ApplyForces() { forces = gravity * mass; }

void Particle::Update(float dt) {
    // The book's shipped EULER_INTEGRATION step (semi-implicit Euler with its velocity retention per 0.03 s).
    oldPosition = position;
    const vec3 acceleration = forces * InvMass();
    velocity = velocity * FactorOverStep(velocityRetention, kBookStep, dt) + acceleration * dt;
    position = position + velocity * dt;
}

void Particle::SolveConstraints(const std::vector<OBB>& constraints) {
    SegmentHit best, hit;
    const vec3 delta = position - oldPosition;
    for (const OBB& box : constraints)
        if (ClipSegment(box, oldPosition, delta, &hit) && hit.t < best.t) best = hit;
    if (best.t == FLT_MAX) return;
    ResolveHit(best.point, best.normal, kContactOffset);
}

void Particle::SolveConstraints(const ParticleConstraint* constraints, std::size_t count, float dt) {
    SegmentHit best, hit;
    float placement = kContactOffset;
    bool reflect = false;
    const vec3 delta(position.x - oldPosition.x, position.y - oldPosition.y, position.z - oldPosition.z);
    for (std::size_t i = 0; i < count; ++i) {
        if (SegmentMissesBounds(oldPosition, position, constraints[i])) continue;
        if (!ClipSegment(constraints[i].box, oldPosition, delta, &hit) || !(hit.t < best.t)) continue;
        // The skin's and the reflect contact's particle rests on the tested surface itself, so its next segment
        // starts on it (inside, to rounding): leaving through that face is no hit, or it could never lift off.
        if (constraints[i].placement == 0.0f && hit.t < 0.0f && Dot3(delta, hit.normal) > 0.0f) continue;
        best = hit;
        placement = constraints[i].placement;
        reflect = constraints[i].reflect;
    }
    if (best.t == FLT_MAX) return;
    if (reflect) {
        ReflectHit(best.point, best.normal, best.t, dt);
    } else {
        ResolveHit(best.point, best.normal, placement);
    }
}

void Particle::ResolveHit(const vec3& point, const vec3& normal, float offset) {
    // Book: place the particle just off the surface, reflect the normal part of the velocity with `bounce`
    // and keep the tangential part. Only an approaching normal part is reflected (a particle pushed out of a
    // box while already leaving keeps its velocity). oldPosition = position: the next segment starts here.
    position = vec3(point.x + normal.x * offset, point.y + normal.y * offset, point.z + normal.z * offset);
    oldPosition = position;
    const float vn = Dot3(velocity, normal);
    if (vn < 0.0f) {
        const float change = -(1.0f + bounce) * vn;  // vt - e vn = v - (1 + e) vn
        velocity = vec3(velocity.x + normal.x * change, velocity.y + normal.y * change, velocity.z + normal.z * change);
    }
}

void Particle::ReflectHit(const vec3& point, const vec3& normal, float t, float dt) {
    // Along the face's normal n, with a the acceleration of the step's last force evaluation and d the distance
    // off the face's plane (d0 at the step's start, d1 at its end, before this contact): taking a constant over the
    // step, the path is the parabola through d0 and d1, d(s) = d0 + (d1 - d0) s / dt + an s (s - dt) / 2, whatever
    // the integrator. It meets the face at s (Newton from the segment's fraction t; 0 for a start on the face),
    // tau = dt - s before the end, with normal velocity vc = d'(s). An ideal bounce leaves with -e vc and ends at
    //   d = -e vc tau + an tau^2 / 2 = d1 - (1 + e) vc tau,   vn = v1n - (1 + e) vc,
    // the tangential parts as the integrator left them (no friction, as the other contacts). Exact when the step's
    // acceleration is constant and the integrator is exact for it (gravity with verlet, velocity-verlet or rk4);
    // any other force is off by O(dt^2) per impact (a's change over the step), an integrator's own error is its
    // own, and the velocity retention's scaling is taken as part of the path. A bounce whose remainder would come
    // back through the face within the step (d < 0) bounces again, as often as the ideal answer does in the time
    // left (BounceTrain), and rests on the face where that train ends within the step. dt = 0: the impact at the
    // end.
    const float an = Dot3(forces * InvMass(), normal);
    const float d0 = Dot3(oldPosition - point, normal), d1 = Dot3(position - point, normal);
    const float v1n = Dot3(velocity, normal);
    float s = t > 0.0f ? t * dt : 0.0f;
    float vc = v1n;
    if (dt > 0.0f) {
        const float chord = (d1 - d0) / dt;
        for (int i = 0; i < 2 && t > 0.0f; ++i) {
            const float slope = chord + an * (s - 0.5f * dt);
            if (!(slope < 0.0f)) break;
            s = Min(Max(s - (d0 + chord * s + 0.5f * an * s * (s - dt)) / slope, 0.0f), dt);
        }
        vc = chord + an * (s - 0.5f * dt);
    }
    const float tau = dt - s;
    float dEnd = d1, vEnd = v1n;
    if (vc < 0.0f) {
        dEnd = d1 - (1.0f + bounce) * vc * tau;
        vEnd = v1n - (1.0f + bounce) * vc;
        if (dEnd < 0.0f) BounceTrain(-bounce * vc, tau, an, bounce, &dEnd, &vEnd);
    }
    if (dEnd < 0.0f) {
        dEnd = 0.0f;
        vEnd = Max(vEnd, 0.0f);
    }
    position += normal * (dEnd - d1);
    velocity += normal * (vEnd - v1n);
    oldPosition = position;
}

void Particle::SetPosition(const vec3& pos) { position = oldPosition = pos; }
void Particle::AddVelocityChange(const vec3& deltaVelocity) { velocity += deltaVelocity; }
float Particle::InvMass() const { return mass == 0.0f ? 0.0f : 1.0f / mass; }
