#pragma once
// Records frames as a video through the ffmpeg program (Debian's `ffmpeg`): frames go as raw RGB down a
// pipe to an ffmpeg process, which encodes on its own core while the caller renders the next frames.
// .mp4 is H.264 (libx264 ultrafast), .webm is VP9 (libvpx-vp9 realtime), .gif uses a palette generated from
// all the frames (palettegen, then paletteuse without dithering, so the demos' flat colours stay exact): a
// second pass after the run, so a GIF costs more than the other two (bench/video_bench.sh).
// The file appears only when the recording is complete: ffmpeg writes a temporary file beside it, renamed at
// Finish; Abort (or the destructor) removes it, and so does SIGINT/SIGTERM (Platform/Files/TempRegistry.h),
// after killing ffmpeg. docs/app.md, "Video".

#include <sys/types.h>

#include <string>
#include <vector>

#include "Platform/Image.h"

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
    /// Sends one frame (width x height as opened). False and *error if ffmpeg has gone away.
    bool WriteFrame(const Image& frame, std::string* error);
    /// Ends the stream, waits for ffmpeg and renames the result into place. False, with ffmpeg's last
    /// message, if it failed; nothing is left behind then.
    bool Finish(std::string* error);
    /// Stops ffmpeg if it runs and removes every temporary file. Safe to call at any time.
    void Abort();
    bool IsOpen() const { return child > 0 || !rawPath.empty(); }
    int FramesWritten() const { return frames; }

private:
    bool Spawn(const std::vector<std::string>& args, bool pipeIn, std::string* error);
    bool Wait(std::string* error);
    /// GIF: closes palettegen's pipe, waits for the palette, then maps the raw frames with paletteuse.
    bool EncodeGif(std::string* error);
    /// ffmpeg arguments reading this recording's raw RGB frames from `source` (a file or pipe:0).
    std::vector<std::string> GifInput(const std::string& source) const;
    /// "fps=50," above 50 fps (GIF delays are hundredths of a second), else "".
    std::string GifResample() const;
    void Cleanup();

    Format format = Format::Mp4;
    std::string path, tempPath, rawPath, palettePath, logPath;
    int tempId = -1, rawId = -1, paletteId = -1, logId = -1;  // TempRegistry slots of the temporaries
    int width = 0, height = 0, frames = 0;
    double fps = 60.0;
    pid_t child = -1;
    int pipeFd = -1;
    int rawFd = -1;
};
