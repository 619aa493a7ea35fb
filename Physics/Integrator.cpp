// The five particle integrators (docs/ch14.md has the table). Hot loops use component arithmetic: the Math
// library's vec3 operators are out-of-line calls.
#include "Physics/Integrator.h"

#include "Physics/EnumIds.h"
#include "Physics/Particle.h"
#include "Physics/StepFactor.h"

namespace {

constexpr EnumId<Integrator> kIds[] = {{Integrator::ExplicitEuler, "explicit-euler"},
                                       {Integrator::SemiImplicitEuler, "euler"},
                                       {Integrator::VelocityVerlet, "velocity-verlet"},
                                       {Integrator::PositionVerlet, "verlet"},
                                       {Integrator::RK4, "rk4"}};

inline vec3 Add(const vec3& a, const vec3& b) { return vec3(a.x + b.x, a.y + b.y, a.z + b.z); }
inline vec3 Scale(const vec3& a, float s) { return vec3(a.x * s, a.y * s, a.z * s); }
/// a + b * s
inline vec3 Mad(const vec3& a, const vec3& b, float s) { return vec3(a.x + b.x * s, a.y + b.y * s, a.z + b.z * s); }
inline bool SameBits(const vec3& a, const vec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

}  // namespace

const char* ToString(Integrator integrator) { return IdOf(kIds, integrator); }

bool ParseIntegrator(const std::string& text, Integrator* out) { return ParseId(kIds, text, out); }

std::string IntegratorIds() { return JoinIds(kIds); }

int ForceEvaluations(Integrator integrator) {
    switch (integrator) {
        case Integrator::VelocityVerlet:
            return 2;
        case Integrator::RK4:
            return 4;
        default:
            return 1;
    }
}

namespace {

// Particle::InvMass inlined (it is out of line): 0 for mass 0.
inline float InvMass(const Particle& p) { return p.GetMass() == 0.0f ? 0.0f : 1.0f / p.GetMass(); }

/// What every integrator's step shares: the force evaluation and the step's velocity retention.
class ParticleStep {
public:
    ParticleStep(float dt, float retentionStep, ForceEvaluator evaluate, void* context)
        : dt(dt), retentionStep(retentionStep), evaluate(evaluate), context(context) {}
    void Evaluate() const { evaluate(context); }
    /// The retention over this step, FactorOverStep(velocityRetention, retentionStep, dt). Particles of a scene
    /// share one value, so pow runs once per distinct retention in a row, not once per particle.
    float Retained(float velocityRetention) const {
        if (velocityRetention != lastRetention) {
            lastRetention = velocityRetention;
            lastFactor = FactorOverStep(lastRetention, retentionStep, dt);
        }
        return lastFactor;
    }

private:
    float dt, retentionStep;
    ForceEvaluator evaluate;
    void* context;
    mutable float lastRetention = -1.0f, lastFactor = 1.0f;
};

}  // namespace

/// One function per integration method, each a friend of Particle (Physics/Particle.h).
struct ParticleIntegrators {
    static void StepExplicitEuler(const ParticleStep& ctx, Particle* const* particles, std::size_t count, float dt) {
        // Forward Euler with the step's retention on the carried velocity: v0 = v f; x += v0 dt; v = v0 + a dt.
        ctx.Evaluate();
        for (std::size_t i = 0; i < count; ++i) {
            Particle& p = *particles[i];
            const vec3 v0 = Scale(p.velocity, ctx.Retained(p.velocityRetention));
            const vec3 a = Scale(p.forces, InvMass(p));
            p.oldPosition = p.position;
            p.position = Mad(p.position, v0, dt);
            p.velocity = Mad(v0, a, dt);
        }
    }

    static void StepSemiImplicitEuler(const ParticleStep& ctx, Particle* const* particles, std::size_t count,
                                      float dt) {
        // The book's shipped Particle::Update: v = v f + a dt; x += v dt.
        ctx.Evaluate();
        for (std::size_t i = 0; i < count; ++i) {
            Particle& p = *particles[i];
            const vec3 a = Scale(p.forces, InvMass(p));
            p.oldPosition = p.position;
            p.velocity = Mad(Scale(p.velocity, ctx.Retained(p.velocityRetention)), a, dt);
            p.position = Mad(p.position, p.velocity, dt);
        }
    }

    static void StepVelocityVerlet(const ParticleStep& ctx, Particle* const* particles, std::size_t count,
                                   IntegratorScratch* scratch, float dt) {
        const float halfDt = 0.5f * dt;
        // x1 = x0 + v0 dt + a0 dt^2/2; a1 = a(x1, v0 + a0 dt); v1 = v0 + (a0 + a1) dt/2, with v0 = v f.
        // Under constant force this is the book's "accurate Euler" (x += (v_old + v_new) dt/2).
        ctx.Evaluate();
        for (std::size_t i = 0; i < count; ++i) {
            Particle& p = *particles[i];
            IntegratorScratch& s = scratch[i];
            s.x0 = p.position;
            s.v0 = Scale(p.velocity, ctx.Retained(p.velocityRetention));
            s.a0 = Scale(p.forces, InvMass(p));
            p.position = Mad(s.x0, Mad(s.v0, s.a0, halfDt), dt);
            p.velocity = Mad(s.v0, s.a0, dt);  // predicted, for velocity-dependent forces
        }
        ctx.Evaluate();
        for (std::size_t i = 0; i < count; ++i) {
            Particle& p = *particles[i];
            const IntegratorScratch& s = scratch[i];
            const vec3 a1 = Scale(p.forces, InvMass(p));
            p.oldPosition = s.x0;
            p.velocity = Mad(s.v0, Add(s.a0, a1), halfDt);
        }
    }

