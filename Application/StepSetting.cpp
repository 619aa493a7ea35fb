#include "Application/StepSetting.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numeric>

#include "Application/CommandLine.h"

std::string RationalText(const Rational& r) {
    return r.den == 1 ? std::to_string(r.num) : std::to_string(r.num) + "/" + std::to_string(r.den);
}

bool ApplyStepSetting(DemoBase& demo, const std::string& label, const std::string& text, Rational* hostStep,
                      std::string* error, std::string* note) {
    note->clear();
    ParameterSet& table = demo.Parameters();
    const bool inTable = table.Find("dt") != nullptr;
    std::string tableNote;  // the table rounds to microseconds; ParseHostStep's rule (exact n/d) is the one said
    if (inTable && !table.Set("dt", text, error, &tableNote)) return false;
    Rational parsed;
    std::string parseError, rounded;
    if (!ParseHostStep(text, &parsed, &parseError, &rounded)) {
        if (inTable) return true;  // a table's 0 (the host's step) or a step below --dt's range: the table's own
        *error = parseError;
        return false;
    }
    *hostStep = parsed;
    if (!rounded.empty()) *note = label + ": " + rounded;
    return true;
}

Rational HostStepOf(const Rational& hostStep, const DemoBase& demo) {
    const float demoStep = demo.PhysicsStep();
    if (!(demoStep > 0.0f) || !std::isfinite(demoStep)) return hostStep;
    if (float(hostStep.ToDouble()) == demoStep) return hostStep;
    const std::int64_t micros = std::llround(double(demoStep) * 1e6);  // exact to 1 us; 0.03f -> 3/100
    if (micros <= 0) return hostStep;
    const std::int64_t g = std::gcd(micros, std::int64_t(1000000));
    return {micros / g, std::int64_t(1000000) / g};
}

namespace {

bool ApplyOne(Options* o, DemoBase& demo, const std::string& label, const std::string& key, const std::string& value,
              std::string* error) {
    std::string reason, note;
    const bool ok = key == "dt" ? ApplyStepSetting(demo, label, value, &o->step, &reason, &note)
                                : demo.Parameters().Set(key, value, &reason, &note);
    if (!ok) {
        *error = label + ": " + reason;
        return false;
    }
    if (!note.empty()) std::fprintf(stderr, "physics-sandbox: %s\n", note.c_str());
    return true;
}

}  // namespace

bool ApplySetList(Options* o, DemoBase& demo, std::string* error) {
    const bool dtGiven = std::find(o->flagsGiven.begin(), o->flagsGiven.end(), "--dt") != o->flagsGiven.end();
    if (dtGiven) {
        const std::string exact = RationalText(o->step);
        if (!ApplyOne(o, demo, "--dt " + exact, "dt", exact, error)) return false;
    }
    const std::vector<std::pair<std::string, std::string>> sets = o->sets;
    for (const auto& [key, value] : sets) {
        if (!ApplyOne(o, demo, "--set " + key + "=" + value, key, value, error)) return false;
    }
    return true;
}
