#include "Platform/Files/TempRegistry.h"

#include <limits.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>

namespace {

constexpr int kSlots = 64;
enum SlotState : int { kFree = 0, kFilling = 1, kActive = 2 };

struct Slot {
    std::atomic<int> state{kFree};
    char path[PATH_MAX];
};

Slot gSlots[kSlots];
constexpr int kChildren = 8;
std::atomic<int> gChildren[kChildren];  // 0 = free
const char* gProgram = "program";

void WriteAll(const char* text) {
    std::size_t left = std::strlen(text);
    while (left > 0) {
        const ssize_t n = write(STDERR_FILENO, text, left);
        if (n <= 0) return;
        text += n;
        left -= std::size_t(n);
    }
}

extern "C" void OnTerminatingSignal(int sig) {
    for (std::atomic<int>& child : gChildren) {
        const int pid = child.load();
        if (pid <= 0) continue;
        kill(pid, SIGKILL);
        while (waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
        }
    }
    for (Slot& slot : gSlots)
        if (slot.state.load() == kActive) unlink(slot.path);
    WriteAll(gProgram);
    WriteAll(sig == SIGINT ? ": interrupted by SIGINT" : ": terminated by SIGTERM");
    WriteAll("; temporary files removed, completed files kept\n");
    _exit(128 + sig);
}

}  // namespace

int RegisterTemporary(const std::string& path) {
    if (path.size() >= PATH_MAX) return -1;
    for (int i = 0; i < kSlots; ++i) {
        int expected = kFree;
        if (!gSlots[i].state.compare_exchange_strong(expected, kFilling)) continue;
        std::memcpy(gSlots[i].path, path.c_str(), path.size() + 1);
        gSlots[i].state.store(kActive);
        return i;
    }
    return -1;
}

void UnregisterTemporary(int id) {
    if (id >= 0 && id < kSlots) gSlots[id].state.store(kFree);
}

bool RegisterChildProcess(int pid) {
    for (std::atomic<int>& child : gChildren) {
        int expected = 0;
        if (child.compare_exchange_strong(expected, pid)) return true;
    }
    return false;
}

void UnregisterChildProcess(int pid) {
    for (std::atomic<int>& child : gChildren) {
        int expected = pid;
        if (child.compare_exchange_strong(expected, 0)) return;
    }
}

void InstallTemporaryCleanupOnSignals(const char* program) {
    gProgram = program;
    struct sigaction action;
    std::memset(&action, 0, sizeof action);
    action.sa_handler = OnTerminatingSignal;
    sigemptyset(&action.sa_mask);
    sigaddset(&action.sa_mask, SIGINT);
    sigaddset(&action.sa_mask, SIGTERM);
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
    signal(SIGXFSZ, SIG_IGN);
}
