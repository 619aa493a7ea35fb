#pragma once
// An 8-bit RGB image, rows top to bottom (PNG order). Frames, goldens and diff images all use it.

#include <cstdint>
#include <vector>

struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgb;  ///< width * height * 3 bytes

    Image() = default;
    Image(int w, int h) : width(w), height(h), rgb(std::size_t(w) * std::size_t(h) * 3, 0) {}
    std::uint8_t* Pixel(int x, int y) { return &rgb[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3]; }
    const std::uint8_t* Pixel(int x, int y) const {
        return &rgb[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3];
    }
    bool operator==(const Image& o) const { return width == o.width && height == o.height && rgb == o.rgb; }
};
