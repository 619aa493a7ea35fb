#pragma once
// What a physics-sandbox run writes (docs/app.md, "Files"): the frame directory, the --state CSV, the golden
// comparison and its evidence. Argument checks come first (exit 2, nothing written); afterwards every file is
// written whole through a unique temporary, and a failed run removes its temporaries and the directories it
// created while they are still empty.

#include <time.h>

#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "Application/CommandLine.h"
#include "Platform/EncodeQueue.h"
#include "Platform/Files/AtomicFile.h"
#include "Platform/ImageCompare.h"
#include "Platform/PngCodec.h"
#include "Platform/VideoEncoder.h"

/// CPU seconds of a clock (CLOCK_THREAD_CPUTIME_ID, CLOCK_PROCESS_CPUTIME_ID).
double CpuSeconds(clockid_t which);

/// The checks of --out, --compare and --state that need the file system, before anything is written: --compare
/// must be a directory (a symlink loop or an over-long name is reported, not thrown), must not be --out itself
/// (also through a symlink or ".."), and --state must be writable as a regular file and must not be a frame
/// or golden path. Returns kExitOk or kExitUsage (message printed).
/// --video must name an .mp4, .webm or .gif in an existing directory, with the ffmpeg program installed.
int CheckOutputArguments(const Options& o);

/// --backend names a back end this build has, when the run draws (o.draws); a build without any (PSB_WITH_RENDERING
/// =OFF) refuses every run that draws. Returns kExitOk or kExitUsage (message printed).
int CheckBackend(const Options& o);

/// One frame's golden comparison, filled in by the encode thread.
struct FrameComparison {
    enum class Golden { Compared, Missing, Unreadable, SizeMismatch };
    std::string name;
    Golden golden = Golden::Compared;
    std::string problem;  ///< what is wrong with the golden (Unreadable, SizeMismatch)
    CompareResult result;
    bool Failed() const { return golden != Golden::Compared || !result.passed; }
};

class RunOutputs {
public:
    explicit RunOutputs(const Options& options);
    /// Waits for the queued jobs; on a failed run removes the temporaries and the still-empty created directories.
    ~RunOutputs();
    RunOutputs(const RunOutputs&) = delete;
    RunOutputs& operator=(const RunOutputs&) = delete;

    /// Creates the frame directory and opens the --state temporary with its header (with the error_estimate
    /// column of an auto model when errorEstimateColumn). False with *error.
    bool Open(std::string* error, bool errorEstimateColumn = false);
    /// Frames are read back when they are written, compared or recorded.
    bool WantsPixels() const { return !frameDir.empty() || comparing || Recording(); }
    /// PNG frames (written or compared) are wanted: --out or --compare.
    bool WantsFrames() const { return !frameDir.empty() || comparing; }
    /// --video: every frame goes to the video, --only-frames or not.
    bool Recording() const { return !o.videoFile.empty(); }
    /// The encode-write-compare job of one frame; it depends only on the image and this object.
    EncodeQueue::Job MakeFrameJob(int frame, Image image);
    /// Sends one frame to ffmpeg (in frame order: the queue runs jobs in order).
    EncodeQueue::Job MakeVideoJob(std::shared_ptr<const Image> image);
    /// Ends the run: waits for the jobs, then commits --state on success or abandons it. Returns code, or
    /// kExitFailure when a job or the commit failed (message printed).
    int Finish(int code);
    /// With --compare: the per-frame summary on stderr and in OUT/compare.txt (after the header, the renderer of
    /// each side: "renderer: ..." and "golden renderer: ..." from DIR/renderer.txt, "unrecorded" without one);
    /// kExitMismatch on a difference.
    int ReportComparisons(int code);
    const std::string& FrameDir() const { return frameDir; }

    /// Written by the encode thread; read after Finish.
    struct JobResults {
        std::mutex mutex;
        std::vector<FrameComparison> comparisons;
        double encodeSeconds = 0.0;
        double encodeCpuSeconds = 0.0;
    };

    /// The GL strings of the run's context (RunStats::glStrings): written to the golden directory's renderer.txt
    /// by --update-golden, and beside the golden's own renderer.txt into compare.txt.
    std::string renderer;
    AtomicFile state;
    VideoEncoder video;  ///< open while --video records; the file appears at Finish on success
    JobResults results;

private:
    bool CompareFrame(const std::string& name, const Image& actual, const std::vector<std::uint8_t>& bytes,
                      std::string* error);
    bool WriteEvidence(const std::string& name, const FrameComparison& c, const Image& expected, const Image& actual,
                       const std::vector<std::uint8_t>& bytes, std::string* error);
    bool MakeDirectories(const std::string& dir, std::string* error);

    const Options& o;
    const std::string frameDir;
    const bool comparing;
    PngOptions png;
    std::vector<std::string> createdDirs;  ///< outermost first
    std::mutex dirsMutex;
    bool keepDirectories = false;

public:
    EncodeQueue queue;  ///< last: destroyed first, so no job outlives what it uses
};
