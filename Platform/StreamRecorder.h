#pragma once
// MP4 (H.264, libx264 ultrafast) and WebM (VP9, libvpx-vp9 realtime, one thread) recordings: frames go down a pipe
// to one ffmpeg, converted here to yuv420p (Platform/Yuv420.h; ffmpeg's own conversion cost as much as encoding).
// Frames of odd width or height are padded by one black row or column. docs/app.md, "Video".

#include <cstdint>
#include <string>
#include <vector>

#include "Platform/FfmpegProcess.h"
#include "Platform/VideoRecorder.h"

class StreamRecorder final : public VideoRecorder {
public:
    /// webm: VP9 in WebM, else H.264 in MP4.
    StreamRecorder(const VideoTarget& target, bool webm) : t(target), webm(webm) {}
    ~StreamRecorder() override { Abort(); }

    bool Start(std::string* error) override;
    bool Record(const Image& frame, int index, std::string* error) override;
    /// Ends the stream, waits for ffmpeg and checks the file plays (ffmpeg may exit 0 and leave a file without
    /// its trailer).
    bool Finish(int frames, std::string* error) override;
    void Abort() override;

private:
    const VideoTarget& t;
    bool webm;
    FfmpegChild ffmpeg;
    std::vector<std::uint8_t> yuv;  // a frame as sent to ffmpeg
};
