#pragma once
// Runs the physics-sandbox executable for the app tests and captures its exit code and output.

#include <string>
#include <vector>

struct SandboxResult {
    int exitCode = -1;
    std::string out;  ///< stdout
    std::string err;  ///< stderr
};

/// Runs PSB_SANDBOX_EXE with args (no shell word splitting surprises: every arg is quoted).
SandboxResult RunSandboxExe(const std::vector<std::string>& args);
/// Runs PSB_SANDBOX_EXE with args inside a subshell: "(" + shellPrefix + " exe args " + shellSuffix + ")", e.g.
/// prefix "ulimit -f 10;" or "timeout --preserve-status -s INT 2", suffix ">/dev/full".
SandboxResult RunSandboxShell(const std::string& shellPrefix, const std::vector<std::string>& args,
                              const std::string& shellSuffix = "");
/// Runs a whole shell command (sh -c) with $PS set to the executable; stdout and stderr captured.
SandboxResult RunShellScript(const std::string& script);
/// True for a temporary an interrupted or failed write could leave: a hidden ".NAME.XXXXXX" or a "*.tmp".
bool IsTemporaryName(const std::string& name);
/// A fresh, empty scratch directory for one test.
std::string ScratchDir(const std::string& name);
/// Ids of the registered demos, from `--list`.
std::vector<std::string> ListDemoIds();
/// Every regular file name in dir, sorted.
std::vector<std::string> FilesIn(const std::string& dir);
std::string ReadText(const std::string& path);
