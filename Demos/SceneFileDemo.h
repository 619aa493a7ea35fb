#pragma once
// A scene read from a scene file (docs/scenes.md), run as a demo: `physics-sandbox --scene FILE`. Not in the demo
// id table (it needs a file); the runner builds it from a loaded SceneDescription.

#include <string>

#include "Demos/DemoBase.h"
#include "Demos/Scenes/FileScene.h"

class SceneFileDemo : public DemoBase {
public:
    /// Builds the scene and registers its model settings (FileScene::AddParameters), the help button and the
    /// error-budget keys, which start at the file's "model" and "budget".
    explicit SceneFileDemo(const SceneDescription& description);
    /// The file's camera (the book's orbit camera); the scene.
    void Initialize(int width, int height) override;
    /// Point size 5, the book's lighting.
    void InitializeDrawing() override;
    /// Origin, light (0, 1, 0, 0), the physics system as the book draws it, then bodies with a colour of their own.
    void Render() override;
    /// Camera, then one physics step of dt.
    void Update(float dt) override;
    /// The scene's step (world.step), 0 = the host's.
    float PhysicsStep() const override { return scene.PhysicsStep(); }
    /// A panel titled with the scene's name: the model in effect and Reset.
    void ImGUI() override;
    /// One row per body in file order ("particle", "sphere", "box"), then cloth particles ("cloth-particle").
    void CollectState(std::vector<BodyState>* out) const override;
    bool Unstable(std::string* report) const override;

    const FileScene& Scene() const { return scene; }

    const PhysicsSystem* World() const override { return &scene.System(); }

private:
    FileScene scene;
};
