#include "Demos/SceneFileDemo.h"

#include <glad/gl.h>

#include "Application/Render/FixedFunctionPhysics.h"
#include "Application/Render/FixedFunctionPrimitives.h"
#include "Demos/ParameterPanel.h"

SceneFileDemo::SceneFileDemo(const SceneDescription& description) : scene(description) {
    scene.AddParameters(&params);
    AddShowHelpButton();
    autoModelRequest = description.autoModel;  // the file's "model" and "budget"; `--set` may change them
    AddAutoModelKeys();
}

void SceneFileDemo::Initialize(int width, int height) {
    DemoBase::Initialize(width, height);
    const SceneCamera& c = scene.Description().camera;
    camera.SetTarget(c.target);
    camera.SetZoom(c.zoom);
    camera.SetRotation(c.rotation);
}

void SceneFileDemo::InitializeDrawing() {
    glPointSize(5.0f);
    EnableBookLighting();
}

void SceneFileDemo::Render() {
    DemoBase::Render();
    SetLightDirection(vec3(0.0f, 1.0f, 0.0f));
    ::Render(scene.System());
    // Bodies with their own colour are drawn again over themselves: same geometry, so GL_LEQUAL passes exactly.
    glDepthFunc(GL_LEQUAL);
    const std::vector<SceneBody>& bodies = scene.Description().bodies;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        if (!bodies[i].hasColor) continue;
        SetLightColors(bodies[i].color * 0.25f, bodies[i].color);
        const FileSceneBody& at = scene.BodyIndex()[i];
        if (at.kind == SceneBodyKind::Particle) {
            ::Render(scene.Particles()[at.index]);
        } else {
            ::Render(scene.Volumes()[at.index]);
        }
    }
    glDepthFunc(GL_LESS);
}

void SceneFileDemo::Update(float dt) {
    DemoBase::Update(dt);
    scene.Step(dt);
}

void SceneFileDemo::ImGUI() {
    DrawPanel(scene.Description().name.c_str(), BookPanel::kHeight);
    DemoBase::ImGUI();
}

void SceneFileDemo::CollectState(std::vector<BodyState>* out) const {
    const std::vector<FileSceneBody>& index = scene.BodyIndex();
    for (std::size_t i = 0; i < index.size(); ++i) {
        const int body = static_cast<int>(i);
        if (index[i].kind == SceneBodyKind::Particle) {
            const Particle& p = scene.Particles()[index[i].index];
            out->push_back({body, "particle", p.GetPosition(), p.GetVelocity()});
        } else {
            const RigidbodyVolume& v = scene.Volumes()[index[i].index];
            out->push_back({body, v.type == RigidbodyType::Sphere ? "sphere" : "box", v.position, v.velocity});
        }
    }
    for (const auto& cloth : scene.Cloths()) {
        for (std::size_t i = 0; i < cloth->verts.size(); ++i) {
            const Particle& p = cloth->verts[i];
            out->push_back({static_cast<int>(i), "cloth-particle", p.GetPosition(), p.GetVelocity()});
        }
    }
}

bool SceneFileDemo::Unstable(std::string* report) const {
    if (!scene.System().StopReason().empty()) {
        *report = scene.System().StopReason();
        return true;
    }
    if (scene.Monitor().Stable()) return false;
    *report = scene.Monitor().Report().message;
    return true;
}
