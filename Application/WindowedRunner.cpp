#include "Application/WindowedRunner.h"

// glad first: it must precede anything that could pull in <GL/gl.h>.
#include <glad/gl.h>
// clang-format off
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl2.h>
// clang-format on

#include <chrono>
#include <cstdio>
#include <memory>
#include <thread>

#include "Application/AutoModelHost.h"
#include "Application/ExitCodes.h"
#include "Application/StepSetting.h"
#include "Demos/DemoBase.h"
#include "Demos/Scenes/AutoModel.h"
#include "Platform/DesktopWindow.h"
#include "Windows/BookImGuiStyle.h"
#include "Windows/DemoWindow.h"

namespace {

/// Window events into the DemoWindow's hooks; mouse presses only when ImGui does not want the mouse
/// (docs/book-reference.md §1.2). Releases always pass, so a drag that ends over a panel does not stick.
class InputBridge : public DesktopInput {
public:
    explicit InputBridge(DemoWindow* w) : window(w) {}
    void OnCursor(int x, int y) override { window->OnMouseMove(x, y); }
    void OnButton(int button, bool down) override {
        if (down && ImGui::GetIO().WantCaptureMouse) return;
        const MouseButton b = static_cast<MouseButton>(button);
        if (down)
            window->OnMouseDown(b);
        else
            window->OnMouseUp(b);
    }
    void OnKey(int key, bool down) override {
        if (key < 0 || key > 255 || ImGui::GetIO().WantCaptureKeyboard) return;
        if (down)
            window->OnKeyDown(key);
        else
            window->OnKeyUp(key);
    }
    void OnResize(int w, int h) override { window->Resize(w, h); }

private:
    DemoWindow* window;
};

/// ImGui for the window: the book's look, no ini file, GLFW input, OpenGL2 drawing.
struct ImGuiSession {
    explicit ImGuiSession(DesktopWindow& w) {
        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGui::GetIO().IniFilename = nullptr;
        ImGui::GetIO().LogFilename = nullptr;
        ApplyBookImGuiStyle();
        ImGui_ImplGlfw_InitForOpenGL(w.Handle(), true);  // chains to the window's own callbacks
        ImGui_ImplOpenGL2_Init();
    }
    ~ImGuiSession() {
        ImGui_ImplOpenGL2_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }
};

bool StartFirstDemo(WindowedOptions& o, DemoWindow& window, AutoModel& model) {
    if (o.demo.empty()) return true;
    if (!window.StartDemo(o.demo)) {
        std::fprintf(stderr, "physics-sandbox: demo '%s' failed to start\n", o.demo.c_str());
        return false;
    }
    DemoBase& demo = *window.CurrentDemo();
    std::string error;
    for (const auto& [key, value] : o.sets) {
        std::string note;
        const bool ok = key == "dt" ? ApplyStepSetting(demo, "--set dt=" + value, value, &o.step, &error, &note)
                                    : demo.Parameters().Set(key, value, &error, &note);
        if (!ok) {
            std::fprintf(stderr, "physics-sandbox: --set %s=%s: %s\n", key.c_str(), value.c_str(), error.c_str());
            return false;
        }
        if (!note.empty()) std::fprintf(stderr, "physics-sandbox: %s\n", note.c_str());
    }
    // `model: auto` (docs/model-choice.md): chosen before the first frame, for the --frames the window will show
    // (a window closed by hand: ChoiceSettings' default run length).
    AutoModelHost host;
    host.name = o.demo;
    host.hostStep = o.step.ToDouble();
    host.runSeconds = o.frames > 0 ? o.frames / 60.0 : ChoiceSettings().runSeconds;
    host.quiet = o.quiet;
    bool explained = false;  // --explain-model is headless only
    return ChooseAutoModel(demo, model, host, &explained) == kExitOk;
}

/// The live watch of the first demo's auto model (while it runs): after each frame's fixed steps, with the
/// simulated time since it started; switches are printed as they happen.
struct AutoModelWatch {
    DemoBase* demo = nullptr;    ///< the demo whose model was chosen; nullptr without auto
    AutoModel* model = nullptr;  ///< the run's (RunWindowed owns it)
    double simulated = 0.0;      ///< s since it started
    std::size_t logged = 0;

