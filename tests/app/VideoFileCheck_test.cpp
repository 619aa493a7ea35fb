// The layout checks a finished video passes before it replaces anything (Platform/VideoFileCheck.h): hand-built
// MP4 boxes and WebM elements, whole, truncated and unfinished.
#include "Platform/VideoFileCheck.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

namespace {

using Bytes = std::vector<std::uint8_t>;

ReadAt Reader(const Bytes& bytes) {
    return [&bytes](std::uint64_t offset, std::uint8_t* buf, std::size_t n) {
        if (offset > bytes.size() || n > bytes.size() - offset) return false;
        std::memcpy(buf, bytes.data() + offset, n);
        return true;
    };
}

/// An MP4 box: 32-bit size, type, payload of `payload` zero bytes.
Bytes Box(const char* type, std::uint32_t payload) {
    const std::uint32_t size = 8 + payload;
    Bytes b = {std::uint8_t(size >> 24), std::uint8_t(size >> 16), std::uint8_t(size >> 8), std::uint8_t(size)};
    b.insert(b.end(), type, type + 4);
    b.resize(size, 0);
    return b;
}

Bytes Join(const std::vector<Bytes>& parts) {
    Bytes out;
    for (const Bytes& p : parts) out.insert(out.end(), p.begin(), p.end());
    return out;
}

bool Mp4(const Bytes& bytes, std::string* error) { return CheckMp4Layout(bytes.size(), Reader(bytes), error); }
bool Webm(const Bytes& bytes, std::string* error) { return CheckWebmLayout(bytes.size(), Reader(bytes), error); }

TEST(VideoFileCheck, Mp4BoxesMustTileTheFileWithFtypMoovAndMdat) {
    std::string error;
    const Bytes whole = Join({Box("ftyp", 8), Box("moov", 20), Box("free", 0), Box("mdat", 100)});
    EXPECT_TRUE(Mp4(whole, &error)) << error;
    // The trailer (moov) never written: what ffmpeg leaves when its last write fails.
    EXPECT_FALSE(Mp4(Join({Box("ftyp", 8), Box("free", 0), Box("mdat", 100)}), &error));
    EXPECT_NE(error.find("moov"), std::string::npos) << error;
    // Cut anywhere inside: the last box claims more than is left.
    for (const std::size_t cut : {std::size_t(3), std::size_t(20), whole.size() - 1}) {
        Bytes truncated(whole.begin(), whole.begin() + std::ptrdiff_t(cut));
        EXPECT_FALSE(Mp4(truncated, &error)) << cut;
    }
    EXPECT_FALSE(Mp4(Join({Box("moov", 20), Box("ftyp", 8), Box("mdat", 4)}), &error)) << "ftyp comes first";
    Bytes tiny = whole;
    tiny[3] = 4;  // an ftyp of 4 bytes cannot hold its own header
    EXPECT_FALSE(Mp4(tiny, &error));
    EXPECT_FALSE(Mp4(Bytes(64, 0xAB), &error)) << "not boxes at all";
}

TEST(VideoFileCheck, Mp4SizeZeroRunsToTheEndAndLargeSizesAreRead) {
    std::string error;
    Bytes last = Box("mdat", 40);
    last[0] = last[1] = last[2] = last[3] = 0;  // size 0: to the end of the file
    EXPECT_TRUE(Mp4(Join({Box("ftyp", 8), Box("moov", 4), last}), &error)) << error;
    // A 64-bit size (size field 1, then the size after the type).
    Bytes large = {0, 0, 0, 1, 'm', 'd', 'a', 't', 0, 0, 0, 0, 0, 0, 0, 24};
    large.resize(24, 0);
    EXPECT_TRUE(Mp4(Join({Box("ftyp", 8), Box("moov", 4), large}), &error)) << error;
    large[15] = 25;  // one byte more than there is
    EXPECT_FALSE(Mp4(Join({Box("ftyp", 8), Box("moov", 4), large}), &error));
    large[15] = 8;  // smaller than its own 16-byte header
    EXPECT_FALSE(Mp4(Join({Box("ftyp", 8), Box("moov", 4), large}), &error));
}

/// A WebM file: an EBML header of 5 payload bytes, then a Segment of `payload` bytes with an 8-byte size
/// field; unknownSize writes the size as "unknown" (all ones), as a muxer does before its trailer.
Bytes WebmFile(std::uint32_t payload, bool unknownSize) {
    Bytes b = {0x1A, 0x45, 0xDF, 0xA3, 0x85, 1, 2, 3, 4, 5, 0x18, 0x53, 0x80, 0x67, 0x01};
    for (int i = 6; i >= 0; --i) b.push_back(unknownSize ? 0xFF : std::uint8_t(std::uint64_t(payload) >> (8 * i)));
    b.resize(b.size() + payload, 0);
    return b;
}

TEST(VideoFileCheck, WebmSegmentMustHaveItsSizeWrittenAndEndAtTheEnd) {
    std::string error;
    EXPECT_TRUE(Webm(WebmFile(300, false), &error)) << error;
    EXPECT_FALSE(Webm(WebmFile(300, true), &error));
    EXPECT_NE(error.find("never written"), std::string::npos) << error;
    Bytes truncated = WebmFile(300, false);
    truncated.resize(truncated.size() - 1);
    EXPECT_FALSE(Webm(truncated, &error));
    Bytes longer = WebmFile(300, false);
    longer.push_back(0);
    EXPECT_FALSE(Webm(longer, &error)) << "bytes after the Segment";
    Bytes noSegment = WebmFile(300, false);
    noSegment[10] = 0x1F;
    EXPECT_FALSE(Webm(noSegment, &error));
    EXPECT_FALSE(Webm(Bytes(4, 0), &error));
    EXPECT_FALSE(Webm(Bytes(), &error));
}

}  // namespace
