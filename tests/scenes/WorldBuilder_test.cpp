// The world builder: body specs and their defaults, the stack layouts against hand-computed positions, the
// benchmark scenes' counts and grounds, RigidWorld's ownership and measures, determinism.
#include "Demos/Scenes/WorldBuilder.h"

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "tests/support/Approx.h"
#include "tests/support/Volumes.h"

namespace {

/// Top face (largest y) of an axis-aligned box spec, m.
float Top(const BodySpec& s) { return s.position.y + s.halfExtents.y; }
/// Bottom face (smallest y) of an axis-aligned box spec, m.
float Bottom(const BodySpec& s) { return s.position.y - s.halfExtents.y; }

BodySpec HalfMetreCube() { return BoxSpec(vec3(), vec3(0.5f, 0.5f, 0.5f), 1.0f); }

}  // namespace

TEST(WorldBuilder, SpecDefaultsAreTheEnginesDefaults) {
    const RigidbodyVolume engine(RigidbodyType::Box);
    const RigidbodyVolume built = MakeBody(BodySpec());
    EXPECT_EQ(built.type, RigidbodyType::Box);
    EXPECT_EQ(built.mass, engine.mass);
    EXPECT_EQ(built.friction, engine.friction);
    EXPECT_EQ(built.cor, engine.cor);
    EXPECT_EQ(built.velocityRetention, engine.velocityRetention);
    EXPECT_EQ(built.velocityEpsilon, engine.velocityEpsilon);
    EXPECT_TRUE(VecNear(built.box.size, engine.box.size, 0.0f));
    EXPECT_EQ(MakeBody(SphereSpec(vec3())).sphere.radius, RigidbodyVolume(RigidbodyType::Sphere).sphere.radius);
    // Identity orientation when the Euler angles are zero.
    EXPECT_EQ(built.orientation.w, 1.0f);
    EXPECT_EQ(built.orientation.x, 0.0f);
}

TEST(WorldBuilder, MakeBodyCopiesEveryFieldAndSyncsTheVolumes) {
    BodySpec s = BoxSpec(vec3(1, 2, 3), vec3(0.5f, 0.25f, 2), 4.0f);
    s.eulerRadians = vec3(0.1f, 0.2f, 0.3f);
    s.velocity = vec3(1, 0, 0);
    s.angularVelocity = vec3(0, 2, 0);
    s.friction = 0.3f;
    s.restitution = 0.1f;
    s.velocityRetention = 1.0f;
    s.velocityEpsilon = 0.0f;
    const RigidbodyVolume b = MakeBody(s);
    EXPECT_TRUE(VecNear(b.position, vec3(1, 2, 3), 0.0f));
    EXPECT_TRUE(VecNear(b.box.position, vec3(1, 2, 3), 0.0f));
    EXPECT_TRUE(VecNear(b.box.size, vec3(0.5f, 0.25f, 2), 0.0f));
    EXPECT_TRUE(VecNear(b.velocity, vec3(1, 0, 0), 0.0f));
    EXPECT_TRUE(VecNear(b.angVel, vec3(0, 2, 0), 0.0f));
    EXPECT_EQ(b.mass, 4.0f);
    EXPECT_EQ(b.friction, 0.3f);
    EXPECT_EQ(b.cor, 0.1f);
    EXPECT_EQ(b.velocityRetention, 1.0f);
    EXPECT_EQ(b.velocityEpsilon, 0.0f);
    RigidbodyVolume expected(RigidbodyType::Box);
    expected.SetEulerOrientation(vec3(0.1f, 0.2f, 0.3f));
    EXPECT_EQ(std::memcmp(&b.orientation, &expected.orientation, sizeof(quat)), 0);
    EXPECT_TRUE(MatNear(b.box.orientation, expected.box.orientation, 0.0f));

    const RigidbodyVolume ball = MakeSphere(vec3(0, 5, 0), 0.25f, 2.0f);
    EXPECT_EQ(ball.type, RigidbodyType::Sphere);
    EXPECT_EQ(ball.sphere.radius, 0.25f);
    EXPECT_TRUE(VecNear(ball.sphere.position, vec3(0, 5, 0), 0.0f));
    EXPECT_EQ(ball.mass, 2.0f);
}

