#pragma once
// One dt for every demo (docs/app.md, "Steps"): `--dt S` and `--set dt=S` are the same setting. Both are read by
// one rule (ParseHostStep) into the host's step; a demo whose parameter table has "dt" (ch14, springs, ch16,
// joints, a scene file) gets the same value written into its table as well, where its panel shows it and the auto
// model refines it (DemoBase::PhysicsStep). The host then runs whole steps of HostStepOf.

#include <string>

#include "Application/CommandLine.h"
#include "Application/FrameClock.h"
#include "Demos/DemoBase.h"

/// "n/d" (or "n" for d = 1): the exact text of a step, read back to the same value by ParseHostStep.
std::string RationalText(const Rational& r);

/// `--set dt=text` (and `--dt text`, handed in as RationalText of the parsed flag): written into the demo's "dt"
/// when its table has one (its range and its "0 = the host's step" apply), and read by ParseHostStep into
/// *hostStep (left alone for a table's 0 or a table value outside `--dt`'s range). *note is the one-line
/// rounding note, prefixed with `label` ("--set dt=0.0166666667"), or "". False with *error.
bool ApplyStepSetting(DemoBase& demo, const std::string& label, const std::string& text, Rational* hostStep,
                      std::string* error, std::string* note);

/// The step the host runs: the demo's physics step when it asks for one (to the microsecond; exactly hostStep
/// when that is the value the demo holds, so `--dt 1/60` stays 1/60), else hostStep.
Rational HostStepOf(const Rational& hostStep, const DemoBase& demo);

/// `--dt` (when given: the first "dt" setting, as RationalText of o->step; its rounding note was printed by the
/// parser), then every `--set` in order: "dt" by ApplyStepSetting into the demo's table and o->step, the rest into
/// the demo's table. Notes go to stderr as they come. False at the first refusal, *error "LABEL: reason" (LABEL
/// "--dt S" or "--set KEY=VALUE").
bool ApplySetList(Options* o, DemoBase& demo, std::string* error);
