#include "Demos/Scenes/WorldBuilder.h"

#include <cmath>

BodySpec BoxSpec(const vec3& position, const vec3& halfExtents, float mass) {
    BodySpec s;
    s.shape = RigidbodyType::Box;
    s.position = position;
    s.halfExtents = halfExtents;
    s.mass = mass;
    return s;
}

BodySpec SphereSpec(const vec3& position, float radius, float mass) {
    BodySpec s;
    s.shape = RigidbodyType::Sphere;
    s.position = position;
    s.radius = radius;
    s.mass = mass;
    return s;
}

BodySpec GroundSpec(const vec3& halfExtents, float topY) {
    return BoxSpec(vec3(0.0f, topY - halfExtents.y, 0.0f), halfExtents, 0.0f);
}

RigidbodyVolume MakeBody(const BodySpec& spec) {
    RigidbodyVolume b(spec.shape);
    b.position = spec.position;
    if (spec.shape == RigidbodyType::Sphere) {
        b.sphere.radius = spec.radius;
    } else {
        b.box.size = spec.halfExtents;
    }
    b.velocity = spec.velocity;
    b.angVel = spec.angularVelocity;
    b.mass = spec.mass;
    b.friction = spec.friction;
    b.cor = spec.restitution;
    b.velocityRetention = spec.velocityRetention;
    b.velocityEpsilon = spec.velocityEpsilon;
    const vec3& e = spec.eulerRadians;
    if (e.x != 0.0f || e.y != 0.0f || e.z != 0.0f) {
        b.SetEulerOrientation(e);  // syncs the volumes
    } else {
        b.SynchCollisionVolumes();
    }
    return b;
}

std::vector<RigidbodyVolume> MakeBodies(const std::vector<BodySpec>& specs) {
    std::vector<RigidbodyVolume> out;
    out.reserve(specs.size());
    for (const BodySpec& spec : specs) out.push_back(MakeBody(spec));
    return out;
}

RigidbodyVolume MakeBox(const vec3& position, const vec3& halfExtents, float mass) {
    return MakeBody(BoxSpec(position, halfExtents, mass));
}

RigidbodyVolume MakeSphere(const vec3& position, float radius, float mass) {
    return MakeBody(SphereSpec(position, radius, mass));
}

RigidbodyVolume MakeGround(const vec3& halfExtents, float topY) { return MakeBody(GroundSpec(halfExtents, topY)); }

BodySpec UndampedSpec(BodySpec spec) {
    spec.velocityRetention = 1.0f;
    spec.velocityEpsilon = 0.0f;
    return spec;
}

TiltedSlab MakeTiltedSlab(double theta, double mu) {
    TiltedSlab t;
    t.spec = UndampedSpec(BoxSpec(vec3(), vec3(6.0f, 0.5f, 2.0f), 0.0f));
    t.spec.friction = float(mu);
    t.spec.restitution = 0.0f;
    t.spec.eulerRadians = vec3(0.0f, 0.0f, float(theta));
    const RigidbodyVolume tilted = MakeBody(t.spec);
    const float* axes = tilted.box.orientation.asArray;  // rows: local X, Y, Z in world space
    t.normal = vec3(axes[3], axes[4], axes[5]);
    t.downhill = vec3(axes[0], axes[1], axes[2]);
    if (t.downhill.y > 0.0f) t.downhill = t.downhill * -1.0f;
    return t;
}

namespace {

/// `cube` moved to `position`, upright.
BodySpec Placed(const BodySpec& cube, const vec3& position) {
    BodySpec s = cube;
    s.position = position;
    s.eulerRadians = vec3();
    return s;
}

}  // namespace

std::vector<BodySpec> Tower(int height, const BodySpec& cube) {
    std::vector<BodySpec> out;
    const float h = cube.halfExtents.y;
    for (int k = 0; k < height; ++k) out.push_back(Placed(cube, vec3(0.0f, h + 2.0f * h * float(k), 0.0f)));
    return out;
}

std::vector<BodySpec> Pyramid(int base, const BodySpec& cube, float gap) {
    std::vector<BodySpec> out;
    const float pitch = 2.0f * cube.halfExtents.x + gap, h = cube.halfExtents.y;
    for (int row = 0; row < base; ++row)
        for (int k = 0; k < base - row; ++k)
            out.push_back(
                Placed(cube, vec3((float(k) - 0.5f * float(base - row - 1)) * pitch, h + 2.0f * h * float(row), 0.0f)));
    return out;
}

namespace {

/// Columns per side of Boxpile(count)'s square grid: ceil(sqrt(ceil(count / 10))).
int BoxpileSide(int count) {
    const int columns = (count + 9) / 10;
    return static_cast<int>(std::ceil(std::sqrt(static_cast<float>(columns))));
}

}  // namespace

std::vector<BodySpec> Boxpile(int count, const BodySpec& cube) {
    std::vector<BodySpec> out;
    const int side = BoxpileSide(count);
    for (int i = 0; i < count; ++i) {
        const int c = i / 10, k = i % 10;
        const float x = (float(c % side) - 0.5f * float(side - 1)) * 2.5f;
        const float z = (float(c / side) - 0.5f * float(side - 1)) * 2.5f;
        out.push_back(Placed(cube, vec3(x, 1.5f + 2.2f * float(k), z)));
    }
    return out;
}

