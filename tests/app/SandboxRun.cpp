#include "tests/app/SandboxRun.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace {

std::string Quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

}  // namespace

std::string ReadText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::string ScratchDir(const std::string& name) {
    const std::string dir = ::testing::TempDir() + "psb_app_" + std::to_string(getpid()) + "_" + name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

namespace {

SandboxResult RunCaptured(const std::string& command) {
    const std::string dir = ScratchDir("run_capture");
    const std::string full = command + " >" + Quote(dir + "/out") + " 2>" + Quote(dir + "/err") + " </dev/null";
    const int status = std::system(full.c_str());
    SandboxResult r;
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = ReadText(dir + "/out");
    r.err = ReadText(dir + "/err");
    std::filesystem::remove_all(dir);
    return r;
}

}  // namespace

SandboxResult RunSandboxExe(const std::vector<std::string>& args) { return RunSandboxShell("", args); }

SandboxResult RunSandboxShell(const std::string& shellPrefix, const std::vector<std::string>& args,
                              const std::string& shellSuffix) {
    std::string command = "(" + shellPrefix + " " + Quote(PSB_SANDBOX_EXE);
    for (const std::string& a : args) command += " " + Quote(a);
    return RunCaptured(command + " " + shellSuffix + ")");
}

SandboxResult RunShellScript(const std::string& script) {
    return RunCaptured("PS=" + Quote(PSB_SANDBOX_EXE) + " sh -c " + Quote(script));
}

bool IsTemporaryName(const std::string& name) {
    return (name.size() > 1 && name[0] == '.' && name != "..") ||
           (name.size() > 4 && name.compare(name.size() - 4, 4, ".tmp") == 0);
}

std::vector<std::string> ListDemoIds() {
    const SandboxResult r = RunSandboxExe({"--list"});
    EXPECT_EQ(r.exitCode, 0) << "--list: " << r.err;
    std::vector<std::string> ids;
    std::istringstream lines(r.out);
    std::string line;
    while (std::getline(lines, line))
        if (!line.empty()) ids.push_back(line.substr(0, line.find('\t')));
    return ids;
}

std::vector<std::string> FilesIn(const std::string& dir) {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(dir, ec))
        if (e.is_regular_file()) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}
