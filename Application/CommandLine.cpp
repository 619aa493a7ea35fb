#include "Application/CommandLine.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numeric>

#include "Demos/Scenes/StepValue.h"

namespace {

// ---- Value parsers: one per value type, each checked against the flag's range.

/// A base-10 integer in [min, max]; rejects junk, empty text and anything that overflows long long.
bool ParseCheckedInt(const std::string& text, long long min, long long max, long long* out) {
    if (text.empty() || text.find_first_not_of("+-0123456789") != std::string::npos) return false;
    char* end = nullptr;
    errno = 0;
    const long long v = std::strtoll(text.c_str(), &end, 10);
    if (errno != 0 || *end != '\0' || v < min || v > max) return false;
    *out = v;
    return true;
}

bool ParseFiniteFloat(const std::string& text, float* out) {
    if (text.empty()) return false;
    char* end = nullptr;
    errno = 0;
    const float v = std::strtof(text.c_str(), &end);
    if (errno != 0 || *end != '\0' || !std::isfinite(v)) return false;
    *out = v;
    return true;
}

std::vector<std::string> Split(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    for (;;) {
        const std::size_t at = text.find(separator, start);
        parts.push_back(text.substr(start, at == std::string::npos ? std::string::npos : at - start));
        if (at == std::string::npos) return parts;
        start = at + 1;
    }
}

// ---- The flag table: every flag once, with its value type, range and help text.

enum class ValueType { None, Int, Float, Rational, Step, Text, Size, FrameList, Vector3, KeyValue };

/// A parsed value; the field that matches the flag's ValueType is set.
struct FlagValue {
    long long integer = 0;
    float real = 0.0f;
    Rational rational;
    std::string text;
    int width = 0, height = 0;
    std::vector<int> frames;
    float vector[3] = {0.0f, 0.0f, 0.0f};
};

struct Flag {
    const char* name;     ///< "--frames"
    const char* metavar;  ///< "N" in the help; "" for a flag without a value
    ValueType type;
    double min, max;  ///< inclusive range of Int, Float and Rational values (and of each Size side, list entry)
    const char* help;
    void (*apply)(Options& o, const FlagValue& v);
    const char* choices = nullptr;  ///< Text flags with a fixed set of values: "a|b|c"
};

constexpr double kMaxFrames = 100000000;

const Flag kFlags[] = {
    {"--help", "", ValueType::None, 0, 0, "this text",
     [](Options& o, const FlagValue&) { o.mode = Options::Mode::Help; }},
    {"--list", "", ValueType::None, 0, 0, "print the demos: id, a tab, the title; one per line",
     [](Options& o, const FlagValue&) { o.mode = Options::Mode::List; }},
    {"--demo", "ID", ValueType::Text, 0, 0, "the demo to run (see --list)",
     [](Options& o, const FlagValue& v) { o.demo = v.text; }},
    {"--scene", "FILE", ValueType::Text, 0, 0,
     "run a scene file (docs/scenes.md) as a demo; --frames defaults to its duration",
     [](Options& o, const FlagValue& v) { o.scene = v.text; }},
    {"--export-scene", "FILE", ValueType::Text, 0, 0,
     "write the demo's scene (after --set) as a scene file and exit; says what the format cannot express",
     [](Options& o, const FlagValue& v) { o.exportScene = v.text; }},
    {"--frames", "N", ValueType::Int, 1, kMaxFrames,
     "output frames to run (default 1); one frame = 1/60 s of simulated time",
     [](Options& o, const FlagValue& v) { o.frames = int(v.integer), o.framesGiven = true; }},
    {"--out", "DIR", ValueType::Text, 0, 0,
     "write DIR/frame_00000.png ... (DIR is created); without it nothing is written",
     [](Options& o, const FlagValue& v) { o.outDir = v.text; }},
    {"--size", "WxH", ValueType::Size, 16, 8192, "frame size (default 800x600)",
     [](Options& o, const FlagValue& v) { o.width = v.width, o.height = v.height; }},
    {"--set", "KEY=VALUE", ValueType::KeyValue, 0, 0,
     "set a demo parameter (repeatable, applied in order); the panel shows the value",
     [](Options& o, const FlagValue& v) {
         const std::size_t eq = v.text.find('=');
         o.sets.emplace_back(v.text.substr(0, eq), v.text.substr(eq + 1));
     }},
    {"--params", "", ValueType::None, 0, 0,
     "print the demo's parameters (keys, ranges, values after --set and after the auto model's choice) and exit",
     [](Options& o, const FlagValue&) { o.showParams = true; }},
    {"--explain-model", "", ValueType::None, 0, 0,
     "with --set model=auto (or a scene file's \"model\": \"auto\"): print every candidate model with its "
     "estimated error and cost, the chosen one marked, and exit without running (exit 2 when none meets the budget)",
     [](Options& o, const FlagValue&) { o.explainModel = true; }},
    {"--state", "FILE", ValueType::Text, 0, 0,
     "write CSV: frame,time,body,kind,x,y,z,vx,vy,vz (one row per body per frame); FILE must not exist or be a "
     "regular file",
     [](Options& o, const FlagValue& v) { o.stateFile = v.text; }},
    {"--video", "FILE", ValueType::Text, 0, 0,
     "also record every frame into FILE (.mp4 H.264, .webm VP9 or .gif) through the ffmpeg program; the file "
     "appears when the run succeeds",
     [](Options& o, const FlagValue& v) { o.videoFile = v.text; }},
    {"--backend", "NAME", ValueType::Text, 0, 0,
     "headless GL: osmesa, egl, or auto (OSMesa when built in, else EGL); goldens are pinned to llvmpipe",
     [](Options& o, const FlagValue& v) { o.backend = v.text; }, "auto|osmesa|egl"},
    {"--window", "", ValueType::None, 0, 0,
     "open the book's interactive 800x600 window instead (needs a display); --demo picks the first demo, "
     "--frames N closes it after N frames",
     [](Options& o, const FlagValue&) { o.window = true; }},
    {"--no-ui", "", ValueType::None, 0, 0, "hide the ImGui panels",
     [](Options& o, const FlagValue&) { o.noUi = true; }},
    {"--camera-yaw", "DEG", ValueType::Float, -360, 360, "orbit camera yaw (rotation.x), replaces the demo's preset",
     [](Options& o, const FlagValue& v) { o.yaw = v.real, o.hasYaw = true; }},
    // The book clamps pitch to [-20, 80] when the mouse rotates; +-89 keeps LookAt well defined.
    {"--camera-pitch", "DEG", ValueType::Float, -89, 89, "orbit camera pitch (rotation.y)",
     [](Options& o, const FlagValue& v) { o.pitch = v.real, o.hasPitch = true; }},
    {"--camera-zoom", "D", ValueType::Float, 0.1, 500, "orbit camera distance to its target",
     [](Options& o, const FlagValue& v) { o.zoom = v.real, o.hasZoom = true; }},
    {"--camera-target", "X,Y,Z", ValueType::Vector3, 0, 0, "orbit camera target",
     [](Options& o, const FlagValue& v) { std::copy(v.vector, v.vector + 3, o.target), o.hasTarget = true; }},
    {"--orbit", "DEG", ValueType::Float, -360, 360, "add DEG of yaw every output frame (turntable)",
     [](Options& o, const FlagValue& v) { o.orbitDegreesPerFrame = v.real; }},
    {"--fps", "F", ValueType::Rational, 1, 1000, "output frames per simulated second (default 60; e.g. 62.5)",
     [](Options& o, const FlagValue& v) { o.frameTime = Reciprocal(v.rational); }},
    {"--dt", "S", ValueType::Step, 0.0001, 1,
     "fixed physics step in seconds (default 0.03 as the book; e.g. 1/30); other than a fraction n/d with n, d <= "
     "1000000, rounded to whole microseconds with a note",
     [](Options& o, const FlagValue& v) {
         o.step = v.rational;
         if (!v.text.empty()) o.notes.push_back(v.text);
     }},
    {"--only-frames", "A,B,...", ValueType::FrameList, 0, kMaxFrames,
     "write (and compare) only these frames; all frames are still simulated",
     [](Options& o, const FlagValue& v) { o.onlyFrames = v.frames; }},
    {"--compare", "DIR", ValueType::Text, 0, 0,
     "compare each written frame with DIR/<same name>; on a mismatch write "
     "OUT/mismatch/*.{expected,actual,diff,amplified}.png "
     "and OUT/compare.txt, exit 1 (DIR must not be OUT)",
     [](Options& o, const FlagValue& v) { o.compareDir = v.text; }},
    {"--update-golden", "", ValueType::None, 0, 0,
     "with --compare DIR: rewrite the goldens in DIR instead of comparing",
     [](Options& o, const FlagValue&) { o.updateGolden = true; }},
    {"--tolerance", "N", ValueType::Int, 0, 255, "per-channel difference a pixel may have and still match (default 8)",
     [](Options& o, const FlagValue& v) { o.thresholds.channelTolerance = int(v.integer); }},
    {"--max-diff", "F", ValueType::Float, 0, 1, "fraction of pixels allowed beyond the tolerance (default 0.002)",
     [](Options& o, const FlagValue& v) { o.thresholds.maxDifferingFraction = v.real; }},
    {"--min-ssim", "S", ValueType::Float, 0, 1,
     "a frame whose SSIM (luminance, 8x8 windows) is at least S passes whatever its pixel counts (default off)",
     [](Options& o, const FlagValue& v) { o.thresholds.minSsim = v.real; }},
    {"--png-level", "N", ValueType::Int, 0, 9, "zlib level (default 3)",
     [](Options& o, const FlagValue& v) { o.pngLevel = int(v.integer); }},
    {"--serial-encode", "", ValueType::None, 0, 0, "encode PNGs on the main thread (same files; for measurement)",
     [](Options& o, const FlagValue&) { o.encodeThread = false; }},
    {"--progress", "N", ValueType::Int, 0, kMaxFrames, "progress line on stderr every N frames (0 = automatic)",
     [](Options& o, const FlagValue& v) { o.progressEvery = int(v.integer); }},
    {"--quiet", "", ValueType::None, 0, 0, "no progress line and no summary",
     [](Options& o, const FlagValue&) { o.quiet = true; }},
    {"--threads", "N", ValueType::Int, 1, 256,
     "threads for the rigid-body step: pair search, manifolds and the soft solve (default: the hardware's "
     "concurrency; 1 = one thread); every N gives the same bits (docs/threads.md)",
     [](Options& o, const FlagValue& v) { o.threads = int(v.integer); }},
    {"--debug-nonfinite-at", "N", ValueType::Int, 0, kMaxFrames,
     "test hook: report frame N as non-finite (exercises exit code 3)",
     [](Options& o, const FlagValue& v) { o.debugNonFiniteAt = int(v.integer); }},
};

const Flag* FindFlag(const std::string& name) {
    if (name == "-h") return &kFlags[0];
    for (const Flag& f : kFlags)
        if (name == f.name) return &f;
    return nullptr;
}

std::string Number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.10g", v);
    return text;
}

