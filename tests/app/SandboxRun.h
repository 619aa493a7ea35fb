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
/// A fresh, empty scratch directory for one test.
std::string ScratchDir(const std::string& name);
/// Ids of the registered demos, from `--list`.
std::vector<std::string> ListDemoIds();
/// Every regular file name in dir, sorted.
std::vector<std::string> FilesIn(const std::string& dir);
std::string ReadText(const std::string& path);
