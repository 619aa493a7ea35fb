// Joining GIF parts and replacing a global table (Platform/GifJoin.h) on hand-made 1x1 GIFs: the first part's header
// stands, later parts' images get their part's palette as a local colour table (unless it equals the first's), later
// loop extensions are dropped, and malformed parts are refused, naming the part. The recorder's GIFs, joined and
// decoded by ffmpeg, are checked pixel for pixel in VideoEncoder_test.cpp.
#include "Platform/GifJoin.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace {

using Bytes = std::vector<std::uint8_t>;

Bytes Cat(std::initializer_list<Bytes> parts) {
    Bytes out;
    for (const Bytes& p : parts) out.insert(out.end(), p.begin(), p.end());
    return out;
}

/// GIF89a, screen w x 1, a global table of two colours (packed 0x80: present, 2 entries).
Bytes Header(std::uint8_t w, const Bytes& table) {
    return Cat({{'G', 'I', 'F', '8', '9', 'a', w, 0, 1, 0, 0x80, 0, 0}, table});
}
const Bytes kLoop = {0x21, 0xFF, 11, 'N', 'E', 'T', 'S', 'C', 'A', 'P', 'E', '2', '.', '0', 3, 1, 0, 0, 0};
const Bytes kDelay = {0x21, 0xF9, 4, 0, 2, 0, 0, 0};  // graphic control: 2/100 s
/// A 1x1 image of colour index 0: descriptor (no local table), LZW code size 2, codes clear, 0, end.
const Bytes kImage = {0x2C, 0, 0, 0, 0, 1, 0, 1, 0, 0x00, 2, 2, 0x44, 0x01, 0};
const Bytes kTrailer = {0x3B};
const Bytes kRedBlack = {255, 0, 0, 0, 0, 0};
const Bytes kGreenBlack = {0, 255, 0, 0, 0, 0};

TEST(GifJoin, LaterPartsBringTheirPaletteAsLocalTables) {
    const Bytes a = Cat({Header(1, kRedBlack), kLoop, kDelay, kImage, kTrailer});
    const Bytes b = Cat({Header(1, kGreenBlack), kLoop, kDelay, kImage, kDelay, kImage, kTrailer});
    Bytes out;
    std::string error;
    ASSERT_TRUE(JoinGifs({a, b}, &out, &error)) << error;
    // The second part's images: the descriptor with a local table of two entries (0x80), the table, the data.
    const Bytes withTable =
        Cat({Bytes(kImage.begin(), kImage.begin() + 9), {0x80}, kGreenBlack, Bytes(kImage.begin() + 10, kImage.end())});
    EXPECT_EQ(out, Cat({Header(1, kRedBlack), kLoop, kDelay, kImage, kDelay, withTable, kDelay, withTable, kTrailer}));
}

TEST(GifJoin, TheLocalTableKeepsThePartsTableSizeAndTheInterlaceFlag) {
    // Part 2: a table of four entries (packed 0x81) and an interlaced image (descriptor packed 0x40): the local
    // table is announced with its size (0x80 | 1) and the interlace bit stays (0x40).
    const Bytes four = {0, 0, 255, 255, 255, 0, 1, 2, 3, 4, 5, 6};
    Bytes b = {'G', 'I', 'F', '8', '9', 'a', 1, 0, 1, 0, 0x81, 0, 0};
    b.insert(b.end(), four.begin(), four.end());
    Bytes interlaced = kImage;
    interlaced[9] = 0x40;
    b.insert(b.end(), interlaced.begin(), interlaced.end());
    b.push_back(0x3B);
    const Bytes a = Cat({Header(1, kRedBlack), kImage, kTrailer});
    Bytes out;
    std::string error;
    ASSERT_TRUE(JoinGifs({a, b}, &out, &error)) << error;
    const Bytes withTable =
        Cat({Bytes(kImage.begin(), kImage.begin() + 9), {0xC1}, four, Bytes(kImage.begin() + 10, kImage.end())});
    EXPECT_EQ(out, Cat({Header(1, kRedBlack), kImage, withTable, kTrailer}));
}