std::string Range(const Flag& f) { return "[" + Number(f.min) + ", " + Number(f.max) + "]"; }

/// What a value of this flag must look like, for the error message.
std::string Expected(const Flag& f) {
    switch (f.type) {
        case ValueType::Int:
            return "expected an integer in " + Range(f);
        case ValueType::Float:
            return "expected a number in " + Range(f);
        case ValueType::Rational:
            return "expected a number or fraction (like 1/30) in " + Range(f);
        case ValueType::Step:
            return "expected a step in seconds, a number or fraction (like 1/30), in " + Range(f) +
                   " after rounding to whole microseconds";
        case ValueType::Size:
            return "expected WxH with " + Number(f.min) + " <= W, H <= " + Number(f.max);
        case ValueType::FrameList:
            return "expected frame numbers like 0,30,90, each in " + Range(f);
        case ValueType::Vector3:
            return "expected x,y,z";
        case ValueType::KeyValue:
            return "expected key=value";
        case ValueType::Text:
            if (f.choices != nullptr) {
                std::string list = f.choices;
                std::replace(list.begin(), list.end(), '|', ',');
                return "expected one of " + list;
            }
            return "expected a non-empty value";
        default:
            return "expected a non-empty value";
    }
}

bool ParseFrameList(const std::string& text, const Flag& f, std::vector<int>* out) {
    out->clear();
    for (const std::string& part : Split(text, ',')) {
        long long v = 0;
        if (!ParseCheckedInt(part, (long long)f.min, (long long)f.max, &v)) return false;
        out->push_back(int(v));
    }
    std::sort(out->begin(), out->end());
    out->erase(std::unique(out->begin(), out->end()), out->end());
    return true;
}