std::vector<BodySpec> TiltedColumn(int count) {
    std::vector<BodySpec> out;
    for (int i = 0; i < count; ++i) {
        BodySpec box = BoxSpec(vec3(0.1f * float(i), 1.0f + 2.2f * float(i), 0.05f * float(i)));
        box.eulerRadians = vec3(0.1f * float(i), 0.2f, 0.05f);
        out.push_back(box);
    }
    return out;
}

std::vector<BodySpec> WithGround(const BodySpec& ground, const std::vector<BodySpec>& bodies) {
    std::vector<BodySpec> out;
    out.reserve(bodies.size() + 1);
    out.push_back(ground);
    out.insert(out.end(), bodies.begin(), bodies.end());
    return out;
}

std::vector<BodySpec> BoxpileScene(int count) {
    const float half = float(BoxpileSide(count)) * 1.25f + 5.0f;
    return WithGround(GroundSpec(vec3(half, 0.5f, half)), Boxpile(count, BodySpec()));
}

std::vector<BodySpec> PyramidScene(int base) {
    const float half = float(base) + 5.0f;
    return WithGround(GroundSpec(vec3(half, 0.5f, half)), Pyramid(base, BodySpec(), 0.01f));
}

std::vector<BodySpec> TowerScene(int height) {
    return WithGround(GroundSpec(vec3(10.0f, 0.5f, 10.0f)), Tower(height, BodySpec()));
}

std::vector<BodySpec> BounceScene(float e, float retention) {
    BodySpec ground = GroundSpec(vec3(10.0f, 0.5f, 10.0f));
    ground.restitution = 1.0f;
    BodySpec ball = SphereSpec(vec3(0.0f, 11.0f, 0.0f));
    ball.restitution = e;
    ball.velocityRetention = retention;
    return {ground, ball};
}

BodySpec PeerCube() {
    BodySpec s = BoxSpec(vec3(), vec3(0.5f, 0.5f, 0.5f), 1.0f);
    s.friction = 0.6f;
    s.restitution = 0.0f;
    s.velocityRetention = 1.0f;
    s.velocityEpsilon = 0.0f;
    return s;
}

BodySpec PeerGround() {
    BodySpec s = GroundSpec(vec3(50.0f, 0.5f, 50.0f));
    s.friction = 0.6f;
    s.restitution = 0.0f;
    s.velocityRetention = 1.0f;
    s.velocityEpsilon = 0.0f;
    return s;
}

std::vector<BodySpec> PeerBoxpile(int count) {
    std::vector<BodySpec> out;
    out.reserve(static_cast<std::size_t>(count > 0 ? count : 0) + 1);
    out.push_back(PeerGround());
    // The layout is computed in double and rounded once, so both engines (and any later port) get the same floats.
    const int g = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count) / 10.0)));
    const double centre = 0.5 * static_cast<double>(g - 1);
    for (int i = 0; i < count; ++i) {
        const int c = i % (g * g), l = i / (g * g), cx = c % g, cz = c / g;
        const double di = static_cast<double>(i);
        BodySpec s = PeerCube();
        s.position =
            vec3(static_cast<float>((cx - centre) * 1.5 + 0.1 * std::sin(1.7 * di)), static_cast<float>(1.0 + 1.5 * l),
                 static_cast<float>((cz - centre) * 1.5 + 0.1 * std::cos(2.3 * di)));
        s.eulerRadians = vec3(0.0f, static_cast<float>(0.2 * std::sin(0.9 * di)), 0.0f);
        out.push_back(s);
    }
    return out;
}

std::vector<BodySpec> PeerPyramid(int base) { return WithGround(PeerGround(), Pyramid(base, PeerCube(), 0.05f)); }

std::vector<BodySpec> PeerTower(int height) { return WithGround(PeerGround(), Tower(height, PeerCube())); }

RigidWorld::RigidWorld(const std::vector<BodySpec>& specs) {
    bodies = MakeBodies(specs);
    start.reserve(specs.size());
    for (RigidbodyVolume& b : bodies) {
        start.push_back(b.position);
        system.AddRigidbody(&b);
    }
}

float RigidWorld::MaxDisplacement() const {
    float worst = 0.0f;
    for (std::size_t i = 0; i < bodies.size(); ++i)
        if (bodies[i].mass > 0.0f) worst = std::fmax(worst, Magnitude(bodies[i].position - start[i]));
    return worst;
}

float RigidWorld::KineticEnergy() const {
    float e = 0.0f;
    for (const RigidbodyVolume& b : bodies) {
        if (!(b.mass > 0.0f)) continue;
        e +=
            0.5f * b.mass * MagnitudeSq(b.velocity) + 0.5f * Dot(b.angVel, MultiplyVector(b.angVel, b.InertiaTensor()));
    }
    return e;
}
