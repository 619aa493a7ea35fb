#pragma once
// PNG encoding and decoding of RGB frames through libpng, and bounded PNG file reads. The whole-or-nothing
// file write (WriteFileAtomic) lives in Platform/Files/AtomicFile.h, included here for its callers.

#include <cstdint>
#include <string>
#include <vector>

#include "Platform/Files/AtomicFile.h"
#include "Platform/Image.h"

/// Row filter: one fixed filter for every row, or libpng's per-row adaptive choice (much slower).
enum class PngFilter { None, Sub, Up, Adaptive };

/// Encoder settings, chosen by measurement on rendered 800x600 frames (docs/app.md): zlib level 3 with no
/// row filter is as fast as level 1 (about 2.8 ms a frame against 3.2-3.9 ms for Up or Sub, 9 ms for libpng's
/// adaptive choice and 16-22 ms for stb_image_write) and its files are 11 % smaller.
struct PngOptions {
    int level = 3;  ///< zlib level 0..9
    PngFilter filter = PngFilter::None;
};

/// Encodes img as an 8-bit RGB PNG into *out (replacing its contents). Output depends only on img and
/// options. False with *error on a libpng failure.
bool EncodePng(const Image& img, const PngOptions& options, std::vector<std::uint8_t>* out, std::string* error);
/// Largest side a decoded PNG may have: the largest frame (--size up to 8192x8192).
constexpr int kMaxPngSide = 8192;
/// Largest PNG file read (bytes): an 8192x8192 frame stored uncompressed is about 201 MB.
constexpr std::size_t kMaxPngFileBytes = std::size_t(256) << 20;

/// Reads only the header of a PNG: its width and height, allocating nothing for the pixels. False with
/// *error when bytes are not a PNG.
bool ReadPngHeader(const std::vector<std::uint8_t>& bytes, int* width, int* height, std::string* error);
/// Decodes any PNG libpng reads (palette, grey, alpha, 16-bit, interlaced) by converting it to 8-bit RGBA
/// (16-bit channels keep their high byte, no gamma), then drops alpha. Refuses a side above kMaxPngSide
/// before allocating. False with *error on a malformed or truncated file.
bool DecodePng(const std::vector<std::uint8_t>& bytes, Image* img, std::string* error);
/// Reads a regular file of at most kMaxPngFileBytes (never a FIFO or device). False with *error naming path.
bool ReadFileBytes(const std::string& path, std::vector<std::uint8_t>* bytes, std::string* error);
/// ReadFileBytes then DecodePng; *error names the path.
bool ReadPngFile(const std::string& path, Image* img, std::string* error);