/// A step (docs/app.md, "Steps"): exact as a rational when ParseRational takes it, else any decimal or fraction
/// rounded to whole microseconds, with the note in v->text. In f's range either way.
bool ParseStep(const Flag& f, const std::string& text, FlagValue* v) {
    if (!ParseRational(text, &v->rational)) {
        double seconds = 0.0;
        bool exact = true;
        if (!ParseStepSeconds(text, &seconds) || seconds > f.max) return false;
        const long long micros = StepMicros(seconds, &exact);
        if (micros <= 0) return false;
        const long long g = std::gcd(micros, kStepMicrosPerSecond);
        v->rational = {micros / g, kStepMicrosPerSecond / g};
        if (!exact) v->text = f.name + std::string(" ") + text + ": " + StepRoundedNote(text, micros);
    }
    return v->rational.ToDouble() >= f.min && v->rational.ToDouble() <= f.max;
}

/// Parses text as a value of flag f, range included.
bool ParseValue(const Flag& f, const std::string& text, FlagValue* v) {
    switch (f.type) {
        case ValueType::None:
            return true;
        case ValueType::Int:
            return ParseCheckedInt(text, (long long)f.min, (long long)f.max, &v->integer);
        case ValueType::Float:
            return ParseFiniteFloat(text, &v->real) && v->real >= f.min && v->real <= f.max;
        case ValueType::Rational:
            return ParseRational(text, &v->rational) && v->rational.ToDouble() >= f.min &&
                   v->rational.ToDouble() <= f.max;
        case ValueType::Step:
            return ParseStep(f, text, v);
        case ValueType::Text:
            v->text = text;
            if (f.choices != nullptr)
                return ("|" + std::string(f.choices) + "|").find("|" + text + "|") != std::string::npos;
            return !text.empty();
        case ValueType::KeyValue:
            v->text = text;
            return text.find('=') != std::string::npos && text[0] != '=';
        case ValueType::FrameList:
            return ParseFrameList(text, f, &v->frames);
        case ValueType::Size: {
            const std::vector<std::string> sides = Split(text, 'x');
            long long w = 0, h = 0;
            if (sides.size() != 2 || !ParseCheckedInt(sides[0], (long long)f.min, (long long)f.max, &w) ||
                !ParseCheckedInt(sides[1], (long long)f.min, (long long)f.max, &h))
                return false;
            v->width = int(w), v->height = int(h);
            return true;
        }
        case ValueType::Vector3: {
            const std::vector<std::string> parts = Split(text, ',');
            if (parts.size() != 3) return false;
            for (int k = 0; k < 3; ++k)
                if (!ParseFiniteFloat(parts[std::size_t(k)], &v->vector[k])) return false;
            return true;
        }
    }
    return false;
}

