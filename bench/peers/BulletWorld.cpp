#include "bench/peers/BulletWorld.h"

#include <btBulletDynamicsCommon.h>

#include <cmath>

#include "Physics/RigidbodyVolume.h"

struct BulletWorld::Impl {
    btDefaultCollisionConfiguration configuration;
    btCollisionDispatcher dispatcher{&configuration};
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
    std::vector<std::unique_ptr<btCollisionShape>> shapes;  // one per distinct size, shared by the bodies
    std::vector<BodySpec> shapeKeys;                        // the spec each shape was made from
    std::vector<std::unique_ptr<btRigidBody>> bodies;       // spec order

    btCollisionShape* ShapeFor(const BodySpec& spec);
    ~Impl();
};

namespace {

btVector3 ToBt(const vec3& v) { return btVector3(v.x, v.y, v.z); }
vec3 FromBt(const btVector3& v) { return vec3(v.x(), v.y(), v.z()); }

}  // namespace

btCollisionShape* BulletWorld::Impl::ShapeFor(const BodySpec& spec) {
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        const BodySpec& k = shapeKeys[i];
        if (k.shape != spec.shape) continue;
        if (spec.shape == RigidbodyType::Sphere
                ? k.radius == spec.radius
                : (k.halfExtents.x == spec.halfExtents.x && k.halfExtents.y == spec.halfExtents.y &&
                   k.halfExtents.z == spec.halfExtents.z))
            return shapes[i].get();
    }
    if (spec.shape == RigidbodyType::Sphere)
        shapes.push_back(std::make_unique<btSphereShape>(spec.radius));
    else
        shapes.push_back(std::make_unique<btBoxShape>(ToBt(spec.halfExtents)));  // margin inside the extents
    shapeKeys.push_back(spec);
    return shapes.back().get();
}

BulletWorld::Impl::~Impl() {
    for (auto it = bodies.rbegin(); it != bodies.rend(); ++it) world.removeRigidBody(it->get());
}

BulletWorld::BulletWorld(const std::vector<BodySpec>& specs, int iterations, bool sleeping)
    : impl(std::make_unique<Impl>()) {
    btDiscreteDynamicsWorld& world = impl->world;
    world.setGravity(ToBt(kVolumeGravity));
    btContactSolverInfo& info = world.getSolverInfo();
    info.m_numIterations = iterations;
    info.m_splitImpulse = 1;
    impl->bodies.reserve(specs.size());
    for (const BodySpec& spec : specs) {
        btCollisionShape* shape = impl->ShapeFor(spec);
        const float mass = spec.mass > 0.0f ? spec.mass : 0.0f;
        btVector3 inertia(0, 0, 0);
        if (mass > 0.0f) shape->calculateLocalInertia(mass, inertia);
        btRigidBody::btRigidBodyConstructionInfo ci(mass, nullptr, shape, inertia);
        // The orientation this engine gives the spec (the book's Euler order), so both start identical.
        const quat q =
            FromEuler(RAD2DEG(spec.eulerRadians.x), RAD2DEG(spec.eulerRadians.y), RAD2DEG(spec.eulerRadians.z));
        ci.m_startWorldTransform = btTransform(btQuaternion(q.x, q.y, q.z, q.w), ToBt(spec.position));
        ci.m_friction = std::sqrt(spec.friction);
        ci.m_restitution = std::sqrt(spec.restitution);
        ci.m_linearDamping = 0;
        ci.m_angularDamping = 0;
        auto body = std::make_unique<btRigidBody>(ci);
        if (mass > 0.0f) {
            body->setLinearVelocity(ToBt(spec.velocity));
            body->setAngularVelocity(ToBt(spec.angularVelocity));
        }
        if (!sleeping) body->setActivationState(DISABLE_DEACTIVATION);  // else Bullet's default deactivation
        world.addRigidBody(body.get());
        impl->bodies.push_back(std::move(body));
    }
}

BulletWorld::~BulletWorld() = default;

void BulletWorld::Step(float dt) { impl->world.stepSimulation(dt, 0); }

std::size_t BulletWorld::BodyCount() const { return impl->bodies.size(); }

std::size_t BulletWorld::AwakeCount() const {
    std::size_t awake = 0;
    for (const auto& b : impl->bodies)
        if (!b->isStaticObject() && b->isActive()) ++awake;
    return awake;
}

BodyState BulletWorld::State(std::size_t i) const {
    const btRigidBody& b = *impl->bodies[i];
    const btTransform& t = b.getWorldTransform();
    const btQuaternion r = t.getRotation();
    BodyState s;
    s.position = FromBt(t.getOrigin());
    s.orientation = quat(r.x(), r.y(), r.z(), r.w());
    s.velocity = FromBt(b.getLinearVelocity());
    s.angularVelocity = FromBt(b.getAngularVelocity());
    return s;
}
