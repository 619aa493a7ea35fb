#include "Math/Random.h"

#include <gtest/gtest.h>

// docs/book-reference.md §0: MSVC rand() with the default seed 1 yields these first outputs.
TEST(MsvcRand, FirstOutputsMatchMsvc) {
    MsvcRand rng;
    const int expected[] = {41, 18467, 6334, 26500, 19169, 15724, 11478, 29358};
    for (int value : expected) EXPECT_EQ(rng.Next(), value);
}

TEST(MsvcRand, RangeReproducesFirstCh14Particle) {
    // min (-4.3505, 4.5, -5.044834), max (3.3505, 8.5, 3.024834); calls x, y, z, bounce.
    MsvcRand rng;
    EXPECT_NEAR(rng.Range(-4.3505f, 3.3505f), -4.34086f, 5e-5f);
    EXPECT_NEAR(rng.Range(4.5f, 8.5f), 6.75434f, 5e-5f);
    EXPECT_NEAR(rng.Range(-5.044834f, 3.024834f), -3.48493f, 5e-5f);
    EXPECT_NEAR(rng.Range(0.0f, 1.0f), 0.80874f, 5e-5f);
}

TEST(MsvcRand, RangeSwapsReversedBounds) {
    MsvcRand a, b;
    EXPECT_FLOAT_EQ(a.Range(1.0f, 0.0f), b.Range(0.0f, 1.0f));
}

TEST(MsvcRand, SeedRestartsSequence) {
    MsvcRand rng(7);
    const int first = rng.Next();
    rng.Next();
    rng.Seed(7);
    EXPECT_EQ(rng.Next(), first);
}
