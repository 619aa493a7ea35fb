#pragma once
// Collision Features, "SAT Test Demo" (docs/book-reference.md §2.2): the contact manifolds of every pair of two boxes
// and two spheres. Headless, a scripted motion replaces dragging the shapes with the gizmo.

#include "Demos/DemoBase.h"
#include "Demos/Scenes/CollisionFeatureScene.h"

class CollisionFeature : public DemoBase {
public:
    CollisionFeature();
    /// The book's start poses.
    void Initialize(int width, int height) override;
    /// Point size 5, lighting on, light (0.5, 1, -1.5, 0) and its colours.
    void InitializeDrawing() override;
    /// Manifolds of the current poses; non-colliding shapes solid in the blue light, colliding ones unlit
    /// blue (box edges, wireframe sphere), then every contact point red (r1..r6: erratum 5.2-24).
    void Render() override;
    /// "SAT Test Demo": Translate / Rotate / Scale and Local / World radio buttons, then help.
    void ImGUI() override;
    /// Poses the shapes for this output frame (script=1), or leaves the book's start (script=0).
    void ScriptFrame(int frame) override;

    const CollisionFeatureScene& Scene() const { return scene; }

private:
    CollisionFeatureScene scene;
    CollisionFeatureParams p;
};
