#pragma once
// Checks a video file ffmpeg says it finished, before it replaces anything (docs/app.md, "Video"): ffmpeg can
// exit 0 after failing to write its trailer (a full disk, a file-size limit), leaving a file that does not play.
// The container's outer layout must tile the file (MP4: top-level boxes with ftyp, moov and mdat; WebM: the EBML
// header and a Segment of known size ending at the end of the file), and, when ffprobe is installed, the file
// must hold exactly the frames sent.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

/// Reads n bytes at offset into buf; false if they are not all there.
using ReadAt = std::function<bool(std::uint64_t offset, std::uint8_t* buf, std::size_t n)>;

/// MP4 (ISO base media): the top-level boxes of a file of fileSize bytes tile it exactly, the first is ftyp,
/// and moov and mdat are among them. False with *error saying what is wrong.
bool CheckMp4Layout(std::uint64_t fileSize, const ReadAt& read, std::string* error);

/// WebM (Matroska): the file starts with an EBML header, followed by a Segment whose size was written (not
/// "unknown", as an unfinished file has) and ends exactly at fileSize. False with *error saying what is wrong.
bool CheckWebmLayout(std::uint64_t fileSize, const ReadAt& read, std::string* error);

enum class VideoContainer { Mp4, Webm };

/// Checks the finished file at path: not empty, its container's layout (above), and, if ffprobe is on PATH,
/// exactly `frames` video packets (ffprobe's output goes to scratchPath, an existing file it overwrites; waited
/// for at most stallSeconds, Platform/FfmpegProcess.h). False with *error giving the reason.
bool CheckVideoFile(const std::string& path, VideoContainer container, int frames, const std::string& scratchPath,
                    double stallSeconds, std::string* error);
