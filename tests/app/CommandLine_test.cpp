#include "Application/CommandLine.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace {

ParseStatus Parse(std::vector<const char*> args, Options* o, std::string* error) {
    args.insert(args.begin(), "physics-sandbox");
    return ParseCommandLine(int(args.size()), args.data(), o, error);
}

// Expects a parse error whose message contains `needle`.
void ExpectError(std::vector<const char*> args, const std::string& needle) {
    Options o;
    std::string error;
    EXPECT_EQ(Parse(args, &o, &error), ParseStatus::Error) << needle;
    EXPECT_NE(error.find(needle), std::string::npos) << "message: " << error;
}

}  // namespace

TEST(CommandLine, Defaults) {
    Options o;
    std::string error;
    ASSERT_EQ(Parse({"--demo", "ch14"}, &o, &error), ParseStatus::Ok) << error;
    EXPECT_EQ(o.demo, "ch14");
    EXPECT_EQ(o.frames, 1);
    EXPECT_EQ(o.width, 800);
    EXPECT_EQ(o.height, 600);
    EXPECT_EQ(o.frameTime.num, 1);
    EXPECT_EQ(o.frameTime.den, 60);
    EXPECT_EQ(o.step.num, 3);
    EXPECT_EQ(o.step.den, 100);
    EXPECT_FALSE(o.noUi);
    EXPECT_TRUE(o.encodeThread);
    EXPECT_LT(o.thresholds.minSsim, 0.0);  // --min-ssim off
}

TEST(CommandLine, EveryFlag) {
    Options o;
    std::string error;
    ASSERT_EQ(Parse({"--demo=ch15",
                     "--frames",
                     "90",
                     "--out",
                     "o",
                     "--size",
                     "400x300",
                     "--set",
                     "a=1",
                     "--set",
                     "b=x=y",
                     "--state",
                     "s.csv",
                     "--no-ui",
                     "--camera-yaw",
                     "-30",
                     "--camera-pitch",
                     "20",
                     "--camera-zoom",
                     "12",
                     "--camera-target",
                     "1,2.5,-3",
                     "--orbit",
                     "0.5",
                     "--fps",
                     "30",
                     "--dt",
                     "1/30",
                     "--only-frames",
                     "30,0,30",
                     "--compare",
                     "g",
                     "--tolerance",
                     "4",
                     "--max-diff",
                     "0.01",
                     "--min-ssim",
                     "0.95",
                     "--png-level",
                     "6",
                     "--serial-encode",
                     "--progress",
                     "5",
                     "--quiet"},
                    &o, &error),
              ParseStatus::Ok)
        << error;
    EXPECT_EQ(o.demo, "ch15");
    EXPECT_EQ(o.frames, 90);
    EXPECT_EQ(o.outDir, "o");
    EXPECT_EQ(o.width, 400);
    EXPECT_EQ(o.height, 300);
    ASSERT_EQ(o.sets.size(), 2u);
    EXPECT_EQ(o.sets[1].first, "b");
    EXPECT_EQ(o.sets[1].second, "x=y");
    EXPECT_EQ(o.stateFile, "s.csv");
    EXPECT_TRUE(o.noUi);
    EXPECT_TRUE(o.hasYaw && o.hasPitch && o.hasZoom && o.hasTarget);
    EXPECT_FLOAT_EQ(o.yaw, -30.0f);
    EXPECT_FLOAT_EQ(o.target[1], 2.5f);
    EXPECT_FLOAT_EQ(o.orbitDegreesPerFrame, 0.5f);
    EXPECT_EQ(o.frameTime.den, 30);
    EXPECT_EQ(o.step.den, 30);
    EXPECT_EQ(o.onlyFrames, (std::vector<int>{0, 30}));
    EXPECT_EQ(o.compareDir, "g");
    EXPECT_EQ(o.thresholds.channelTolerance, 4);
    EXPECT_FLOAT_EQ(float(o.thresholds.maxDifferingFraction), 0.01f);
    EXPECT_FLOAT_EQ(float(o.thresholds.minSsim), 0.95f);
    EXPECT_EQ(o.pngLevel, 6);
    EXPECT_FALSE(o.encodeThread);
    EXPECT_EQ(o.progressEvery, 5);
    EXPECT_TRUE(o.quiet);
}

