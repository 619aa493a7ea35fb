#pragma once
// The application window (docs/book-reference.md §1.1 DemoWindow): the "Physics Demo" panel, the current demo and its
// camera. The host (Platform/) owns the GL context, the ImGui context and backend, and the frame loop; it
// calls the hooks below with the context current, and OnUpdate inside an ImGui frame when the UI is visible.

#include <memory>
#include <string>

#include "Windows/GLWindow.h"

class DemoBase;

class DemoWindow : public GLWindow {
public:
    /// The book's window is "Physics Sandbox", 800 x 600; no demo running (the book's start-up screen).
    explicit DemoWindow(const std::string& title = "Physics Sandbox", int width = 800, int height = 600);
    ~DemoWindow() override;

    /// GL state (GLWindow), three-button mode, no demo.
    void OnInitialize() override;
    /// Clears, then loads the demo camera's projection and view and calls demo->Render().
    void OnRender() override;
    /// Viewport, then demo->Resize.
    void OnResize(int width, int height) override;
    /// The "Physics Demo" panel, then the demo's own panels (only when the UI is visible).
    void OnUpdate(float deltaTime) override;
    /// One physics step of fixedDeltaTime seconds (the host runs whole steps of CurrentDemo()->PhysicsStep(), or
    /// its own step when that is 0): forwards the mouse state (delta as a fraction of the window size), then
    /// demo->Update(fixedDeltaTime).
    void OnFixedUpdate(float fixedDeltaTime) override;
    void OnShutdown() override;

    /// Stops the current demo and starts the registry's demo `id`: Initialize(width, height), then one
    /// camera Update so the view is valid on the first frame (erratum 5.2-29). Needs the GL context current.
    /// False (and no demo running) if the id is unknown.
    bool StartDemo(const std::string& id);
    /// Stops the current demo and starts `created` (a demo outside the id table, such as a scene file's) under
    /// the name `id`, as StartDemo(id) does. False (and no demo running) if `created` is null.
    bool StartDemo(std::unique_ptr<DemoBase> created, const std::string& id);
    /// Shuts the current demo down; nothing if none runs.
    void StopDemo();
    DemoBase* CurrentDemo() { return demo.get(); }
    /// "" when no demo runs.
    const std::string& CurrentDemoId() const { return demoId; }
    /// Off: a host without a GL context (a run that writes no pictures). OnInitialize, OnResize and StartDemo
    /// then make no GL call (no demo InitializeDrawing), and the host never calls OnRender or OnUpdate with the
    /// UI visible. Set before OnInitialize; on by default.
    void SetDrawing(bool value) { drawing = value; }
    bool Drawing() const { return drawing; }
    /// Hidden: OnUpdate draws nothing (the host then skips the ImGui frame).
    void SetUIVisible(bool visible) { uiVisible = visible; }
    bool UIVisible() const { return uiVisible; }
    /// The ms/frame the panel shows (a deterministic stand-in for the wall clock); FPS = 1000 / ms.
    void SetNominalFrameTime(float milliseconds);
    float NominalFrameTime() const { return nominalFrameMs; }
    /// The book's select_all mode: a list box of every demo instead of the three chapter buttons.
    void SetSelectAll(bool value) { selectAll = value; }
    bool SelectAll() const { return selectAll; }

private:
    void MainPanel();

    std::unique_ptr<DemoBase> demo;
    std::string demoId;
    bool uiVisible = true;
    bool drawing = true;
    bool selectAll = false;
    float nominalFrameMs = 16.0f;  // the book's frame limiter: 1000 / 60 in integer ms (docs/book-reference.md §1.2)
    vec2 prevMousePos;
};
