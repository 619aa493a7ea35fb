#pragma once
// The one rule for a physics step a user gives (docs/app.md, "Steps"): `--dt`, `--set dt=` and a scene file's
// world.step. A step is a decimal or a fraction n/d in seconds. The host's clock counts whole microseconds (and
// exact fractions n/d with n, d <= 10^6 for --dt, Application/FrameClock.h), so any other value is rounded to the
// nearest microsecond and the caller prints a one-line note saying so; a positive value that rounds to 0 is refused.
// GL-free, header-only.

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

/// Microseconds per second: the step's unit of rounding.
constexpr long long kStepMicrosPerSecond = 1000000;

namespace step_value_detail {
inline bool ParseFinite(const std::string& text, double* out) {
    if (text.empty()) return false;
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(text.c_str(), &end);
    if (errno != 0) return false;  // out of a double's range: "1e-400" must not become 0, the host's step
    if (end == text.c_str() || *end != '\0' || !std::isfinite(v)) return false;
    *out = v;
    return true;
}
}  // namespace step_value_detail

/// Parses a step in seconds written as a decimal ("0.0166666667", "1e-3") or a fraction ("1/60") into *seconds
/// (finite, >= 0). False for anything else, a negative value or a zero denominator.
inline bool ParseStepSeconds(const std::string& text, double* seconds) {
    const std::size_t slash = text.find('/');
    double v = 0.0;
    if (slash == std::string::npos) {
        if (!step_value_detail::ParseFinite(text, &v)) return false;
    } else {
        double num = 0.0, den = 0.0;
        if (!step_value_detail::ParseFinite(text.substr(0, slash), &num) ||
            !step_value_detail::ParseFinite(text.substr(slash + 1), &den) || !(den > 0.0))
            return false;
        v = num / den;
    }
    if (!(v >= 0.0) || !std::isfinite(v)) return false;
    *seconds = v;
    return true;
}

/// The nearest whole number of microseconds to `seconds` (finite, >= 0, at most a few hours); *exact says whether
/// that is `seconds` itself to a float's precision (the engine's type: the float nearest 0.03 counts as 30000 us).
inline long long StepMicros(double seconds, bool* exact) {
    const double micros = seconds * double(kStepMicrosPerSecond);
    const long long rounded = std::llround(micros);
    *exact = std::fabs(micros - double(rounded)) <= 1.2e-7 * micros;
    return rounded;
}

/// `micros` microseconds in seconds, as the shortest decimal ("0.016667").
inline std::string StepText(long long micros) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6f", double(micros) / double(kStepMicrosPerSecond));
    std::string s = text;
    while (s.size() > 1 && s.back() == '0') s.pop_back();
    if (!s.empty() && s.back() == '.') s.pop_back();
    return s;
}

/// The note for a rounded step: "0.0166666667 s rounded to 0.016667 s (a step is a whole number of
/// microseconds; ...)"; the caller puts what was given in front.
inline std::string StepRoundedNote(const std::string& given, long long micros) {
    return given + " s rounded to " + StepText(micros) +
           " s (a step is a whole number of microseconds; docs/app.md, \"Steps\")";
}
