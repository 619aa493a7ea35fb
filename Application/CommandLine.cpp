#include "Application/CommandLine.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace {

bool ParseLong(const std::string& text, long* out) {
    if (text.empty()) return false;
    char* end = nullptr;
    errno = 0;
    const long v = std::strtol(text.c_str(), &end, 10);
    if (errno != 0 || *end != '\0') return false;
    *out = v;
    return true;
}

bool ParseFloat(const std::string& text, float* out) {
    if (text.empty()) return false;
    char* end = nullptr;
    errno = 0;
    const float v = std::strtof(text.c_str(), &end);
    if (errno != 0 || *end != '\0' || !std::isfinite(v)) return false;
    *out = v;
    return true;
}

bool ParseSize(const std::string& text, int* w, int* h) {
    const std::size_t x = text.find('x');
    long a = 0, b = 0;
    if (x == std::string::npos || !ParseLong(text.substr(0, x), &a) || !ParseLong(text.substr(x + 1), &b)) return false;
    if (a < 16 || b < 16 || a > 8192 || b > 8192) return false;
    *w = int(a);
    *h = int(b);
    return true;
}

bool ParseFrameList(const std::string& text, std::vector<int>* out) {
    out->clear();
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        long v = 0;
        if (!ParseLong(text.substr(start, comma - start), &v) || v < 0 || v > 100000000) return false;
        out->push_back(int(v));
        start = comma + 1;
    }
    std::sort(out->begin(), out->end());
    out->erase(std::unique(out->begin(), out->end()), out->end());
    return !out->empty();
}

}  // namespace

