#pragma once
// The program's entry, above both hosts: parses the command line and hands the run to the headless runner
// (Application/Runner.h) or the window (Application/WindowedRunner.h).

/// The whole program: installs the signal policy (Platform/Files/TempRegistry.h), parses, --help, --list, run.
int RunCommandLine(int argc, const char* const* argv);
