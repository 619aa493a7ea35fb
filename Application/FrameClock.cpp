#include "Application/FrameClock.h"

#include <cctype>
#include <numeric>

namespace {

Rational Reduced(std::int64_t num, std::int64_t den) {
    const std::int64_t g = std::gcd(num, den);
    return {num / g, den / g};
}

bool ParseDecimal(const std::string& text, std::int64_t* num, std::int64_t* den) {
    std::int64_t n = 0, d = 1;
    bool digits = false, point = false;
    int decimals = 0;
    for (char c : text) {
        if (c == '.' && !point) {
            point = true;
        } else if (std::isdigit(static_cast<unsigned char>(c))) {
            if (n > 99999999) return false;
            n = n * 10 + (c - '0');
            digits = true;
            if (point) {
                if (++decimals > 6) return false;
                d *= 10;
            }
        } else {
            return false;
        }
    }
    if (!digits) return false;
    *num = n;
    *den = d;
    return true;
}

}  // namespace

bool ParseRational(const std::string& text, Rational* out) {
    const std::size_t slash = text.find('/');
    std::int64_t n = 0, d = 1;
    if (slash == std::string::npos) {
        if (!ParseDecimal(text, &n, &d)) return false;
    } else {
        std::int64_t n1, d1, n2, d2;
        if (!ParseDecimal(text.substr(0, slash), &n1, &d1) || !ParseDecimal(text.substr(slash + 1), &n2, &d2))
            return false;
        if (n2 == 0) return false;
        n = n1 * d2;
        d = d1 * n2;
    }
    if (n <= 0) return false;
    *out = Reduced(n, d);
    return out->num <= 1000000 && out->den <= 1000000;
}

Rational Reciprocal(const Rational& r) { return {r.den, r.num}; }

FrameClock::FrameClock(const Rational& frame, const Rational& step) : frameTime(frame) {
    // One tick = 1/lcm(frame.den, step.den) s; both times are then integers. With num, den <= 1e6 (what
    // ParseRational accepts) the tick counts stay below 1e18 < 2^63.
    ticksPerSecond = std::lcm(frame.den, step.den);
    frameTicks = frame.num * (ticksPerSecond / frame.den);
    stepTicks = step.num * (ticksPerSecond / step.den);
    frameSeconds = frame.ToDouble();
    stepSeconds = step.ToDouble();
}

int FrameClock::AdvanceFrame() {
    ++frames;
    accumulator += frameTicks;
    int n = 0;
    while (accumulator > stepTicks) {  // strict, as main-win32's `fixed_ellapsed > 0.03`
        accumulator -= stepTicks;
        ++n;
    }
    steps += n;
    return n;
}

void FrameClock::SetStep(const Rational& step) {
    const std::int64_t ticks = std::lcm(ticksPerSecond, step.den);
    const std::int64_t scale = ticks / ticksPerSecond;
    ticksPerSecond = ticks;
    frameTicks *= scale;
    accumulator *= scale;
    stepTicks = step.num * (ticksPerSecond / step.den);
    stepSeconds = step.ToDouble();
}

double FrameClock::FrameSeconds() const { return double(frames * frameTime.num) / double(frameTime.den); }

double FrameClock::PhysicsSeconds() const { return FrameSeconds() - double(accumulator) / double(ticksPerSecond); }

double FrameClock::LandOnFrameTime() {
    if (accumulator == 0) return 0.0;
    const double owed = double(accumulator) / double(ticksPerSecond);
    accumulator = 0;
    ++steps;
    return owed;
}