TEST(WorldBuilder, GroundTopIsAtTheGivenHeightAndStatic) {
    const BodySpec g = GroundSpec(vec3(50, 0.5f, 50));
    EXPECT_EQ(Top(g), 0.0f);
    EXPECT_TRUE(VecNear(g.position, vec3(0, -0.5f, 0), 0.0f));
    EXPECT_EQ(g.mass, 0.0f);
    EXPECT_EQ(Top(GroundSpec(vec3(3, 2, 3), 7.0f)), 7.0f);
    const RigidbodyVolume built = MakeGround(vec3(20, 0.5f, 20));
    EXPECT_EQ(built.box.position.y + built.box.size.y, 0.0f);
    EXPECT_EQ(built.InvMass(), 0.0f);
    EXPECT_EQ(MakeGroundSlab().box.size.x, 20.0f);
}

TEST(WorldBuilder, TowerStacksCubesFaceOnFaceFromTheGround) {
    BodySpec cube = HalfMetreCube();
    cube.position = vec3(9, 9, 9);  // replaced
    cube.eulerRadians = vec3(1, 0, 0);
    cube.friction = 0.2f;
    const std::vector<BodySpec> t = Tower(3, cube);
    ASSERT_EQ(t.size(), 3u);
    EXPECT_TRUE(VecNear(t[0].position, vec3(0, 0.5f, 0), 0.0f));
    EXPECT_TRUE(VecNear(t[1].position, vec3(0, 1.5f, 0), 0.0f));
    EXPECT_TRUE(VecNear(t[2].position, vec3(0, 2.5f, 0), 0.0f));
    for (const BodySpec& s : t) {
        EXPECT_TRUE(VecNear(s.eulerRadians, vec3(), 0.0f));
        EXPECT_EQ(s.friction, 0.2f);
    }
    EXPECT_EQ(Bottom(t[0]), 0.0f);
    EXPECT_EQ(Top(t[0]), Bottom(t[1]));
    EXPECT_TRUE(Tower(0, cube).empty());
    // The bench's unit cubes (half extent 1): centres at 1, 3, 5 ...
    const std::vector<BodySpec> unit = Tower(10, BodySpec());
    EXPECT_EQ(unit[9].position.y, 19.0f);
}

TEST(WorldBuilder, PyramidRowsAndGaps) {
    // base 3, unit cubes (half 1), gap 0.01: pitch 2.01; row 0 at y = 1: x = -2.01, 0, 2.01; row 1 at y = 3:
    // x = -1.005, 1.005; row 2 at y = 5: x = 0.
    const std::vector<BodySpec> p = Pyramid(3, BodySpec(), 0.01f);
    ASSERT_EQ(p.size(), 6u);
    const vec3 expected[6] = {vec3(-2.01f, 1, 0),  vec3(0, 1, 0),      vec3(2.01f, 1, 0),
                              vec3(-1.005f, 3, 0), vec3(1.005f, 3, 0), vec3(0, 5, 0)};
    for (int i = 0; i < 6; ++i) EXPECT_TRUE(VecNear(p[i].position, expected[i], tol::kExact)) << i;
    EXPECT_EQ(Pyramid(10, BodySpec(), 0.01f).size(), 55u);
    // Neighbours in a row are exactly `gap` apart (to float rounding).
    EXPECT_NEAR((p[1].position.x - p[1].halfExtents.x) - (p[0].position.x + p[0].halfExtents.x), 0.01f, 1e-6f);
}

TEST(WorldBuilder, BoxpileColumnsOfTenOnASquareGrid) {
    // 25 cubes: 3 columns, side = ceil(sqrt(3)) = 2, grid offsets (c mod 2 - 0.5) 2.5 and (c / 2 - 0.5) 2.5.
    const std::vector<BodySpec> b = Boxpile(25, BodySpec());
    ASSERT_EQ(b.size(), 25u);
    EXPECT_TRUE(VecNear(b[0].position, vec3(-1.25f, 1.5f, -1.25f), tol::kExact));   // column 0, level 0
    EXPECT_TRUE(VecNear(b[13].position, vec3(1.25f, 8.1f, -1.25f), tol::kExact));   // column 1, level 3
    EXPECT_TRUE(VecNear(b[24].position, vec3(-1.25f, 10.3f, 1.25f), tol::kExact));  // column 2, level 4
    EXPECT_TRUE(VecNear(b[9].position, vec3(-1.25f, 21.3f, -1.25f), tol::kTight));  // column 0, level 9
    // Every cube starts above the ground and apart from the one below it.
    for (std::size_t i = 0; i < b.size(); ++i) {
        EXPECT_GT(Bottom(b[i]), 0.0f) << i;
        if (i % 10 != 0) {
            EXPECT_NEAR(Bottom(b[i]) - Top(b[i - 1]), 0.2f, 1e-5f) << i;
        }
    }
}

