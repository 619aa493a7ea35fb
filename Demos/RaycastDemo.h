#pragma once
// Raycast Demo (docs/book-reference.md §2.0): pick the closest of five primitives (and an OBJ mesh model) under the
// cursor. Headless, a scripted cursor sweeps the pick ray across the screen (RaycastScene::ScriptedCursor).

#include <string>

#include "Demos/DemoBase.h"
#include "Demos/Scenes/RaycastScene.h"

class RaycastDemo : public DemoBase {
public:
    RaycastDemo();
    /// Loads the first OBJ of Demos/assets.
    void Initialize(int width, int height) override;
    /// Point size 5, lighting on, light (0.5, 1, -1.5, 0).
    void InitializeDrawing() override;
    /// Origin, the shapes in the blue light, then unlit: the hit (red point, green unit normal) and the pick
    /// ray (blue).
    void Render() override;
    /// A "Raycast Demo" panel with the script parameters and the current hit (the book has none), then help.
    void ImGUI() override;
    /// Moves the scripted cursor; with script=0 nothing is picked (the book before any click).
    void ScriptFrame(int frame) override;

    const RaycastScene& Scene() const { return scene; }
    /// The pick ray of the last ScriptFrame (the default Ray() before any pick) and its closest hit.
    const Ray& PickRay() const { return screenRay; }
    const RaycastResult& Hit() const { return hit; }
    RaycastScene::Shape HitShape() const { return hitShape; }

private:
    RaycastScene scene;
    RaycastParams p;
    Ray screenRay;  // the book's default: origin 0, direction +Z
    RaycastResult hit;
    RaycastScene::Shape hitShape = RaycastScene::Shape::None;
    bool picking = false;
    std::string modelStatus;
};
