#include "Demos/Scenes/CollisionFeatureScene.h"

#include <cmath>

namespace {
const vec3 kStart[4] = {{4.0f, 2.0f, 0.0f}, {-4.0f, -2.0f, 0.0f}, {-4.0f, 2.0f, 0.0f}, {4.0f, -2.0f, 0.0f}};
constexpr float kTwoPi = 6.28318530717958647692f;
}  // namespace

CollisionFeatureScene::CollisionFeatureScene() { Reset(); }

void CollisionFeatureScene::Reset() {
    obb[0] = OBB(kStart[0], vec3(1, 1, 1));
    obb[1] = OBB(kStart[1], vec3(1, 1, 1), Rotation3x3(30.0f, 20.0f, 0.0f));
    sphere[0] = Sphere(kStart[2], 1.0f);
    sphere[1] = Sphere(kStart[3], 0.5f);
    for (CollisionManifold& m : results) ResetCollisionManifold(&m);
}

void CollisionFeatureScene::Script(int frame, float speed) {
    // Cycle phase in [0, 1); approach a = (1 - cos 2 pi phase) / 2 goes 0 -> 1 -> 0.
    const double cycles = static_cast<double>(frame) * static_cast<double>(speed) / kCycleFrames;
    const float phase = static_cast<float>(cycles - std::floor(cycles));
    const float approach = 0.5f * (1.0f - std::cos(kTwoPi * phase));
    const float scale = 1.0f - 0.85f * approach;  // centres at 1.0 .. 0.15 of their start (all six pairs meet)
    obb[0].position = kStart[0] * scale;
    obb[1].position = kStart[1] * scale;
    sphere[0].position = kStart[2] * scale;
    sphere[1].position = kStart[3] * scale;
    // Turning makes the box-box contacts change between face, edge and corner features.
    const float angle = 360.0f * phase;
    obb[0].orientation = Rotation3x3(0.0f, angle, 0.25f * angle);
    obb[1].orientation = Rotation3x3(30.0f, 20.0f + 0.5f * angle, 0.0f);
}

void CollisionFeatureScene::Compute() {
    // The allocation-free forms reuse each manifold's contact storage from frame to frame.
    FindCollisionFeatures(obb[0], obb[1], &results[0]);
    FindCollisionFeatures(obb[0], sphere[0], &results[1]);
    FindCollisionFeatures(obb[1], sphere[0], &results[2]);
    FindCollisionFeatures(sphere[0], sphere[1], &results[3]);
    FindCollisionFeatures(obb[0], sphere[1], &results[4]);
    FindCollisionFeatures(obb[1], sphere[1], &results[5]);
}

bool CollisionFeatureScene::Colliding(int index) const {
    for (std::size_t p = 0; p < kPairs.size(); ++p)
        if (results[p].colliding && (kPairs[p][0] == index || kPairs[p][1] == index)) return true;
    return false;
}

void AddCollisionFeatureParameters(ParameterSet* set, CollisionFeatureParams* params) {
    using Widget = ParameterSet::Widget;
    set->AddBool("script", &params->script,
                 "move and turn the shapes along a scripted path (0: the book's static start)");
    set->AddFloat("speed", &params->speed, 0.0f, 8.0f, "approach cycles per 240 output frames");
    set->AddChoice("gizmo", &params->gizmo, {"translate", "rotate", "scale"},
                   "the panel's gizmo operation (shown only: there is no gizmo headless)")
        .OnPanel(Widget::RadioButtons({"Translate", "Rotate", "Scale"}));
    set->AddChoice("space", &params->space, {"local", "world"}, "the panel's gizmo space (shown only)")
        .OnPanel(Widget::RadioButtons({"Local", "World"}));
}
