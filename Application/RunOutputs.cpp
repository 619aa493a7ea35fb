#include "Application/RunOutputs.h"

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "Application/ExitCodes.h"
#include "Application/StateCsv.h"
#include "Platform/HeadlessContext.h"

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

/// OUT/mismatch/*.amplified.png: |expected - actual| x 16, so a difference of 16 per channel is full scale.
constexpr int kAmplifiedDiffGain = 16;

std::string FrameName(int frame) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.png", frame);
    return name;
}

std::string JoinPath(const std::string& dir, const std::string& name) {
    return dir.empty() || dir.back() == '/' ? dir + name : dir + "/" + name;
}

int Usage(const std::string& message) {
    std::fprintf(stderr, "physics-sandbox: %s\n", message.c_str());
    return kExitUsage;
}

/// The absolute path with symlinks and ".." resolved as far as it exists, without a trailing separator.
fs::path Resolved(const std::string& path) {
    std::error_code ec;
    // Absolute first: weakly_canonical leaves a relative path relative when none of it exists yet.
    fs::path p = fs::weakly_canonical(fs::absolute(fs::path(path.empty() ? "." : path), ec), ec);
    if (ec) p = fs::absolute(path, ec).lexically_normal();
    if (!p.has_filename() && p.has_parent_path() && p != p.root_path()) p = p.parent_path();
    return p;
}

bool SameDirectory(const std::string& a, const std::string& b) {
    std::error_code ec;
    return Resolved(a) == Resolved(b) || (fs::equivalent(a, b, ec) && !ec);
}

/// True if inner is outer or lies inside it (both resolved as far as they exist).
bool IsWithin(const std::string& inner, const std::string& outer) {
    const fs::path in = Resolved(inner), out = Resolved(outer);
    auto i = in.begin();
    for (auto o = out.begin(); o != out.end(); ++o, ++i)
        if (i == in.end() || *i != *o) return false;
    return true;
}

/// The directory the run writes its frames into and creates (--out; --compare with --update-golden), or "".
std::string FrameDirectory(const Options& o) { return o.updateGolden ? o.compareDir : o.outDir; }

/// A file target (--state, --video) must not be the frame directory or one of the directories the run creates on
/// the way to it: the run would make it a directory, then fail to write the file. Exit 2 if it is.
int CheckNotTheFrameDirectory(const std::string& flag, const std::string& file, const Options& o) {
    const std::string dir = FrameDirectory(o);
    if (dir.empty() || !IsWithin(dir, file)) return kExitOk;
    return Usage(flag + " " + file + ": the run creates it as a directory for the frames (" +
                 (o.updateGolden ? "--compare " : "--out ") + dir + "); name a file outside it");
}

/// A name physics-sandbox writes or reads as a frame, a golden or the comparison report.
bool IsFrameOrReportName(const std::string& name) {
    const bool frame =
        name.rfind("frame_", 0) == 0 && name.size() > 10 && name.compare(name.size() - 4, 4, ".png") == 0;
    return frame || name == "compare.txt";
}

int CheckStatePath(const Options& o) {
    std::string error;
    if (!CheckWritableTarget(o.stateFile, &error)) return Usage("--state: " + error);
    if (CheckNotTheFrameDirectory("--state", o.stateFile, o) != kExitOk) return kExitUsage;
    const fs::path state(o.stateFile);
    const std::string parent = state.parent_path().empty() ? "." : state.parent_path().string();
    for (const std::string& dir : {o.updateGolden ? o.compareDir : o.outDir, o.compareDir})
        if (!dir.empty() && IsFrameOrReportName(state.filename().string()) && SameDirectory(parent, dir))
            return Usage("--state " + o.stateFile + ": is a frame or golden path in " + dir +
                         "; the CSV would replace a frame");
    return kExitOk;
}