ParseStatus ParseCommandLine(int argc, const char* const* argv, Options* o, std::string* error) {
    bool sawDemo = false;
    for (int i = 1; i < argc; ++i) {
        std::string flag = argv[i];
        std::string value;
        bool hasInlineValue = false;
        // --flag=value is accepted as well as --flag value.
        if (flag.rfind("--", 0) == 0) {
            const std::size_t eq = flag.find('=');
            if (eq != std::string::npos) {
                value = flag.substr(eq + 1);
                flag = flag.substr(0, eq);
                hasInlineValue = true;
            }
        }
        const auto bad = [&](const std::string& why) {
            *error = flag + " " + value + ": " + why;
            return ParseStatus::Error;
        };
        const auto needValue = [&]() {
            if (hasInlineValue) return true;
            if (i + 1 >= argc) return false;
            value = argv[++i];
            return true;
        };
        const auto noValue = [&]() { return !hasInlineValue; };

        if (flag == "--help" || flag == "-h") {
            if (!noValue()) return bad("takes no value");
            o->mode = Options::Mode::Help;
        } else if (flag == "--list") {
            if (!noValue()) return bad("takes no value");
            o->mode = Options::Mode::List;
        } else if (flag == "--no-ui" || flag == "--quiet" || flag == "--update-golden" || flag == "--serial-encode" ||
                   flag == "--params") {
            if (!noValue()) return bad("takes no value");
            if (flag == "--params") o->showParams = true;
            if (flag == "--no-ui") o->noUi = true;
            if (flag == "--quiet") o->quiet = true;
            if (flag == "--update-golden") o->updateGolden = true;
            if (flag == "--serial-encode") o->encodeThread = false;
        } else {
            // Every other flag takes a value.
            static const char* const valued[] = {
                "--demo",      "--frames",     "--out",          "--size",        "--set",
                "--state",     "--camera-yaw", "--camera-pitch", "--camera-zoom", "--camera-target",
                "--orbit",     "--fps",        "--dt",           "--only-frames", "--compare",
                "--tolerance", "--max-diff",   "--png-level",    "--progress",    "--debug-nonfinite-at"};
            if (std::find_if(std::begin(valued), std::end(valued), [&](const char* f) { return flag == f; }) ==
                std::end(valued)) {
                *error = "unknown option '" + flag + "' (see --help)";
                return ParseStatus::Error;
            }
            if (!needValue()) {
                *error = flag + " needs a value (see --help)";
                return ParseStatus::Error;
            }
            long n = 0;
            float f = 0.0f;
            if (flag == "--demo") {
                if (value.empty()) return bad("empty demo id (see --list)");
                o->demo = value;
                sawDemo = true;
            } else if (flag == "--frames") {
                if (!ParseLong(value, &n) || n < 1 || n > 100000000)
                    return bad("the frame count must be an integer from 1 to 100000000");
                o->frames = int(n);
            } else if (flag == "--out") {
                if (value.empty()) return bad("empty directory");
                o->outDir = value;
            } else if (flag == "--size") {
                if (!ParseSize(value, &o->width, &o->height)) return bad("expected WxH with 16 <= W, H <= 8192");
            } else if (flag == "--set") {
                const std::size_t eq = value.find('=');
                if (eq == std::string::npos || eq == 0) return bad("expected key=value");
                o->sets.emplace_back(value.substr(0, eq), value.substr(eq + 1));
            } else if (flag == "--state") {
                if (value.empty()) return bad("empty file name");
                o->stateFile = value;
            } else if (flag == "--camera-yaw") {
                if (!ParseFloat(value, &f) || std::fabs(f) > 360.0f) return bad("expected degrees in [-360, 360]");
                o->yaw = f, o->hasYaw = true;
            } else if (flag == "--camera-pitch") {
                // The book clamps pitch to [-20, 80] when the mouse rotates; +-89 keeps LookAt well defined.
                if (!ParseFloat(value, &f) || std::fabs(f) > 89.0f) return bad("expected degrees in [-89, 89]");
                o->pitch = f, o->hasPitch = true;
            } else if (flag == "--camera-zoom") {
                if (!ParseFloat(value, &f) || f < 0.1f || f > 500.0f) return bad("expected a distance in [0.1, 500]");
                o->zoom = f, o->hasZoom = true;
            } else if (flag == "--camera-target") {
                float t[3];
                std::size_t start = 0;
                for (int k = 0; k < 3; ++k) {
                    const std::size_t comma = k < 2 ? value.find(',', start) : value.size();
                    if (comma == std::string::npos || !ParseFloat(value.substr(start, comma - start), &t[k]))
                        return bad("expected x,y,z");
                    start = comma + 1;
                }
                std::copy(t, t + 3, o->target);
                o->hasTarget = true;
            } else if (flag == "--orbit") {
                if (!ParseFloat(value, &f) || std::fabs(f) > 360.0f)
                    return bad("expected degrees of yaw per frame in [-360, 360]");
                o->orbitDegreesPerFrame = f;
            } else if (flag == "--fps") {
                Rational r;
                if (!ParseRational(value, &r) || r.ToDouble() < 1.0 || r.ToDouble() > 1000.0)
                    return bad("expected frames per simulated second in [1, 1000], e.g. 60 or 62.5");
                o->frameTime = Reciprocal(r);
            } else if (flag == "--dt") {
                Rational r;
                if (!ParseRational(value, &r) || r.ToDouble() < 0.0001 || r.ToDouble() > 1.0)
                    return bad("expected a physics step in seconds in [0.0001, 1], e.g. 0.03 or 1/30");
                o->step = r;
            } else if (flag == "--only-frames") {
                if (!ParseFrameList(value, &o->onlyFrames)) return bad("expected frame numbers like 0,30,90");
            } else if (flag == "--compare") {
                if (value.empty()) return bad("empty directory");
                o->compareDir = value;
            } else if (flag == "--tolerance") {
                if (!ParseLong(value, &n) || n < 0 || n > 255) return bad("expected a channel difference 0..255");
                o->thresholds.channelTolerance = int(n);
            } else if (flag == "--max-diff") {
                if (!ParseFloat(value, &f) || f < 0.0f || f > 1.0f) return bad("expected a pixel fraction in [0, 1]");
                o->thresholds.maxDifferingFraction = f;
            } else if (flag == "--png-level") {
                if (!ParseLong(value, &n) || n < 0 || n > 9) return bad("expected a zlib level 0..9");
                o->pngLevel = int(n);
            } else if (flag == "--progress") {
                if (!ParseLong(value, &n) || n < 0 || n > 100000000)
                    return bad("expected a frame interval (0 = automatic)");
                o->progressEvery = int(n);
            } else if (flag == "--debug-nonfinite-at") {
                if (!ParseLong(value, &n) || n < 0) return bad("expected a frame number");
                o->debugNonFiniteAt = int(n);
            }
        }
    }
    if (o->mode != Options::Mode::Run) return ParseStatus::Ok;
    if (!sawDemo) {
        *error = "no --demo given (see --list for the ids, --help for usage)";
        return ParseStatus::Error;
    }
    if (o->updateGolden && o->compareDir.empty()) {
        *error = "--update-golden needs --compare DIR (the golden directory to rewrite)";
        return ParseStatus::Error;
    }
    if (!o->compareDir.empty() && !o->updateGolden && o->outDir.empty()) {
        *error = "--compare needs --out DIR (frames and mismatch images are written there)";
        return ParseStatus::Error;
    }
    if (!o->onlyFrames.empty() && o->onlyFrames.back() >= o->frames) {
        *error = "--only-frames " + std::to_string(o->onlyFrames.back()) + " is not below --frames " +
                 std::to_string(o->frames);
        return ParseStatus::Error;
    }
    return ParseStatus::Ok;
}

