#pragma once
// Records frames as a video through the ffmpeg program (Debian's `ffmpeg`), which encodes in processes of its
// own while the caller renders the next frames.
// - .mp4 is H.264 (libx264 ultrafast), .webm VP9 (libvpx-vp9 realtime, one thread): frames go down a pipe to one
//   ffmpeg, converted here to yuv420p (Platform/Yuv420.h; ffmpeg's own conversion cost as much as encoding).
// - .gif is made in parts of up to 100 frames, each with a palette generated from its own frames: while a part
//   has at most 256 colours, exactly its colours, each pixel stored as its index (raw pal8, which ffmpeg only
//   encodes); past 256, palettegen and paletteuse (no dithering, so the demos' flat colours stay exact) over
//   its frames as BGRA. Each part's ffmpeg starts with the part and works while the next part renders; the
//   parts are joined at Finish (Platform/GifJoin.h).
// The file appears only when the recording is complete: ffmpeg writes a temporary file beside it, checked
// (Platform/VideoFileCheck.h) and renamed at Finish; every wait on ffmpeg is bounded (Platform/FfmpegProcess.h); Abort
// (or the destructor) removes it, and so does SIGINT/SIGTERM (Platform/Files/TempRegistry.h), after killing ffmpeg.
// docs/app.md, "Video".

#include <sys/types.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "Platform/GifPalette.h"
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
    /// Sends one frame (width x height as opened). False and *error if the frame has another size or ffmpeg has
    /// gone away; the recording cannot be finished then (Finish refuses it, and every later frame fails).
    bool WriteFrame(const Image& frame, std::string* error);
    /// Ends the stream, waits for ffmpeg and renames the result into place. False, with ffmpeg's last
    /// message, if it failed; nothing is left behind then.
    bool Finish(std::string* error);
    /// Stops ffmpeg if it runs and removes every temporary file. Safe to call at any time.
    void Abort();
    bool IsOpen() const { return !tempPath.empty(); }
    int FramesWritten() const { return frames; }
    /// GIF: frames per part (each part has its own palette); set before Open, for tests. 0: by frame size.
    void SetGifPartFrames(int n) { gifPartFrames = n; }
    /// The number of frames the caller will send, when it knows (set before Open; 0: unknown). A GIF's last parts
    /// are then made short, so the run waits less for their mapping at the end.
    void ExpectFrames(int n) { expectedFrames = n; }
    /// GIF: the sizes of the parts of a recording of `frames` GIF frames (after resampling) with parts of at most
    /// partFrames: shrinking towards the end (8, 19, 44 from the end), the first part taking what is left.
    static std::vector<int> PlanGifParts(int frames, int partFrames);

private:
    bool RecordFrame(const Image& frame, std::string* error);
    bool Spawn(const std::vector<std::string>& args, bool pipeIn, std::string* error);
    /// Waits for `child` (bounded: Platform/FfmpegProcess.h, output growing is progress); false with *error if it
    /// failed, stalled or logged an error.
    bool Wait(const std::string& output, std::string* error);
    /// GIF: records one frame (after resampling) into the current part, ending the part when it is full.
    bool WriteGifFrame(const Image& frame, std::string* error);
    /// GIF: rewrites the current part's frames so far, stored as indices, as BGRA (the part has met its 257th
    /// colour).
    bool ExpandGifPartToBgra(std::string* error);
    /// GIF: opens the next raw file for a new part (waiting for the part that read it last) and starts the
    /// part's ffmpeg, which waits for the palette.
    bool BeginGifPart(std::string* error);
    /// GIF: closes the current part's frames and sends its palette to its ffmpeg, which maps them in the
    /// background (a part of more than 256 colours gets an ffmpeg that generates its palette instead).
    bool EndGifPart(std::string* error);
    /// GIF: ffmpeg's input arguments for a raw file of this recording's frames in pixelFormat (pal8 or bgra).
    std::vector<std::string> GifRawInput(const std::string& raw, const char* pixelFormat) const;
    /// GIF: ffmpeg's output arguments for a part's GIF.
    std::vector<std::string> GifOutput(const std::string& gif) const;
    /// GIF: waits for part k's ffmpeg if it still runs.
    bool WaitGifPart(std::size_t k, std::string* error);
    /// GIF: ends the last part, waits for every part and joins them into tempPath.
    bool JoinGifParts(std::string* error);
    /// GIF: whether input frame i is recorded (all of them up to 50 fps; above, those nearest 1/50 s steps).
    bool KeepGifFrame(int i) const;
    /// GIF: the recorded frame rate, fps up to 50 (GIF delays are whole hundredths of a second).
    double GifFramesPerSecond() const;
    /// GIF: frames per part by default for this frame size (at most 192 MiB of raw frames and 100 frames, at least
    /// 10).
    static int DefaultGifPartFrames(int width, int height);
    void Cleanup();

    Format format = Format::Mp4;
    struct TempFile {
        std::string path;  // a temporary beside the target
        int id = -1;       // its TempRegistry slot
    };
    /// A part of a GIF: the GIF its ffmpeg maps the part's frames into.
    struct GifPart {
        TempFile gif;
        int rawIndex = -1;                   // the raw file its frames are in (gifRaw), until its ffmpeg has finished
        pid_t pid = -1;                      // its ffmpeg, until waited for
        std::vector<std::uint8_t> bytes;     // the part's GIF, read once its ffmpeg has finished
        int startFd = -1;                    // the pipe its ffmpeg waits on before reading the part, until it ends
        int epoch = -1;                      // its run of shared colours (-1: more than 256, palettegen's)
        std::vector<std::uint32_t> colours;  // the run's colours as the part ended (0xRRGGBB, by index)
    };

    std::string path, tempPath, logPath;
    int tempId = -1, logId = -1;  // TempRegistry slots of the temporaries
    std::vector<GifPart> gifParts;
    TempFile gifRaw[3];                    // GIF: the parts' raw frames, in turn
    int gifRawIndex = -1, gifRawFd = -1;   // GIF: the current part's raw file, open while its frames arrive
    int gifPartFrames = 0;                 // GIF: frames per part as set (0: by frame size)
    int gifPartSize = 0;                   // GIF: frames per part of this recording
    int expectedFrames = 0;                // frames the caller said it will send (0: unknown)
    std::vector<int> gifPlan;              // GIF: part sizes planned from expectedFrames (then gifPartSize)
    int gifPartFrameCount = 0;             // GIF: frames in the current part so far
    std::vector<std::uint8_t> yuv;         // MP4, WebM: a frame as sent to ffmpeg
    Image gifPrevious;                     // GIF: the last frame recorded (to find the pixels that changed)
    std::vector<std::uint8_t> gifBgra;     // GIF: a frame as stored in the raw file
    GifPalette gifPalette;                 // GIF: the current run's colours (Platform/GifPalette.h)
    std::vector<std::uint8_t> gifIndices;  // GIF: a frame's indices into the part's colours
    bool gifColoursOverflow = false;       // GIF: more than 256 colours in the current part
    int width = 0, height = 0, frames = 0;
    double fps = 60.0;
    pid_t child = -1;
    double stallSeconds = 60.0;  // EncoderStallSeconds() at Open
    int pipeFd = -1;
    bool failed = false;  // a frame could not be recorded: Finish refuses
};