TEST(CommandLine, ListAndHelpNeedNoDemo) {
    Options o;
    std::string error;
    ASSERT_EQ(Parse({"--list"}, &o, &error), ParseStatus::Ok);
    EXPECT_EQ(o.mode, Options::Mode::List);
    Options h;
    ASSERT_EQ(Parse({"--help"}, &h, &error), ParseStatus::Ok);
    EXPECT_EQ(h.mode, Options::Mode::Help);
    EXPECT_NE(UsageText().find("--demo ID"), std::string::npos);
}

TEST(CommandLine, ErrorsNameTheFlagAndValue) {
    ExpectError({"--demo", "x", "--bogus"}, "unknown option '--bogus'");
    ExpectError({}, "no --demo");
    ExpectError({"--demo"}, "--demo needs a value");
    ExpectError({"--demo", "x", "--frames", "0"}, "--frames 0");
    ExpectError({"--demo", "x", "--frames", "-5"}, "--frames -5");
    ExpectError({"--demo", "x", "--frames", "ten"}, "--frames ten");
    ExpectError({"--demo", "x", "--size", "800"}, "--size 800");
    ExpectError({"--demo", "x", "--size", "0x600"}, "--size 0x600");
    ExpectError({"--demo", "x", "--size", "800x-1"}, "--size 800x-1");
    ExpectError({"--demo", "x", "--set", "novalue"}, "expected key=value");
    ExpectError({"--demo", "x", "--set", "=1"}, "expected key=value");
    ExpectError({"--demo", "x", "--camera-pitch", "95"}, "--camera-pitch 95");
    ExpectError({"--demo", "x", "--camera-zoom", "nan"}, "--camera-zoom nan");
    ExpectError({"--demo", "x", "--camera-target", "1,2"}, "--camera-target 1,2");
    ExpectError({"--demo", "x", "--fps", "0"}, "--fps 0");
    ExpectError({"--demo", "x", "--dt", "-0.03"}, "--dt -0.03");
    ExpectError({"--demo", "x", "--dt", "2"}, "--dt 2");
    ExpectError({"--demo", "x", "--only-frames", "1,,2"}, "--only-frames");
    ExpectError({"--demo", "x", "--frames", "10", "--only-frames", "10"}, "not below --frames");
    ExpectError({"--demo", "x", "--compare", "g"}, "--compare needs --out");
    ExpectError({"--demo", "x", "--update-golden"}, "--update-golden needs --compare");
    ExpectError({"--demo", "x", "--update-golden", "--window"}, "--update-golden is for headless runs");
    ExpectError({"--window", "--only-frames", "3"}, "--only-frames is for headless runs");
    ExpectError({"--demo", "x", "--png-level", "10"}, "--png-level 10");
    ExpectError({"--no-ui=1", "--demo", "x"}, "takes no value");
}

TEST(CommandLine, EveryIntegerIsRangeCheckedWithoutOverflow) {
    // 4294967297 = 2^32 + 1 would wrap to 1 in an int; 2147483648 = 2^31 to INT_MIN.
    for (const char* big : {"4294967297", "2147483648", "9223372036854775808", "99999999999999999999"}) {
        for (const char* flag : {"--debug-nonfinite-at", "--frames", "--progress", "--tolerance", "--png-level"})
            ExpectError({"--demo", "x", flag, big}, std::string(flag) + " " + big);
        ExpectError({"--demo", "x", "--only-frames", big}, "--only-frames");
        ExpectError({"--demo", "x", "--size", (std::string(big) + "x16").c_str()}, "--size");
    }
    ExpectError({"--demo", "x", "--debug-nonfinite-at", "-1"}, "--debug-nonfinite-at -1");
    ExpectError({"--demo", "x", "--tolerance", "256"}, "--tolerance 256");
    ExpectError({"--demo", "x", "--min-ssim", "1.5"}, "--min-ssim 1.5");
    ExpectError({"--demo", "x", "--frames", "1.5"}, "--frames 1.5");
    ExpectError({"--demo", "x", "--frames", " 5"}, "--frames  5");
    Options o;
    std::string error;
    ASSERT_EQ(Parse({"--demo", "x", "--frames", "100000000", "--debug-nonfinite-at", "99999999"}, &o, &error),
              ParseStatus::Ok)
        << error;
    EXPECT_EQ(o.frames, 100000000);
    EXPECT_EQ(o.debugNonFiniteAt, 99999999);
}

