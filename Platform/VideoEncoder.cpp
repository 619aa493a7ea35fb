#include "Platform/VideoEncoder.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <sstream>

#include "Platform/FfmpegProcess.h"
#include "Platform/Files/AtomicFile.h"
#include "Platform/Files/TempRegistry.h"
#include "Platform/GifJoin.h"
#include "Platform/GifPalette.h"
#include "Platform/PngCodec.h"
#include "Platform/VideoFileCheck.h"
#include "Platform/Yuv420.h"

namespace {

std::string Lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

std::string Number(double v) {
    std::ostringstream out;
    out.precision(10);
    out << v;
    return out.str();
}

bool WriteAll(int fd, const std::uint8_t* data, std::size_t size, std::string* error, const char* what) {
    while (size > 0) {
        const ssize_t n = write(fd, data, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            *error = std::string("writing to ") + what + " failed: " + std::strerror(errno);
            return false;
        }
        data += n;
        size -= std::size_t(n);
    }
    return true;
}

/// Writes bytes into the file at path (an existing temporary), replacing its contents.
bool WriteWhole(const std::string& path, const std::vector<std::uint8_t>& bytes, std::string* error) {
    const int fd = open(path.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
    if (fd < 0) {
        *error = "cannot open " + path + ": " + std::strerror(errno);
        return false;
    }
    const bool ok = WriteAll(fd, bytes.data(), bytes.size(), error, path.c_str());
    if (close(fd) != 0 && ok) {
        *error = "writing " + path + " failed: " + std::strerror(errno);
        return false;
    }
    return ok;
}

}  // namespace

bool VideoEncoder::FormatOf(const std::string& path, Format* out) {
    const std::size_t dot = path.rfind('.');
    if (dot == std::string::npos || path.find('/', dot) != std::string::npos) return false;
    const std::string ext = Lower(path.substr(dot));
    if (ext == ".mp4")
        *out = Format::Mp4;
    else if (ext == ".webm")
        *out = Format::Webm;
    else if (ext == ".gif")
        *out = Format::Gif;
    else
        return false;
    return true;
}

bool VideoEncoder::FfmpegAvailable(std::string* error) {
    if (ProgramOnPath("ffmpeg")) return true;
    *error = "--video needs the ffmpeg program, which is not on PATH (Debian package 'ffmpeg')";
    return false;
}

bool VideoEncoder::Open(const std::string& target, int w, int h, double framesPerSecond, std::string* error) {
    Abort();
    if (!FormatOf(target, &format)) {
        *error = "video file '" + target + "' must end in .mp4, .webm or .gif";
        return false;
    }
    if (w < 1 || h < 1 || !(framesPerSecond > 0.0)) {
        *error = "bad video size or frame rate";
        return false;
    }
    if (!FfmpegAvailable(error)) return false;
    signal(SIGPIPE, SIG_IGN);  // a dead ffmpeg must be an error from write(), not the end of this process
    stallSeconds = EncoderStallSeconds();
    path = target;
    width = w;
    height = h;
    fps = framesPerSecond;
    frames = 0;
    // Temporaries beside the target, removed by Cleanup and, on SIGINT/SIGTERM, by the signal handler (which
    // first kills ffmpeg, so it cannot write them again).
    tempPath = CreateTemporaryBeside(path, &tempId, error);
    if (tempPath.empty()) return false;
    logPath = CreateTemporaryBeside(path, &logId, error);
    if (logPath.empty()) return Cleanup(), false;
    if (format == Format::Gif) {
        // A palette generated from all the frames could only be applied after the run. Instead the GIF is made
        // in parts of up to gifPartSize frames, each with a palette generated from its own frames and encoded by
        // its own ffmpeg while the next part renders; JoinGifs puts the parts together at Finish.
        gifPartSize = gifPartFrames > 0 ? gifPartFrames : DefaultGifPartFrames(width, height);
        int kept = 0;
        for (int i = 0; i < expectedFrames; ++i) kept += KeepGifFrame(i) ? 1 : 0;
        gifPlan = PlanGifParts(kept, gifPartSize);
        return true;
    }
    std::vector<std::string> args = {"ffmpeg", "-hide_banner", "-loglevel", "error", "-y", "-f", "rawvideo",
                                     // Frames arrive as yuv420p, converted by WriteFrame (Platform/Yuv420.h).
                                     "-pix_fmt", "yuv420p", "-video_size",
                                     std::to_string(EvenSide(w)) + "x" + std::to_string(EvenSide(h)), "-framerate",
                                     Number(fps), "-i", "pipe:0"};
    // Tagged as what Yuv420 makes, BT.601 in the limited range: untagged, players take frames of HD sizes for
    // BT.709.
    for (const char* a :
         {"-colorspace", "smpte170m", "-color_primaries", "smpte170m", "-color_trc", "smpte170m", "-color_range", "tv"})
        args.push_back(a);
    if (format == Format::Mp4) {
        for (const char* a : {"-c:v", "libx264", "-preset", "ultrafast", "-crf", "18", "-pix_fmt", "yuv420p",
                              "-movflags", "+faststart", "-f", "mp4"})
            args.push_back(a);
    } else {
        for (const char* a : {"-c:v", "libvpx-vp9", "-deadline", "realtime", "-cpu-used", "8", "-threads", "1", "-b:v",
                              "0", "-crf", "30", "-pix_fmt", "yuv420p", "-f", "webm"})
            args.push_back(a);
    }
    args.push_back(tempPath);
    if (!Spawn(args, true, error)) return Cleanup(), false;
    return true;
}

bool VideoEncoder::Spawn(const std::vector<std::string>& args, bool pipeIn, std::string* error) {
    return StartChild(args, pipeIn, logPath, &child, &pipeFd, error);
}

bool VideoEncoder::Wait(const std::string& output, std::string* error) {
    if (child <= 0) {  // never waitpid(-1): it would reap another part's ffmpeg
        *error = "ffmpeg is not running";
        return false;
    }
    const pid_t pid = child;
    child = -1;
    return WaitForFfmpeg(pid, stallSeconds, output, logPath, error);
}

bool VideoEncoder::WriteFrame(const Image& frame, std::string* error) {
    // After a failed frame the recording cannot be completed (Finish refuses it); every later frame fails too.
    if (failed) {
        *error = "video recording failed at an earlier frame";
        return false;
    }
    failed = !RecordFrame(frame, error);
    return !failed;
}

bool VideoEncoder::RecordFrame(const Image& frame, std::string* error) {
    if (frame.width != width || frame.height != height) {
        *error = "video frame is " + std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                 ", the recording " + std::to_string(width) + "x" + std::to_string(height);
        return false;
    }
    if (!IsOpen()) {
        *error = "video recording is not open";
        return false;
    }
    if (format == Format::Gif) return WriteGifFrame(frame, error);
    if (pipeFd < 0) {
        *error = "video recording is not open";
        return false;
    }
    RgbToYuv420(frame, &yuv);
    bool stalled = false;
    if (!WriteToChild(pipeFd, yuv.data(), yuv.size(), stallSeconds, &stalled, error)) {
        close(pipeFd);
        pipeFd = -1;
        if (stalled) {  // ffmpeg stopped reading: stopped here
            KillChild(child);
            child = -1;
            *error = "ffmpeg failed: " + *error;
            return false;
        }
        // ffmpeg went away: its own message says why, if it gave one.
        if (Wait(tempPath, error)) *error = "ffmpeg ended before it read frame " + std::to_string(frames);
        return false;
    }
    ++frames;
    return true;
}

int VideoEncoder::DefaultGifPartFrames(int w, int h) {
    // A part's frames wait in a raw file until the part is complete (1 byte a pixel, 4 once it has more than 256
    // colours), and the run waits for the last part: at most 100 frames (2 s at GIF's 50 fps; 70 to 150 measured
    // alike at 800x600) and 192 MiB as BGRA, at least 10.
    const long long bytes = 4LL * w * h;
    return int(std::clamp<long long>((192LL << 20) / bytes, 10, 100));
}

std::vector<int> VideoEncoder::PlanGifParts(int frames, int partFrames) {
    // The run waits at its end for the last part's mapping, and for the one before it if that is still mapping:
    // so the last parts shrink. Mapping a frame (about 3 ms at 800x600) takes a little less than rendering one,
    // so a part may be 2.3 times the next and still be mapped before the next ends: from the end 8, 19, 44 and
    // then whole parts; the first part takes what is left.
    std::vector<int> plan;
    partFrames = std::max(1, partFrames);
    int planned = 0;
    for (int size = std::min(8, partFrames); planned < frames;
         size = std::min(partFrames, int(std::ceil(size * 2.3)))) {
        const int n = std::min(size, frames - planned);
        plan.push_back(n);
        planned += n;
    }
    std::reverse(plan.begin(), plan.end());
    return plan;
}

double VideoEncoder::GifFramesPerSecond() const { return std::min(fps, 50.0); }

bool VideoEncoder::KeepGifFrame(int i) const {
    // GIF delays are whole hundredths of a second: above 50 fps, frames are resampled to 50. Output frame j
    // shows the input frame nearest its time j / 50 (as ffmpeg's fps filter does): frame i is kept when an
    // output time falls in [(i - 1/2) / fps, (i + 1/2) / fps).
    if (fps <= 50.0) return true;
    const double ratio = 50.0 / fps;
    return std::ceil((i + 0.5) * ratio) > std::ceil((i - 0.5) * ratio);
}

bool VideoEncoder::WriteGifFrame(const Image& frame, std::string* error) {
    if (!KeepGifFrame(frames)) return ++frames, true;
    if (gifPartFrameCount > 0) {  // the current part is the last started; full by the plan, else by the size
        const std::size_t part = gifParts.size() - 1;
        const int size = part < gifPlan.size() ? gifPlan[part] : gifPartSize;
        if (gifPartFrameCount >= size && !EndGifPart(error)) return false;
    }
    if (gifPartFrameCount == 0 && !BeginGifPart(error)) return false;
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    const std::string& raw = gifRaw[gifRawIndex].path;
    if (!gifColoursOverflow) {
        // Indices into the part's colours, in the order it meets them: every pixel of its first frame, then only
        // those that changed (the demos change a fraction of a percent of their pixels a frame); the others keep
        // their index. The frame is stored as ffmpeg's raw pal8: the indices, then 256 palette entries of 4 bytes,
        // written when the part ends.
        gifIndices.resize(pixels);
        const std::uint8_t* p = frame.rgb.data();
        const std::uint8_t* q = gifPartFrameCount > 0 ? gifPrevious.rgb.data() : nullptr;
        for (std::size_t i = 0; i < pixels && !gifColoursOverflow; ++i, p += 3) {
            if (q && p[0] == q[3 * i] && p[1] == q[3 * i + 1] && p[2] == q[3 * i + 2]) continue;
            const int index = gifPalette.IndexOf(std::uint32_t(p[0]) << 16 | std::uint32_t(p[1]) << 8 | p[2]);
            if (index < 0) {
                gifColoursOverflow = true;  // more than 256: this part is stored as BGRA from here on
                if (!ExpandGifPartToBgra(error)) return false;
            } else {
                gifIndices[i] = std::uint8_t(index);
            }
        }
        if (!gifColoursOverflow) {
            if (!WriteAll(gifRawFd, gifIndices.data(), pixels, error, raw.c_str())) return false;
            const std::uint8_t blank[1024] = {};  // the palette, filled in when the part ends
            if (!WriteAll(gifRawFd, blank, sizeof blank, error, raw.c_str())) return false;
        }
    }
    if (gifColoursOverflow) {
        // More than 256 colours in the part: BGRA (the format paletteuse takes) for palettegen and paletteuse.
        gifBgra.resize(4 * pixels);
        const std::uint8_t* in = frame.rgb.data();
        std::uint8_t* out = gifBgra.data();
        for (std::size_t i = 0; i < pixels; ++i, in += 3, out += 4)
            out[0] = in[2], out[1] = in[1], out[2] = in[0], out[3] = 255;
        if (!WriteAll(gifRawFd, gifBgra.data(), gifBgra.size(), error, raw.c_str())) return false;
    }
    gifPrevious.rgb.assign(frame.rgb.begin(), frame.rgb.end());
    ++gifPartFrameCount;
    ++frames;
    return true;
}

bool VideoEncoder::ExpandGifPartToBgra(std::string* error) {
    // Rewrites the part's frames so far (pal8, indices into the colours met so far) as BGRA. The BGRA frames
    // overwrite the pal8 ones, so every frame's indices are read first (a quarter of the BGRA's size).
    const std::string& raw = gifRaw[gifRawIndex].path;
    const std::size_t pixels = std::size_t(width) * std::size_t(height), pal8 = pixels + 1024;
    const std::size_t count = static_cast<std::size_t>(gifPartFrameCount);
    std::vector<std::uint8_t> indices(pixels * count);
    const int in = open(raw.c_str(), O_RDONLY | O_CLOEXEC);
    if (in < 0) {
        *error = "cannot open " + raw + ": " + std::strerror(errno);
        return false;
    }
    bool ok = true;
    for (std::size_t k = 0; ok && k < count; ++k)
        ok = pread(in, &indices[pixels * k], pixels, off_t(pal8 * k)) == ssize_t(pixels);
    close(in);
    if (!ok) {
        *error = "reading " + raw + " back failed";
        return false;
    }
    if (lseek(gifRawFd, 0, SEEK_SET) != 0) {
        *error = "cannot rewind " + raw + ": " + std::strerror(errno);
        return false;
    }
    gifBgra.resize(4 * pixels);
    for (std::size_t k = 0; k < count; ++k) {
        for (std::size_t i = 0; i < pixels; ++i) {
            const std::uint32_t c = gifPalette.Colours()[indices[pixels * k + i]];
            std::uint8_t* out = &gifBgra[4 * i];
            out[0] = std::uint8_t(c), out[1] = std::uint8_t(c >> 8), out[2] = std::uint8_t(c >> 16), out[3] = 255;
        }
        if (!WriteAll(gifRawFd, gifBgra.data(), gifBgra.size(), error, raw.c_str())) return false;
    }
    return true;
}

bool VideoEncoder::BeginGifPart(std::string* error) {
    // Parts take turns over three raw files, rewritten in place (new pages for every part cost more than the
    // copy). The part that last used this file must have finished reading it.
    gifRawIndex = (gifRawIndex + 1) % 3;
    TempFile& raw = gifRaw[gifRawIndex];
    for (std::size_t k = 0; k < gifParts.size(); ++k)
        if (gifParts[k].rawIndex == gifRawIndex && !WaitGifPart(k, error)) return false;
    if (raw.path.empty() && (raw.path = CreateTemporaryBeside(path, &raw.id, error)).empty()) return false;
    gifRawFd = open(raw.path.c_str(), O_WRONLY | O_CLOEXEC);
    if (gifRawFd < 0) {
        *error = "cannot open " + raw.path + ": " + std::strerror(errno);
        return false;
    }
    // The colours go on from part to part (the parts then share one palette, and the joined GIF needs no local
    // tables), until a part meets more than 256: the next part starts afresh.
    if (gifColoursOverflow || gifParts.empty()) gifPalette.StartRun();
    gifColoursOverflow = false;
    // The part's ffmpeg starts now, so that its start-up (about 0.07 s of loading libraries) overlaps the
    // part's frames: it first reads a small image on its standard input (unused otherwise), which EndGifPart
    // writes, and only then opens the raw file, complete by then.
    GifPart part;
    part.rawIndex = gifRawIndex;
    part.gif.path = CreateTemporaryBeside(path, &part.gif.id, error);
    gifParts.push_back(part);
    if (part.gif.path.empty()) return false;
    std::vector<std::string> args = {"ffmpeg", "-hide_banner", "-loglevel", "error", "-y",
                                     "-f",     "png_pipe",     "-i",        "pipe:0"};
    for (const std::string& a : GifRawInput(raw.path, "pal8")) args.push_back(a);
    args.push_back("-map");
    args.push_back("1:v");
    for (const std::string& a : GifOutput(part.gif.path)) args.push_back(a);
    if (!Spawn(args, true, error)) return false;
    gifParts.back().pid = child;
    gifParts.back().startFd = pipeFd;
    child = -1;
    pipeFd = -1;
    return true;
}

std::vector<std::string> VideoEncoder::GifRawInput(const std::string& raw, const char* pixelFormat) const {
    return {"-f",          "rawvideo",
            "-pix_fmt",    pixelFormat,
            "-video_size", std::to_string(width) + "x" + std::to_string(height),
            "-framerate",  Number(GifFramesPerSecond()),
            "-i",          raw};
}

std::vector<std::string> VideoEncoder::GifOutput(const std::string& gif) const {
    // The delay after a part's last frame is one frame's: ffmpeg cannot know it for a part of one frame, and
    // would write 0 (which players and ffmpeg's own reader take as a tenth of a second).
    const long delay = std::lround(100.0 / GifFramesPerSecond());
    return {"-final_delay", std::to_string(delay), "-loop", "0", "-f", "gif", gif};
}

bool VideoEncoder::EndGifPart(std::string* error) {
    const TempFile& raw = gifRaw[gifRawIndex];
    GifPart& part = gifParts.back();
    const int fd = gifRawFd;
    gifRawFd = -1;
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    const std::size_t frameBytes = gifColoursOverflow ? 4 * pixels : pixels + 1024;
    bool written = true;
    if (!gifColoursOverflow) {
        // At most 256 colours: the palette is exactly the part's colours, which is what palettegen would find
        // for them, and each pixel's index is its exact colour, which is what paletteuse would map it to. Every
        // frame gets the palette (ffmpeg's pal8 entries: 0xAARRGGBB, little-endian; unused entries transparent,
        // which the GIF encoder uses for the pixels a frame leaves unchanged).
        std::uint8_t palette[1024];
        Pal8Palette(gifPalette.Colours(), palette);
        for (int f = 0; written && f < gifPartFrameCount; ++f)
            written = pwrite(fd, palette, sizeof palette, off_t(frameBytes * std::size_t(f) + pixels)) ==
                      ssize_t(sizeof palette);
    }
    written = written && ftruncate(fd, off_t(frameBytes * std::size_t(gifPartFrameCount))) == 0;  // shorter?
    gifPartFrameCount = 0;
    if (close(fd) != 0 || !written) {
        *error = "writing " + raw.path + " failed: " + std::strerror(errno);
        return false;
    }
    const int gateFd = part.startFd;
    part.startFd = -1;
    if (!gifColoursOverflow) {
        part.epoch = gifPalette.Run();
        part.colours = gifPalette.Colours();
        // Release the waiting ffmpeg: a 1x1 image on its standard input.
        std::vector<std::uint8_t> png;
        if (!EncodePng(Image(1, 1), PngOptions{}, &png, error)) return close(gateFd), false;
        bool stalled = false;
        const bool sent = WriteToChild(gateFd, png.data(), png.size(), stallSeconds, &stalled, error);
        close(gateFd);
        if (sent) return true;
        // ffmpeg went away before it read the image: its own message says why.
        child = part.pid;
        part.pid = -1;
        if (!stalled && Wait(part.gif.path, error)) *error = "ffmpeg ended before it read the part's frames";
        if (!stalled) return false;
        KillChild(child);
        child = -1;
        *error = "ffmpeg failed: " + *error;
        return false;
    }
    // More than 256: palettegen chooses them from the part's frames (stats_mode=full: weighted by area), and
    // paletteuse maps them without dithering and only where a frame changed, in an ffmpeg of its own instead of
    // the waiting one.
    close(gateFd);
    KillChild(part.pid);
    part.pid = -1;
    std::vector<std::string> args = {"ffmpeg", "-hide_banner", "-loglevel", "error", "-y"};
    for (const std::string& a : GifRawInput(raw.path, "bgra")) args.push_back(a);
    args.push_back("-filter_complex");
    args.push_back(
        "[0:v]split[keep][stats];[stats]palettegen=stats_mode=full:reserve_transparent=0[p];[keep][p]"
        "paletteuse=dither=none:diff_mode=rectangle");
    for (const std::string& a : GifOutput(part.gif.path)) args.push_back(a);
    if (!Spawn(args, false, error)) return false;
    part.pid = child;
    child = -1;
    return true;
}

bool VideoEncoder::WaitGifPart(std::size_t k, std::string* error) {
    GifPart& part = gifParts[k];
    if (part.pid <= 0) return true;
    child = part.pid;
    part.pid = -1;
    part.rawIndex = -1;  // done with its raw file
    if (!Wait(part.gif.path, error) || !ReadFileBytes(part.gif.path, &part.bytes, error)) return false;
    // Kept in memory from here on (a part's GIF is small): the file and its registry slot are freed, so a long
    // recording never holds more than a few temporaries.
    unlink(part.gif.path.c_str());
    part.gif.path.clear();
    UnregisterTemporary(part.gif.id);
    part.gif.id = -1;
    return true;
}

bool VideoEncoder::JoinGifParts(std::string* error) {
    if (gifPartFrameCount > 0 && !EndGifPart(error)) return false;
    std::vector<std::vector<std::uint8_t>> bytes(gifParts.size());
    for (std::size_t k = 0; k < gifParts.size(); ++k) {
        if (!WaitGifPart(k, error)) return false;
        bytes[k].swap(gifParts[k].bytes);
    }
    // Parts of one run of shared colours index them alike, each knowing those met so far: each gets the last
    // one's palette as its global table, so that JoinGifs finds them equal. (A part's transparent index is a
    // colour it had not met; in its frames it still marks the pixels a frame left unchanged.)
    for (std::size_t k = 0; k < gifParts.size(); ++k) {
        const int epoch = gifParts[k].epoch;
        if (epoch < 0) continue;
        const std::vector<std::uint32_t>* last = &gifParts[k].colours;
        for (std::size_t j = k + 1; j < gifParts.size() && gifParts[j].epoch == epoch; ++j) last = &gifParts[j].colours;
        if (!ReplaceGlobalColourTable(&bytes[k], GifColourTable(*last), error)) {
            *error = "GIF part " + std::to_string(k + 1) + " from ffmpeg: " + *error;
            return false;
        }
    }
    std::vector<std::uint8_t> joined;
    if (!JoinGifs(bytes, &joined, error)) return false;
    return WriteWhole(tempPath, joined, error);
}

bool VideoEncoder::Finish(std::string* error) {
    if (!IsOpen()) {
        *error = "video recording is not open";
        return false;
    }
    if (failed) {
        *error = "video recording failed at an earlier frame; nothing was written";
        Abort();
        return false;
    }
    bool ok = true;
    if (format == Format::Gif) {
        ok = (frames > 0 || (*error = "no frames were recorded", false)) && JoinGifParts(error);
        if (!ok) {  // parts may still be running (the run failed before JoinGifParts)
            Abort();
            return false;
        }
    } else {
        close(pipeFd);
        pipeFd = -1;
        // ffmpeg may exit 0 and leave a file that does not play (its trailer unwritten): checked before it
        // replaces anything.
        ok = Wait(tempPath, error) &&
             CheckVideoFile(tempPath, format == Format::Mp4 ? VideoContainer::Mp4 : VideoContainer::Webm, frames,
                            logPath, stallSeconds, error);
    }
    if (ok && std::rename(tempPath.c_str(), path.c_str()) != 0) {
        *error = "cannot rename " + tempPath + " to " + path + ": " + std::strerror(errno);
        ok = false;
    }
    if (ok) {
        UnregisterTemporary(tempId);  // renamed: it is the result now
        tempId = -1;
        tempPath.clear();
    }
    Cleanup();
    return ok;
}

void VideoEncoder::Abort() {
    if (pipeFd >= 0) close(pipeFd), pipeFd = -1;
    std::vector<pid_t> running = {child};
    for (GifPart& part : gifParts) {
        running.push_back(part.pid), part.pid = -1;
        if (part.startFd >= 0) close(part.startFd), part.startFd = -1;
    }
    if (gifRawFd >= 0) close(gifRawFd), gifRawFd = -1;
    child = -1;
    for (const pid_t pid : running) KillChild(pid);
    Cleanup();
}

void VideoEncoder::Cleanup() {
    std::vector<TempFile*> temporaries = {&gifRaw[0], &gifRaw[1], &gifRaw[2]};
    for (GifPart& part : gifParts) temporaries.push_back(&part.gif);
    for (TempFile* file : temporaries) {
        if (!file->path.empty()) unlink(file->path.c_str());
        file->path.clear();
        UnregisterTemporary(file->id);
        file->id = -1;
    }
    for (auto [file, id] : {std::pair<std::string*, int*>{&tempPath, &tempId}, {&logPath, &logId}}) {
        if (!file->empty()) unlink(file->c_str());
        file->clear();
        UnregisterTemporary(*id);
        *id = -1;
    }
    gifParts.clear();
    gifPartFrameCount = 0;
    gifRawIndex = -1;
    failed = false;
}