TEST(WorldBuilder, BenchmarkScenesHaveTheGroundFirstWithItsTopAtZero) {
    struct Case {
        std::vector<BodySpec> specs;
        std::size_t count;
        float groundHalf;
    };
    const Case cases[] = {
        {BoxpileScene(100), 101, 10.0f},    // 10 columns: side 4, 4 * 1.25 + 5
        {BoxpileScene(1000), 1001, 17.5f},  // 100 columns: side 10
        {PyramidScene(20), 211, 25.0f},    {TowerScene(10), 11, 10.0f}, {BounceScene(0.5f, 1.0f), 2, 10.0f},
    };
    for (const Case& c : cases) {
        ASSERT_EQ(c.specs.size(), c.count);
        const BodySpec& g = c.specs[0];
        EXPECT_EQ(g.mass, 0.0f);
        EXPECT_EQ(Top(g), 0.0f);
        EXPECT_EQ(g.halfExtents.x, c.groundHalf) << c.count;
        EXPECT_EQ(g.halfExtents.z, c.groundHalf) << c.count;
        for (std::size_t i = 1; i < c.specs.size(); ++i) EXPECT_GT(c.specs[i].mass, 0.0f);
    }
    const std::vector<BodySpec> bounce = BounceScene(0.8f, 0.98f);
    EXPECT_EQ(bounce[1].shape, RigidbodyType::Sphere);
    EXPECT_EQ(bounce[1].position.y - bounce[1].radius, 10.0f);  // bottom 10 m above the ground
    EXPECT_EQ(bounce[1].restitution, 0.8f);
    EXPECT_EQ(bounce[1].velocityRetention, 0.98f);
    EXPECT_EQ(bounce[0].restitution, 1.0f);
}

TEST(WorldBuilder, TiltedColumnLayout) {
    const std::vector<BodySpec> c = TiltedColumn(5);
    ASSERT_EQ(c.size(), 5u);
    EXPECT_TRUE(VecNear(c[0].position, vec3(0, 1, 0), 0.0f));
    EXPECT_TRUE(VecNear(c[0].eulerRadians, vec3(0, 0.2f, 0.05f), 0.0f));
    EXPECT_TRUE(VecNear(c[3].position, vec3(0.3f, 7.6f, 0.15f), tol::kTight));
    EXPECT_TRUE(VecNear(c[3].eulerRadians, vec3(0.3f, 0.2f, 0.05f), tol::kTight));
}

TEST(WorldBuilder, RigidWorldOwnsTheBodiesAndAddsThemInOrder) {
    std::vector<BodySpec> specs = WithGround(GroundSlabSpec(), Tower(4, HalfMetreCube()));
    specs.push_back(BoxSpec(vec3(5, 1, 0), vec3(0, 1, 1)));  // zero size: refused by the system
    RigidWorld w(specs);
    ASSERT_EQ(w.Bodies().size(), 6u);
    ASSERT_EQ(w.system.Volumes().size(), 5u);
    EXPECT_NE(w.system.LastError().find("box.size.x = 0"), std::string::npos) << w.system.LastError();
    for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(w.system.Volumes()[i], &w.Body(i));
    for (std::size_t i = 0; i < specs.size(); ++i)
        EXPECT_TRUE(VecNear(w.StartPositions()[i], specs[i].position, 0.0f)) << i;
    EXPECT_EQ(w.MaxDisplacement(), 0.0f);
    EXPECT_EQ(w.KineticEnergy(), 0.0f);
}

