#include "Application/FrameClock.h"

#include <gtest/gtest.h>

TEST(ParseRational, DecimalsAndFractionsAreExact) {
    Rational r;
    ASSERT_TRUE(ParseRational("0.03", &r));
    EXPECT_EQ(r.num, 3);
    EXPECT_EQ(r.den, 100);
    ASSERT_TRUE(ParseRational("1/30", &r));
    EXPECT_EQ(r.num, 1);
    EXPECT_EQ(r.den, 30);
    ASSERT_TRUE(ParseRational("62.5", &r));
    EXPECT_EQ(r.num, 125);
    EXPECT_EQ(r.den, 2);
    ASSERT_TRUE(ParseRational("60", &r));
    EXPECT_EQ(r.num, 60);
    EXPECT_EQ(r.den, 1);
}

TEST(ParseRational, RejectsZeroNegativeAndJunk) {
    Rational r;
    for (const char* bad : {"0", "0.0", "-1", "1/0", "abc", "", ".", "1e3", "0.0000001", "1..2", "1/2/3"})
        EXPECT_FALSE(ParseRational(bad, &r)) << bad;
}

TEST(FrameClock, BookStepsAtSixtyFramesPerSecond) {
    // Frame 1/60 s, step 0.03 s: ticks of 1/300 s, 5 per frame, 9 per step; strict '>' as main-win32.
    FrameClock clock({1, 60}, {3, 100});
    EXPECT_EQ(clock.TicksPerSecond(), 300);
    EXPECT_EQ(clock.FrameTicks(), 5);
    EXPECT_EQ(clock.StepTicks(), 9);
    EXPECT_EQ(clock.AdvanceFrame(), 0);  // 5
    EXPECT_EQ(clock.AdvanceFrame(), 1);  // 10 > 9 -> 1 left
    EXPECT_EQ(clock.AdvanceFrame(), 0);  // 6
    EXPECT_EQ(clock.AdvanceFrame(), 1);  // 11 -> 2
    EXPECT_EQ(clock.RemainderTicks(), 2);
}

TEST(FrameClock, StrictComparisonHoldsBackAnExactMultiple) {
    // Frame = step = 1/30: the accumulator equals the step after one frame, which is not '>' it.
    FrameClock clock({1, 30}, {1, 30});
    EXPECT_EQ(clock.AdvanceFrame(), 0);
    EXPECT_EQ(clock.AdvanceFrame(), 1);
    EXPECT_EQ(clock.AdvanceFrame(), 1);
}

TEST(FrameClock, NoDriftOverAMillionFrames) {
    FrameClock clock({1, 60}, {3, 100});
    const std::int64_t frames = 1000000;
    for (std::int64_t i = 0; i < frames; ++i) clock.AdvanceFrame();
    // 1e6 frames = 50000/3 s exactly; steps = floor of (total ticks - 1) / 9 with the strict comparison:
    // 5e6 ticks, 555555 steps use 4999995, leaving 5 (5 is not > 9).
    EXPECT_EQ(clock.Steps(), 555555);
    EXPECT_EQ(clock.RemainderTicks(), 5);
    EXPECT_EQ(clock.Steps() * clock.StepTicks() + clock.RemainderTicks(), frames * clock.FrameTicks());
    EXPECT_DOUBLE_EQ(clock.FrameSeconds(), 1000000.0 / 60.0);
}

// The auto model may refine the step during a run (docs/model-choice.md): the clock keeps every tick it has
// accumulated, even when the new step needs a finer tick (1/7 s does not divide 1/300 s), and from then on
// hands out steps of the new length.
TEST(FrameClock, SetStepKeepsTheAccumulatedTimeExactly) {
    FrameClock clock({1, 60}, {3, 100});
    for (int i = 0; i < 7; ++i) clock.AdvanceFrame();
    const std::int64_t before = clock.Steps();
    const double remainder = double(clock.RemainderTicks()) / double(clock.TicksPerSecond());
    clock.SetStep({1, 7});
    EXPECT_EQ(clock.TicksPerSecond(), 2100);
    EXPECT_EQ(clock.StepTicks(), 300);
    EXPECT_EQ(clock.FrameTicks(), 35);
    EXPECT_DOUBLE_EQ(double(clock.RemainderTicks()) / double(clock.TicksPerSecond()), remainder);
    for (int i = 0; i < 600; ++i) clock.AdvanceFrame();
    const std::int64_t after = clock.Steps() - before;
    // Every tick of the 607 frames is in a step of its length or in the remainder.
    const std::int64_t tps = clock.TicksPerSecond();
    EXPECT_EQ(before * 3 * tps / 100 + after * tps / 7 + clock.RemainderTicks(), 607 * tps / 60);
    EXPECT_EQ(after, 70);  // floor((600 / 60 + remainder) * 7): 10.03 s of 1/7 s steps
    // The same step again changes nothing.
    clock.SetStep({1, 7});
    EXPECT_EQ(clock.TicksPerSecond(), tps);
    EXPECT_EQ(clock.StepTicks(), 300);
}

TEST(FrameClock, PhysicsTimeLagsByTheOwedStepAndLandsOnTheFramesTime) {
    // Step 0.1 s at 60 frames per second: after 90 frames (1.5 s) the strict rule has run 14 steps (1.4 s) and
    // owes 0.1 s; landing hands it out as a 15th step and the physics is at 1.5 s.
    FrameClock clock({1, 60}, {1, 10});
    for (int i = 0; i < 90; ++i) clock.AdvanceFrame();
    EXPECT_EQ(clock.Steps(), 14);
    EXPECT_NEAR(clock.PhysicsSeconds(), 1.4, 1e-12);
    EXPECT_NEAR(clock.LandOnFrameTime(), 0.1, 1e-12);
    EXPECT_EQ(clock.Steps(), 15);
    EXPECT_DOUBLE_EQ(clock.PhysicsSeconds(), clock.FrameSeconds());
    EXPECT_EQ(clock.LandOnFrameTime(), 0.0);  // nothing owed any more
    EXPECT_EQ(clock.Steps(), 15);
    // The book's step: 91 frames (455 ticks of 1/300 s) run 50 steps and owe 5 ticks; the landing step is 5 ticks.
    FrameClock book({1, 60}, {3, 100});
    for (int i = 0; i < 91; ++i) book.AdvanceFrame();
    EXPECT_NEAR(book.PhysicsSeconds(), 1.5, 1e-12);
    EXPECT_NEAR(book.LandOnFrameTime(), 5.0 / 300.0, 1e-12);
    EXPECT_NEAR(book.PhysicsSeconds(), 91.0 / 60.0, 1e-12);
}
