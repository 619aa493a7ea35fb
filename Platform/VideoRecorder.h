#pragma once
// The recorders behind VideoEncoder (docs/app.md, "Video"): one per format, each feeding ffmpeg processes
// (FfmpegChild, Platform/FfmpegProcess.h) and leaving a complete file at the recording's temporary path when it
// finishes. VideoEncoder owns the target, its temporaries and the checks every format shares.

#include <string>

#include "Platform/Image.h"

/// The recording a recorder writes: the result's path, the temporary it writes instead (renamed into place by
/// VideoEncoder), ffmpeg's log, and the frames' geometry and rate.
struct VideoTarget {
    std::string path, tempPath, logPath;
    int width = 0, height = 0;
    double fps = 60.0;
    double stallSeconds = 60.0;  ///< EncoderStallSeconds() at Open: the bound on every wait
};

class VideoRecorder {
public:
    VideoRecorder() = default;
    VideoRecorder(const VideoRecorder&) = delete;
    VideoRecorder& operator=(const VideoRecorder&) = delete;
    virtual ~VideoRecorder() = default;

    /// Starts recording into the target (its temporaries exist). False with *error.
    virtual bool Start(std::string* error) = 0;
    /// Records input frame number `index` (of the target's size, checked by VideoEncoder). False with *error.
    virtual bool Record(const Image& frame, int index, std::string* error) = 0;
    /// Completes the target's temporary from the `frames` frames recorded. False with *error (VideoEncoder then
    /// aborts).
    virtual bool Finish(int frames, std::string* error) = 0;
    /// Stops every ffmpeg it started and removes the temporaries of its own. Safe at any time.
    virtual void Abort() = 0;
};