// ---- Where each flag applies: a flag given where it would be ignored is refused (exit 2), never dropped.

/// A flag that means something besides a headless run. Every flag not listed is for headless runs only.
struct FlagScope {
    const char* name;
    bool window;       ///< --window uses it (Application/WindowedRunner.h: demo, --set, length, size, step, panels)
    bool exportScene;  ///< --export-scene uses it (the demo's scene after --set, and its camera)
};

constexpr FlagScope kScopes[] = {
    {"--demo", true, true},         {"--set", true, true},
    {"--quiet", true, true},        {"--window", true, false},
    {"--frames", true, false},      {"--size", true, false},
    {"--dt", true, false},          {"--no-ui", true, false},
    {"--threads", true, false},     {"--export-scene", false, true},
    {"--camera-yaw", false, true},  {"--camera-pitch", false, true},
    {"--camera-zoom", false, true}, {"--camera-target", false, true},
};

/// The first flag given that --window (window) or --export-scene (!window) would ignore, or nullptr.
const char* IgnoredFlag(const Options& o, bool window) {
    for (const std::string& given : o.flagsGiven) {
        const FlagScope* scope = nullptr;
        for (const FlagScope& s : kScopes)
            if (given == s.name) scope = &s;
        if (scope == nullptr || !(window ? scope->window : scope->exportScene)) return FindFlag(given)->name;
    }
    return nullptr;
}

/// Checks the combinations a single flag cannot (after every flag was read).

bool CheckCombinations(const Options& o, std::string* error) {
    if (o.mode != Options::Mode::Run) return true;
    if (!o.demo.empty() && !o.scene.empty()) {
        *error = "--demo and --scene both given; give one";
        return false;
    }
    if (!o.exportScene.empty() && (o.demo.empty() || o.window)) {
        *error = "--export-scene needs --demo ID (and no --window)";
        return false;
    }
    if (!o.exportScene.empty() && o.explainModel) {
        *error =
            "--export-scene and --explain-model both given; give one (an exported scene keeps \"model\": \"auto\")";
        return false;
    }
    if (!o.exportScene.empty()) {
        if (const char* flag = IgnoredFlag(o, false)) {
            *error = std::string("--export-scene writes the demo's scene file and exits; ") + flag +
                     " does not apply to it (it takes --demo, --set and the --camera-* flags)";
            return false;
        }
    }
    if (o.window) {
        if (!o.scene.empty()) {
            *error = "--scene runs headless; --window opens the book's demos only";
            return false;
        }
        if (const char* flag = IgnoredFlag(o, true)) {
            *error = std::string("--window shows frames on the screen; ") + flag + " is for headless runs";
            return false;
        }
        return true;  // no --demo: the book's start screen
    }
    if (o.demo.empty() && o.scene.empty())
        *error = "no --demo or --scene given (see --list for the ids, --help for usage)";
    else if (o.updateGolden && o.compareDir.empty())
        *error = "--update-golden needs --compare DIR (the golden directory to rewrite)";
    else if (!o.compareDir.empty() && !o.updateGolden && o.outDir.empty())
        *error = "--compare needs --out DIR (frames and mismatch images are written there)";
    else if (!o.onlyFrames.empty() && o.onlyFrames.back() >= o.frames && (o.scene.empty() || o.framesGiven))
        *error = "--only-frames " + std::to_string(o.onlyFrames.back()) + " is not below --frames " +
                 std::to_string(o.frames);
    else
        return true;
    return false;
}

}  // namespace

