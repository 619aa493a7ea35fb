#include "Platform/Yuv420.h"

#include <cstddef>

namespace {

// BT.601, limited range, in 8-bit fixed point (coefficients x 256, rounded; Y's sum to 220, so white is
// 16 + 219 = 235, and U's and V's to 0, so greys carry no chroma): Y = 16 + (66 R + 129 G + 25 B) / 256, U = 128 + (-38
// R - 74 G + 112 B) / 256, V = 128 + (112 R - 94 G - 18 B) / 256.
inline std::uint8_t Luma(int r, int g, int b) { return std::uint8_t(16 + ((66 * r + 129 * g + 25 * b + 128) >> 8)); }

/// r, g, b: sums of four samples (0..1020); the mean's chroma, rounded.
inline std::uint8_t ChromaU(int r, int g, int b) {
    return std::uint8_t(128 + ((-38 * r - 74 * g + 112 * b + 512) >> 10));
}
inline std::uint8_t ChromaV(int r, int g, int b) {
    return std::uint8_t(128 + ((112 * r - 94 * g - 18 * b + 512) >> 10));
}

}  // namespace

void RgbToYuv420(const Image& img, std::vector<std::uint8_t>* out) {
    const int w = img.width, h = img.height, pw = EvenSide(w), ph = EvenSide(h);
    const std::size_t lumaSize = std::size_t(pw) * std::size_t(ph), chromaWidth = std::size_t(pw / 2);
    out->resize(lumaSize * 3 / 2);
    std::uint8_t* yPlane = out->data();
    std::uint8_t* uPlane = yPlane + lumaSize;
    std::uint8_t* vPlane = uPlane + lumaSize / 4;
    // Padding is black: RGB 0 (Y 16, and it weighs in its chroma block as 0).
    auto at = [&](int x, int y, int c) -> int {
        return x < w && y < h ? img.rgb[(std::size_t(y) * std::size_t(w) + std::size_t(x)) * 3 + std::size_t(c)] : 0;
    };
    for (int y = 0; y < ph; y += 2) {
        const bool inside = y + 1 < h;
        const std::uint8_t* row0 = img.rgb.data() + std::size_t(y) * std::size_t(w) * 3;
        const std::uint8_t* row1 = inside ? row0 + std::size_t(w) * 3 : nullptr;
        std::uint8_t* y0 = yPlane + std::size_t(y) * std::size_t(pw);
        std::uint8_t* y1 = y0 + pw;
        std::uint8_t* u = uPlane + std::size_t(y / 2) * chromaWidth;
        std::uint8_t* v = vPlane + std::size_t(y / 2) * chromaWidth;
        const int fast = inside ? w & ~1 : 0;  // whole 2x2 blocks inside the image
        for (int x = 0; x < fast; x += 2) {
            const std::uint8_t* a = row0 + 3 * x;
            const std::uint8_t* b = row1 + 3 * x;
            y0[x] = Luma(a[0], a[1], a[2]);
            y0[x + 1] = Luma(a[3], a[4], a[5]);
            y1[x] = Luma(b[0], b[1], b[2]);
            y1[x + 1] = Luma(b[3], b[4], b[5]);
            const int r = a[0] + a[3] + b[0] + b[3], g = a[1] + a[4] + b[1] + b[4], bl = a[2] + a[5] + b[2] + b[5];
            u[x / 2] = ChromaU(r, g, bl);
            v[x / 2] = ChromaV(r, g, bl);
        }
        for (int x = fast; x < pw; x += 2) {  // blocks that reach into the padding
            int r = 0, g = 0, bl = 0;
            for (int dy = 0; dy < 2; ++dy)
                for (int dx = 0; dx < 2; ++dx) {
                    const int pr = at(x + dx, y + dy, 0), pg = at(x + dx, y + dy, 1), pb = at(x + dx, y + dy, 2);
                    (dy == 0 ? y0 : y1)[x + dx] = Luma(pr, pg, pb);
                    r += pr, g += pg, bl += pb;
                }
            u[x / 2] = ChromaU(r, g, bl);
            v[x / 2] = ChromaV(r, g, bl);
        }
    }
}
