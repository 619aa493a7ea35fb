// The GIF palette (Platform/GifPalette.h): colours indexed in the order met, at most 256 a run, a new run starting
// afresh; the pal8 and GIF-table bytes ffmpeg and GifJoin read.
#include "Platform/GifPalette.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

TEST(GifPalette, IndexesColoursInTheOrderMetAndRefusesThe257th) {
    GifPalette palette;
    EXPECT_EQ(palette.Run(), 0);
    palette.StartRun();
    EXPECT_EQ(palette.IndexOf(0xFF0000u), 0);
    EXPECT_EQ(palette.IndexOf(0x00FF00u), 1);
    EXPECT_EQ(palette.IndexOf(0xFF0000u), 0);  // met before: the same index, nothing added
    for (std::uint32_t c = 0; c < 254; ++c) EXPECT_EQ(palette.IndexOf(0x000100u * c + 7u), int(c) + 2);
    ASSERT_EQ(palette.Colours().size(), 256u);
    EXPECT_EQ(palette.IndexOf(0x123456u), -1);  // a 257th colour
    EXPECT_EQ(palette.IndexOf(0x00FF00u), 1);   // the full palette still finds its own
    palette.StartRun();
    EXPECT_EQ(palette.Run(), 2);
    EXPECT_TRUE(palette.Colours().empty());
    EXPECT_EQ(palette.IndexOf(0x123456u), 0);
}

TEST(GifPalette, WritesPal8EntriesAndAGifColourTable) {
    const std::vector<std::uint32_t> colours = {0x102030u, 0xA0B0C0u};
    std::uint8_t pal8[1024];
    Pal8Palette(colours, pal8);
    const std::uint8_t first[8] = {0x30, 0x20, 0x10, 255, 0xC0, 0xB0, 0xA0, 255};  // 0xAARRGGBB, little-endian
    for (int i = 0; i < 8; ++i) EXPECT_EQ(pal8[i], first[i]) << i;
    for (int i = 8; i < 1024; ++i) ASSERT_EQ(pal8[i], 0) << i;  // unused entries transparent
    const std::vector<std::uint8_t> table = GifColourTable(colours);
    ASSERT_EQ(table.size(), 768u);
    const std::uint8_t rgb[6] = {0x10, 0x20, 0x30, 0xA0, 0xB0, 0xC0};
    for (int i = 0; i < 6; ++i) EXPECT_EQ(table[i], rgb[i]) << i;
    for (int i = 6; i < 768; ++i) ASSERT_EQ(table[i], 0) << i;  // then black
}