TEST(CommandLine, ThreadsTakesACountFrom1To256AndDefaultsToTheHardware) {
    Options o;
    std::string error;
    ASSERT_EQ(Parse({"--demo", "ch15"}, &o, &error), ParseStatus::Ok) << error;
    EXPECT_EQ(o.threads, 0) << "0: the hardware's concurrency (SetDefaultThreadCount)";
    ASSERT_EQ(Parse({"--demo", "ch15", "--threads", "3"}, &o, &error), ParseStatus::Ok) << error;
    EXPECT_EQ(o.threads, 3);
    ExpectError({"--demo", "ch15", "--threads", "0"}, "--threads 0: expected an integer in [1, 256]");
    ExpectError({"--demo", "ch15", "--threads", "257"}, "--threads 257");
    ExpectError({"--demo", "ch15", "--threads", "two"}, "--threads two");
}

TEST(CommandLine, HelpListsEveryFlagTheParserAccepts) {
    const std::string help = UsageText();
    for (const char* flag : {"--help",
                             "--list",
                             "--demo",
                             "--frames",
                             "--out",
                             "--size",
                             "--set",
                             "--params",
                             "--state",
                             "--no-ui",
                             "--camera-yaw",
                             "--camera-pitch",
                             "--camera-zoom",
                             "--camera-target",
                             "--orbit",
                             "--fps",
                             "--dt",
                             "--only-frames",
                             "--compare",
                             "--update-golden",
                             "--tolerance",
                             "--max-diff",
                             "--min-ssim",
                             "--png-level",
                             "--serial-encode",
                             "--progress",
                             "--quiet",
                             "--debug-nonfinite-at",
                             "--threads",
                             "--explain-model"}) {
        EXPECT_NE(help.find(std::string("  ") + flag + " "), std::string::npos) << flag;
        Options o;
        std::string error;
        Parse({flag}, &o, &error);
        EXPECT_EQ(error.find("unknown option"), std::string::npos) << flag << ": " << error;
    }
    // Ranges in the help come from the same table the parser checks.
    EXPECT_NE(help.find("[-89, 89]"), std::string::npos);
    EXPECT_NE(help.find("[0, 255]"), std::string::npos);
    // The error budget's --set keys (the demos' tables are not the parser's) are documented in the help.
    for (const char* key : {"model=fixed|auto", "tolerance=T", "budget=position|energy|constraint"})
        EXPECT_NE(help.find(key), std::string::npos) << key;
}

// --explain-model (docs/model-choice.md): a headless run's flag that needs no value; whether the demo's model is
// auto is known only after --set, so the runner checks that (tests/app/AutoModelCli_test.cpp).
TEST(CommandLine, ExplainModel) {
    Options o;
    std::string error;
    ASSERT_EQ(Parse({"--demo", "springs", "--set", "model=auto", "--explain-model"}, &o, &error), ParseStatus::Ok)
        << error;
    EXPECT_TRUE(o.explainModel);
    Options plain;
    ASSERT_EQ(Parse({"--demo", "springs"}, &plain, &error), ParseStatus::Ok) << error;
    EXPECT_FALSE(plain.explainModel);
    ExpectError({"--window", "--explain-model"}, "--explain-model is for headless runs");
    ExpectError({"--demo", "x", "--explain-model=1"}, "takes no value");
    ExpectError({"--demo", "x", "--export-scene", "f.json", "--explain-model"}, "give one");
}

