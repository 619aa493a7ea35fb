#pragma once
// The fixed-step accumulator of docs/book-reference.md §1.2, in exact integer ticks. The frame time and the physics
// step are rationals; one tick is 1/lcm of their denominators, so both are whole numbers of ticks and the accumulator
// never drifts, however many frames run.

#include <cstdint>
#include <string>

/// A positive rational number num/den in lowest terms.
struct Rational {
    std::int64_t num = 0;
    std::int64_t den = 1;
    double ToDouble() const { return double(num) / double(den); }
};

/// Parses "0.03", "1/30", "60" or "62.5" exactly (no binary rounding). At most 6 decimals; the reduced
/// numerator and denominator at most 1e6. False for zero, negatives, non-numbers.
bool ParseRational(const std::string& text, Rational* out);
/// The reciprocal; requires a positive value.
Rational Reciprocal(const Rational& r);

class FrameClock {
public:
    /// frameTime: simulated seconds per output frame (1/60 by default); step: the fixed physics step
    /// (0.03 s, the book's GetFixedFPS()/1000, erratum 5.2-16). Both positive.
    FrameClock(const Rational& frameTime, const Rational& step);

    /// Advances by one output frame and returns how many fixed steps to run now: while accumulated > step
    /// (strictly, as the book), subtract one step.
    int AdvanceFrame();
    /// Changes the physics step from the next AdvanceFrame on (the auto model refining its step during a run,
    /// docs/model-choice.md). Exact: the tick becomes 1/lcm(ticks per second, step.den), the accumulated time is
    /// kept to the tick, and frames and steps go on counting. A step of the same value changes nothing.
    void SetStep(const Rational& step);
    /// Output frames advanced so far.
    std::int64_t Frames() const { return frames; }
    /// Fixed steps handed out so far.
    std::int64_t Steps() const { return steps; }
    /// Simulated seconds of output frames so far (frames * frameTime), rounded once.
    double FrameSeconds() const;
    /// Simulated seconds the physics has reached: the frames' time less what is still owed in the accumulator
    /// (the strict rule above leaves up to one step owed, so the physics lags the frames by (0, step]).
    double PhysicsSeconds() const;
    /// Ends a run on its frames' time: hands out what the accumulator still owes as one shortened step and
    /// returns its length in seconds (0 when nothing is owed). After it PhysicsSeconds() == FrameSeconds()
    /// (docs/app.md "Time").
    double LandOnFrameTime();
    /// Time left in the accumulator, in ticks (0 <= remainder <= step).
    std::int64_t RemainderTicks() const { return accumulator; }
    std::int64_t TicksPerSecond() const { return ticksPerSecond; }
    std::int64_t FrameTicks() const { return frameTicks; }
    std::int64_t StepTicks() const { return stepTicks; }
    float FrameSecondsFloat() const { return float(frameSeconds); }
    float StepSecondsFloat() const { return float(stepSeconds); }

private:
    std::int64_t ticksPerSecond;
    std::int64_t frameTicks;
    std::int64_t stepTicks;
    std::int64_t accumulator = 0;
    std::int64_t frames = 0;
    std::int64_t steps = 0;
    Rational frameTime;
    double frameSeconds;
    double stepSeconds;
};