TEST(WorldBuilder, RigidWorldMeasuresDynamicBodiesOnly) {
    BodySpec box = BoxSpec(vec3(0, 0, 0), vec3(1, 1, 1), 2.0f);
    box.velocity = vec3(3, 0, 0);  // 0.5 * 2 * 9 = 9 J
    BodySpec ball = SphereSpec(vec3(10, 0, 0), 1.0f, 1.0f);
    ball.angularVelocity = vec3(0, 0, 2);  // I = 2/5 m r^2 = 0.4: 0.5 * 0.4 * 4 = 0.8 J
    BodySpec wall = BoxSpec(vec3(-10, 0, 0), vec3(1, 1, 1), 0.0f);
    wall.velocity = vec3(100, 0, 0);  // static: not counted
    RigidWorld w({box, ball, wall});
    EXPECT_NEAR(w.KineticEnergy(), 9.8f, tol::kTight);
    w.Body(1).position = vec3(10, 3, 4);
    w.Body(2).position = vec3(-100, 0, 0);
    EXPECT_EQ(w.MaxDisplacement(), 5.0f);
}

TEST(WorldBuilder, SameSpecsGiveBitwiseIdenticalRuns) {
    auto run = [] {
        RigidWorld w(BoxpileScene(30));
        w.system.settings.contactSolver = ContactSolver::Accumulated;
        for (int i = 0; i < 90; ++i) w.system.Update(1.0f / 60.0f);
        return Snapshot(w.Bodies());
    };
    const std::vector<unsigned char> a = run(), b = run();
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size()), 0);
    // And the run moved: the cubes fell.
    RigidWorld fresh(BoxpileScene(30));
    EXPECT_NE(std::memcmp(a.data(), Snapshot(fresh.Bodies()).data(), a.size()), 0);
}

TEST(WorldBuilder, PeerCubeAndGroundAreTheSharedDefinition) {
    const BodySpec cube = PeerCube();
    EXPECT_EQ(cube.shape, RigidbodyType::Box);
    EXPECT_TRUE(VecNear(cube.halfExtents, vec3(0.5f, 0.5f, 0.5f), 0.0f));
    EXPECT_EQ(cube.mass, 1.0f);
    EXPECT_EQ(cube.friction, 0.6f);
    EXPECT_EQ(cube.restitution, 0.0f);
    EXPECT_EQ(cube.velocityRetention, 1.0f);  // no damping
    EXPECT_EQ(cube.velocityEpsilon, 0.0f);
    const BodySpec ground = PeerGround();
    EXPECT_EQ(ground.mass, 0.0f);
    EXPECT_TRUE(VecNear(ground.halfExtents, vec3(50, 0.5f, 50), 0.0f));
    EXPECT_TRUE(VecNear(ground.position, vec3(0, -0.5f, 0), 0.0f));
    EXPECT_EQ(ground.friction, 0.6f);
    EXPECT_EQ(ground.restitution, 0.0f);
    for (const std::vector<BodySpec>& scene : {PeerBoxpile(50), PeerPyramid(4), PeerTower(3)}) {
        ASSERT_FALSE(scene.empty());
        EXPECT_EQ(std::memcmp(&scene[0], &ground, sizeof(BodySpec)), 0);  // ground at index 0
        for (std::size_t i = 1; i < scene.size(); ++i) {
            EXPECT_TRUE(VecNear(scene[i].halfExtents, cube.halfExtents, 0.0f)) << i;
            EXPECT_EQ(scene[i].mass, 1.0f) << i;
            EXPECT_EQ(scene[i].friction, 0.6f) << i;
            EXPECT_EQ(scene[i].restitution, 0.0f) << i;
            EXPECT_EQ(scene[i].velocityRetention, 1.0f) << i;
            EXPECT_EQ(scene[i].velocityEpsilon, 0.0f) << i;
        }
    }
}

