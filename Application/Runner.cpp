#include "Application/Runner.h"

// glad first: it must precede anything that could pull in <GL/gl.h>.
#include <glad/gl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <new>
#include <numeric>
#include <vector>

#include "Application/AutoModelHost.h"
#include "Application/ImGuiGl.h"
#include "Application/ProgressLine.h"
#include "Application/RunOutputs.h"
#include "Application/StateCsv.h"
#include "Application/StepSetting.h"
#include "Demos/DemoBase.h"
#include "Demos/DemoRegistry.h"
#include "Demos/SceneFileDemo.h"
#include "Demos/Scenes/AutoModel.h"
#include "Demos/Scenes/SceneExport.h"
#include "Demos/Scenes/SceneFile.h"
#include "Platform/Files/AtomicFile.h"
#include "Platform/Files/TempRegistry.h"
#include "Platform/HeadlessContext.h"
#include "Windows/BookImGuiStyle.h"
#include "Windows/DemoWindow.h"

namespace {

using Clock = std::chrono::steady_clock;

double Since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// glReadPixels returns rows bottom-up as RGBA; frames are top-down RGB. One pass does both.
void ReadFrame(int width, int height, std::vector<std::uint8_t>* scratch, Image* out) {
    scratch->resize(std::size_t(width) * std::size_t(height) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, scratch->data());
    *out = Image(width, height);
    for (int y = 0; y < height; ++y) {
        const std::uint8_t* src = scratch->data() + std::size_t(height - 1 - y) * std::size_t(width) * 4;
        std::uint8_t* dst = out->rgb.data() + std::size_t(y) * std::size_t(width) * 3;
        for (int x = 0; x < width; ++x) {
            dst[0] = src[0], dst[1] = src[1], dst[2] = src[2];
            src += 4;
            dst += 3;
        }
    }
}

// Owns the GL-side lifetime: ImGui back end, window, context, in reverse order of creation.
struct Session {
    AutoModel autoModel;  ///< the run's model choice (docs/model-choice.md), owned here; the demo's panel shows it
    std::unique_ptr<HeadlessContext> context;
    std::unique_ptr<DemoWindow> window;
    bool imgui = false;
    ~Session() {
        if (window) window->OnShutdown();
        window.reset();
        if (imgui) {
            ImGui_ImplOpenGL2_Shutdown();
            ImGui::DestroyContext();
        }
    }
};

// ---- Before the run: exit 2 on any bad argument, with nothing written.

// The window and the demo, with the context current when drawing. Exit 3 when the demo cannot start.
int StartDemo(const Options& o, const SceneDescription* scene, Session* s, bool drawing) {
    s->window = std::make_unique<DemoWindow>("Physics Sandbox", o.width, o.height);
    s->window->SetDrawing(drawing);
    s->window->OnInitialize();
    s->window->OnResize(o.width, o.height);
    s->window->SetUIVisible(!o.noUi);
    s->window->SetNominalFrameTime(float(1000.0 * o.frameTime.ToDouble()));
    const bool started = scene != nullptr ? s->window->StartDemo(std::make_unique<SceneFileDemo>(*scene), o.demo)
                                          : s->window->StartDemo(o.demo);
    if (!started || !s->window->CurrentDemo()) {
        std::fprintf(stderr, "physics-sandbox: demo '%s' failed to start\n", o.demo.c_str());
        return kExitFailure;
    }
    return kExitOk;
}

// Without pictures (o.draws false): the window and the demo only, no GL context. Otherwise one headless context,
// ImGui with its OpenGL2 back end (no ini file, fixed display size and delta time, the book's look:
// docs/book-reference.md §1.7), the window and the demo. Exit 3 when the context or the demo cannot start.
int StartSession(const Options& o, const SceneDescription* scene, Session* s, RunStats* stats) {
    if (!o.draws) return StartDemo(o, scene, s, false);
    PinSoftwareRasterizer();
    HeadlessInfo info;
    std::string error;
    HeadlessBackend backend = HeadlessBackend::Auto;
    ParseHeadlessBackend(o.backend, &backend);  // the command line accepts only valid names
    s->context = CreateHeadlessContext(o.width, o.height, backend, &info, &error);
    if (!s->context) {
        std::fprintf(stderr, "physics-sandbox: no OpenGL context (--backend %s): %s\n", o.backend.c_str(),
                     error.c_str());
        return kExitFailure;
    }
    stats->renderer = info.renderer + " via " + info.backend + (info.device.empty() ? "" : " " + info.device);
    stats->glStrings = "GL_VENDOR " + info.vendor + "; GL_RENDERER " + info.renderer + "; GL_VERSION " + info.version +
                       "; back end " + info.backend + (info.device.empty() ? "" : " " + info.device);
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    s->imgui = true;
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.LogFilename = nullptr;
    io.DisplaySize = ImVec2(float(o.width), float(o.height));
    io.DeltaTime = float(o.frameTime.ToDouble());
    ApplyBookImGuiStyle();  // StyleColorsClassic() plus the book's 1.50 look (Windows/)
    ImGui_ImplOpenGL2_Init();
    return StartDemo(o, scene, s, true);
}

// --dt and --set in order (ApplySetList); exit 2 naming the value and listing the table.
int ApplySets(Options& o, DemoBase& demo) {
    std::string error;
    if (ApplySetList(&o, demo, &error)) return kExitOk;
    std::fprintf(stderr, "physics-sandbox: %s\nparameters of %s:\n%s", error.c_str(), o.demo.c_str(),
                 demo.Parameters().Describe().c_str());
    return kExitUsage;
}

// --params: prints the table (the values in effect) and ends the run.
int ShowParameters(const Options& o, const DemoBase& demo) {
    std::printf("parameters of %s (--set KEY=VALUE):\n%s", o.demo.c_str(), demo.Parameters().Describe().c_str());
    return FinishStdout();
}

// --set, then --params (prints and ends the run).
int ApplyParameters(Options& o, DemoBase& demo) {
    if (const int code = ApplySets(o, demo); code != kExitOk || !o.showParams) return code;
    return ShowParameters(o, demo);
}

/// The simulated seconds a run covers (the auto model estimates the error at its end).
double RunSeconds(const Options& o) { return double(o.frames) * o.frameTime.ToDouble(); }

// Camera overrides, then one camera update so the view is valid on frame 0 (docs/book-reference.md §1.2). Returns the
// yaw the
// --orbit turntable starts from.
float ApplyCamera(const Options& o, DemoBase& demo) {
    vec2 rotation = demo.camera.GetRotation();
    if (o.hasYaw) rotation.x = o.yaw;
    if (o.hasPitch) rotation.y = o.pitch;
    demo.camera.SetRotation(rotation);
    if (o.hasZoom) demo.camera.SetZoom(o.zoom);
    if (o.hasTarget) demo.camera.SetTarget(vec3(o.target[0], o.target[1], o.target[2]));
    demo.camera.Update(0.0f);
    return rotation.x;
}

// ---- The run loop.

/// The host's fixed step (HostStepOf): the demo's physics step when it asks for one (e.g. --set dt=0.01 on
/// springs), else the host's (--dt or --set dt=). Whole physics steps run inside host time, so simulated time
/// follows it at any step.
Rational HostStep(const Options& o, const DemoBase& demo) { return HostStepOf(o.step, demo); }

/// Everything the frame loop carries from one frame to the next.
struct RunLoop {
    const Options& o;
    DemoWindow& window;
    DemoBase& demo;
    RunOutputs& outputs;
    RunStats* stats;
    Rational step;  ///< the host's fixed step (HostStep); an auto model's switch may change it
    FrameClock clock;
    AutoModel* autoModel = nullptr;   ///< the run's, while active (docs/model-choice.md)
    std::size_t autoModelLogged = 0;  ///< lines of its Log() already printed
    float baseYaw = 0.0f;
    ProgressLine progress;
    std::vector<std::uint8_t> scratch;
    std::vector<BodyState> bodies;
    std::string rows;
    std::size_t nextOnly = 0;
    int missedAt = -1;      ///< the frame from which an auto model's running estimate stayed over its budget
    double queueCpu = 0.0;  // main-thread CPU spent inside Push (serial mode: the encode itself)