    void AfterFrame(const WindowedOptions& o, DemoWindow& window, double seconds) {
        if (demo == nullptr || window.CurrentDemo() != demo || demo->ShownAutoModel() != model) return;
        simulated += seconds;
        for (const std::string& line : WatchAutoModel(*demo, *model, simulated, &logged))
            if (!o.quiet) std::fprintf(stderr, "physics-sandbox: %s: model auto: %s\n", o.demo.c_str(), line.c_str());
    }
};

void ReportDemo(const WindowedOptions& o, const std::string& id) {
    if (o.quiet) return;
    std::printf("demo: %s\n", id.empty() ? "none" : id.c_str());
    std::fflush(stdout);
}

void ReportSummary(const WindowedOptions& o, DemoWindow& window, int frames, long long steps, const AutoModel& model) {
    if (o.quiet) return;
    std::printf("window: %d frames, %lld fixed steps, demo %s", frames, steps,
                window.CurrentDemoId().empty() ? "none" : window.CurrentDemoId().c_str());
    if (DemoBase* demo = window.CurrentDemo()) {
        const vec2 r = demo->camera.GetRotation();
        const vec3 t = demo->camera.GetTarget();
        std::printf(", camera yaw %.4f pitch %.4f zoom %.4f target %.4f %.4f %.4f", double(r.x), double(r.y),
                    double(demo->camera.GetZoom()), double(t.x), double(t.y), double(t.z));
    }
    std::printf("\n");
    if (DemoBase* demo = window.CurrentDemo(); demo != nullptr && demo->ShownAutoModel() == &model && model.Active())
        std::printf("%s\n", model.Summary().c_str());
    std::fflush(stdout);
}

}  // namespace

int RunWindowed(const WindowedOptions& options) {
    WindowedOptions o = options;  // --set dt= sets its step
    std::string error;
    std::unique_ptr<DesktopWindow> desktop =
        DesktopWindow::Create("Physics Sandbox", o.width, o.height, o.vsync, &error);
    if (!desktop) {
        std::fprintf(stderr, "physics-sandbox: --window: %s\n", error.c_str());
        return kExitFailure;
    }
    AutoModel model;  // the first demo's `model: auto` (docs/model-choice.md), owned by this host
    DemoWindow window("Physics Sandbox", o.width, o.height);
    InputBridge input(&window);
    desktop->SetInput(&input);
    ImGuiSession imgui(*desktop);

    window.OnInitialize();
    window.OnResize(o.width, o.height);
    window.SetUIVisible(!o.noUi);
    if (!StartFirstDemo(o, window, model)) return kExitUsage;
    AutoModelWatch watch;
    if (window.CurrentDemo() != nullptr && model.Active()) {
        watch.demo = window.CurrentDemo();
        watch.model = &model;
    }
    std::string shownDemo = window.CurrentDemoId();
    ReportDemo(o, shownDemo);

    using Clock = std::chrono::steady_clock;
    // The book's frame limiter: SKIP_TICKS = 1000 / 60 whole milliseconds (docs/book-reference.md §1.2).
    const auto frameBudget = std::chrono::milliseconds(1000 / 60);
    double last = DesktopWindow::Seconds(), fixedElapsed = 0.0;
    int frames = 0;
    long long steps = 0;
    while (!desktop->ShouldClose() && !window.GetQuitFlag() && (o.frames == 0 || frames < o.frames)) {
        const Clock::time_point frameStart = Clock::now();
        desktop->PollEvents();
        const double now = DesktopWindow::Seconds();
        const double deltaTime = now - last;
        last = now;
        if (window.GetAndResetTitleDirtyFlag()) desktop->SetTitle(window.GetTitle());

        ImGui_ImplOpenGL2_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        const float framerate = ImGui::GetIO().Framerate;
        if (framerate > 0.0f) window.SetNominalFrameTime(1000.0f / framerate);
        window.OnUpdate(float(deltaTime));
        // The book's accumulator (strict >), docs/book-reference.md §1.2, stepping the running demo's own
        // physics step when it asks for one (HostStepOf), else --dt / --set dt=.
        const DemoBase* demo = window.CurrentDemo();
        const double step = (demo != nullptr ? HostStepOf(o.step, *demo) : o.step).ToDouble();
        fixedElapsed += deltaTime;
        double stepped = 0.0;
        while (fixedElapsed > step) {
            window.OnFixedUpdate(float(step));
            fixedElapsed -= step;
            stepped += step;
            ++steps;
        }
        watch.AfterFrame(o, window, stepped);
        window.OnRender();
        ImGui::Render();
        ImGui_ImplOpenGL2_RenderDrawData(ImGui::GetDrawData());
        desktop->SwapBuffers();
        ++frames;

        if (window.CurrentDemoId() != shownDemo) {
            shownDemo = window.CurrentDemoId();
            ReportDemo(o, shownDemo);
        }
        std::this_thread::sleep_until(frameStart + frameBudget);
    }
    ReportSummary(o, window, frames, steps, model);
    window.OnShutdown();
    return FinishStdout();  // the demo lines and the summary must have reached stdout (exit 3 if not)
}
