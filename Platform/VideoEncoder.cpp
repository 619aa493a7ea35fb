#include "Platform/VideoEncoder.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "Platform/Files/AtomicFile.h"
#include "Platform/Files/TempRegistry.h"

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

/// The last non-empty line of a text file ("" if none).
std::string LastLine(const std::string& path) {
    std::ifstream in(path);
    std::string line, last;
    while (std::getline(in, line))
        if (!line.empty()) last = line;
    return last;
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
    const char* pathEnv = std::getenv("PATH");
    std::stringstream dirs(pathEnv ? pathEnv : "/usr/bin:/bin");
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        const std::string candidate = (dir.empty() ? "." : dir) + "/ffmpeg";
        if (access(candidate.c_str(), X_OK) == 0) return true;
    }
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
        // The palette needs every frame before the first can be mapped: keep them raw on disk, not in memory, and
        // feed them to palettegen while the run goes on (its statistics are ready when the run ends; only the
        // mapping pass, paletteuse, runs after it).
        rawPath = CreateTemporaryBeside(path, &rawId, error);
        if (rawPath.empty()) return Cleanup(), false;
        rawFd = open(rawPath.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
        if (rawFd < 0) {
            *error = "cannot open " + rawPath + ": " + std::strerror(errno);
            return Cleanup(), false;
        }
        palettePath = CreateTemporaryBeside(path, &paletteId, error);
        if (palettePath.empty()) return Cleanup(), false;
        std::vector<std::string> pass1 = {"ffmpeg", "-hide_banner", "-loglevel", "error", "-y"};
        for (const std::string& a : GifInput("pipe:0")) pass1.push_back(a);
        for (const std::string& a :
             {std::string("-vf"), GifResample() + "palettegen=stats_mode=full:reserve_transparent=0",
              std::string("-c:v"), std::string("png"), std::string("-f"), std::string("image2"), palettePath})
            pass1.push_back(a);
        if (!Spawn(pass1, true, error)) return Cleanup(), false;
        return true;
    }
    std::vector<std::string> args = {"ffmpeg",
                                     "-hide_banner",
                                     "-loglevel",
                                     "error",
                                     "-y",
                                     "-f",
                                     "rawvideo",
                                     "-pix_fmt",
                                     "rgb24",
                                     "-video_size",
                                     std::to_string(w) + "x" + std::to_string(h),
                                     "-framerate",
                                     Number(fps),
                                     "-i",
                                     "pipe:0",
                                     "-vf",
                                     "pad=ceil(iw/2)*2:ceil(ih/2)*2"};
    if (format == Format::Mp4) {
        for (const char* a : {"-c:v", "libx264", "-preset", "ultrafast", "-crf", "18", "-pix_fmt", "yuv420p",
                              "-movflags", "+faststart", "-f", "mp4"})
            args.push_back(a);
    } else {
        for (const char* a : {"-c:v", "libvpx-vp9", "-deadline", "realtime", "-cpu-used", "8", "-row-mt", "1", "-b:v",
                              "0", "-crf", "30", "-pix_fmt", "yuv420p", "-f", "webm"})
            args.push_back(a);
    }
    args.push_back(tempPath);
    if (!Spawn(args, true, error)) return Cleanup(), false;
    return true;
}

