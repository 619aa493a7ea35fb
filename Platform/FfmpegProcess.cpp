#include "Platform/FfmpegProcess.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>

#include "Platform/Files/TempRegistry.h"

namespace {

using Clock = std::chrono::steady_clock;

double Since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

/// The size of path, or -1 if it cannot be read.
long long FileSize(const std::string& path) {
    struct stat st {};
    return stat(path.c_str(), &st) == 0 ? (long long)st.st_size : -1;
}

}  // namespace

double EncoderStallSeconds() {
    const char* text = std::getenv("PSB_ENCODER_TIMEOUT");
    if (text == nullptr || *text == '\0') return 60.0;
    char* end = nullptr;
    const double seconds = std::strtod(text, &end);
    return *end == '\0' && std::isfinite(seconds) && seconds > 0.0 ? seconds : 60.0;
}

std::string FfmpegNumber(double v) {
    std::ostringstream out;
    out.precision(10);
    out << v;
    return out.str();
}

bool ProgramOnPath(const std::string& program) {
    const char* pathEnv = std::getenv("PATH");
    std::stringstream dirs(pathEnv ? pathEnv : "/usr/bin:/bin");
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        const std::string candidate = (dir.empty() ? "." : dir) + "/" + program;
        if (access(candidate.c_str(), X_OK) == 0) return true;
    }
    return false;
}

bool StartChild(const std::vector<std::string>& args, bool pipeIn, const std::string& outputPath, pid_t* pid,
                int* stdinFd, std::string* error) {
    *pid = -1;
    *stdinFd = -1;
    int fds[2] = {-1, -1};
    if (pipeIn && pipe2(fds, O_CLOEXEC) != 0) {
        *error = std::string("pipe failed: ") + std::strerror(errno);
        return false;
    }
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const int out = open(outputPath.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);  // children may share it
    const pid_t child = fork();
    if (child == 0) {
        // Child: stdin from the pipe (or /dev/null), stdout and stderr to the output file, then the program.
        const int in = pipeIn ? fds[0] : open("/dev/null", O_RDONLY);
        if (in < 0 || dup2(in, 0) < 0) _exit(127);
        if (out >= 0) dup2(out, 1), dup2(out, 2);
        signal(SIGPIPE, SIG_DFL);
        execvp(argv[0], argv.data());
        _exit(127);
    }
    if (out >= 0) close(out);
    if (pipeIn) close(fds[0]);
    if (child < 0) {
        if (pipeIn) close(fds[1]);
        *error = "cannot start " + args[0] + ": " + std::strerror(errno);
        return false;
    }
    RegisterChildProcess(child);
    // Non-blocking, so that a child that stops reading is noticed (WriteToChild) instead of blocking the writer.
    if (pipeIn) fcntl(fds[1], F_SETFL, fcntl(fds[1], F_GETFL) | O_NONBLOCK);
    *pid = child;
    *stdinFd = pipeIn ? fds[1] : -1;
    return true;
}

bool WriteToChild(int fd, const void* data, std::size_t size, double stallSeconds, bool* stalled, std::string* error) {
    *stalled = false;
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    Clock::time_point progress = Clock::now();
    while (size > 0) {
        const ssize_t n = write(fd, bytes, size);
        if (n > 0) {
            bytes += n;
            size -= std::size_t(n);
            progress = Clock::now();
            continue;
        }
        if (n < 0 && errno == EINTR) continue;
        if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK) {
            *error = std::string("writing to the encoder failed: ") + std::strerror(errno);
            return false;
        }
        const double left = stallSeconds - Since(progress);
        if (left <= 0.0) {
            *stalled = true;
            std::ostringstream text;
            text << "the encoder took no input for " << stallSeconds << " s (PSB_ENCODER_TIMEOUT); stopped";
            *error = text.str();
            return false;
        }
        pollfd p{fd, POLLOUT, 0};
        poll(&p, 1, int(std::ceil(std::min(left, 1.0) * 1000.0)));  // a closed reader wakes it (POLLERR)
    }
    return true;
}

ChildEnd WaitForChild(pid_t pid, double stallSeconds, const std::string& progressPath, int* exitCode) {
    // Polled, with a pause growing from 1 ms to 10 ms: a child that ends soon costs little latency, and a long
    // wait costs little CPU.
    Clock::time_point progress = Clock::now();
    long long size = progressPath.empty() ? -1 : FileSize(progressPath);
    int pauseMicros = 1000;
    for (;;) {
        int status = 0;
        const pid_t r = waitpid(pid, &status, WNOHANG);
        if (r == pid || (r < 0 && errno != EINTR)) {
            UnregisterChildProcess(pid);
            if (r == pid && WIFEXITED(status)) {
                *exitCode = WEXITSTATUS(status);
                return ChildEnd::Exited;
            }
            return ChildEnd::Signalled;
        }
        if (!progressPath.empty()) {
            const long long now = FileSize(progressPath);
            if (now != size) size = now, progress = Clock::now();
        }
        if (Since(progress) >= stallSeconds) {
            KillChild(pid);
            return ChildEnd::Stalled;
        }
        std::this_thread::sleep_for(std::chrono::microseconds(pauseMicros));
        pauseMicros = std::min(2 * pauseMicros, 10000);
    }
}

bool WaitForFfmpeg(pid_t pid, double stallSeconds, const std::string& output, const std::string& logPath,
                   std::string* error) {
    int code = -1;
    const ChildEnd end = WaitForChild(pid, stallSeconds, output, &code);
    const std::string last = LastLineOf(logPath);
    if (end == ChildEnd::Exited && code == 0 && last.empty()) return true;
    std::ostringstream text;
    text << "ffmpeg failed";
    if (end == ChildEnd::Stalled)
        text << ": no progress for " << stallSeconds << " s (PSB_ENCODER_TIMEOUT); stopped";
    else if (end == ChildEnd::Signalled)
        text << " (killed by a signal)";
    else if (code != 0)
        text << " with exit code " << code;
    if (!last.empty()) text << ": " << last;
    *error = text.str();
    return false;
}

void KillChild(pid_t pid) {
    if (pid <= 0) return;
    kill(pid, SIGKILL);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    UnregisterChildProcess(pid);
}

std::string LastLineOf(const std::string& outputPath) {
    std::ifstream in(outputPath);
    std::string line, last;
    while (std::getline(in, line))
        if (!line.empty()) last = line;
    return last;
}

bool FfmpegChild::Wait(double stallSeconds, const std::string& output, const std::string& logPath, std::string* error) {
    if (pid <= 0) {  // never waitpid(-1): it would reap another part's ffmpeg
        *error = "ffmpeg is not running";
        return false;
    }
    const pid_t waited = pid;
    pid = -1;
    return WaitForFfmpeg(waited, stallSeconds, output, logPath, error);
}

void FfmpegChild::Kill() {
    KillChild(pid);
    pid = -1;
}

void FfmpegChild::CloseInput() {
    if (input >= 0) close(input);
    input = -1;
}
