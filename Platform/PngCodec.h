#pragma once
// PNG encoding and decoding of RGB frames through libpng, and the whole-or-nothing file write.

#include <cstdint>
#include <string>
#include <vector>

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
/// Decodes any PNG libpng reads (palette, grey, alpha, 16-bit) to 8-bit RGB; alpha is dropped.
bool DecodePng(const std::vector<std::uint8_t>& bytes, Image* img, std::string* error);
bool ReadFileBytes(const std::string& path, std::vector<std::uint8_t>* bytes, std::string* error);
bool ReadPngFile(const std::string& path, Image* img, std::string* error);
/// Writes bytes to path whole or not at all: a temporary file in the same directory, flushed, then renamed
/// over path. On failure the temporary is removed and *error names the path and the reason.
bool WriteFileAtomic(const std::string& path, const std::vector<std::uint8_t>& bytes, std::string* error);
