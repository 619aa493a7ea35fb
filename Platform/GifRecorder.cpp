#include "Platform/GifRecorder.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <sstream>

#include "Platform/Files/AtomicFile.h"
#include "Platform/Files/TempRegistry.h"
#include "Platform/GifJoin.h"
#include "Platform/PngCodec.h"

namespace {

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

bool GifRecorder::Start(std::string* /*error*/) {
    // A palette generated from all the frames could only be applied after the run. Instead the GIF is made in
    // parts of up to partSize frames, each with a palette generated from its own frames and encoded by its own
    // ffmpeg while the next part renders; JoinGifs puts the parts together at Finish.
    partSize = partFramesSet > 0 ? partFramesSet : DefaultPartFrames(t.width, t.height);
    int kept = 0;
    for (int i = 0; i < expectedFrames; ++i) kept += KeepFrame(i) ? 1 : 0;
    plan = PlanParts(kept, partSize);
    return true;
}

bool GifRecorder::Finish(int frames, std::string* error) {
    if (frames == 0) {
        *error = "no frames were recorded";
        return false;
    }
    if (partFrameCount > 0 && !EndPart(error)) return false;
    std::vector<std::vector<std::uint8_t>> bytes(parts.size());
    for (std::size_t k = 0; k < parts.size(); ++k) {
        if (!WaitPart(k, error)) return false;
        bytes[k].swap(parts[k].bytes);
    }
    // Parts of one run of shared colours index them alike, each knowing those met so far: each gets the last
    // one's palette as its global table, so that JoinGifs finds them equal. (A part's transparent index is a
    // colour it had not met; in its frames it still marks the pixels a frame left unchanged.)
    for (std::size_t k = 0; k < parts.size(); ++k) {
        const int run = parts[k].run;
        if (run < 0) continue;
        const std::vector<std::uint32_t>* last = &parts[k].colours;
        for (std::size_t j = k + 1; j < parts.size() && parts[j].run == run; ++j) last = &parts[j].colours;
        if (!ReplaceGlobalColourTable(&bytes[k], GifColourTable(*last), error)) {
            *error = "GIF part " + std::to_string(k + 1) + " from ffmpeg: " + *error;
            return false;
        }
    }
    std::vector<std::uint8_t> joined;
    if (!JoinGifs(bytes, &joined, error)) return false;
    return WriteWhole(t.tempPath, joined, error);
}

int GifRecorder::DefaultPartFrames(int w, int h) {
    // A part's frames wait in a raw file until the part is complete (1 byte a pixel, 4 once it has more than 256
    // colours), and the run waits for the last part: at most 100 frames (2 s at GIF's 50 fps; 70 to 150 measured
    // alike at 800x600) and 192 MiB as BGRA, at least 10.
    const long long bytes = 4LL * w * h;
    return int(std::clamp<long long>((192LL << 20) / bytes, 10, 100));
}

std::vector<int> GifRecorder::PlanParts(int frames, int partFrames) {
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

double GifRecorder::FramesPerSecond() const { return std::min(t.fps, 50.0); }

bool GifRecorder::KeepFrame(int i) const {
    // GIF delays are whole hundredths of a second: above 50 fps, frames are resampled to 50. Output frame j
    // shows the input frame nearest its time j / 50 (as ffmpeg's fps filter does): frame i is kept when an
    // output time falls in [(i - 1/2) / fps, (i + 1/2) / fps).
    if (t.fps <= 50.0) return true;
    const double ratio = 50.0 / t.fps;
    return std::ceil((i + 0.5) * ratio) > std::ceil((i - 0.5) * ratio);
}

bool GifRecorder::Record(const Image& frame, int index, std::string* error) {
    if (!KeepFrame(index)) return true;
    if (partFrameCount > 0) {  // the current part is the last started; full by the plan, else by the size
        const std::size_t part = parts.size() - 1;
        const int size = part < plan.size() ? plan[part] : partSize;
        if (partFrameCount >= size && !EndPart(error)) return false;
    }
    if (partFrameCount == 0 && !BeginPart(error)) return false;
    const std::size_t pixels = std::size_t(t.width) * std::size_t(t.height);
    const std::string& raw = rawFiles[rawIndex].path;
    if (!overflow) {
        // Indices into the part's colours, in the order it meets them: every pixel of its first frame, then only
        // those that changed (the demos change a fraction of a percent of their pixels a frame); the others keep
        // their index. The frame is stored as ffmpeg's raw pal8: the indices, then 256 palette entries of 4 bytes,
        // written when the part ends.
        indices.resize(pixels);
        const std::uint8_t* p = frame.rgb.data();
        const std::uint8_t* q = partFrameCount > 0 ? previous.rgb.data() : nullptr;
        for (std::size_t i = 0; i < pixels && !overflow; ++i, p += 3) {
            if (q && p[0] == q[3 * i] && p[1] == q[3 * i + 1] && p[2] == q[3 * i + 2]) continue;
            const int index = palette.IndexOf(std::uint32_t(p[0]) << 16 | std::uint32_t(p[1]) << 8 | p[2]);
            if (index < 0) {
                overflow = true;  // more than 256: this part is stored as BGRA from here on
                if (!ExpandPartToBgra(error)) return false;
            } else {
                indices[i] = std::uint8_t(index);
            }
        }
        if (!overflow) {
            if (!WriteAll(rawFd, indices.data(), pixels, error, raw.c_str())) return false;
            const std::uint8_t blank[1024] = {};  // the palette, filled in when the part ends
            if (!WriteAll(rawFd, blank, sizeof blank, error, raw.c_str())) return false;
        }
    }
    if (overflow) {
        // More than 256 colours in the part: BGRA (the format paletteuse takes) for palettegen and paletteuse.
        bgra.resize(4 * pixels);
        const std::uint8_t* in = frame.rgb.data();
        std::uint8_t* out = bgra.data();
        for (std::size_t i = 0; i < pixels; ++i, in += 3, out += 4)
            out[0] = in[2], out[1] = in[1], out[2] = in[0], out[3] = 255;
        if (!WriteAll(rawFd, bgra.data(), bgra.size(), error, raw.c_str())) return false;
    }
    previous.rgb.assign(frame.rgb.begin(), frame.rgb.end());
    ++partFrameCount;
    return true;
}

bool GifRecorder::ExpandPartToBgra(std::string* error) {
    // Rewrites the part's frames so far (pal8, stored into the colours met so far) as BGRA. The BGRA frames
    // overwrite the pal8 ones, so every frame's stored are read first (a quarter of the BGRA's size).
    const std::string& raw = rawFiles[rawIndex].path;
    const std::size_t pixels = std::size_t(t.width) * std::size_t(t.height), pal8 = pixels + 1024;
    const std::size_t count = static_cast<std::size_t>(partFrameCount);
    std::vector<std::uint8_t> stored(pixels * count);
    const int in = open(raw.c_str(), O_RDONLY | O_CLOEXEC);
    if (in < 0) {
        *error = "cannot open " + raw + ": " + std::strerror(errno);
        return false;
    }
    bool ok = true;
    for (std::size_t k = 0; ok && k < count; ++k)
        ok = pread(in, &stored[pixels * k], pixels, off_t(pal8 * k)) == ssize_t(pixels);
    close(in);
    if (!ok) {
        *error = "reading " + raw + " back failed";
        return false;
    }
    if (lseek(rawFd, 0, SEEK_SET) != 0) {
        *error = "cannot rewind " + raw + ": " + std::strerror(errno);
        return false;
    }
    bgra.resize(4 * pixels);
    for (std::size_t k = 0; k < count; ++k) {
        for (std::size_t i = 0; i < pixels; ++i) {
            const std::uint32_t c = palette.Colours()[stored[pixels * k + i]];
            std::uint8_t* out = &bgra[4 * i];
            out[0] = std::uint8_t(c), out[1] = std::uint8_t(c >> 8), out[2] = std::uint8_t(c >> 16), out[3] = 255;
        }
        if (!WriteAll(rawFd, bgra.data(), bgra.size(), error, raw.c_str())) return false;
    }
    return true;
}

bool GifRecorder::BeginPart(std::string* error) {
    // Parts take turns over three raw files, rewritten in place (new pages for every part cost more than the
    // copy). The part that last used this file must have finished reading it.
    rawIndex = (rawIndex + 1) % 3;
    TempFile& raw = rawFiles[rawIndex];
    for (std::size_t k = 0; k < parts.size(); ++k)
        if (parts[k].rawIndex == rawIndex && !WaitPart(k, error)) return false;
    if (raw.path.empty() && (raw.path = CreateTemporaryBeside(t.path, &raw.id, error)).empty()) return false;
    rawFd = open(raw.path.c_str(), O_WRONLY | O_CLOEXEC);
    if (rawFd < 0) {
        *error = "cannot open " + raw.path + ": " + std::strerror(errno);
        return false;
    }
    // The colours go on from part to part (the parts then share one palette, and the joined GIF needs no local
    // tables), until a part meets more than 256: the next part starts afresh.
    if (overflow || parts.empty()) palette.StartRun();
    overflow = false;
    // The part's ffmpeg starts now, so that its start-up (about 0.07 s of loading libraries) overlaps the
    // part's frames: it first reads a small image on its standard input (unused otherwise), which EndPart
    // writes, and only then opens the raw file, complete by then.
    Part part;
    part.rawIndex = rawIndex;
    part.gif.path = CreateTemporaryBeside(t.path, &part.gif.id, error);
    parts.push_back(part);
    if (part.gif.path.empty()) return false;
    std::vector<std::string> args = {"ffmpeg", "-hide_banner", "-loglevel", "error", "-y",
                                     "-f",     "png_pipe",     "-i",        "pipe:0"};
    for (const std::string& a : RawInput(raw.path, "pal8")) args.push_back(a);
    args.push_back("-map");
    args.push_back("1:v");
    for (const std::string& a : Output(part.gif.path)) args.push_back(a);
    if (!ffmpeg.Start(args, true, t.logPath, error)) return false;
    parts.back().pid = ffmpeg.pid;
    parts.back().startFd = ffmpeg.input;
    ffmpeg = FfmpegChild();
    return true;
}

std::vector<std::string> GifRecorder::RawInput(const std::string& raw, const char* pixelFormat) const {
    return {"-f",          "rawvideo",
            "-pix_fmt",    pixelFormat,
            "-video_size", std::to_string(t.width) + "x" + std::to_string(t.height),
            "-framerate",  FfmpegNumber(FramesPerSecond()),
            "-i",          raw};
}

std::vector<std::string> GifRecorder::Output(const std::string& gif) const {
    // The delay after a part's last frame is one frame's: ffmpeg cannot know it for a part of one frame, and
    // would write 0 (which players and ffmpeg's own reader take as a tenth of a second).
    const long delay = std::lround(100.0 / FramesPerSecond());
    return {"-final_delay", std::to_string(delay), "-loop", "0", "-f", "gif", gif};
}

bool GifRecorder::EndPart(std::string* error) {
    const TempFile& raw = rawFiles[rawIndex];
    Part& part = parts.back();
    const int fd = rawFd;
    rawFd = -1;
    const std::size_t pixels = std::size_t(t.width) * std::size_t(t.height);
    const std::size_t frameBytes = overflow ? 4 * pixels : pixels + 1024;
    bool written = true;
    if (!overflow) {
        // At most 256 colours: the palette is exactly the part's colours, which is what palettegen would find
        // for them, and each pixel's index is its exact colour, which is what paletteuse would map it to. Every
        // frame gets the palette (ffmpeg's pal8 entries: 0xAARRGGBB, little-endian; unused entries transparent,
        // which the GIF encoder uses for the pixels a frame leaves unchanged).
        std::uint8_t pal8[1024];
        Pal8Palette(palette.Colours(), pal8);
        for (int f = 0; written && f < partFrameCount; ++f)
            written =
                pwrite(fd, pal8, sizeof pal8, off_t(frameBytes * std::size_t(f) + pixels)) == ssize_t(sizeof pal8);
    }
    written = written && ftruncate(fd, off_t(frameBytes * std::size_t(partFrameCount))) == 0;  // shorter?
    partFrameCount = 0;
    if (close(fd) != 0 || !written) {
        *error = "writing " + raw.path + " failed: " + std::strerror(errno);
        return false;
    }
    const int gateFd = part.startFd;
    part.startFd = -1;
    if (!overflow) {
        part.run = palette.Run();
        part.colours = palette.Colours();
        // Release the waiting ffmpeg: a 1x1 image on its standard input.
        std::vector<std::uint8_t> png;
        if (!EncodePng(Image(1, 1), PngOptions{}, &png, error)) return close(gateFd), false;
        bool stalled = false;
        const bool sent = WriteToChild(gateFd, png.data(), png.size(), t.stallSeconds, &stalled, error);
        close(gateFd);
        if (sent) return true;
        // ffmpeg went away before it read the image: its own message says why.
        ffmpeg.pid = part.pid;
        part.pid = -1;
        if (!stalled && ffmpeg.Wait(t.stallSeconds, part.gif.path, t.logPath, error))
            *error = "ffmpeg ended before it read the part's frames";
        if (!stalled) return false;
        ffmpeg.Kill();
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
    for (const std::string& a : RawInput(raw.path, "bgra")) args.push_back(a);
    args.push_back("-filter_complex");
    args.push_back(
        "[0:v]split[keep][stats];[stats]palettegen=stats_mode=full:reserve_transparent=0[p];[keep][p]"
        "paletteuse=dither=none:diff_mode=rectangle");
    for (const std::string& a : Output(part.gif.path)) args.push_back(a);
    if (!ffmpeg.Start(args, false, t.logPath, error)) return false;
    part.pid = ffmpeg.pid;
    ffmpeg.pid = -1;
    return true;
}

bool GifRecorder::WaitPart(std::size_t k, std::string* error) {
    Part& part = parts[k];
    if (part.pid <= 0) return true;
    ffmpeg.pid = part.pid;
    part.pid = -1;
    part.rawIndex = -1;  // done with its raw file
    if (!ffmpeg.Wait(t.stallSeconds, part.gif.path, t.logPath, error) ||
        !ReadFileBytes(part.gif.path, &part.bytes, error))
        return false;
    // Kept in memory from here on (a part's GIF is small): the file and its registry slot are freed, so a long
    // recording never holds more than a few temporaries.
    unlink(part.gif.path.c_str());
    part.gif.path.clear();
    UnregisterTemporary(part.gif.id);
    part.gif.id = -1;
    return true;
}

void GifRecorder::Abort() {
    std::vector<pid_t> running = {ffmpeg.pid};
    ffmpeg.CloseInput();
    ffmpeg.pid = -1;
    for (Part& part : parts) {
        running.push_back(part.pid), part.pid = -1;
        if (part.startFd >= 0) close(part.startFd), part.startFd = -1;
    }
    if (rawFd >= 0) close(rawFd), rawFd = -1;
    for (const pid_t pid : running) KillChild(pid);
    std::vector<TempFile*> temporaries = {&rawFiles[0], &rawFiles[1], &rawFiles[2]};
    for (Part& part : parts) temporaries.push_back(&part.gif);
    for (TempFile* file : temporaries) {
        if (!file->path.empty()) unlink(file->path.c_str());
        file->path.clear();
        UnregisterTemporary(file->id);
        file->id = -1;
    }
    parts.clear();
    partFrameCount = 0;
    rawIndex = -1;
}
