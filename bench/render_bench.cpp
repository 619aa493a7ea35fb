// render_bench [frames] [demo...]: the headless pipeline's speed at 800x600 (timings belong here, not in
// tests). Prints, per demo:
//   serial   render / readback / encode ms per frame with everything on the main thread
//   overlap  fps with encoding on the second core (the default); the CPU ms per frame of the main thread
//            and of the encode thread; the target 1 / max(those two) it should reach within 90 %; the cores
//            the process actually got (process CPU time / wall time: below ~1.9 the target is out of reach)
// and, once: a bare OSMesa render-and-read loop (clear, one lit quad, glFinish, glReadPixels) and the PNG
// encoders on a rendered frame (libpng levels and filters, stb_image_write). The machine is shared, so
// every figure is the best of a few repetitions.
#include <glad/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "Application/Runner.h"
#include "Demos/DemoRegistry.h"
#include "Platform/HeadlessContext.h"
#include "Platform/PngCodec.h"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb_image_write.h>

namespace {

using Clock = std::chrono::steady_clock;
constexpr int kWidth = 800, kHeight = 600;
constexpr int kRepeats = 3;

double Seconds(Clock::time_point a) { return std::chrono::duration<double>(Clock::now() - a).count(); }

// The floor under any demo: clear, a single lit quad, glFinish and glReadPixels; best ms of kRepeats.
void BareLoop(int frames, double* renderMs, double* readMs) {
    PinSoftwareRasterizer();
    HeadlessInfo info;
    std::string error;
    auto context = CreateHeadlessContext(kWidth, kHeight, &info, &error);
    if (!context) {
        std::fprintf(stderr, "bare loop: %s\n", error.c_str());
        std::exit(1);
    }
    std::vector<unsigned char> pixels(std::size_t(kWidth) * kHeight * 4);
    *renderMs = *readMs = 1e9;
    for (int rep = 0; rep < kRepeats; ++rep) {
        double render = 0.0, read = 0.0;
        for (int i = 0; i < frames; ++i) {
            const Clock::time_point t0 = Clock::now();
            glClearColor(0.5f, 0.6f, 0.7f, 1.0f);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
            glEnable(GL_DEPTH_TEST);
            glEnable(GL_LIGHTING);
            glEnable(GL_LIGHT0);
            glBegin(GL_TRIANGLES);
            glNormal3f(0, 0, 1);
            glVertex3f(-0.5f, -0.5f, 0), glVertex3f(0.5f, -0.5f, 0), glVertex3f(0.5f, 0.5f, 0);
            glVertex3f(-0.5f, -0.5f, 0), glVertex3f(0.5f, 0.5f, 0), glVertex3f(-0.5f, 0.5f, 0);
            glEnd();
            glFinish();
            const Clock::time_point t1 = Clock::now();
            glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
            render += std::chrono::duration<double>(t1 - t0).count();
            read += Seconds(t1);
        }
        *renderMs = std::min(*renderMs, 1000.0 * render / frames);
        *readMs = std::min(*readMs, 1000.0 * read / frames);
    }
    std::printf("renderer: %s (GL %s)\n", info.renderer.c_str(), info.version.c_str());
}

double BestEncodeMs(const std::function<std::size_t()>& encode, std::size_t* bytes) {
    double best = 1e9;
    for (int i = 0; i < 25; ++i) {
        const Clock::time_point t = Clock::now();
        *bytes = encode();
        best = std::min(best, 1000.0 * Seconds(t));
    }
    return best;
}

void CompareEncoders(const std::string& framePath) {
    Image img;
    std::string error;
    if (!ReadPngFile(framePath, &img, &error)) {
        std::fprintf(stderr, "encoders: %s\n", error.c_str());
        return;
    }
    std::printf("\nPNG encoders on %s (%dx%d), best of 25:\n", framePath.c_str(), img.width, img.height);
    const char* filterNames[] = {"none", "sub", "up", "adaptive"};
    for (int level : {1, 3, 6}) {
        for (PngFilter filter : {PngFilter::None, PngFilter::Sub, PngFilter::Up, PngFilter::Adaptive}) {
            std::size_t bytes = 0;
            const double ms = BestEncodeMs(
                [&] {
                    std::vector<std::uint8_t> out;
                    EncodePng(img, {level, filter}, &out, &error);
                    return out.size();
                },
                &bytes);
            std::printf("  libpng level %d filter %-8s %7.2f ms %8zu bytes\n", level, filterNames[int(filter)], ms,
                        bytes);
        }
    }
    for (int level : {1, 8}) {
        std::size_t bytes = 0;
        const double ms = BestEncodeMs(
            [&] {
                stbi_write_png_compression_level = level;
                int length = 0;
                unsigned char* png =
                    stbi_write_png_to_mem(img.rgb.data(), img.width * 3, img.width, img.height, 3, &length);
                std::free(png);
                return std::size_t(length);
            },
            &bytes);
        std::printf("  stb_image_write level %d       %7.2f ms %8zu bytes\n", level, ms, bytes);
    }
}

RunStats RunDemo(const std::string& id, int frames, bool threaded, const std::string& out) {
    Options o;
    o.demo = id;
    o.frames = frames;
    o.outDir = out;
    o.encodeThread = threaded;
    o.quiet = true;
    RunStats best;
    best.wallSeconds = 1e9;
    for (int rep = 0; rep < kRepeats; ++rep) {
        RunStats s;
        if (RunSandbox(o, &s) != kExitOk) std::exit(1);
        if (s.wallSeconds < best.wallSeconds) best = s;
    }
    return best;
}

}  // namespace

