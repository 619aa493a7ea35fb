#include "Demos/ParticleSceneDemo.h"

#include "Application/Render/FixedFunctionPhysics.h"
#include "Application/Render/FixedFunctionPrimitives.h"
#include "Demos/SoftDemoPanel.h"

template <>
const ParticleSceneLook ParticleSceneDemo<SpringsScene>::kLook{"springs", "Simple Springs Demo", true, false};
template <>
const ParticleSceneLook ParticleSceneDemo<Ch16Scene>::kLook{"ch16", "Chapter 16 Demo", false, false};
template <>
const ParticleSceneLook ParticleSceneDemo<JointScene>::kLook{"joints", "Joint Demo", true, true};

namespace {

void RenderScene(const SpringsScene& scene) { RenderSystemOrConstraints(scene.System(), scene.Monitor()); }
void RenderScene(const JointScene& scene) { RenderSystemOrConstraints(scene.System(), scene.Monitor()); }
void RenderScene(const Ch16Scene& scene) {
    SetLightColors(BookColors::kConstraintAmbient, BookColors::kConstraintDiffuse);
    for (int i = 0; i < 4; ++i) ::Render(Ch16Scene::PostVisual(i));
    SetLightColors(BookColors::kGroundAmbient, BookColors::kGroundDiffuse);
    ::Render(Ch16Scene::Ground());
    // The book's DebugRender cannot be toggled (erratum 5.2-25): always the red one-sided triangles.
    if (scene.Monitor().Stable()) ::Render(scene.GetCloth(), scene.System().DebugRender);
}

void CollectParticles(const std::vector<Particle>& particles, const char* kind, std::vector<BodyState>* out) {
    for (std::size_t i = 0; i < particles.size(); ++i)
        out->push_back({static_cast<int>(i), kind, particles[i].GetPosition(), particles[i].GetVelocity()});
}
void CollectScene(const SpringsScene& scene, std::vector<BodyState>* out) {
    CollectParticles(scene.Particles(), "particle", out);
}
void CollectScene(const JointScene& scene, std::vector<BodyState>* out) {
    CollectParticles(scene.Particles(), "particle", out);
}
void CollectScene(const Ch16Scene& scene, std::vector<BodyState>* out) {
    CollectParticles(scene.GetCloth().verts, "cloth-particle", out);
}

}  // namespace

template <class SceneT>
ParticleSceneDemo<SceneT>::ParticleSceneDemo() {
    UseBookCamera(9.0f);
    scene.AddParameters(&params);
    if (kLook.showHelp) AddShowHelpButton();
    AddAutoModelKeys();
}

template <class SceneT>
void ParticleSceneDemo<SceneT>::Initialize(int width, int height) {
    DemoBase::Initialize(width, height);
    if (initialized || !kLook.keepsFirstBuild) scene.Reset();
    initialized = true;
    reported = false;
}

template <class SceneT>
void ParticleSceneDemo<SceneT>::Update(float dt) {
    DemoBase::Update(dt);
    scene.Step(dt);
    ReportOnce(scene.Monitor(), kLook.id, &reported);
}

template <class SceneT>
void ParticleSceneDemo<SceneT>::Render() {
    DemoBase::Render();
    SetLightDirection(kSoftDemoLight);
    RenderScene(scene);
}

template <class SceneT>
void ParticleSceneDemo<SceneT>::ImGUI() {
    DrawSoftDemoPanel(kLook.title, params, scene.Params().integrator, scene.Params().dt, scene.Monitor(),
                      AutoModelRowHeight());
    DemoBase::ImGUI();
}

template <class SceneT>
void ParticleSceneDemo<SceneT>::CollectState(std::vector<BodyState>* out) const {
    CollectScene(scene, out);
}

template class ParticleSceneDemo<SpringsScene>;
template class ParticleSceneDemo<Ch16Scene>;
template class ParticleSceneDemo<JointScene>;
