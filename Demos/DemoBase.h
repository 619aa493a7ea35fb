#pragma once
// Base of every demo (docs/book-reference.md §1.1): an orbit camera, mouse state, a help window, and the parameter
// table that feeds both its ImGui panel and `--set`. Subclasses drive a PhysicsSystem (usually through a GL-free scene
// in Demos/Scenes) and draw through the fixed-function Render(...) overloads.

#include <string>
#include <vector>

#include "Application/View/Camera.h"
#include "Demos/ParameterPanel.h"
#include "Demos/Scenes/ModelRequest.h"
#include "Demos/Scenes/Parameters.h"
#include "Physics/PhysicsSystem.h"

class AutoModel;  // Demos/Scenes/AutoModel.h, owned by the host

/// One row of the --state CSV.
struct BodyState {
    int body = 0;
    const char* kind = "";  ///< "particle", "sphere", "box", "cloth-particle", ...
    vec3 position;
    vec3 velocity;
};

class DemoBase {
public:
    /// The view; each demo sets its starting view in its constructor (UseBookCamera), so it is known before
    /// Initialize (--export-scene writes it).
    OrbitCamera camera;

    DemoBase();
    virtual ~DemoBase() = default;
    DemoBase(const DemoBase&) = delete;
    DemoBase& operator=(const DemoBase&) = delete;

    /// Calls Resize; subclasses build their scene here (no GL calls: InitializeDrawing).
    virtual void Initialize(int width, int height);
    /// The GL state the demo draws with (lights, point size). The host calls it after Initialize, with the
    /// context current, only when it draws: a run without pictures has no GL context. Default: nothing.
    virtual void InitializeDrawing() {}
    /// camera.Perspective(60, w/h, 0.01, 1000) and remembers the viewport size.
    virtual void Resize(int width, int height);
    /// Draws the origin axes (no depth test, unlit).
    virtual void Render();
    /// The host's fixed update: one physics step of dt seconds. Here camera control from the mouse state (right
    /// rotates, middle zooms, left pans), then camera.Update(dt); subclasses then step their scene by dt.
    virtual void Update(float dt);
    /// The physics step (s) this demo asks its host for: the host's fixed-step accumulator then runs whole
    /// steps of it, so simulated time follows host time at any step. 0 (the default) takes the host's own
    /// step (--dt, book 0.03 s).
    virtual float PhysicsStep() const { return 0.0f; }
    /// The help window ("How to use"); subclasses draw their panel and call this.
    virtual void ImGUI();
    virtual void Shutdown() {}

    void SetMouseState(bool left, bool middle, bool right, const vec2& delta, const vec2& mouse);

    /// The demo's parameters: its panel widgets, settable with --set key=value.
    ParameterSet& Parameters() { return params; }
    const ParameterSet& Parameters() const { return params; }
    /// Appends one row per simulated body (for --state and the non-finite check).
    virtual void CollectState(std::vector<BodyState>* /*out*/) const {}
    /// Deterministic stand-in for the mouse (pick rays, dragging) in headless runs; called once per output
    /// frame before the fixed updates of that frame. Default: nothing.
    virtual void ScriptFrame(int /*frame*/) {}
    /// False if any collected body state is non-finite; *where then names the body and the value.
    bool StateIsFinite(std::string* where) const;
    /// True once the demo's world has stopped: its stability monitor reported a blow-up, or the world refused to go
    /// on (PhysicsSystem::StopReason: a pair search over its limit); *report is the one-line reason. The world is then
    /// frozen. Demos without a monitor are never stopped.
    virtual bool Unstable(std::string* /*report*/) const { return false; }
    /// The simulated world, for --export-scene (docs/scenes.md, "Export"); nullptr for a demo whose motion is
    /// scripted rather than simulated.
    virtual const PhysicsSystem* World() const { return nullptr; }
    /// Appends what the demo does beyond its world that a scene file cannot express (for --export-scene).
    virtual void ExportNotes(std::vector<std::string>* /*notes*/) const {}
    /// The demo's error-budget request (the `--set` keys model, error-budget, budget: docs/model-choice.md), or
    /// nullptr for a demo without them (a scripted one). The host chooses the model when it is auto.
    AutoModelRequest* AutoModelRequestOf() { return hasAutoModelKeys ? &autoModelRequest : nullptr; }
    const AutoModelRequest* AutoModelRequestOf() const { return hasAutoModelKeys ? &autoModelRequest : nullptr; }
    /// The run's auto model, owned by the host (Application/AutoModelHost.h), shown in this demo's panel row while
    /// active; nullptr: none.
    void ShowAutoModel(const AutoModel* model) { shownModel = model; }
    const AutoModel* ShownAutoModel() const { return shownModel; }

protected:
    /// The demo's panel: BeginDemoPanel, the parameter table's widgets (DrawParameterPanel), End.
    void DrawPanel(const char* title, float height, PanelScrollbar scrollbar = PanelScrollbar::Hidden) const;
    /// Appends the book's panel-only "Show Help" button (on the line of the widget before it) to the table.
    void AddShowHelpButton();
    /// Appends the error-budget keys model, error-budget and budget (AddAutoModelParameters, bound to
    /// autoModelRequest) and a panel row with the auto model's summary, drawn only while the auto model is active
    /// (so a fixed model's panel is unchanged). Called last in the constructor, so `--params` only gains lines.
    void AddAutoModelKeys();
    /// The panel rows of an active auto model: its summary, one part a line; "" otherwise.
    std::string AutoModelPanelText() const;
    /// px: the height of those rows, 0 without an active auto model (the book's panels stay as they are).
    float AutoModelRowHeight() const;
    /// The book's chapter 14-16 camera preset (docs/book-reference.md §1.4): target (3.75622, 2.98255, 0), rotation
    /// (-67.9312, 19.8) degrees, and `zoom` (9 in most demos; 12 in CH15 and Conservation Of Momentum). Called in
    /// the demo's constructor (the book does it in Initialize), so `camera` is the demo's view before any GL context
    /// exists: --export-scene writes it.
    void UseBookCamera(float zoom);
    /// Turns on GL_LIGHTING and GL_LIGHT0, as each demo's InitializeDrawing does (docs/book-reference.md §1.5).
    static void EnableBookLighting();
    /// CH14's and the chapter 16 demos' InitializeDrawing: EnableBookLighting, the light (0.5, 1, -1.5, 0) until
    /// the first Render (docs/book-reference.md §1.5). Their camera is set by their constructor (UseBookCamera(9)).
    void InitializeBookView();

    bool show_help = false;
    bool mouseLeftDown = false;
    bool mouseRightDown = false;
    bool mouseMiddleDown = false;
    vec2 mouseDelta;
    vec2 mousePos;
    vec2 size;
    bool configHelpWindow = true;
    ParameterSet params;
    AutoModelRequest autoModelRequest;  ///< a scene-file demo starts from its file's request

private:
    bool hasAutoModelKeys = false;
    const AutoModel* shownModel = nullptr;
};
