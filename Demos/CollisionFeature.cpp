#include "Demos/CollisionFeature.h"

#include <glad/gl.h>

#include "Application/Render/FixedFunctionPrimitives.h"
#include "Demos/ParameterPanel.h"

namespace {
const vec3 kLightDirection{0.5f, 1.0f, -1.5f};
const vec3 kLightColor{0.0f, 0.0f, 0.5f};  // ambient and diffuse (docs/book-reference.md §2.2)
}  // namespace

CollisionFeature::CollisionFeature() { AddCollisionFeatureParameters(&params, &p); }

void CollisionFeature::Initialize(int width, int height) {
    DemoBase::Initialize(width, height);
    scene.Reset();
}

void CollisionFeature::InitializeDrawing() {
    glPointSize(5.0f);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    SetLightDirection(kLightDirection);
    SetLightColors(kLightColor, kLightColor);
}

void CollisionFeature::ScriptFrame(int frame) {
    if (p.script)
        scene.Script(frame, p.speed);
    else
        scene.Reset();
}

void CollisionFeature::Render() {
    DemoBase::Render();
    SetLightDirection(kLightDirection);
    SetLightColors(kLightColor, kLightColor);
    scene.Compute();

    bool colliding[CollisionFeatureScene::kShapeCount];
    for (int i = 0; i < CollisionFeatureScene::kShapeCount; ++i) colliding[i] = scene.Colliding(i);

    for (int i = 0; i < 2; ++i)
        if (!colliding[i]) ::Render(scene.obb[static_cast<std::size_t>(i)]);
    for (int i = 0; i < 2; ++i)
        if (!colliding[2 + i]) ::Render(scene.sphere[static_cast<std::size_t>(i)]);

    glDisable(GL_LIGHTING);
    glColor3f(0.0f, 0.0f, 1.0f);
    for (int i = 0; i < 2; ++i)
        if (colliding[i]) ::Render(GetEdges(scene.obb[static_cast<std::size_t>(i)]));
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    for (int i = 0; i < 2; ++i)
        if (colliding[2 + i]) ::Render(scene.sphere[static_cast<std::size_t>(i)]);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);

    // Contacts of all six pairs; the book skips r5 and r6 (erratum 5.2-24).
    glColor3f(1.0f, 0.0f, 0.0f);
    for (const CollisionManifold& m : scene.results)
        if (m.colliding)
            for (const vec3& c : m.contacts) ::Render(Point(c));
    glEnable(GL_LIGHTING);
}

void CollisionFeature::ImGUI() {
    DrawPanel("SAT Test Demo", BookPanel::kHeight);
    DemoBase::ImGUI();
}