/// --video: a known extension, the ffmpeg program, and a target the run may write (as --state); exit 2 if not.
int CheckVideoPath(const Options& o) {
    VideoEncoder::Format format;
    if (!VideoEncoder::FormatOf(o.videoFile, &format))
        return Usage("--video " + o.videoFile + ": the name must end in .mp4, .webm or .gif");
    std::string error;
    if (!VideoEncoder::FfmpegAvailable(&error)) return Usage(error);
    if (!CheckWritableTarget(o.videoFile, &error)) return Usage("--video: " + error);
    if (CheckNotTheFrameDirectory("--video", o.videoFile, o) != kExitOk) return kExitUsage;
    const fs::path video(o.videoFile);
    std::error_code ec;
    const fs::path parent = video.parent_path().empty() ? fs::path(".") : video.parent_path();
    // The frame directory and those on the way to it are created before the recording starts.
    const std::string frameDir = FrameDirectory(o);
    if (!fs::is_directory(parent, ec) && (frameDir.empty() || !IsWithin(frameDir, parent.string())))
        return Usage("--video " + o.videoFile + ": directory " + parent.string() + " does not exist");
    if (!o.stateFile.empty() && fs::absolute(video).lexically_normal() == fs::absolute(o.stateFile).lexically_normal())
        return Usage("--video and --state name the same file " + o.videoFile);
    return kExitOk;
}

}  // namespace

