#pragma once
// Joining two GIF files that share one header (the same screen descriptor and global colour table, as two
// paletteuse runs with one palette write them): the frames of the second are appended to the first. The GIF
// recording maps its frames in two ffmpeg processes at once and joins the halves (Platform/VideoEncoder.cpp,
// docs/app.md "Video"). GIF89a layout: 6-byte signature, 7-byte logical screen descriptor, the optional global
// colour table, then extension blocks (0x21), image descriptors (0x2C) and the trailer (0x3B).

#include <cstddef>
#include <string>

/// Offset of the first frame of a GIF in `bytes`: its graphic control extension (0x21 0xF9), or its image
/// descriptor (0x2C) when it has none; application and comment extensions before it are skipped. False when
/// `bytes` is not a GIF87a/GIF89a stream or ends before a frame.
bool GifFirstFrameOffset(const std::string& bytes, std::size_t* offset);

/// Appends the frames of the GIF file `second` to the GIF file `first`, in place: `first` loses its trailer and
/// gets `second` from its first frame on. Both must start with the same bytes up to their first frames' screen
/// descriptor and global colour table (else nothing is changed and *error says why). False with *error naming
/// the file on a read or write failure.
bool AppendGifFrames(const std::string& first, const std::string& second, std::string* error);