    RunLoop(const Options& options, DemoWindow& w, DemoBase& d, AutoModel& m, RunOutputs& out, RunStats* s, float yaw)
        : o(options),
          window(w),
          demo(d),
          outputs(out),
          stats(s),
          step(HostStep(o, d)),
          clock(o.frameTime, step),
          baseYaw(yaw),
          progress(o) {
        if (m.Active()) autoModel = &m;
    }
};

bool Selected(RunLoop& r, int frame) {
    if (r.o.onlyFrames.empty()) return true;
    if (r.nextOnly < r.o.onlyFrames.size() && r.o.onlyFrames[r.nextOnly] == frame) {
        ++r.nextOnly;
        return true;
    }
    return false;
}

// Book order (1.2): UI and update, fixed steps. With --no-ui the window draws no widgets: no ImGui frame.
void SimulateFrame(RunLoop& r, int frame) {
    if (!r.o.noUi) {
        ImGui_ImplOpenGL2_NewFrame();
        ImGui::NewFrame();
    }
    r.window.OnUpdate(float(r.o.frameTime.ToDouble()));
    r.demo.ScriptFrame(frame);
    const float stepDt = float(r.step.ToDouble());
    for (int n = r.clock.AdvanceFrame(); n > 0; --n) r.window.OnFixedUpdate(stepDt);
    if (r.o.orbitDegreesPerFrame != 0.0f) {
        const float yaw = std::fmod(r.baseYaw + r.o.orbitDegreesPerFrame * float(frame), 360.0f);
        r.demo.camera.SetRotation(vec2(yaw, r.demo.camera.GetRotation().y));
        r.demo.camera.Update(0.0f);
    }
}

// After the frame's fixed steps: the auto model's live watch; a switch is printed as it happens, and a new step
// (dt refined) takes effect from the next frame on, the clock keeping its accumulated time.
void WatchModel(RunLoop& r, double time) {
    for (const std::string& line : WatchAutoModel(r.demo, *r.autoModel, time, &r.autoModelLogged))
        r.progress.Note(r.o.demo + ": model auto: " + line);
    const Rational step = HostStep(r.o, r.demo);
    if (step.num != r.step.num || step.den != r.step.den) {
        r.clock.SetStep(step);
        r.step = step;
    }
}

// The state checks and, when `record`, the --state rows of one frame at physics time `time`; false with *failure
// (exit 3).
bool CheckAndRecordState(RunLoop& r, int frame, double time, bool record, std::string* failure) {
    std::string where;
    bool finite = r.demo.StateIsFinite(&where);
    if (frame == r.o.debugNonFiniteAt) finite = false, where = "body -1 (injected by --debug-nonfinite-at)";
    if (!finite) {
        char head[96];
        std::snprintf(head, sizeof head, "frame %d (t = %.4f s): non-finite simulation state: ", frame, time);
        *failure = head + where;
        return false;
    }
    if (!record || !r.outputs.state.IsOpen()) return true;
    r.bodies.clear();
    r.demo.CollectState(&r.bodies);
    r.rows.clear();
    if (r.autoModel != nullptr) {
        const double estimate = r.autoModel->RunningEstimate();
        AppendStateRows(frame, time, r.bodies, &r.rows, &estimate);
    } else {
        AppendStateRows(frame, time, r.bodies, &r.rows);
    }
    return r.outputs.state.Write(r.rows.data(), r.rows.size(), failure);
}

void RenderFrame(RunLoop& r) {
    r.window.OnRender();
    if (!r.o.noUi) {
        ImGui::Render();
        ImGui_ImplOpenGL2_RenderDrawData(ImGui::GetDrawData());
    }
    glFinish();
}

// Reads the frame back and queues its encode, write and comparison (a selected frame) and its video frame
// (--video). False once a job has failed.
bool QueueFrame(RunLoop& r, int frame, bool selected) {
    const Clock::time_point readStart = Clock::now();
    Image image;
    ReadFrame(r.o.width, r.o.height, &r.scratch, &image);
    r.stats->readbackSeconds += Since(readStart);
    const double pushCpu = CpuSeconds(CLOCK_THREAD_CPUTIME_ID);
    bool queued = true;
    if (r.outputs.Recording()) {
        auto shared = std::make_shared<const Image>(selected ? image : std::move(image));
        queued = r.outputs.queue.Push(r.outputs.MakeVideoJob(std::move(shared)));
    }
    if (queued && selected) queued = r.outputs.queue.Push(r.outputs.MakeFrameJob(frame, std::move(image)));
    r.queueCpu += CpuSeconds(CLOCK_THREAD_CPUTIME_ID) - pushCpu;
    return queued;
}

// After the last frame is drawn: the step the strict accumulator still owes, shortened, so the physics ends at the
// run's time (docs/app.md "Time"). The frame was drawn before it, so every picture stays the book's.
void LandOnRunTime(RunLoop& r) {
    const double owed = r.clock.LandOnFrameTime();
    if (owed > 0.0) r.window.OnFixedUpdate(float(owed));
}

// An auto model whose live watch found its estimate over the budget and kept the model (AutoModel::MissedBudget):
// the frame from which it stayed so (exit 4 at the end unless a later check brings it back).
void TrackBudget(RunLoop& r, int frame) {
    if (r.autoModel == nullptr) return;
    double estimate = 0.0, time = 0.0;
    if (!r.autoModel->MissedBudget(&estimate, &time))
        r.missedAt = -1;
    else if (r.missedAt < 0)
        r.missedAt = frame;
}

/// One output frame. False ends the run: *failure set for exit 3 (empty when a queued job failed).
bool RunFrame(RunLoop& r, int frame, std::string* failure) {
    const Clock::time_point renderStart = Clock::now();
    // Unstable before this frame's update: the panel drawn in this frame shows the monitor's report.
    std::string report;
    const bool blownUp = r.demo.Unstable(&report);
    SimulateFrame(r, frame);
    if (r.autoModel != nullptr) WatchModel(r, r.clock.PhysicsSeconds());
    const bool last = frame + 1 == r.o.frames;
    // The last frame's row waits for the landing step below; its state is checked before it is drawn all the same.
    if (!CheckAndRecordState(r, frame, r.clock.PhysicsSeconds(), !last, failure)) {
        if (!r.o.noUi) ImGui::EndFrame();
        return false;
    }
    if (r.o.draws) RenderFrame(r);
    r.stats->renderSeconds += Since(renderStart);
    const bool selected = r.outputs.WantsFrames() && Selected(r, frame);
    if ((selected || r.outputs.Recording()) && !QueueFrame(r, frame, selected)) return false;
    if (blownUp) {
        *failure = "frame " + std::to_string(frame) + ": the simulation stopped: " + report;
        return false;
    }
    if (last) {
        LandOnRunTime(r);
        if (!CheckAndRecordState(r, frame, r.clock.PhysicsSeconds(), true, failure)) return false;
    }
    TrackBudget(r, frame);
    return true;
}

// The loop over the output frames; returns kExitOk or kExitFailure (the message printed).
int RunFrames(RunLoop& r, Clock::time_point wallStart) {
    const double renderCpuStart = CpuSeconds(CLOCK_THREAD_CPUTIME_ID);
    std::string failure;
    bool ok = true;
    for (int frame = 0; ok && frame < r.o.frames; ++frame) {
        ok = RunFrame(r, frame, &failure);
        if (ok) r.progress.Frame(frame + 1, r.clock.PhysicsSeconds(), Since(wallStart));
    }
    std::string report;
    if (ok && r.demo.Unstable(&report))  // blew up during the last frame's steps
        ok = false, failure = "the simulation stopped after the last frame: " + report;
    r.progress.End();
    r.stats->renderCpuSeconds = CpuSeconds(CLOCK_THREAD_CPUTIME_ID) - renderCpuStart - r.queueCpu;
    if (!failure.empty()) std::fprintf(stderr, "physics-sandbox: %s\n", failure.c_str());
    return ok ? kExitOk : kExitFailure;
}

void FillStats(const RunLoop& r, Clock::time_point wallStart, double processCpuStart, RunStats* stats) {
    stats->frames = int(r.clock.Frames());
    stats->steps = r.clock.Steps();
    stats->simulatedSeconds = r.clock.PhysicsSeconds();
    stats->encodeSeconds = r.outputs.results.encodeSeconds;
    stats->encodeCpuSeconds = r.outputs.results.encodeCpuSeconds;
    stats->processCpuSeconds = CpuSeconds(CLOCK_PROCESS_CPUTIME_ID) - processCpuStart;
    stats->waitSeconds = r.outputs.queue.ProducerWaitSeconds();
    stats->wallSeconds = Since(wallStart);
}

// The run ended with an auto model's running estimate over its budget (TrackBudget): exit 4, or 1 when a golden
// comparison also failed (a mismatch is the older, more specific report). Outputs are already complete.
int ReportMissedBudget(const RunLoop& r, int code) {
    const AutoModel& model = *r.autoModel;
    std::fprintf(stderr,
                 "physics-sandbox: %s: ran, but missed its error budget: the running estimate %.3g went over the "
                 "budget %.3g at frame %d and no finer model brought it back (outputs written; exit 4)\n",
                 r.o.demo.c_str(), model.RunningEstimate(), double(model.Request().bound), r.missedAt);
    return code == kExitOk ? kExitMissedBudget : code;
}

void PrintSummary(const Options& o, const RunStats& s, const std::string& frameDir, const AutoModel& model) {
    const double frames = std::max(1, s.frames);
    std::fprintf(stderr,
                 "physics-sandbox: %s: %d frames, %.3f simulated s, %lld steps, wall %.2f s, %.1f fps "
                 "(render %.1f ms, readback %.1f ms, encode %.1f ms per frame; %s)%s%s\n",
                 o.demo.c_str(), s.frames, s.simulatedSeconds, s.steps, s.wallSeconds,
                 s.wallSeconds > 0 ? s.frames / s.wallSeconds : 0.0, 1000.0 * s.renderSeconds / frames,
                 1000.0 * s.readbackSeconds / frames, 1000.0 * s.encodeSeconds / frames, s.renderer.c_str(),
                 frameDir.empty() ? "" : "; frames in ", frameDir.c_str());
    if (model.Active()) std::fprintf(stderr, "physics-sandbox: %s: %s\n", o.demo.c_str(), model.Summary().c_str());
}

/// --scene: loads the file into *scene (exit 2 listing every problem, before anything is written), names the run
/// after it in o->demo and, without --frames, runs the scene's duration.
int LoadScene(Options* o, SceneDescription* scene) {
    std::vector<std::string> errors, notes;
    if (!LoadSceneFile(o->scene, scene, &errors, &notes)) {
        for (const std::string& e : errors) std::fprintf(stderr, "physics-sandbox: %s\n", e.c_str());
        return kExitUsage;
    }
    for (const std::string& note : notes) std::fprintf(stderr, "physics-sandbox: %s\n", note.c_str());
    o->demo = "scene " + o->scene;
    if (!o->framesGiven) {
        const double frames = std::ceil(double(scene->duration) / o->frameTime.ToDouble() - 1e-9);
        o->frames = int(std::clamp(frames, 1.0, 1e8));
    }
    if (!o->onlyFrames.empty() && o->onlyFrames.back() >= o->frames) {
        std::fprintf(stderr, "physics-sandbox: --only-frames %d is not below the scene's %d frames\n",
                     o->onlyFrames.back(), o->frames);
        return kExitUsage;
    }
    return kExitOk;
}

/// --export-scene: the demo (built without a GL context, --set applied) described as a scene file, written whole.
/// Exit 2 for a demo whose motion is scripted; each thing the format cannot express is listed on stderr.
int ExportScene(const Options& given) {
    Options o = given;  // --set dt= may set its step
    if (const int code = CheckDemoId(o.demo); code != kExitOk) return code;
    std::string error;
    if (!CheckWritableTarget(o.exportScene, &error)) {  // as --state and --video: a link or device is never replaced
        std::fprintf(stderr, "physics-sandbox: --export-scene: %s\n", error.c_str());
        return kExitUsage;
    }
    const DemoInfo* info = FindDemo(o.demo);
    std::unique_ptr<DemoBase> demo = info->create();
    if (const int code = ApplyParameters(o, *demo); code != kExitOk || o.showParams) return code;
    const PhysicsSystem* world = demo->World();
    if (world == nullptr) {
        std::fprintf(stderr,
                     "physics-sandbox: --export-scene: demo '%s' is scripted, not simulated; nothing to export\n",
                     o.demo.c_str());
        return kExitUsage;
    }
    std::vector<std::string> notes;
    SceneDescription description = DescribeWorld(*world, info->title, &notes);
    // The demo's own step, else the host's when --set dt= gave one (a demo without its own dt).
    const bool stepSet = o.step.num != given.step.num || o.step.den != given.step.den;
    description.world.step = demo->PhysicsStep() > 0.0f || !stepSet ? demo->PhysicsStep() : float(o.step.ToDouble());
    // The demo's own view (set by its constructor) with the run's camera flags, as a run would start.
    ApplyCamera(o, *demo);
    description.camera.target = demo->camera.GetTarget();
    description.camera.rotation = demo->camera.GetRotation();
    description.camera.zoom = demo->camera.GetZoom();
    demo->ExportNotes(&notes);
    if (const AutoModelRequest* request = demo->AutoModelRequestOf()) description.autoModel = *request;
    const std::string text = WriteSceneText(description);
    if (!WriteFileAtomic(o.exportScene, std::vector<std::uint8_t>(text.begin(), text.end()), &error)) {
        std::fprintf(stderr, "physics-sandbox: --export-scene: %s\n", error.c_str());
        return kExitFailure;
    }
    for (const std::string& note : notes)
        std::fprintf(stderr, "physics-sandbox: --export-scene: not expressed: %s\n", note.c_str());
    return kExitOk;
}

int RunUnguarded(const Options& given, RunStats* stats) {
    if (!given.exportScene.empty()) return ExportScene(given);
    const Clock::time_point wallStart = Clock::now();
    const double processCpuStart = CpuSeconds(CLOCK_PROCESS_CPUTIME_ID);
    Options o = given;
    SceneDescription scene;
    const bool fromFile = !o.scene.empty();
    // A run that writes no picture makes no GL context and draws nothing; its UI frames go too (the panels
    // only read the parameters), so the physics and the --state rows are those of a drawn run.
    o.draws = !o.outDir.empty() || !o.compareDir.empty() || !o.videoFile.empty();
    if (!o.draws) o.noUi = true, stats->renderer = "no drawing";
    int code = fromFile ? LoadScene(&o, &scene) : CheckDemoId(o.demo);
    if (code == kExitOk) code = CheckBackend(o);
    if (code == kExitOk) code = CheckOutputArguments(o);
    if (code != kExitOk) return code;
    Session session;
    if ((code = StartSession(o, fromFile ? &scene : nullptr, &session, stats)) != kExitOk) return code;
    DemoBase& demo = *session.window->CurrentDemo();
    if ((code = ApplySets(o, demo)) != kExitOk) return code;
    AutoModelHost host;
    host.name = o.demo;
    host.hostStep = o.step.ToDouble();
    host.runSeconds = RunSeconds(o);
    host.explain = o.explainModel;
    host.quiet = o.quiet;
    bool explained = false;
    if ((code = ChooseAutoModel(demo, session.autoModel, host, &explained)) != kExitOk || explained) return code;
    if (o.showParams) return ShowParameters(o, demo);
    const float baseYaw = ApplyCamera(o, demo);

    // From here on a failure is a run-time failure (exit 3).
    RunOutputs outputs(o);
    outputs.renderer = stats->glStrings;
    std::string error;
    if (!outputs.Open(&error, session.autoModel.Active())) {
        std::fprintf(stderr, "physics-sandbox: %s\n", error.c_str());
        return kExitFailure;
    }
    RunLoop loop(o, *session.window, demo, session.autoModel, outputs, stats, baseYaw);
    code = RunFrames(loop, wallStart);
    code = outputs.Finish(code);
    FillStats(loop, wallStart, processCpuStart, stats);
    if (code == kExitOk || code == kExitMismatch) code = outputs.ReportComparisons(code);
    if (!o.quiet && code != kExitFailure) PrintSummary(o, *stats, outputs.FrameDir(), session.autoModel);
    if ((code == kExitOk || code == kExitMismatch) && loop.missedAt >= 0) return ReportMissedBudget(loop, code);
    return code;
}

}  // namespace

int CheckDemoId(const std::string& id) {
    if (FindDemo(id)) return kExitOk;
    std::string ids;
    for (const DemoInfo& d : AllDemos()) ids += (ids.empty() ? "" : ", ") + d.id;
    std::fprintf(stderr, "physics-sandbox: unknown demo '%s'; valid ids: %s\n", id.c_str(),
                 ids.empty() ? "(none registered)" : ids.c_str());
    return kExitUsage;
}

int RunSandbox(const Options& options, RunStats* stats) {
    try {
        return RunUnguarded(options, stats);
    } catch (const std::bad_alloc&) {
        // Every temporary and every directory this run created was removed while unwinding.
        std::fprintf(stderr,
                     "physics-sandbox: out of memory (a %dx%d frame); the run stopped, its partial output "
                     "removed\n",
                     options.width, options.height);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "physics-sandbox: the run stopped: %s\n", e.what());
    }
    return kExitFailure;
}
