#pragma once
// GIF recordings (docs/app.md, "Video"), made in parts of up to 100 frames, each with a palette from its own frames:
// while a part has at most 256 colours, exactly its colours (Platform/GifPalette.h), each pixel stored as its index
// (raw pal8, which ffmpeg only encodes); past 256, palettegen and paletteuse (no dithering, so the demos' flat
// colours stay exact) over its frames as BGRA. Each part's ffmpeg starts with the part and works while the next part
// renders; the parts are joined at Finish (Platform/GifJoin.h). Frames above 50 fps are resampled to 50 (GIF delays
// are whole hundredths of a second).

#include <sys/types.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "Platform/FfmpegProcess.h"
#include "Platform/GifPalette.h"
#include "Platform/VideoRecorder.h"

class GifRecorder final : public VideoRecorder {
public:
    /// partFrames: frames per part (0: by frame size); expectedFrames: the input frames the caller will send (0:
    /// unknown), so the last parts are made short and the run waits less for their mapping at the end.
    GifRecorder(const VideoTarget& target, int partFrames, int expectedFrames)
        : t(target), partFramesSet(partFrames), expectedFrames(expectedFrames) {}
    ~GifRecorder() override { Abort(); }

    bool Start(std::string* error) override;
    /// Records the frame (when kept by the resampling) into the current part, ending the part when it is full.
    bool Record(const Image& frame, int index, std::string* error) override;
    /// Ends the last part, waits for every part and joins them into the target's temporary.
    bool Finish(int frames, std::string* error) override;
    void Abort() override;

    /// The sizes of the parts of a recording of `frames` GIF frames (after resampling) with parts of at most
    /// partFrames: shrinking towards the end (8, 19, 44 from the end), the first part taking what is left.
    static std::vector<int> PlanParts(int frames, int partFrames);

private:
    struct TempFile {
        std::string path;  // a temporary beside the target
        int id = -1;       // its TempRegistry slot
    };
    /// A part of the GIF: the GIF its ffmpeg maps the part's frames into.
    struct Part {
        TempFile gif;
        int rawIndex = -1;                   // the raw file its frames are in (raw), until its ffmpeg has finished
        pid_t pid = -1;                      // its ffmpeg, until waited for
        std::vector<std::uint8_t> bytes;     // the part's GIF, read once its ffmpeg has finished
        int startFd = -1;                    // the pipe its ffmpeg waits on before reading the part, until it ends
        int run = -1;                        // its run of shared colours (-1: more than 256, palettegen's)
        std::vector<std::uint32_t> colours;  // the run's colours as the part ended (0xRRGGBB, by index)
    };

    /// Rewrites the current part's frames so far, stored as indices, as BGRA (the part has met its 257th colour).
    bool ExpandPartToBgra(std::string* error);
    /// Opens the next raw file for a new part (waiting for the part that read it last) and starts the part's
    /// ffmpeg, which waits for the palette.
    bool BeginPart(std::string* error);
    /// Closes the current part's frames and sends its palette to its ffmpeg, which maps them in the background (a
    /// part of more than 256 colours gets an ffmpeg that generates its palette instead).
    bool EndPart(std::string* error);
    /// ffmpeg's input arguments for a raw file of this recording's frames in pixelFormat (pal8 or bgra).
    std::vector<std::string> RawInput(const std::string& raw, const char* pixelFormat) const;
    /// ffmpeg's output arguments for a part's GIF.
    std::vector<std::string> Output(const std::string& gif) const;
    /// Waits for part k's ffmpeg if it still runs.
    bool WaitPart(std::size_t k, std::string* error);
    /// Whether input frame i is recorded (all of them up to 50 fps; above, those nearest 1/50 s steps).
    bool KeepFrame(int i) const;
    /// The recorded frame rate, fps up to 50.
    double FramesPerSecond() const;
    /// Frames per part by default for this frame size (at most 192 MiB of raw frames and 100 frames, at least 10).
    static int DefaultPartFrames(int width, int height);

    const VideoTarget& t;
    int partFramesSet;
    int expectedFrames;
    FfmpegChild ffmpeg;  // the ffmpeg being started or waited for
    std::vector<Part> parts;
    TempFile rawFiles[3];               // the parts' raw frames, in turn
    int rawIndex = -1, rawFd = -1;      // the current part's raw file, open while its frames arrive
    int partSize = 0;                   // frames per part of this recording
    std::vector<int> plan;              // part sizes planned from expectedFrames (then partSize)
    int partFrameCount = 0;             // frames in the current part so far
    Image previous;                     // the last frame recorded (to find the pixels that changed)
    std::vector<std::uint8_t> bgra;     // a frame as stored in the raw file
    GifPalette palette;                 // the current run's colours
    std::vector<std::uint8_t> indices;  // a frame's indices into the palette
    bool overflow = false;              // more than 256 colours in the current part
};
