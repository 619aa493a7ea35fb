#pragma once
// The project's seeded RNG. The book's spawns come from MSVC's rand() (never seeded, so seed 1):
// seed = seed * 214013 + 2531011; return (seed >> 16) & 0x7FFF, RAND_MAX 32767. Reproducing it gives the
// book's scenes exactly; glibc's rand() would not. No global state: each scene owns its generator.

#include <cstdint>

class MsvcRand {
public:
    static constexpr int kRandMax = 32767;
    explicit MsvcRand(uint32_t seed = 1) : state_(seed) {}
    void Seed(uint32_t seed) { state_ = seed; }
    /// Next value in [0, 32767], identical to MSVC's rand().
    int Next() {
        state_ = state_ * 214013u + 2531011u;
        return static_cast<int>((state_ >> 16) & 0x7FFFu);
    }
    /// The book's Random(min, max) = min + (rand()/RAND_MAX)*(max-min), bounds swapped if reversed.
    float Range(float min, float max) {
        if (max < min) {
            const float t = min;
            min = max;
            max = t;
        }
        return min + (static_cast<float>(Next()) / static_cast<float>(kRandMax)) * (max - min);
    }

private:
    uint32_t state_;
};