TEST(WorldBuilder, PeerBoxpileFollowsItsFormula) {
    // Hand-computed from the definition (docs/peers.md): boxpile 1000 has g = 10, so (g - 1) / 2 = 4.5.
    // Box 0: c = 0, l = 0: x = -6.75 + 0.1 sin 0, z = -6.75 + 0.1 cos 0, y = 1, angle 0.
    // Box 123: c = 23, l = 1, cx = 3, cz = 2: x = -2.25 + 0.1 sin 209.1, z = -3.75 + 0.1 cos 282.9, y = 2.5,
    // angle 0.2 sin 110.7. Box 999: c = 99, l = 9: x = 6.75 + 0.1 sin 1698.3, y = 14.5.
    const std::vector<BodySpec> pile = PeerBoxpile(1000);
    ASSERT_EQ(pile.size(), 1001u);
    struct Expect {
        int i;
        vec3 position;
        float yaw;
    };
    const Expect expected[] = {{0, vec3(-6.75f, 1.0f, -6.65f), 0.0f},
                               {123, vec3(-2.151690f, 2.5f, -3.651225f), -0.135485f},
                               {999, vec3(6.846399f, 14.5f, 6.713370f), 0.113670f}};
    for (const Expect& e : expected) {
        const BodySpec& s = pile[static_cast<std::size_t>(e.i) + 1];
        EXPECT_TRUE(VecNear(s.position, e.position, tol::kTight)) << e.i;
        EXPECT_TRUE(VecNear(s.eulerRadians, vec3(0, e.yaw, 0), tol::kExact)) << e.i;
    }
    // Boxpile 100: g = ceil(sqrt(10)) = 4, 16 per layer; box 37: c = 5, l = 2, cx = cz = 1.
    const std::vector<BodySpec> small = PeerBoxpile(100);
    ASSERT_EQ(small.size(), 101u);
    EXPECT_TRUE(VecNear(small[38].position, vec3(-0.743191f, 4.0f, -0.846188f), tol::kTight));
    EXPECT_NEAR(small[38].eulerRadians.y, 0.190266f, tol::kExact);
    EXPECT_EQ(small[100].position.y, 10.0f);  // box 99: layer 6
    // Boxpile 4000: g = 20; the last box, 3999, is at c = 399, l = 9.
    const std::vector<BodySpec> big = PeerBoxpile(4000);
    ASSERT_EQ(big.size(), 4001u);
    EXPECT_TRUE(VecNear(big[4000].position, vec3(14.239370f, 14.5f, 14.313461f), tol::kTight));
    EXPECT_TRUE(PeerBoxpile(0).size() == 1u);  // the ground alone
}

TEST(WorldBuilder, PeerBoxpileRotatesRightHandedAboutYAndStartsApart) {
    const std::vector<BodySpec> pile = PeerBoxpile(100);
    // Box 37 turned by a = 0.190266 rad about +Y: its local x axis is (cos a, 0, -sin a) in the world.
    const RigidbodyVolume b = MakeBody(pile[38]);
    const float a = 0.190266f;
    EXPECT_TRUE(VecNear(GetRow(b.box.orientation, 0), vec3(std::cos(a), 0, -std::sin(a)), tol::kTight));
    EXPECT_TRUE(VecNear(GetRow(b.box.orientation, 1), vec3(0, 1, 0), tol::kTight));
    // No two bodies touch at the start (the ground included): this engine's manifolds find no pair.
    std::vector<RigidbodyVolume> bodies = MakeBodies(pile);
    CollisionManifold m;
    int touching = 0;
    for (std::size_t i = 0; i < bodies.size(); ++i)
        for (std::size_t j = i + 1; j < bodies.size(); ++j) {
            FindCollisionFeatures(bodies[i], bodies[j], &m);
            if (m.colliding) ++touching;
        }
    EXPECT_EQ(touching, 0);
}

TEST(WorldBuilder, PeerPyramidAndTowerLayouts) {
    const std::vector<BodySpec> p = PeerPyramid(20);
    ASSERT_EQ(p.size(), 211u);                                                 // 20 + 19 + ... + 1 cubes and the ground
    EXPECT_TRUE(VecNear(p[1].position, vec3(-9.975f, 0.5f, 0), tol::kTight));  // row 0, k 0: -9.5 * 1.05
    EXPECT_TRUE(VecNear(p[20].position, vec3(9.975f, 0.5f, 0), tol::kTight));  // row 0, k 19
    EXPECT_TRUE(VecNear(p[21].position, vec3(-9.45f, 1.5f, 0), tol::kTight));  // row 1, k 0: -9 * 1.05
    EXPECT_TRUE(VecNear(p[210].position, vec3(0, 19.5f, 0), tol::kTight));     // the top
    EXPECT_NEAR(p[2].position.x - p[1].position.x, 1.05f, tol::kTight);        // 0.05 m gaps
    EXPECT_EQ(PeerPyramid(30).size(), 466u);
    const std::vector<BodySpec> t = PeerTower(20);
    ASSERT_EQ(t.size(), 21u);
    for (int i = 0; i < 20; ++i)
        EXPECT_TRUE(VecNear(t[static_cast<std::size_t>(i) + 1].position, vec3(0, 0.5f + float(i), 0), 0.0f)) << i;
    EXPECT_EQ(t[1].position.y - t[1].halfExtents.y, 0.0f);  // resting on the ground's top
}
