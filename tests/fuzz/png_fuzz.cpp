// Fuzz target: bytes -> the PNG decoder -> the golden comparison against a fixed 4x4 frame, as a --compare run
// reads a golden. Calls DecodePng and EncodePng (Platform/PngCodec.h), CompareImages, MakeDiffImage and
// DescribeComparison (Platform/ImageCompare.h). The input is decoded as given and, when some chunk's CRC is
// wrong, once more with every complete chunk's CRC recomputed, so mutations also reach the chunk parsing
// behind libpng's CRC check. docs/testing.md "Fuzzing".

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "Platform/ImageCompare.h"
#include "Platform/PngCodec.h"

namespace {

void Require(bool ok, const char* what) {
    if (ok) return;
    std::fprintf(stderr, "png_fuzz: check failed: %s\n", what);
    std::abort();
}

// CRC-32 of the PNG specification (reflected polynomial 0xEDB88320), bit by bit: inputs are small.
std::uint32_t Crc32(const std::uint8_t* data, std::size_t size) {
    std::uint32_t crc = 0xFFFFFFFFu;
    for (std::size_t i = 0; i < size; ++i) {
        crc ^= data[i];
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return crc ^ 0xFFFFFFFFu;
}

// Rewrites the CRC of every complete chunk after the 8-byte signature (length, type, data, CRC).
std::vector<std::uint8_t> WithChunkCrcsFixed(std::vector<std::uint8_t> bytes) {
    std::size_t at = 8;
    while (at + 12 <= bytes.size()) {
        const std::size_t length = std::size_t(bytes[at]) << 24 | std::size_t(bytes[at + 1]) << 16 |
                                   std::size_t(bytes[at + 2]) << 8 | std::size_t(bytes[at + 3]);
        if (length > bytes.size() - at - 12) break;
        const std::uint32_t crc = Crc32(&bytes[at + 4], length + 4);
        for (int k = 0; k < 4; ++k) bytes[at + 8 + length + std::size_t(k)] = std::uint8_t(crc >> (24 - 8 * k));
        at += length + 12;
    }
    return bytes;
}

Image FixedFrame() {
    Image frame(4, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            std::uint8_t* p = frame.Pixel(x, y);
            p[0] = std::uint8_t(60 * x), p[1] = std::uint8_t(60 * y), p[2] = 128;
        }
    return frame;
}

void DecodeAndCompare(const std::vector<std::uint8_t>& bytes) {
    Image decoded;
    std::string error;
    if (!DecodePng(bytes, &decoded, &error)) {
        Require(!error.empty(), "a failed decode says why");
        return;
    }
    Require(decoded.width > 0 && decoded.height > 0, "a decoded image has pixels");
    Require(decoded.rgb.size() == std::size_t(decoded.width) * std::size_t(decoded.height) * 3, "3 bytes a pixel");

    const CompareThresholds thresholds;
    const CompareResult self = CompareImages(decoded, decoded, thresholds);
    Require(self.exact && self.passed, "an image matches itself exactly");

    static const Image golden = FixedFrame();
    const CompareResult r = CompareImages(golden, decoded, thresholds);
    const bool sameSize = decoded.width == golden.width && decoded.height == golden.height;
    Require(r.sizeMismatch != sameSize, "a size mismatch is reported as one");
    Require(!r.sizeMismatch || !r.passed, "a size mismatch never passes");
    Require(r.differingPixels >= 0 && r.differingPixels <= r.totalPixels, "differing pixels within the frame");
    Require(r.maxChannelDiff >= 0 && r.maxChannelDiff <= 255, "channel difference within 0..255");
    Require(!DescribeComparison(r, thresholds).empty(), "the comparison is described");
    const Image diff = MakeDiffImage(golden, decoded, thresholds);
    Require(diff.width == golden.width && diff.height == golden.height, "the diff image has the golden's size");

    // What a --compare run writes back (the actual frame) must decode to the same pixels.
    if (decoded.rgb.size() <= 3 * 4096) {
        std::vector<std::uint8_t> encoded;
        Image again;
        Require(EncodePng(decoded, PngOptions{}, &encoded, &error), "a decoded image encodes");
        Require(DecodePng(encoded, &again, &error) && again == decoded, "encode then decode is lossless");
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::vector<std::uint8_t> bytes(data, data + size);
    DecodeAndCompare(bytes);
    const std::vector<std::uint8_t> fixed = WithChunkCrcsFixed(bytes);
    if (fixed != bytes) DecodeAndCompare(fixed);
    return 0;
}
