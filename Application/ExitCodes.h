#pragma once
// The bottom of the application layer: physics-sandbox's exit codes and the check that stdout was written. Every
// host (Application/Runner.h headless, Application/WindowedRunner.h window, Application/AutoModelHost.h) and the
// program's entry (Application/Program.h) include this; it includes nothing of theirs.

/// Exit codes of physics-sandbox (docs/app.md "Exit codes"). kExitMissedBudget: the run finished and wrote its
/// outputs, but an auto model's running estimate ended over its budget.
enum ExitCode { kExitOk = 0, kExitMismatch = 1, kExitUsage = 2, kExitFailure = 3, kExitMissedBudget = 4 };

/// Flushes stdout after --help, --list or --params: kExitOk, or kExitFailure with a message when the output
/// could not be written (a full disk, a closed pipe).
int FinishStdout();
