#pragma once
// RGB frames to the YUV 4:2:0 planes video encoders take (yuv420p: a full-size Y plane, then U and V at half
// width and height), BT.601 with the limited "studio" range (Y 16-235, U and V 16-240), the conversion ffmpeg's
// scaler makes by default for these sizes. Done here because the scaler's conversion of rgb24 cost ffmpeg about
// as much as encoding the frame (docs/app.md, "Video").

#include <cstdint>
#include <vector>

#include "Platform/Image.h"

/// The even size a frame is padded to (yuv420p needs even sides).
inline int EvenSide(int n) { return n + (n & 1); }

/// Converts img into *out (resized to EvenSide(w) * EvenSide(h) * 3 / 2 bytes). An odd last row or column is
/// padded with black. Each chroma sample is the mean of its 2x2 block's RGB, converted.
void RgbToYuv420(const Image& img, std::vector<std::uint8_t>* out);
