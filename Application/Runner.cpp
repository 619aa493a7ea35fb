#include "Application/Runner.h"

// glad first: it must precede anything that could pull in <GL/gl.h>.
#include <glad/gl.h>
// clang-format off
#include <imgui.h>
#include <backends/imgui_impl_opengl2.h>
// clang-format on
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <mutex>
#include <vector>

#include "Application/StateCsv.h"
#include "Demos/DemoBase.h"
#include "Demos/DemoRegistry.h"
#include "Platform/EncodeQueue.h"
#include "Platform/HeadlessContext.h"
#include "Platform/ImageCompare.h"
#include "Platform/PngCodec.h"
#include "Windows/BookImGuiStyle.h"
#include "Windows/DemoWindow.h"

namespace {

using Clock = std::chrono::steady_clock;

double Since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

double CpuSeconds(clockid_t which) {
    timespec t{};
    clock_gettime(which, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

std::string FrameName(int frame) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.png", frame);
    return name;
}

std::string JoinPath(const std::string& dir, const std::string& name) {
    return dir.empty() || dir.back() == '/' ? dir + name : dir + "/" + name;
}

bool MakeDirectories(const std::string& dir, std::string* error) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir)) {
        *error = "cannot create directory " + dir + ": " + (ec ? ec.message() : "not a directory");
        return false;
    }
    return true;
}

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

// One frame's golden comparison, filled in by the encode thread.
struct FrameComparison {
    std::string name;
    bool missing = false;
    CompareResult result;
};

class ProgressLine {
public:
    ProgressLine(const Options& o) : total(o.frames), tty(isatty(STDERR_FILENO) != 0) {
        if (o.quiet) return;
        if (o.progressEvery > 0)
            every = o.progressEvery;
        else if (tty)
            every = 10;  // cheap \r updates
        else if (o.frames >= 300)
            every = std::max(100, o.frames / 10);  // a long run in a log: about ten lines
    }
    void Frame(int done, double simulated, double wall) {
        if (every == 0 || done % every != 0 || done == total) return;
        std::fprintf(stderr, "%sframe %d/%d  simulated %.2f s  wall %.1f s  %.1f fps%s", tty ? "\r" : "", done, total,
                     simulated, wall, wall > 0 ? done / wall : 0.0, tty ? "" : "\n");
        std::fflush(stderr);
        pending = tty;
    }
    void End() {
        if (pending) std::fputc('\n', stderr);
        pending = false;
    }

private:
    int total;
    bool tty;
    int every = 0;
    bool pending = false;
};

// Owns the GL-side lifetime: ImGui back end, window, context, in reverse order of creation.
struct Session {
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

}  // namespace

