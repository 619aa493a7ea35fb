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
#include <memory>
#include <utility>

#include "Platform/FfmpegProcess.h"
#include "Platform/Files/AtomicFile.h"
#include "Platform/Files/TempRegistry.h"
#include "Platform/GifRecorder.h"
#include "Platform/StreamRecorder.h"

namespace {

std::string Lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
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

bool VideoEncoder::Open(const std::string& path, int w, int h, double framesPerSecond, std::string* error) {
    Abort();
    if (!FormatOf(path, &format)) {
        *error = "video file '" + path + "' must end in .mp4, .webm or .gif";
        return false;
    }
    if (w < 1 || h < 1 || !(framesPerSecond > 0.0)) {
        *error = "bad video size or frame rate";
        return false;
    }
    if (!FfmpegAvailable(error)) return false;
    signal(SIGPIPE, SIG_IGN);  // a dead ffmpeg must be an error from write(), not the end of this process
    target.stallSeconds = EncoderStallSeconds();
    target.path = path;
    target.width = w;
    target.height = h;
    target.fps = framesPerSecond;
    frames = 0;
    // Temporaries beside the target, removed by Cleanup and, on SIGINT/SIGTERM, by the signal handler (which
    // first kills ffmpeg, so it cannot write them again).
    target.tempPath = CreateTemporaryBeside(path, &tempId, error);
    if (target.tempPath.empty()) return false;
    target.logPath = CreateTemporaryBeside(path, &logId, error);
    if (target.logPath.empty()) return Cleanup(), false;
    if (format == Format::Gif)
        recorder = std::make_unique<GifRecorder>(target, gifPartFrames, expectedFrames);
    else
        recorder = std::make_unique<StreamRecorder>(target, format == Format::Webm);
    if (!recorder->Start(error)) return Cleanup(), false;
    return true;
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
    if (frame.width != target.width || frame.height != target.height) {
        *error = "video frame is " + std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                 ", the recording " + std::to_string(target.width) + "x" + std::to_string(target.height);
        return false;
    }
    if (!IsOpen() || !recorder) {
        *error = "video recording is not open";
        return false;
    }
    if (!recorder->Record(frame, frames, error)) return false;
    ++frames;
    return true;
}

std::vector<int> VideoEncoder::PlanGifParts(int frames, int partFrames) {
    return GifRecorder::PlanParts(frames, partFrames);
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
    if (!recorder->Finish(frames, error)) {  // parts may still be running
        Abort();
        return false;
    }
    bool ok = true;
    if (std::rename(target.tempPath.c_str(), target.path.c_str()) != 0) {
        *error = "cannot rename " + target.tempPath + " to " + target.path + ": " + std::strerror(errno);
        ok = false;
    }
    if (ok) {
        UnregisterTemporary(tempId);  // renamed: it is the result now
        tempId = -1;
        target.tempPath.clear();
    }
    Cleanup();
    return ok;
}

void VideoEncoder::Abort() {
    if (recorder) recorder->Abort();
    Cleanup();
}

void VideoEncoder::Cleanup() {
    recorder.reset();  // its own temporaries first
    for (auto [file, id] : {std::pair<std::string*, int*>{&target.tempPath, &tempId}, {&target.logPath, &logId}}) {
        if (!file->empty()) unlink(file->c_str());
        file->clear();
        UnregisterTemporary(*id);
        *id = -1;
    }
    failed = false;
}