bool ParseHostStep(const std::string& text, Rational* step, std::string* error, std::string* note) {
    const Flag& dt = *FindFlag("--dt");
    FlagValue v;
    if (!ParseStep(dt, text, &v)) {
        *error = Expected(dt);
        return false;
    }
    *step = v.rational;
    *note = v.text.empty() ? "" : StepRoundedNote(text, std::llround(v.rational.ToDouble() * 1e6));
    return true;
}

ParseStatus ParseCommandLine(int argc, const char* const* argv, Options* o, std::string* error) {
    for (int i = 1; i < argc; ++i) {
        std::string name = argv[i], text;
        // --flag=value is accepted as well as --flag value.
        const std::size_t eq = name.rfind("--", 0) == 0 ? name.find('=') : std::string::npos;
        const bool inlineValue = eq != std::string::npos;
        if (inlineValue) text = name.substr(eq + 1), name.resize(eq);
        const Flag* flag = FindFlag(name);
        if (!flag) {
            *error = "unknown option '" + name + "' (see --help)";
            return ParseStatus::Error;
        }
        if (flag->type == ValueType::None && inlineValue) {
            *error = name + " " + text + ": takes no value";
            return ParseStatus::Error;
        }
        if (flag->type != ValueType::None && !inlineValue) {
            if (i + 1 >= argc) {
                *error = name + " needs a value (see --help)";
                return ParseStatus::Error;
            }
            text = argv[++i];
        }
        FlagValue value;
        if (!ParseValue(*flag, text, &value)) {
            *error = name + " " + text + ": " + Expected(*flag);
            return ParseStatus::Error;
        }
        flag->apply(*o, value);
        o->flagsGiven.push_back(flag->name);
    }
    return CheckCombinations(*o, error) ? ParseStatus::Ok : ParseStatus::Error;
}

std::string UsageText() {
    std::string text =
        "Usage: physics-sandbox --demo ID [options]\n"
        "       physics-sandbox --scene FILE [options]\n"
        "       physics-sandbox --window [--demo ID] [--frames N] [--set KEY=VALUE]...\n"
        "       physics-sandbox --list | --help\n\n"
        "Renders a demo of the Game Physics Cookbook (ch. 14-16) off-screen (OSMesa or EGL, llvmpipe) to PNG frames\n"
        "or a video, or runs it in the book's interactive window.\n\n";
    for (const Flag& f : kFlags) {
        std::string head = std::string("  ") + f.name + (*f.metavar ? " " : "") + f.metavar;
        head.resize(std::max<std::size_t>(head.size() + 2, 25), ' ');
        std::string help = f.help;
        if (f.type == ValueType::Int || f.type == ValueType::Float || f.type == ValueType::Rational)
            help += "; " + Range(f);
        text += head + help + "\n";
    }
    text +=
        "\nError budget (docs/model-choice.md): the demos ch14, ch15, springs, ch16, joints, linear-impulse and\n"
        "momentum, and every scene file, take --set model=fixed|auto, --set error-budget=T (the bound, > 0;\n"
        "tolerance=T, its deprecated spelling, is still taken) and --set budget=position|energy|constraint\n"
        "(m, relative, m; default position). With model=auto the run first estimates candidate models\n"
        "(integrator, dt, iterations, contact solver) on the scene itself and runs the cheapest whose estimated\n"
        "error at the end of the run is within T, re-estimating as it goes; a budget no candidate meets is refused\n"
        "(exit 2) with the best estimate reached.\n"
        "--state then gets an error_estimate column, the summary and the panel name the model. A scene file says\n"
        "\"model\": \"auto\", \"budget\": {\"quantity\": \"position\", \"bound\": 0.01} (docs/scenes.md).\n"
        "\nExit codes: 0 success, 1 golden mismatch, 2 bad usage (nothing written), 3 failure while running\n"
        "(also a detected blow-up, an unwritable output, out of memory), 130/143 interrupted by SIGINT/SIGTERM.\n";
    return text;
}