bool VideoEncoder::Spawn(const std::vector<std::string>& args, bool pipeIn, std::string* error) {
    int fds[2] = {-1, -1};
    if (pipeIn && pipe2(fds, O_CLOEXEC) != 0) {
        *error = std::string("pipe failed: ") + std::strerror(errno);
        return false;
    }
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const int log = open(logPath.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
    const pid_t pid = fork();
    if (pid == 0) {
        // Child: stdin from the pipe (or /dev/null), stdout and stderr to the log, then ffmpeg.
        const int in = pipeIn ? fds[0] : open("/dev/null", O_RDONLY);
        if (in < 0 || dup2(in, 0) < 0) _exit(127);
        if (log >= 0) dup2(log, 1), dup2(log, 2);
        signal(SIGPIPE, SIG_DFL);
        execvp("ffmpeg", argv.data());
        _exit(127);
    }
    if (log >= 0) close(log);
    if (pipeIn) close(fds[0]);
    if (pid < 0) {
        if (pipeIn) close(fds[1]);
        *error = std::string("cannot start ffmpeg: ") + std::strerror(errno);
        return false;
    }
    child = pid;
    RegisterChildProcess(pid);
    pipeFd = pipeIn ? fds[1] : -1;
    return true;
}

bool VideoEncoder::Wait(std::string* error) {
    int status = 0;
    pid_t r;
    do r = waitpid(child, &status, 0);
    while (r < 0 && errno == EINTR);
    UnregisterChildProcess(child);
    child = -1;
    if (r > 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0) return true;
    const std::string last = LastLine(logPath);
    *error = "ffmpeg failed" +
             (r > 0 && WIFEXITED(status) ? " with exit code " + std::to_string(WEXITSTATUS(status))
                                         : std::string(" (killed by a signal)")) +
             (last.empty() ? std::string() : ": " + last);
    return false;
}

bool VideoEncoder::WriteFrame(const Image& frame, std::string* error) {
    if (frame.width != width || frame.height != height) {
        *error = "video frame is " + std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                 ", the recording " + std::to_string(width) + "x" + std::to_string(height);
        return false;
    }
    if (pipeFd < 0 || (format == Format::Gif && rawFd < 0)) {
        *error = "video recording is not open";
        return false;
    }
    if (format == Format::Gif && !WriteAll(rawFd, frame.rgb.data(), frame.rgb.size(), error, rawPath.c_str()))
        return false;
    if (!WriteAll(pipeFd, frame.rgb.data(), frame.rgb.size(), error, "ffmpeg")) {
        // ffmpeg went away: its own message says why.
        close(pipeFd);
        pipeFd = -1;
        std::string why;
        Wait(&why);
        *error = why;
        return false;
    }
    ++frames;
    return true;
}

std::vector<std::string> VideoEncoder::GifInput(const std::string& source) const {
    return {"-f",         "rawvideo",    "-pix_fmt",
            "rgb24",      "-video_size", std::to_string(width) + "x" + std::to_string(height),
            "-framerate", Number(fps),   "-i",
            source};
}

std::string VideoEncoder::GifResample() const {
    // GIF delays are whole hundredths of a second: above 50 fps, resample to 50 (2/100 s per frame).
    return fps > 50.0 ? "fps=50," : "";
}

bool VideoEncoder::EncodeGif(std::string* error) {
    // Pass 1 (palettegen) has read every frame from its pipe: close it and wait for the palette.
    close(pipeFd);
    pipeFd = -1;
    if (!Wait(error)) return false;
    std::vector<std::string> pass2 = {"ffmpeg", "-hide_banner", "-loglevel", "error", "-y"};
    for (const std::string& a : GifInput(rawPath)) pass2.push_back(a);
    for (const std::string& a :
         {std::string("-i"), palettePath, std::string("-lavfi"),
          "[0:v]" + GifResample() + "null[v];[v][1:v]paletteuse=dither=none:diff_mode=rectangle", std::string("-loop"),
          std::string("0"), std::string("-f"), std::string("gif"), tempPath})
        pass2.push_back(a);
    return Spawn(pass2, false, error) && Wait(error);
}

bool VideoEncoder::Finish(std::string* error) {
    if (!IsOpen()) {
        *error = "video recording is not open";
        return false;
    }
    bool ok = true;
    if (format == Format::Gif) {
        ok = close(rawFd) == 0;
        rawFd = -1;
        if (!ok) *error = "writing " + rawPath + " failed: " + std::strerror(errno);
        ok = ok && (frames > 0 || (*error = "no frames were recorded", false)) && EncodeGif(error);
        if (!ok && child > 0) {  // palettegen still reading its pipe (the run failed before EncodeGif)
            Abort();
            return false;
        }
    } else {
        close(pipeFd);
        pipeFd = -1;
        ok = Wait(error);
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
    if (child > 0) {
        kill(child, SIGKILL);
        int status = 0;
        while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
        }
        UnregisterChildProcess(child);
        child = -1;
    }
    Cleanup();
}

void VideoEncoder::Cleanup() {
    if (rawFd >= 0) close(rawFd), rawFd = -1;
    const std::pair<std::string*, int*> temporaries[] = {
        {&tempPath, &tempId}, {&rawPath, &rawId}, {&palettePath, &paletteId}, {&logPath, &logId}};
    for (const auto& [path, id] : temporaries) {
        if (!path->empty()) unlink(path->c_str());
        path->clear();
        UnregisterTemporary(*id);
        *id = -1;
    }
}