TEST(GifJoin, PartsWithTheFirstsPaletteAreCopiedAsTheyAre) {
    const Bytes a = Cat({Header(1, kRedBlack), kLoop, kDelay, kImage, kTrailer});
    Bytes out;
    std::string error;
    ASSERT_TRUE(JoinGifs({a, a, a}, &out, &error)) << error;
    EXPECT_EQ(out, Cat({Header(1, kRedBlack), kLoop, kDelay, kImage, kDelay, kImage, kDelay, kImage, kTrailer}));
    ASSERT_TRUE(JoinGifs({a}, &out, &error)) << error;
    EXPECT_EQ(out, a) << "one part is the whole";
}

TEST(GifJoin, AnImagesOwnLocalTableIsKept) {
    Bytes own = {0x2C, 0, 0, 0, 0, 1, 0, 1, 0, 0x80};
    own.insert(own.end(), {0, 0, 255, 0, 0, 0, 2, 2, 0x44, 0x01, 0});
    const Bytes a = Cat({Header(1, kRedBlack), kImage, kTrailer});
    const Bytes b = Cat({Header(1, kGreenBlack), own, kTrailer});
    Bytes out;
    std::string error;
    ASSERT_TRUE(JoinGifs({a, b}, &out, &error)) << error;
    EXPECT_EQ(out, Cat({Header(1, kRedBlack), kImage, own, kTrailer}));
}

TEST(GifJoin, AGlobalTableIsReplacedWithItsSize) {
    // A two-entry table (packed 0x80) replaced by four entries: packed 0x81, the new table, the rest unchanged.
    // The colour resolution and sort bits (0x78) stay.
    Bytes gif = Cat({Header(1, kRedBlack), kLoop, kImage, kTrailer});
    gif[10] |= 0x70;
    const Bytes four = {0, 0, 255, 255, 255, 0, 1, 2, 3, 4, 5, 6};
    std::string error;
    ASSERT_TRUE(ReplaceGlobalColourTable(&gif, four, &error)) << error;
    Bytes expected = Cat({Bytes{'G', 'I', 'F', '8', '9', 'a', 1, 0, 1, 0, 0xF1, 0, 0}, four, kLoop, kImage, kTrailer});
    EXPECT_EQ(gif, expected);
    EXPECT_FALSE(ReplaceGlobalColourTable(&gif, Bytes(9, 0), &error)) << "three entries: not a power of two";
    EXPECT_NE(error.find("9 bytes"), std::string::npos) << error;
    Bytes png = {'P', 'N', 'G'};
    EXPECT_FALSE(ReplaceGlobalColourTable(&png, four, &error));
    EXPECT_EQ(gif, expected) << "a refused table changes nothing";
}

TEST(GifJoin, MalformedPartsAreRefusedByNumber) {
    const Bytes good = Cat({Header(1, kRedBlack), kDelay, kImage, kTrailer});
    const struct {
        Bytes bad;
        const char* says;
    } cases[] = {
        {Bytes{'P', 'N', 'G'}, "is not a GIF"},
        {Cat({Header(1, kRedBlack), kDelay, kImage}), "ends before its trailer"},
        {Cat({Header(1, kRedBlack), Bytes(kImage.begin(), kImage.end() - 3)}), "ends inside an image"},
        {Cat({Header(1, kRedBlack), Bytes{0x21, 0xF9, 4, 0}}), "ends inside an extension"},
        {Cat({Header(2, kRedBlack), kImage, kTrailer}), "another screen size"},
        {Cat({Header(1, kRedBlack), Bytes{0x07}, kTrailer}), "unknown block"},
        {Bytes{'G', 'I', 'F', '8', '9', 'a', 1, 0, 1, 0, 0x87, 0, 0, 1, 2, 3}, "is not a GIF"},  // table cut short
    };
    for (const auto& c : cases) {
        Bytes out;
        std::string error;
        EXPECT_FALSE(JoinGifs({good, c.bad}, &out, &error)) << c.says;
        EXPECT_NE(error.find("GIF part 2 of 2"), std::string::npos) << error;
        EXPECT_NE(error.find(c.says), std::string::npos) << error;
    }
    Bytes out;
    std::string error;
    EXPECT_FALSE(JoinGifs({}, &out, &error));
    EXPECT_FALSE(error.empty());
}

}  // namespace