int RunSandbox(const Options& o, RunStats* stats) {
    const Clock::time_point wallStart = Clock::now();
    const double processCpuStart = CpuSeconds(CLOCK_PROCESS_CPUTIME_ID);
    // ---- Validation: nothing is written until every argument has been checked (exit 2).
    if (!FindDemo(o.demo)) {
        std::string ids;
        for (const DemoInfo& d : AllDemos()) ids += (ids.empty() ? "" : ", ") + d.id;
        std::fprintf(stderr, "physics-sandbox: unknown demo '%s'; valid ids: %s\n", o.demo.c_str(),
                     ids.empty() ? "(none registered)" : ids.c_str());
        return kExitUsage;
    }
    if (!o.compareDir.empty() && !o.updateGolden && !std::filesystem::is_directory(o.compareDir)) {
        std::fprintf(stderr, "physics-sandbox: --compare %s: no such directory\n", o.compareDir.c_str());
        return kExitUsage;
    }

    PinSoftwareRasterizer();
    Session s;
    HeadlessInfo info;
    std::string error;
    s.context = CreateHeadlessContext(o.width, o.height, &info, &error);
    if (!s.context) {
        std::fprintf(stderr, "physics-sandbox: no OpenGL context: %s\n", error.c_str());
        return kExitFailure;
    }
    stats->renderer = info.renderer;

    // ImGui: no ini file, fixed display size and delta time, classic colours (docs/book-reference.md §1.7).
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    s.imgui = true;
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.LogFilename = nullptr;
    io.DisplaySize = ImVec2(float(o.width), float(o.height));
    io.DeltaTime = float(o.frameTime.ToDouble());
    ApplyBookImGuiStyle();  // StyleColorsClassic() plus the book's 1.50 look (Windows/)
    ImGui_ImplOpenGL2_Init();

    s.window = std::make_unique<DemoWindow>("Physics Sandbox", o.width, o.height);
    DemoWindow& window = *s.window;
    window.OnInitialize();
    window.OnResize(o.width, o.height);
    window.SetUIVisible(!o.noUi);
    window.SetNominalFrameTime(float(1000.0 * o.frameTime.ToDouble()));
    if (!window.StartDemo(o.demo) || !window.CurrentDemo()) {
        std::fprintf(stderr, "physics-sandbox: demo '%s' failed to start\n", o.demo.c_str());
        return kExitFailure;
    }
    DemoBase& demo = *window.CurrentDemo();
    for (const auto& [key, value] : o.sets) {
        if (!demo.Parameters().Set(key, value, &error)) {
            std::fprintf(stderr, "physics-sandbox: --set %s=%s: %s\nparameters of %s:\n%s", key.c_str(), value.c_str(),
                         error.c_str(), o.demo.c_str(), demo.Parameters().Describe().c_str());
            return kExitUsage;
        }
    }

    if (o.showParams) {
        std::printf("parameters of %s (--set KEY=VALUE):\n%s", o.demo.c_str(), demo.Parameters().Describe().c_str());
        return kExitOk;
    }

    // Camera overrides, then one camera update so the view is valid on frame 0 (docs/book-reference.md §1.2).
    vec2 rotation = demo.camera.GetRotation();
    if (o.hasYaw) rotation.x = o.yaw;
    if (o.hasPitch) rotation.y = o.pitch;
    demo.camera.SetRotation(rotation);
    if (o.hasZoom) demo.camera.SetZoom(o.zoom);
    if (o.hasTarget) demo.camera.SetTarget(vec3(o.target[0], o.target[1], o.target[2]));
    demo.camera.Update(0.0f);
    const float baseYaw = rotation.x;

    // ---- Outputs. From here on a failure is a run-time failure (exit 3).
    const bool updating = o.updateGolden;
    const std::string frameDir = updating ? o.compareDir : o.outDir;
    const bool comparing = !o.compareDir.empty() && !updating;
    if (!frameDir.empty() && !MakeDirectories(frameDir, &error)) {
        std::fprintf(stderr, "physics-sandbox: %s\n", error.c_str());
        return kExitFailure;
    }
    std::FILE* stateFile = nullptr;
    std::string stateTemp;
    if (!o.stateFile.empty()) {
        // Written to a temporary beside it and renamed at the end: whole or not at all.
        const std::filesystem::path target(o.stateFile);
        stateTemp = (target.parent_path() / ("." + target.filename().string() + ".tmp")).string();
        stateFile = std::fopen(stateTemp.c_str(), "wb");
        if (!stateFile) {
            std::fprintf(stderr, "physics-sandbox: cannot write %s: %s\n", o.stateFile.c_str(), std::strerror(errno));
            return kExitFailure;
        }
        std::fputs(StateCsvHeader(), stateFile);
    }
    const auto abandonState = [&]() {
        if (stateFile) std::fclose(stateFile), stateFile = nullptr;
        if (!stateTemp.empty()) std::remove(stateTemp.c_str());
    };

    const CompareThresholds thresholds = o.thresholds;
    PngOptions png;
    png.level = o.pngLevel;
    std::mutex resultsMutex;
    std::vector<FrameComparison> comparisons;
    double encodeSeconds = 0.0;  // written by the encode thread only, read after Finish
    double encodeCpuSeconds = 0.0;
    EncodeQueue queue(3, o.encodeThread);

    FrameClock clock(o.frameTime, o.step);
    const float frameDt = float(o.frameTime.ToDouble());
    const float stepDt = float(o.step.ToDouble());
    const bool wantPixels = !frameDir.empty() || comparing;
    std::vector<std::uint8_t> scratch;
    std::vector<BodyState> bodies;
    std::string rows;
    ProgressLine progress(o);
    std::size_t nextOnly = 0;
    int exitCode = kExitOk;
    const double renderCpuStart = CpuSeconds(CLOCK_THREAD_CPUTIME_ID);
    double queueCpu = 0.0;  // main-thread CPU spent inside Push (serial mode: the encode itself)

    for (int frame = 0; frame < o.frames; ++frame) {
        const Clock::time_point renderStart = Clock::now();
        // Book order (1.2): UI and update, fixed steps, render, ImGui on top.
        // With --no-ui the window draws no widgets, so there is no ImGui frame at all.
        if (!o.noUi) {
            ImGui_ImplOpenGL2_NewFrame();
            ImGui::NewFrame();
        }
        window.OnUpdate(frameDt);
        demo.ScriptFrame(frame);
        for (int n = clock.AdvanceFrame(); n > 0; --n) window.OnFixedUpdate(stepDt);
        if (o.orbitDegreesPerFrame != 0.0f) {
            const float yaw = std::fmod(baseYaw + o.orbitDegreesPerFrame * float(frame), 360.0f);
            demo.camera.SetRotation(vec2(yaw, demo.camera.GetRotation().y));
            demo.camera.Update(0.0f);
        }
        // Simulated time of this frame's state: frames advanced so far times the frame time.
        const double time = clock.FrameSeconds();

        std::string where;
        bool finite = demo.StateIsFinite(&where);
        if (frame == o.debugNonFiniteAt) finite = false, where = "body -1 (injected by --debug-nonfinite-at)";
        if (!finite) {
            if (!o.noUi) ImGui::EndFrame();
            progress.End();
            std::fprintf(stderr, "physics-sandbox: frame %d (t = %.4f s): non-finite simulation state: %s\n", frame,
                         time, where.c_str());
            exitCode = kExitFailure;
            break;
        }
        if (stateFile) {
            bodies.clear();
            demo.CollectState(&bodies);
            rows.clear();
            AppendStateRows(frame, time, bodies, &rows);
            if (std::fwrite(rows.data(), 1, rows.size(), stateFile) != rows.size()) {
                std::fprintf(stderr, "physics-sandbox: cannot write %s: %s\n", o.stateFile.c_str(),
                             std::strerror(errno));
                exitCode = kExitFailure;
                if (!o.noUi) ImGui::EndFrame();
                break;
            }
        }

        window.OnRender();
        if (!o.noUi) {
            ImGui::Render();
            ImGui_ImplOpenGL2_RenderDrawData(ImGui::GetDrawData());
        }
        glFinish();
        stats->renderSeconds += Since(renderStart);

        bool selected = o.onlyFrames.empty();
        if (!selected && nextOnly < o.onlyFrames.size() && o.onlyFrames[nextOnly] == frame) {
            selected = true;
            ++nextOnly;
        }
        if (wantPixels && selected) {
            const Clock::time_point readStart = Clock::now();
            Image image;
            ReadFrame(o.width, o.height, &scratch, &image);
            stats->readbackSeconds += Since(readStart);
            const std::string name = FrameName(frame);
            const std::string outDir = o.outDir;
            const std::string compareDir = comparing ? o.compareDir : std::string();
            // The job owns its image; everything it does depends only on the image and these strings.
            EncodeQueue::Job job = [=, &png, &thresholds, &comparisons, &resultsMutex, &encodeSeconds,
                                    &encodeCpuSeconds](std::string* err) {
                const Clock::time_point start = Clock::now();
                const double cpuStart = CpuSeconds(CLOCK_THREAD_CPUTIME_ID);
                std::vector<std::uint8_t> bytes;
                if (!EncodePng(image, png, &bytes, err)) return false;
                if (!frameDir.empty() && !WriteFileAtomic(JoinPath(frameDir, name), bytes, err)) return false;
                if (!compareDir.empty()) {
                    FrameComparison c;
                    c.name = name;
                    Image expected;
                    std::string readError;
                    if (!ReadPngFile(JoinPath(compareDir, name), &expected, &readError)) {
                        c.missing = true;
                    } else {
                        c.result = CompareImages(expected, image, thresholds);
                    }
                    if (c.missing || !c.result.passed) {
                        // Evidence for the mismatch: expected, actual and a diff image side by side.
                        const std::string dir = JoinPath(outDir, "mismatch");
                        if (!MakeDirectories(dir, err)) return false;
                        const std::string stem = JoinPath(dir, name.substr(0, name.size() - 4));
                        if (!WriteFileAtomic(stem + ".actual.png", bytes, err)) return false;
                        if (!c.missing) {
                            std::vector<std::uint8_t> other;
                            if (!EncodePng(expected, png, &other, err) ||
                                !WriteFileAtomic(stem + ".expected.png", other, err))
                                return false;
                            if (!EncodePng(MakeDiffImage(expected, image, thresholds), png, &other, err) ||
                                !WriteFileAtomic(stem + ".diff.png", other, err))
                                return false;
                        }
                    }
                    std::lock_guard<std::mutex> lock(resultsMutex);
                    comparisons.push_back(c);
                }
                encodeSeconds += Since(start);
                encodeCpuSeconds += CpuSeconds(CLOCK_THREAD_CPUTIME_ID) - cpuStart;
                return true;
            };
            const double pushCpu = CpuSeconds(CLOCK_THREAD_CPUTIME_ID);
            const bool queued = queue.Push(std::move(job));
            queueCpu += CpuSeconds(CLOCK_THREAD_CPUTIME_ID) - pushCpu;
            if (!queued) break;  // the failure is reported by Finish below
        }
        progress.Frame(frame + 1, time, Since(wallStart));
    }
    progress.End();
    stats->renderCpuSeconds = CpuSeconds(CLOCK_THREAD_CPUTIME_ID) - renderCpuStart - queueCpu;

    if (!queue.Finish(&error)) {
        std::fprintf(stderr, "physics-sandbox: %s\n", error.c_str());
        exitCode = kExitFailure;
    }
    if (stateFile) {
        const bool closed = std::fclose(stateFile) == 0;
        stateFile = nullptr;
        if (exitCode == kExitOk && (!closed || std::rename(stateTemp.c_str(), o.stateFile.c_str()) != 0)) {
            std::fprintf(stderr, "physics-sandbox: cannot write %s: %s\n", o.stateFile.c_str(), std::strerror(errno));
            exitCode = kExitFailure;
        }
        if (exitCode != kExitOk) abandonState();
    }

    stats->frames = int(clock.Frames());
    stats->steps = clock.Steps();
    stats->simulatedSeconds = clock.FrameSeconds();
    stats->encodeSeconds = encodeSeconds;
    stats->encodeCpuSeconds = encodeCpuSeconds;
    stats->processCpuSeconds = CpuSeconds(CLOCK_PROCESS_CPUTIME_ID) - processCpuStart;
    stats->waitSeconds = queue.ProducerWaitSeconds();
    stats->wallSeconds = Since(wallStart);

    if (comparing && exitCode == kExitOk) {
        // Per-frame metric summary, in frame order, on stderr and in OUT/compare.txt.
        std::string report;
        int failures = 0;
        for (const FrameComparison& c : comparisons) {
            const std::string line =
                c.name + ": " + (c.missing ? "missing golden (FAIL)" : DescribeComparison(c.result, thresholds));
            report += line + "\n";
            if (c.missing || !c.result.passed) ++failures;
        }
        char head[160];
        std::snprintf(head, sizeof head,
                      "compare with %s: %d frame(s), %d mismatch(es); tolerance %d, max fraction %g\n",
                      o.compareDir.c_str(), int(comparisons.size()), failures, thresholds.channelTolerance,
                      thresholds.maxDifferingFraction);
        report = head + report;
        std::vector<std::uint8_t> bytes(report.begin(), report.end());
        if (!WriteFileAtomic(JoinPath(o.outDir, "compare.txt"), bytes, &error)) {
            std::fprintf(stderr, "physics-sandbox: %s\n", error.c_str());
            return kExitFailure;
        }
        if (!o.quiet || failures) std::fputs(report.c_str(), stderr);
        if (failures) {
            std::fprintf(stderr, "physics-sandbox: %d frame(s) differ from %s; see %s/mismatch/\n", failures,
                         o.compareDir.c_str(), o.outDir.c_str());
            exitCode = kExitMismatch;
        }
    }
    if (!o.quiet && exitCode != kExitFailure) {
        std::fprintf(stderr,
                     "physics-sandbox: %s: %d frames, %.3f simulated s, %lld steps, wall %.2f s, %.1f fps "
                     "(render %.1f ms, readback %.1f ms, encode %.1f ms per frame; %s)%s%s\n",
                     o.demo.c_str(), stats->frames, stats->simulatedSeconds, stats->steps, stats->wallSeconds,
                     stats->wallSeconds > 0 ? stats->frames / stats->wallSeconds : 0.0,
                     1000.0 * stats->renderSeconds / std::max(1, stats->frames),
                     1000.0 * stats->readbackSeconds / std::max(1, stats->frames),
                     1000.0 * stats->encodeSeconds / std::max(1, stats->frames), stats->renderer.c_str(),
                     frameDir.empty() ? "" : "; frames in ", frameDir.c_str());
    }
    return exitCode;
}

int RunCommandLine(int argc, const char* const* argv) {
    Options options;
    std::string error;
    if (ParseCommandLine(argc, argv, &options, &error) != ParseStatus::Ok) {
        std::fprintf(stderr, "physics-sandbox: %s\n", error.c_str());
        return kExitUsage;
    }
    if (options.mode == Options::Mode::Help) {
        std::fputs(UsageText().c_str(), stdout);
        return kExitOk;
    }
    if (options.mode == Options::Mode::List) {
        for (const DemoInfo& d : AllDemos()) std::printf("%s\t%s\n", d.id.c_str(), d.title.c_str());
        return kExitOk;
    }
    RunStats stats;
    return RunSandbox(options, &stats);
}