TEST(CommandLine, AFlagTheModeWouldIgnoreIsRefused) {
    // --window runs the book's loop with the demo, --set, --frames, --size, --dt, --no-ui and --quiet; anything
    // else (a back end, a camera, outputs) would be dropped silently.
    for (const std::vector<const char*>& extra : {std::vector<const char*>{"--backend", "egl"},
                                                  {"--backend", "auto"},
                                                  {"--camera-yaw", "10"},
                                                  {"--fps", "30"},
                                                  {"--orbit", "1"},
                                                  {"--png-level", "1"},
                                                  {"--serial-encode"},
                                                  {"--progress", "5"},
                                                  {"--tolerance", "3"}}) {
        std::vector<const char*> args = {"--window", "--demo", "ch14"};
        args.insert(args.end(), extra.begin(), extra.end());
        ExpectError(args, std::string(extra[0]) + " is for headless runs");
    }
    // --export-scene writes the scene of the demo after --set, seen from its camera, and exits.
    for (const std::vector<const char*>& extra : {std::vector<const char*>{"--out", "o"},
                                                  {"--frames", "5"},
                                                  {"--state", "s.csv"},
                                                  {"--video", "v.mp4"},
                                                  {"--size", "64x48"},
                                                  {"--dt", "0.01"},
                                                  {"--params"},
                                                  {"--backend", "osmesa"},
                                                  {"--no-ui"}}) {
        std::vector<const char*> args = {"--demo", "ch15", "--export-scene", "f.json"};
        args.insert(args.end(), extra.begin(), extra.end());
        ExpectError(args, std::string(extra[0]) + " does not apply to it");
    }
    // What each mode uses is accepted.
    Options o;
    std::string error;
    EXPECT_EQ(Parse({"--window", "--demo", "ch14", "--frames", "5", "--size", "640x480", "--dt", "0.01", "--set",
                     "particles=10", "--no-ui", "--quiet"},
                    &o, &error),
              ParseStatus::Ok)
        << error;
    Options exported;
    EXPECT_EQ(Parse({"--demo", "ch15", "--set", "iterations=3", "--camera-yaw", "10", "--camera-pitch", "20",
                     "--camera-zoom", "9", "--camera-target", "0,1,0", "--quiet", "--export-scene", "f.json"},
                    &exported, &error),
              ParseStatus::Ok)
        << error;
}

// One rule for a step (docs/app.md, "Steps"): an exact fraction n/d (n, d <= 10^6) or a whole number of
// microseconds is taken as it is; any other decimal or fraction is rounded to the nearest microsecond with a note;
// one that rounds below the range is refused. "--dt 0.0166666667" was refused as not a number.
TEST(CommandLine, DtIsExactOrRoundedToMicrosecondsWithANote) {
    struct Case {
        const char* text;
        std::int64_t num, den;
        bool note;
    } cases[] = {{"0.03", 3, 100, false},
                 {"1/30", 1, 30, false},
                 {"1/60", 1, 60, false},
                 {"0.0001", 1, 10000, false},
                 {"0.0166666667", 16667, 1000000, true},
                 {"1e-3", 1, 1000, false},
                 {"1/3000", 1, 3000, false},
                 {"1000/7000001", 143, 1000000, true}};
    for (const Case& c : cases) {
        Options o;
        std::string error;
        ASSERT_EQ(Parse({"--demo", "x", "--dt", c.text}, &o, &error), ParseStatus::Ok) << c.text << ": " << error;
        EXPECT_EQ(o.step.num, c.num) << c.text;
        EXPECT_EQ(o.step.den, c.den) << c.text;
        EXPECT_EQ(o.notes.size(), c.note ? 1u : 0u) << c.text;
    }
    Options o;
    std::string error;
    ASSERT_EQ(Parse({"--demo", "x", "--dt", "0.0166666667"}, &o, &error), ParseStatus::Ok) << error;
    ASSERT_EQ(o.notes.size(), 1u);
    EXPECT_EQ(o.notes[0],
              "--dt 0.0166666667: 0.0166666667 s rounded to 0.016667 s (a step is a whole number of "
              "microseconds; docs/app.md, \"Steps\")");
    for (const char* bad : {"0.00000001", "1/3000000", "0.00009", "1.0000001", "abc", "1/0", "nan"})
        ExpectError({"--demo", "x", "--dt", bad}, std::string("--dt ") + bad + ": expected a step in seconds");
}
