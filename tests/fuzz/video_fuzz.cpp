// Fuzz target: bytes -> the checks a finished video passes before it replaces anything (Platform/VideoFileCheck.h):
// CheckMp4Layout and CheckWebmLayout read the file ffmpeg left, which a failed write can cut anywhere. The input
// is checked whole and cut at a point taken from its last byte (a write failure's truncation).
// docs/testing.md "Fuzzing".

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "Platform/VideoFileCheck.h"

namespace {

void Require(bool ok, const char* what) {
    if (ok) return;
    std::fprintf(stderr, "video_fuzz: check failed: %s\n", what);
    std::abort();
}

/// Reads within the first `size` bytes only, as a file of that length.
ReadAt Reader(const std::uint8_t* data, std::size_t size) {
    return [data, size](std::uint64_t offset, std::uint8_t* buf, std::size_t n) {
        if (offset > size || n > size - offset) return false;
        std::memcpy(buf, data + offset, n);
        return true;
    };
}

bool Contains(const std::uint8_t* data, std::size_t size, const char* word) {
    const std::size_t n = std::strlen(word);
    for (std::size_t i = 0; i + n <= size; ++i)
        if (std::memcmp(data + i, word, n) == 0) return true;
    return false;
}

void CheckLength(const std::uint8_t* data, std::size_t size) {
    std::string error;
    if (CheckMp4Layout(size, Reader(data, size), &error)) {
        Require(size >= 24 && std::memcmp(data + 4, "ftyp", 4) == 0, "an accepted MP4 starts with ftyp");
        Require(Contains(data, size, "moov") && Contains(data, size, "mdat"), "an accepted MP4 has moov and mdat");
    } else {
        Require(!error.empty(), "a refused MP4 says why");
    }
    error.clear();
    if (CheckWebmLayout(size, Reader(data, size), &error)) {
        Require(size >= 9 && data[0] == 0x1A && data[1] == 0x45 && data[2] == 0xDF && data[3] == 0xA3,
                "an accepted WebM starts with the EBML magic");
        // The Segment ends exactly at the end: one byte less is a truncated file.
        Require(!CheckWebmLayout(size - 1, Reader(data, size - 1), &error), "a WebM cut by a byte is refused");
    } else {
        Require(!error.empty(), "a refused WebM says why");
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    CheckLength(data, size);
    if (size > 1) CheckLength(data, std::size_t(data[size - 1]) * size / 256);
    return 0;
}
