#pragma once
// Records frames as a video through the ffmpeg program (Debian's `ffmpeg`), which encodes in processes of its
// own while the caller renders the next frames. One recorder per format (Platform/VideoRecorder.h):
// - .mp4 (H.264) and .webm (VP9): Platform/StreamRecorder.h, one ffmpeg fed yuv420p frames down a pipe;
// - .gif: Platform/GifRecorder.h, parts with palettes of their own (Platform/GifPalette.h) joined at Finish.
// This class owns what they share: the format check, the temporaries, the frame checks and the rename.
// The file appears only when the recording is complete: ffmpeg writes a temporary file beside it, checked
// (Platform/VideoFileCheck.h) and renamed at Finish; every wait on ffmpeg is bounded (Platform/FfmpegProcess.h); Abort
// (or the destructor) removes it, and so does SIGINT/SIGTERM (Platform/Files/TempRegistry.h), after killing ffmpeg.
// docs/app.md, "Video".

#include <memory>
#include <string>
#include <vector>

#include "Platform/Image.h"
#include "Platform/VideoRecorder.h"

class VideoEncoder {
public:
    enum class Format { Mp4, Webm, Gif };

    /// The format named by the file's extension (.mp4, .webm, .gif, any case); false for anything else.
    static bool FormatOf(const std::string& path, Format* format);
    /// True if an `ffmpeg` executable is on PATH; else false and *error names the Debian package.
    static bool FfmpegAvailable(std::string* error);

    VideoEncoder() = default;
    ~VideoEncoder() { Abort(); }
    VideoEncoder(const VideoEncoder&) = delete;
    VideoEncoder& operator=(const VideoEncoder&) = delete;

    /// Starts recording width x height frames at fps frames per second into path (its directory must exist).
    /// MP4 and WebM frames of odd width or height are padded by one black row or column (yuv420p needs even
    /// sizes); GIF frames are resampled to 50 fps when fps is higher (GIF delays are whole 1/100 s).
    bool Open(const std::string& path, int width, int height, double fps, std::string* error);
    /// Sends one frame (width x height as opened). False and *error if the frame has another size or ffmpeg has
    /// gone away; the recording cannot be finished then (Finish refuses it, and every later frame fails).
    bool WriteFrame(const Image& frame, std::string* error);
    /// Ends the stream, waits for ffmpeg and renames the result into place. False, with ffmpeg's last
    /// message, if it failed; nothing is left behind then.
    bool Finish(std::string* error);
    /// Stops ffmpeg if it runs and removes every temporary file. Safe to call at any time.
    void Abort();
    bool IsOpen() const { return !target.tempPath.empty(); }
    int FramesWritten() const { return frames; }
    /// GIF: frames per part (each part has its own palette); set before Open, for tests. 0: by frame size.
    void SetGifPartFrames(int n) { gifPartFrames = n; }
    /// The number of frames the caller will send, when it knows (set before Open; 0: unknown). A GIF's last parts
    /// are then made short, so the run waits less for their mapping at the end.
    void ExpectFrames(int n) { expectedFrames = n; }
    /// GIF: the sizes of the parts of a recording of `frames` GIF frames (GifRecorder::PlanParts).
    static std::vector<int> PlanGifParts(int frames, int partFrames);

private:
    bool RecordFrame(const Image& frame, std::string* error);
    void Cleanup();

    Format format = Format::Mp4;
    VideoTarget target;
    std::unique_ptr<VideoRecorder> recorder;
    int tempId = -1, logId = -1;  // TempRegistry slots of the temporaries
    int gifPartFrames = 0;        // GIF: frames per part as set (0: by frame size)
    int expectedFrames = 0;       // frames the caller said it will send (0: unknown)
    int frames = 0;
    bool failed = false;  // a frame could not be recorded: Finish refuses
};
