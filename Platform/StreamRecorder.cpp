#include "Platform/StreamRecorder.h"

#include "Platform/VideoFileCheck.h"
#include "Platform/Yuv420.h"

bool StreamRecorder::Start(std::string* error) {
    std::vector<std::string> args = {"ffmpeg", "-hide_banner", "-loglevel", "error", "-y", "-f", "rawvideo",
                                     // Frames arrive as yuv420p, converted by Record (Platform/Yuv420.h).
                                     "-pix_fmt", "yuv420p", "-video_size",
                                     std::to_string(EvenSide(t.width)) + "x" + std::to_string(EvenSide(t.height)),
                                     "-framerate", FfmpegNumber(t.fps), "-i", "pipe:0"};
    // Tagged as what Yuv420 makes, BT.601 in the limited range: untagged, players take frames of HD sizes for
    // BT.709.
    for (const char* a :
         {"-colorspace", "smpte170m", "-color_primaries", "smpte170m", "-color_trc", "smpte170m", "-color_range", "tv"})
        args.push_back(a);
    if (!webm) {
        for (const char* a : {"-c:v", "libx264", "-preset", "ultrafast", "-crf", "18", "-pix_fmt", "yuv420p",
                              "-movflags", "+faststart", "-f", "mp4"})
            args.push_back(a);
    } else {
        for (const char* a : {"-c:v", "libvpx-vp9", "-deadline", "realtime", "-cpu-used", "8", "-threads", "1", "-b:v",
                              "0", "-crf", "30", "-pix_fmt", "yuv420p", "-f", "webm"})
            args.push_back(a);
    }
    args.push_back(t.tempPath);
    return ffmpeg.Start(args, true, t.logPath, error);
}

bool StreamRecorder::Record(const Image& frame, int index, std::string* error) {
    if (ffmpeg.input < 0) {
        *error = "video recording is not open";
        return false;
    }
    RgbToYuv420(frame, &yuv);
    bool stalled = false;
    if (WriteToChild(ffmpeg.input, yuv.data(), yuv.size(), t.stallSeconds, &stalled, error)) return true;
    ffmpeg.CloseInput();
    if (stalled) {  // ffmpeg stopped reading: stopped here
        ffmpeg.Kill();
        *error = "ffmpeg failed: " + *error;
        return false;
    }
    // ffmpeg went away: its own message says why, if it gave one.
    if (ffmpeg.Wait(t.stallSeconds, t.tempPath, t.logPath, error))
        *error = "ffmpeg ended before it read frame " + std::to_string(index);
    return false;
}

bool StreamRecorder::Finish(int frames, std::string* error) {
    ffmpeg.CloseInput();
    return ffmpeg.Wait(t.stallSeconds, t.tempPath, t.logPath, error) &&
           CheckVideoFile(t.tempPath, webm ? VideoContainer::Webm : VideoContainer::Mp4, frames, t.logPath,
                          t.stallSeconds, error);
}

void StreamRecorder::Abort() {
    ffmpeg.CloseInput();
    ffmpeg.Kill();
}