int main(int argc, char** argv) {
    const int frames = argc > 1 ? std::max(1, std::atoi(argv[1])) : 120;
    std::vector<std::string> ids;
    for (int i = 2; i < argc; ++i) ids.push_back(argv[i]);
    if (ids.empty())
        for (const DemoInfo& d : AllDemos()) ids.push_back(d.id);
    const std::string out = (std::filesystem::temp_directory_path() / "psb_render_bench").string();

    double bareRender = 0.0, bareRead = 0.0;
    BareLoop(frames, &bareRender, &bareRead);
    const double bareFps = 1000.0 / (bareRender + bareRead);
    std::printf("bare OSMesa loop %dx%d: render %.2f ms, readback %.2f ms -> %.1f fps\n\n", kWidth, kHeight, bareRender,
                bareRead, bareFps);

    std::printf("%-19s %7s %7s %7s %7s | %7s %7s %7s %7s %6s %6s %6s\n", "", "render", "readbk", "encode", "serial",
                "overlap", "rendCPU", "encCPU", "target", "of tgt", "cores", "/bare");
    std::printf("%-19s %7s %7s %7s %7s | %7s %7s %7s %7s %6s %6s %6s\n", "demo", "ms", "ms", "ms", "fps", "fps", "ms",
                "ms", "fps", "", "used", "");
    for (const std::string& id : ids) {
        std::filesystem::remove_all(out);
        const RunStats serial = RunDemo(id, frames, false, out);
        std::filesystem::remove_all(out);
        const RunStats overlap = RunDemo(id, frames, true, out);
        const double n = serial.frames;
        const double render = 1000.0 * serial.renderSeconds / n, read = 1000.0 * serial.readbackSeconds / n,
                     encode = 1000.0 * serial.encodeSeconds / n;
        const double serialFps = serial.frames / serial.wallSeconds;
        const double overlapFps = overlap.frames / overlap.wallSeconds;
        // Target from CPU time, which other processes on the machine do not inflate: the main thread's work
        // (update, physics, rasterising, readback) against the encode thread's.
        const double renderCpu = 1000.0 * overlap.renderCpuSeconds / overlap.frames;
        const double encodeCpu = 1000.0 * overlap.encodeCpuSeconds / overlap.frames;
        const double target = 1000.0 / std::max(renderCpu, encodeCpu);
        const double cores = overlap.processCpuSeconds / overlap.wallSeconds;
        std::printf("%-19s %7.2f %7.2f %7.2f %7.1f | %7.1f %7.2f %7.2f %7.1f %5.0f%% %6.2f %6.2f\n", id.c_str(), render,
                    read, encode, serialFps, overlapFps, renderCpu, encodeCpu, target, 100.0 * overlapFps / target,
                    cores, overlapFps / bareFps);
    }
    // Encoders on a rendered frame of the last demo (frame 60 if it exists).
    std::string frame = out + "/frame_00060.png";
    if (!std::filesystem::exists(frame)) frame = out + "/frame_00000.png";
    CompareEncoders(frame);
    std::filesystem::remove_all(out);
    return 0;
}
