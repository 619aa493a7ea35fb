// Microbenchmarks of the hot functions, so a regression shows per function: raycasts,
// line tests, manifolds per pair type, ApplyImpulse, one integrator step per integrator, spring force.
// Inputs are fixed (seeded where random), outputs go through benchmark::DoNotOptimize.
#include <benchmark/benchmark.h>

#include <vector>

#include "Application/View/Tessellation.h"
#include "Demos/Scenes/WorldBuilder.h"
#include "Math/matrices.h"
#include "Physics/Geometry/Geometry3D.h"
#include "Physics/Integrator.h"
#include "Physics/Particle.h"
#include "Physics/RigidbodyVolume.h"
#include "Physics/Spring.h"
#include "Physics/WorldSettings.h"

namespace {

// ---- Raycasts: a ray that hits, from 5 m away.
const Ray kRay(vec3(-5.0f, 0.2f, 0.1f), vec3(1.0f, 0.0f, 0.0f));

void BM_RaycastSphere(benchmark::State& state) {
    const Sphere s(vec3(), 1.0f);
    RaycastResult r;
    for (auto _ : state) benchmark::DoNotOptimize(Raycast(s, kRay, &r));
}
void BM_RaycastAABB(benchmark::State& state) {
    const AABB box(vec3(), vec3(1.0f, 1.0f, 1.0f));
    RaycastResult r;
    for (auto _ : state) benchmark::DoNotOptimize(Raycast(box, kRay, &r));
}
void BM_RaycastOBB(benchmark::State& state) {
    const OBB box(vec3(), vec3(1.0f, 0.5f, 1.0f), Rotation3x3(30.0f, 20.0f, 10.0f));
    RaycastResult r;
    for (auto _ : state) benchmark::DoNotOptimize(Raycast(box, kRay, &r));
}
void BM_RaycastTriangle(benchmark::State& state) {
    const Triangle t(vec3(0.0f, -1.0f, -1.0f), vec3(0.0f, 1.0f, 0.0f), vec3(0.0f, -1.0f, 1.0f));
    RaycastResult r;
    for (auto _ : state) benchmark::DoNotOptimize(Raycast(t, kRay, &r));
}
/// Icosphere mesh of 20 * 4^range(0) triangles behind its BVH (book depth 3).
void BM_RaycastMesh(benchmark::State& state) {
    const TriangleList list = Icosphere(int(state.range(0)), 1.0f);
    Mesh mesh;
    for (int i = 0; i < list.TriangleCount(); ++i)
        mesh.triangles.emplace_back(list.positions[3 * i], list.positions[3 * i + 1], list.positions[3 * i + 2]);
    AccelerateMesh(mesh, 3);
    RaycastResult r;
    for (auto _ : state) benchmark::DoNotOptimize(Raycast(mesh, kRay, &r));
    state.counters["triangles"] = double(mesh.triangles.size());
}

// ---- Line tests: a segment through each shape.
const Line kLine(vec3(-5.0f, 0.2f, 0.1f), vec3(5.0f, -0.1f, 0.0f));

void BM_LinetestSphere(benchmark::State& state) {
    const Sphere s(vec3(), 1.0f);
    for (auto _ : state) benchmark::DoNotOptimize(Linetest(s, kLine));
}
void BM_LinetestAABB(benchmark::State& state) {
    const AABB box(vec3(), vec3(1.0f, 1.0f, 1.0f));
    for (auto _ : state) benchmark::DoNotOptimize(Linetest(box, kLine));
}
void BM_LinetestOBB(benchmark::State& state) {
    const OBB box(vec3(), vec3(1.0f, 0.5f, 1.0f), Rotation3x3(30.0f, 20.0f, 10.0f));
    for (auto _ : state) benchmark::DoNotOptimize(Linetest(box, kLine));
}
void BM_LinetestTriangle(benchmark::State& state) {
    const Triangle t(vec3(0.0f, -1.0f, -1.0f), vec3(0.0f, 1.0f, 0.0f), vec3(0.0f, -1.0f, 1.0f));
    for (auto _ : state) benchmark::DoNotOptimize(Linetest(t, kLine));
}

// ---- Manifolds, one per pair type, for overlapping shapes (the expensive case).
void BM_ManifoldSphereSphere(benchmark::State& state) {
    const Sphere a(vec3(), 1.0f), b(vec3(1.5f, 0.2f, 0.0f), 1.0f);
    CollisionManifold m;
    for (auto _ : state) {
        FindCollisionFeatures(a, b, &m);
        benchmark::DoNotOptimize(m.depth);
    }
}
void BM_ManifoldOBBSphere(benchmark::State& state) {
    const OBB a(vec3(), vec3(1.0f, 1.0f, 1.0f), Rotation3x3(0.0f, 30.0f, 0.0f));
    const Sphere b(vec3(0.3f, 1.6f, 0.1f), 1.0f);
    CollisionManifold m;
    for (auto _ : state) {
        FindCollisionFeatures(a, b, &m);
        benchmark::DoNotOptimize(m.depth);
    }
}
void BM_ManifoldOBBOBB(benchmark::State& state) {
    const OBB a(vec3(), vec3(1.0f, 1.0f, 1.0f));
    const OBB b(vec3(0.3f, 1.8f, 0.1f), vec3(1.0f, 1.0f, 1.0f), Rotation3x3(10.0f, 30.0f, 5.0f));
    CollisionManifold m;
    for (auto _ : state) {
        FindCollisionFeatures(a, b, &m);
        benchmark::DoNotOptimize(m.depth);
    }
}
/// The RigidbodyVolume wrapper used by PhysicsSystem (box resting on a box: 4 contacts).
void BM_ManifoldVolumesBoxBox(benchmark::State& state) {
    RigidbodyVolume a = MakeBox(vec3(), vec3(0.5f, 0.5f, 0.5f));
    RigidbodyVolume b = MakeBox(vec3(0.1f, 0.99f, 0.0f), vec3(0.5f, 0.5f, 0.5f));
    CollisionManifold m;
    for (auto _ : state) {
        FindCollisionFeatures(a, b, &m);
        benchmark::DoNotOptimize(m.depth);
    }
    state.counters["contacts"] = double(m.contacts.size());
}

// ---- ApplyImpulse: one contact of a box landing on a static box; velocities reset each iteration.
void BM_ApplyImpulse(benchmark::State& state) {
    RigidbodyVolume ground = MakeGround(vec3(5.0f, 0.5f, 5.0f));
    RigidbodyVolume box = MakeBox(vec3(0.1f, 0.49f, 0.0f), vec3(0.5f, 0.5f, 0.5f));
    const CollisionManifold m = FindCollisionFeatures(ground, box);
    const vec3 v(0.3f, -2.0f, 0.1f), w(0.1f, 0.2f, 0.3f);
    for (auto _ : state) {
        box.velocity = v;
        box.angVel = w;
        ApplyImpulse(ground, box, m, 0);
        benchmark::DoNotOptimize(box.velocity);
    }
}

// ---- One integrator step of range(0) particles joined in a chain by springs (range(0) - 1 springs).
struct Chain {
    std::vector<Particle> particles;
    std::vector<Particle*> pointers;
    std::vector<Spring> springs;
    std::vector<IntegratorScratch> scratch;
    explicit Chain(int n) : particles(std::size_t(n)), scratch(std::size_t(n)) {
        for (int i = 0; i < n; ++i) {
            particles[i].SetPosition(vec3(0.11f * float(i), 0.0f, 0.0f));
            pointers.push_back(&particles[i]);
        }
        for (int i = 0; i + 1 < n; ++i) {
            Spring s(-100.0f, 0.5f, 0.1f);
            s.SetParticles(&particles[i], &particles[i + 1]);
            springs.push_back(s);
        }
    }
    static void Forces(void* self) {
        Chain& c = *static_cast<Chain*>(self);
        for (Particle& p : c.particles) {
            p.ApplyForces();
        }
        for (Spring& s : c.springs) s.ApplyForce(0.0f);
    }
};

void IntegratorStep(benchmark::State& state, Integrator method) {
    Chain chain(int(state.range(0)));
    for (auto _ : state) {
        IntegrateParticleStates(method, chain.pointers.data(), chain.pointers.size(), chain.scratch.data(), 1e-3f,
                                kBookStep, Chain::Forces, &chain);
        benchmark::DoNotOptimize(chain.particles[0]);
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}
void BM_StepExplicitEuler(benchmark::State& s) { IntegratorStep(s, Integrator::ExplicitEuler); }
void BM_StepSemiImplicitEuler(benchmark::State& s) { IntegratorStep(s, Integrator::SemiImplicitEuler); }
void BM_StepVelocityVerlet(benchmark::State& s) { IntegratorStep(s, Integrator::VelocityVerlet); }
void BM_StepPositionVerlet(benchmark::State& s) { IntegratorStep(s, Integrator::PositionVerlet); }
void BM_StepRK4(benchmark::State& s) { IntegratorStep(s, Integrator::RK4); }

void BM_SpringApplyForce(benchmark::State& state) {
    Particle a, b;
    a.SetPosition(vec3());
    b.SetPosition(vec3(1.2f, 0.1f, 0.0f));
    b.SetVelocity(vec3(0.5f, 0.0f, 0.1f));
    Spring s(-100.0f, 0.5f, 1.0f);
    s.SetParticles(&a, &b);
    for (auto _ : state) {
        s.ApplyForce(0.0f);
        benchmark::DoNotOptimize(b);
    }
}

}  // namespace

BENCHMARK(BM_RaycastSphere);
BENCHMARK(BM_RaycastAABB);
BENCHMARK(BM_RaycastOBB);
BENCHMARK(BM_RaycastTriangle);
BENCHMARK(BM_RaycastMesh)->Arg(1)->Arg(3);
BENCHMARK(BM_LinetestSphere);
BENCHMARK(BM_LinetestAABB);
BENCHMARK(BM_LinetestOBB);
BENCHMARK(BM_LinetestTriangle);
BENCHMARK(BM_ManifoldSphereSphere);
BENCHMARK(BM_ManifoldOBBSphere);
BENCHMARK(BM_ManifoldOBBOBB);
BENCHMARK(BM_ManifoldVolumesBoxBox);
BENCHMARK(BM_ApplyImpulse);
BENCHMARK(BM_StepExplicitEuler)->Arg(1)->Arg(225);
BENCHMARK(BM_StepSemiImplicitEuler)->Arg(1)->Arg(225);
BENCHMARK(BM_StepVelocityVerlet)->Arg(1)->Arg(225);
BENCHMARK(BM_StepPositionVerlet)->Arg(1)->Arg(225);
BENCHMARK(BM_StepRK4)->Arg(1)->Arg(225);
BENCHMARK(BM_SpringApplyForce);

BENCHMARK_MAIN();