std::string UsageText() {
    return R"(Usage: physics-sandbox --demo ID [options]
       physics-sandbox --list | --help

Renders a demo of the Game Physics Cookbook (ch. 14-16) off-screen (OSMesa, llvmpipe) to PNG frames.

  --list                 print the demos: id, a tab, the title; one per line
  --demo ID              the demo to run (see --list)
  --frames N             output frames to run (default 1); one frame = 1/60 s of simulated time
  --out DIR              write DIR/frame_00000.png ... (DIR is created); without it nothing is written
  --size WxH             frame size (default 800x600)
  --set KEY=VALUE        set a demo parameter (repeatable, applied in order); the panel shows the value
  --params               print the demo's parameters (keys, ranges, values after --set) and exit
  --state FILE           write CSV: frame,time,body,kind,x,y,z,vx,vy,vz (one row per body per frame)
  --no-ui                hide the ImGui panels
  --camera-yaw DEG       orbit camera yaw (rotation.x), replaces the demo's preset
  --camera-pitch DEG     orbit camera pitch (rotation.y), in [-89, 89]
  --camera-zoom D        orbit camera distance to its target
  --camera-target X,Y,Z  orbit camera target
  --orbit DEG            add DEG of yaw every output frame (turntable)
  --fps F                output frames per simulated second (default 60)
  --dt S                 fixed physics step in seconds (default 0.03 as the book; e.g. 1/30)
  --only-frames A,B,...  write (and compare) only these frames; all frames are still simulated
  --compare DIR          compare each written frame with DIR/<same name>; on a mismatch write
                         OUT/mismatch/*.{expected,actual,diff}.png and OUT/compare.txt, exit 1
  --update-golden        with --compare DIR: rewrite the goldens in DIR instead of comparing
  --tolerance N          per-channel difference a pixel may have and still match (default 8)
  --max-diff F           fraction of pixels allowed beyond the tolerance (default 0.002)
  --png-level N          zlib level 0..9 (default 3)
  --serial-encode        encode PNGs on the main thread (same files; for measurement)
  --progress N           progress line on stderr every N frames (default: automatic)
  --quiet                no progress line and no summary

Exit codes: 0 success, 1 golden mismatch, 2 bad usage (nothing written), 3 failure while running.
)";
}
