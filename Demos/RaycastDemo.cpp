#include "Demos/RaycastDemo.h"

#include <glad/gl.h>

#include <cstdio>

#include "Application/Render/FixedFunctionPrimitives.h"
#include "Demos/ParameterPanel.h"

#ifndef PSB_DEMO_ASSET_DIR
#define PSB_DEMO_ASSET_DIR "Demos/assets"
#endif

namespace {
const vec3 kLightDirection{0.5f, 1.0f, -1.5f};
const vec3 kLightColor{0.0f, 0.0f, 0.5f};  // ambient and diffuse: the demo's blue tint (docs/book-reference.md §1.5)

const char* ShapeName(RaycastScene::Shape s) {
    switch (s) {
        case RaycastScene::Shape::Sphere:
            return "sphere";
        case RaycastScene::Shape::AABB:
            return "AABB";
        case RaycastScene::Shape::OBB:
            return "OBB";
        case RaycastScene::Shape::Plane:
            return "plane";
        case RaycastScene::Shape::Triangle:
            return "triangle";
        case RaycastScene::Shape::Model:
            return "model";
        case RaycastScene::Shape::None:
            break;
    }
    return "nothing";
}
}  // namespace

RaycastDemo::RaycastDemo() {
    ResetRaycastResult(&hit);
    AddRaycastParameters(&params, &p);
    // Not a book row: the current hit, or why there is none.
    params.AddPanelText([this] {
        if (!(picking && hit.hit)) return "No hit; " + modelStatus;
        char row[64];
        std::snprintf(row, sizeof row, "Hit %s at t = %.3f", ShapeName(hitShape), static_cast<double>(hit.t));
        return std::string(row);
    });
}

void RaycastDemo::Initialize(int width, int height) {
    DemoBase::Initialize(width, height);
    const std::string path = FirstObjFile(PSB_DEMO_ASSET_DIR);
    std::string error = path.empty() ? std::string("no .obj file in " PSB_DEMO_ASSET_DIR) : std::string();
    if (!path.empty() && scene.LoadModel(path, &error)) {
        modelStatus = "model: " + path.substr(path.find_last_of('/') + 1);
    } else {
        modelStatus = "no model (" + error + ")";
        std::fprintf(stderr, "raycast: %s\n", modelStatus.c_str());
    }
}

void RaycastDemo::InitializeDrawing() {
    glPointSize(5.0f);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    SetLightDirection(kLightDirection);
}

void RaycastDemo::ScriptFrame(int frame) {
    picking = p.script;
    if (!picking) {
        screenRay = Ray();
        ResetRaycastResult(&hit);
        hitShape = RaycastScene::Shape::None;
        return;
    }
    // The book's left-click pick (docs/book-reference.md §2.0), with the scripted cursor as the mouse position.
    mousePos = RaycastScene::ScriptedCursor(frame, p.speed, size);
    screenRay = GetPickRay(mousePos, vec2(0.0f, 0.0f), size, camera.GetViewMatrix(), camera.GetProjectionMatrix());
    screenRay.NormalizeDirection();
    hit = scene.CastAll(screenRay, &hitShape);
}

void RaycastDemo::Render() {
    DemoBase::Render();
    SetLightDirection(kLightDirection);
    SetLightColors(kLightColor, kLightColor);
    ::Render(scene.sphere);
    ::Render(scene.aabb);
    ::Render(scene.obb);
    ::Render(scene.plane);
    ::Render(scene.triangle);
    if (scene.HasModel()) ::Render(scene.model);

    glDisable(GL_LIGHTING);
    if (picking && hit.hit) {
        glColor3f(1.0f, 0.0f, 0.0f);
        ::Render(Point(hit.point));
        glColor3f(0.0f, 1.0f, 0.0f);
        ::Render(Line(hit.point, hit.point + hit.normal));
    }
    glColor3f(0.0f, 0.0f, 1.0f);
    ::Render(screenRay);
    glEnable(GL_LIGHTING);
}

void RaycastDemo::ImGUI() {
    DrawPanel("Raycast Demo", BookPanel::kHeight);
    DemoBase::ImGUI();
}