double CpuSeconds(clockid_t which) {
    timespec t{};
    clock_gettime(which, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

int CheckOutputArguments(const Options& o) {
    if (!o.compareDir.empty() && !o.updateGolden) {
        std::error_code ec;
        const fs::file_status status = fs::status(o.compareDir, ec);
        if (!fs::is_directory(status))
            return Usage("--compare " + o.compareDir + ": " + (ec ? ec.message() : std::string("not a directory")));
        if (SameDirectory(o.outDir, o.compareDir))
            return Usage("--out " + o.outDir + " and --compare " + o.compareDir +
                         " are the same directory; the frames would overwrite the goldens they are compared with");
    }
    if (!o.videoFile.empty() && CheckVideoPath(o) != kExitOk) return kExitUsage;
    return o.stateFile.empty() ? kExitOk : CheckStatePath(o);
}

int CheckBackend(const Options& o) {
    HeadlessBackend backend = HeadlessBackend::Auto;
    const bool known = ParseHeadlessBackend(o.backend, &backend);
    if (known && (!o.draws || HeadlessBackendBuilt(backend))) return kExitOk;
    if (known && !HeadlessBackendBuilt(HeadlessBackend::Auto)) {
        std::fprintf(stderr,
                     "physics-sandbox: this build draws nothing (CMake PSB_WITH_RENDERING=OFF): --out, --compare and "
                     "--video need a build with rendering; runs with --state alone need none\n");
        return kExitUsage;
    }
    std::fprintf(stderr, "physics-sandbox: --backend %s: this build has no %s back end (CMake PSB_WITH_%s)\n",
                 o.backend.c_str(), o.backend.c_str(), backend == HeadlessBackend::Egl ? "EGL" : "OSMESA");
    return kExitUsage;
}

RunOutputs::RunOutputs(const Options& options)
    : o(options),
      frameDir(options.updateGolden ? options.compareDir : options.outDir),
      comparing(!options.compareDir.empty() && !options.updateGolden),
      queue(3, options.encodeThread) {
    png.level = options.pngLevel;
}

RunOutputs::~RunOutputs() {
    queue.Finish(nullptr);
    state.Abandon();
    if (keepDirectories) return;
    std::error_code ec;
    for (auto dir = createdDirs.rbegin(); dir != createdDirs.rend(); ++dir) fs::remove(*dir, ec);  // only if empty
}

bool RunOutputs::MakeDirectories(const std::string& dir, std::string* error) {
    std::error_code ec;
    std::vector<std::string> missing;  // dir and its missing ancestors, innermost first
    for (fs::path p = fs::path(dir).lexically_normal(); !p.empty() && !fs::exists(fs::symlink_status(p, ec));
         p = p.parent_path()) {
        missing.push_back(p.string());
        if (p == p.parent_path()) break;
    }
    fs::create_directories(dir, ec);
    {
        std::lock_guard<std::mutex> lock(dirsMutex);
        createdDirs.insert(createdDirs.end(), missing.rbegin(), missing.rend());
    }
    std::error_code isDirError;
    if (ec || !fs::is_directory(dir, isDirError)) {
        *error = "cannot create directory " + dir + ": " + (ec ? ec.message() : "not a directory");
        return false;
    }
    return true;
}

bool RunOutputs::Open(std::string* error, bool errorEstimateColumn) {
    if (!frameDir.empty() && !MakeDirectories(frameDir, error)) return false;
    if (!o.videoFile.empty()) {
        const double fps = 1.0 / o.frameTime.ToDouble();
        video.ExpectFrames(o.frames);
        if (!video.Open(o.videoFile, o.width, o.height, fps, error)) return false;
    }
    if (o.stateFile.empty()) return true;
    const std::string header = StateCsvHeader(errorEstimateColumn);
    return state.Open(o.stateFile, error) && state.Write(header.data(), header.size(), error);
}

EncodeQueue::Job RunOutputs::MakeFrameJob(int frame, Image image) {
    return [this, name = FrameName(frame), image = std::move(image)](std::string* error) {
        const Clock::time_point start = Clock::now();
        const double cpuStart = CpuSeconds(CLOCK_THREAD_CPUTIME_ID);
        std::vector<std::uint8_t> bytes;
        if (!EncodePng(image, png, &bytes, error)) return false;
        if (!frameDir.empty() && !WriteFileAtomic(JoinPath(frameDir, name), bytes, error)) return false;
        if (comparing && !CompareFrame(name, image, bytes, error)) return false;
        results.encodeSeconds += std::chrono::duration<double>(Clock::now() - start).count();
        results.encodeCpuSeconds += CpuSeconds(CLOCK_THREAD_CPUTIME_ID) - cpuStart;
        return true;
    };
}

EncodeQueue::Job RunOutputs::MakeVideoJob(std::shared_ptr<const Image> image) {
    return [this, image = std::move(image)](std::string* error) {
        const double cpuStart = CpuSeconds(CLOCK_THREAD_CPUTIME_ID);
        const bool ok = video.WriteFrame(*image, error);
        results.encodeCpuSeconds += CpuSeconds(CLOCK_THREAD_CPUTIME_ID) - cpuStart;
        if (!ok) *error = "--video " + o.videoFile + ": " + *error;
        return ok;
    };
}

namespace {

/// Reads the golden for actual. Checks the file (regular, size-limited) and the header's size against the
/// frame before decoding, so a hostile header never allocates. False with c->golden and c->problem set.
bool LoadGolden(const std::string& path, const Image& actual, Image* expected, FrameComparison* c) {
    std::vector<std::uint8_t> bytes;
    ReadFailure failure = ReadFailure::None;
    int width = 0, height = 0;
    if (!ReadRegularFile(path, kMaxPngFileBytes, &bytes, &failure, &c->problem)) {
        c->golden =
            failure == ReadFailure::Missing ? FrameComparison::Golden::Missing : FrameComparison::Golden::Unreadable;
        return false;
    }
    if (!ReadPngHeader(bytes, &width, &height, &c->problem)) {
        c->golden = FrameComparison::Golden::Unreadable;
        return false;
    }
    if (width != actual.width || height != actual.height) {
        c->golden = FrameComparison::Golden::SizeMismatch;
        c->problem = "golden is " + std::to_string(width) + "x" + std::to_string(height) + ", the frame " +
                     std::to_string(actual.width) + "x" + std::to_string(actual.height);
        return false;
    }
    if (!DecodePng(bytes, expected, &c->problem)) {
        c->golden = FrameComparison::Golden::Unreadable;
        return false;
    }
    return true;
}

/// DIR/renderer.txt's first line (what --update-golden recorded), or "unrecorded".
std::string GoldenRenderer(const std::string& dir) {
    std::vector<std::uint8_t> bytes;
    ReadFailure failure = ReadFailure::None;
    std::string problem;
    if (!ReadRegularFile(JoinPath(dir, "renderer.txt"), 4096, &bytes, &failure, &problem)) return "unrecorded";
    std::string text(bytes.begin(), bytes.end());
    text = text.substr(0, text.find('\n'));
    return text.empty() ? "unrecorded" : text;
}

std::string DescribeFrame(const FrameComparison& c, const CompareThresholds& thresholds) {
    switch (c.golden) {
        case FrameComparison::Golden::Missing:
            return "missing golden (FAIL)";
        case FrameComparison::Golden::Unreadable:
            return "unreadable golden: " + c.problem + " (FAIL)";
        case FrameComparison::Golden::SizeMismatch:
            return "size differs: " + c.problem + " (FAIL)";
        case FrameComparison::Golden::Compared:
            break;
    }
    return DescribeComparison(c.result, thresholds);
}

}  // namespace

bool RunOutputs::CompareFrame(const std::string& name, const Image& actual, const std::vector<std::uint8_t>& bytes,
                              std::string* error) {
    FrameComparison c;
    c.name = name;
    Image expected;
    if (LoadGolden(JoinPath(o.compareDir, name), actual, &expected, &c))
        c.result = CompareImages(expected, actual, o.thresholds);
    if (c.Failed() && !WriteEvidence(name, c, expected, actual, bytes, error)) return false;
    std::lock_guard<std::mutex> lock(results.mutex);
    results.comparisons.push_back(std::move(c));
    return true;
}

// Evidence for a mismatch: the actual frame, and when the golden decoded, it and a diff image.
bool RunOutputs::WriteEvidence(const std::string& name, const FrameComparison& c, const Image& expected,
                               const Image& actual, const std::vector<std::uint8_t>& bytes, std::string* error) {
    const std::string dir = JoinPath(o.outDir, "mismatch");
    if (!MakeDirectories(dir, error)) return false;
    const std::string stem = JoinPath(dir, name.substr(0, name.size() - 4));
    if (!WriteFileAtomic(stem + ".actual.png", bytes, error)) return false;
    if (c.golden != FrameComparison::Golden::Compared) return true;
    std::vector<std::uint8_t> other;
    return EncodePng(expected, png, &other, error) && WriteFileAtomic(stem + ".expected.png", other, error) &&
           EncodePng(MakeDiffImage(expected, actual, o.thresholds), png, &other, error) &&
           WriteFileAtomic(stem + ".diff.png", other, error) &&
           EncodePng(MakeAmplifiedDiff(expected, actual, kAmplifiedDiffGain), png, &other, error) &&
           WriteFileAtomic(stem + ".amplified.png", other, error);
}

int RunOutputs::Finish(int code) {
    std::string error;
    if (!queue.Finish(&error)) {
        std::fprintf(stderr, "physics-sandbox: %s\n", error.c_str());
        code = kExitFailure;
    }
    // The video first: it is checked as it finishes (Platform/VideoFileCheck.h), and a failed run keeps no CSV.
    if (video.IsOpen() && code == kExitOk && !video.Finish(&error)) {
        std::fprintf(stderr, "physics-sandbox: --video %s: %s\n", o.videoFile.c_str(), error.c_str());
        code = kExitFailure;
    }
    if (state.IsOpen() && code == kExitOk && !state.Commit(&error)) {
        std::fprintf(stderr, "physics-sandbox: %s\n", error.c_str());
        code = kExitFailure;
    }
    const std::string line = renderer + "\n";
    if (o.updateGolden && code == kExitOk && !renderer.empty() &&
        !WriteFileAtomic(JoinPath(frameDir, "renderer.txt"), std::vector<std::uint8_t>(line.begin(), line.end()),
                         &error)) {
        std::fprintf(stderr, "physics-sandbox: %s\n", error.c_str());
        code = kExitFailure;
    }
    if (code != kExitOk) state.Abandon(), video.Abort();
    keepDirectories = code == kExitOk;
    return code;
}

int RunOutputs::ReportComparisons(int code) {
    if (!comparing) return code;
    // Per-frame metric summary, in frame order, on stderr and in OUT/compare.txt.
    std::string lines;
    int failures = 0;
    for (const FrameComparison& c : results.comparisons) {
        lines += c.name + ": " + DescribeFrame(c, o.thresholds) + "\n";
        if (c.Failed()) ++failures;
    }
    char counts[256];
    char minSsim[48] = "";
    if (o.thresholds.minSsim >= 0.0) std::snprintf(minSsim, sizeof minSsim, ", min SSIM %g", o.thresholds.minSsim);
    std::snprintf(counts, sizeof counts,
                  ": %d frame(s), %d mismatch(es); tolerance %d, max fraction %g%s; SSIM of luminance, 8x8 windows\n",
                  int(results.comparisons.size()), failures, o.thresholds.channelTolerance,
                  o.thresholds.maxDifferingFraction, minSsim);
    const std::string report = "compare with " + o.compareDir + counts + "renderer: " + renderer +
                               "\ngolden renderer: " + GoldenRenderer(o.compareDir) + "\n" + lines;
    std::string error;
    if (!WriteFileAtomic(JoinPath(o.outDir, "compare.txt"), std::vector<std::uint8_t>(report.begin(), report.end()),
                         &error)) {
        std::fprintf(stderr, "physics-sandbox: %s\n", error.c_str());
        return kExitFailure;
    }
    if (!o.quiet || failures) std::fputs(report.c_str(), stderr);
    if (failures == 0) return code;
    std::fprintf(stderr, "physics-sandbox: %d frame(s) differ from %s; see %s/mismatch/\n", failures,
                 o.compareDir.c_str(), o.outDir.c_str());
    return kExitMismatch;
}
