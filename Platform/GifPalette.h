#pragma once
// The palette side of a GIF recording (Platform/VideoEncoder.h, docs/app.md "Video"): while the parts of a recording
// meet at most 256 colours, the palette is exactly those colours, each pixel stored as its colour's index. The
// parts of one run share the palette (the joined GIF then needs no local tables); a part that meets a 257th colour
// is handed to ffmpeg's palettegen, and the next part starts a new run.

#include <cstdint>
#include <vector>

class GifPalette {
public:
    static constexpr int kMaxColours = 256;

    /// The index of a colour (0xRRGGBB) in the run's palette, adding it at the end; -1 if the palette already holds
    /// 256 others.
    int IndexOf(std::uint32_t rgb);
    /// Forgets every colour: a new run starts (Run() goes up by one; 0 before the first).
    void StartRun();
    int Run() const { return run; }
    /// The run's colours (0xRRGGBB) by index, in the order they were met.
    const std::vector<std::uint32_t>& Colours() const { return colours; }

private:
    std::vector<std::uint32_t> colours;
    std::uint64_t slots[512] = {};  // open addressing: the colour with bit 24 set, its index in bits 25-32; 0 empty
    int run = 0;
};

/// ffmpeg's raw pal8 palette of `colours` (at most 256) into out: 256 entries of 0xAARRGGBB, little-endian; unused
/// entries transparent (the GIF encoder uses one for the pixels a frame leaves unchanged).
void Pal8Palette(const std::vector<std::uint32_t>& colours, std::uint8_t out[1024]);
/// A GIF global colour table of `colours` (at most 256): 256 RGB entries, the colours by index, then black.
std::vector<std::uint8_t> GifColourTable(const std::vector<std::uint32_t>& colours);