    static void StepPositionVerlet(const ParticleStep& ctx, Particle* const* particles, std::size_t count,
                                   IntegratorScratch* scratch, float dt) {
        const float halfDt = 0.5f * dt;
        // The book's Verlet, x1 = x0 + (x0 - x_prev) f + a0 dt^2, with the mass divided out (erratum
        // 5.2-22: the book multiplies forces = g m by dt^2, so heavier particles fall faster). The history
        // x0 - x_prev is kept in `velocity` (m/s at x0): x0 - x_prev = v dt - a_prev dt^2/2, where a_prev is
        // the acceleration of the previous step (still in `forces`). This reproduces x_prev exactly after
        // an undisturbed step, lets impulses, bounces and setters act on velocity as for every other
        // integrator, and gives a second-order (Taylor) start for a fresh particle (oldPosition ==
        // position after SetPosition or a constraint hit): there a_prev := a0, so x1 = x0 + v dt + a0 dt^2/2.
        const float dtSq = dt * dt;
        for (std::size_t i = 0; i < count; ++i) scratch[i].a0 = Scale(particles[i]->forces, InvMass(*particles[i]));
        ctx.Evaluate();
        for (std::size_t i = 0; i < count; ++i) {
            Particle& p = *particles[i];
            const vec3 a = Scale(p.forces, InvMass(p));
            const vec3 aPrev = SameBits(p.oldPosition, p.position) ? a : scratch[i].a0;
            const vec3 history = Mad(Scale(p.velocity, dt), aPrev, -0.5f * dtSq);               // x0 - x_prev
            const vec3 step = Mad(Scale(history, ctx.Retained(p.velocityRetention)), a, dtSq);  // x1 - x0
            p.oldPosition = p.position;
            p.position = Add(p.position, step);
            // Velocity at x1 to second order: the mean velocity over the step plus half the step's a dt. It
            // is taken from the intended displacement, not from the rounded positions, so float rounding
            // of large positions does not random-walk into the velocity (plain Verlet's weakness in float).
            p.velocity = Mad(Scale(step, 1.0f / dt), a, halfDt);
        }
    }

    static void StepRk4(const ParticleStep& ctx, Particle* const* particles, std::size_t count,
                        IntegratorScratch* scratch, float dt) {
        const float halfDt = 0.5f * dt;
        // Classical RK4 on (x, v) from (x0, v0 = v f): k_x = v, k_v = a(x, v) at t, t+dt/2 (twice), t+dt.
        const float sixthDt = dt / 6.0f;
        for (std::size_t i = 0; i < count; ++i) {
            Particle& p = *particles[i];
            IntegratorScratch& s = scratch[i];
            s.x0 = p.position;
            s.v0 = Scale(p.velocity, ctx.Retained(p.velocityRetention));
            p.velocity = s.v0;
        }
        ctx.Evaluate();  // k1 at (x0, v0)
        for (std::size_t i = 0; i < count; ++i) {
            Particle& p = *particles[i];
            IntegratorScratch& s = scratch[i];
            const vec3 kv = Scale(p.forces, InvMass(p));
            s.sumX = s.v0;
            s.sumV = kv;
            p.position = Mad(s.x0, s.v0, halfDt);
            p.velocity = Mad(s.v0, kv, halfDt);
        }
        // k2 and k3: add 2 k to the sums and predict the next evaluation point x0 + k h, v0 + k h.
        auto addMiddleStage = [&](float h) {
            for (std::size_t i = 0; i < count; ++i) {
                Particle& p = *particles[i];
                IntegratorScratch& s = scratch[i];
                const vec3 kx = p.velocity;
                const vec3 kv = Scale(p.forces, InvMass(p));
                s.sumX = Mad(s.sumX, kx, 2.0f);
                s.sumV = Mad(s.sumV, kv, 2.0f);
                p.position = Mad(s.x0, kx, h);
                p.velocity = Mad(s.v0, kv, h);
            }
        };
        ctx.Evaluate();  // k2 at the midpoint predicted by k1
        addMiddleStage(halfDt);
        ctx.Evaluate();  // k3 at the midpoint predicted by k2
        addMiddleStage(dt);
        ctx.Evaluate();  // k4 at the end predicted by k3
        for (std::size_t i = 0; i < count; ++i) {
            Particle& p = *particles[i];
            const IntegratorScratch& s = scratch[i];
            const vec3 kx = p.velocity;
            const vec3 kv = Scale(p.forces, InvMass(p));
            p.oldPosition = s.x0;
            p.position = Mad(s.x0, Add(s.sumX, kx), sixthDt);
            p.velocity = Mad(s.v0, Add(s.sumV, kv), sixthDt);
        }
    }
};

void IntegrateParticleStates(Integrator method, Particle* const* particles, std::size_t count,
                             IntegratorScratch* scratch, float dt, float retentionStep, ForceEvaluator evaluate,
                             void* context) {
    if (count == 0 || !(dt > 0.0f)) return;
    const ParticleStep ctx(dt, retentionStep, evaluate, context);
    switch (method) {
        case Integrator::ExplicitEuler:
            return ParticleIntegrators::StepExplicitEuler(ctx, particles, count, dt);
        case Integrator::SemiImplicitEuler:
            return ParticleIntegrators::StepSemiImplicitEuler(ctx, particles, count, dt);
        case Integrator::VelocityVerlet:
            return ParticleIntegrators::StepVelocityVerlet(ctx, particles, count, scratch, dt);
        case Integrator::PositionVerlet:
            return ParticleIntegrators::StepPositionVerlet(ctx, particles, count, scratch, dt);
        case Integrator::RK4:
            return ParticleIntegrators::StepRk4(ctx, particles, count, scratch, dt);
    }
}
