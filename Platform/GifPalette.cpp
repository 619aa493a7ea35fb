#include "Platform/GifPalette.h"

#include <algorithm>
#include <iterator>

int GifPalette::IndexOf(std::uint32_t rgb) {
    // Open addressing in 512 slots for at most 256 colours: a slot holds the colour with bit 24 set and its index
    // (the order in which the run met it) in bits 25-32; 0 is empty.
    const std::uint64_t key = rgb | 0x1000000u;
    for (std::uint32_t h = (rgb * 2654435761u) >> 23;; h = (h + 1) & 511u) {
        const std::uint64_t slot = slots[h];
        if (slot == 0) {
            if (colours.size() == std::size_t(kMaxColours)) return -1;
            slots[h] = key | std::uint64_t(colours.size()) << 25;
            colours.push_back(rgb);
            return int(colours.size() - 1);
        }
        if ((slot & 0x1FFFFFFu) == key) return int(slot >> 25);
    }
}

void GifPalette::StartRun() {
    colours.clear();
    std::fill(std::begin(slots), std::end(slots), std::uint64_t(0));
    ++run;
}

void Pal8Palette(const std::vector<std::uint32_t>& colours, std::uint8_t out[1024]) {
    std::fill(out, out + 1024, std::uint8_t(0));
    for (std::size_t k = 0; k < colours.size(); ++k) {
        const std::uint32_t c = colours[k];
        out[4 * k] = std::uint8_t(c), out[4 * k + 1] = std::uint8_t(c >> 8);
        out[4 * k + 2] = std::uint8_t(c >> 16), out[4 * k + 3] = 255;
    }
}

std::vector<std::uint8_t> GifColourTable(const std::vector<std::uint32_t>& colours) {
    std::vector<std::uint8_t> table(768, 0);
    for (std::size_t c = 0; c < colours.size(); ++c) {
        const std::uint32_t rgb = colours[c];
        table[3 * c] = std::uint8_t(rgb >> 16), table[3 * c + 1] = std::uint8_t(rgb >> 8);
        table[3 * c + 2] = std::uint8_t(rgb);
    }
    return table;
}
