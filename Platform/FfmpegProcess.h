#pragma once
// The child processes of a video recording (ffmpeg, and ffprobe checking its result), with every wait bounded
// (docs/app.md, "Video"): a pipe that takes no input, or a child that neither ends nor grows its output file,
// for EncoderStallSeconds() is killed and reported, never waited on without end.

#include <sys/types.h>

#include <cstddef>
#include <string>
#include <vector>

/// Seconds a child may make no progress before it is stopped: PSB_ENCODER_TIMEOUT when it holds a number > 0,
/// else 60.
double EncoderStallSeconds();

/// Starts args[0] (found on PATH) with args. Its standard input is a pipe whose write end, non-blocking, is
/// returned in *stdinFd when pipeIn (else /dev/null and -1); its standard output and error are appended to
/// outputPath (an existing file). The child is registered for SIGINT/SIGTERM (Platform/Files/TempRegistry.h)
/// and gets SIGPIPE back. False with *error when it cannot be started (an exec failure exits it with 127).
bool StartChild(const std::vector<std::string>& args, bool pipeIn, const std::string& outputPath, pid_t* pid,
                int* stdinFd, std::string* error);

/// Writes all of data into a child's standard input (a StartChild pipe). False with *error when the child has
/// closed it (EPIPE) or took nothing for stallSeconds; *stalled says which.
bool WriteToChild(int fd, const void* data, std::size_t size, double stallSeconds, bool* stalled, std::string* error);

enum class ChildEnd { Exited, Signalled, Stalled };

/// Waits for pid to end, for at most stallSeconds without progress (the file progressPath, when not empty,
/// growing is progress). A stalled child is killed and reaped. *exitCode is its exit status when it Exited.
/// The child is unregistered in every case.
ChildEnd WaitForChild(pid_t pid, double stallSeconds, const std::string& progressPath, int* exitCode);

/// Waits for an ffmpeg started at `-loglevel error` with its output in logPath (WaitForChild, output growing
/// is progress). True only if it exited 0 with nothing in its log: it exits 0 after "Error writing trailer"
/// (a full disk, a file-size limit), so any line there is a failure. Else false, *error saying how it ended
/// and its last line.
bool WaitForFfmpeg(pid_t pid, double stallSeconds, const std::string& output, const std::string& logPath,
                   std::string* error);

/// Kills pid (SIGKILL), reaps it and unregisters it. Ignores pid <= 0.
void KillChild(pid_t pid);

/// The last non-empty line of a child's output file ("" if none): its last message.
std::string LastLineOf(const std::string& outputPath);

/// True if an executable named program is on PATH.
bool ProgramOnPath(const std::string& program);

/// A number as an ffmpeg argument: up to 10 significant digits ("-framerate 60", "-framerate 29.97").
std::string FfmpegNumber(double v);

/// One ffmpeg of a recording (the recorders' process wrapper): started with StartChild, its output appended to
/// a log, waited for with WaitForFfmpeg, killed with KillChild. Not owning: a recorder hands its pid and input on
/// (a GIF part keeps them) and kills what still runs when it aborts.
struct FfmpegChild {
    pid_t pid = -1;  ///< while it runs and has not been waited for
    int input = -1;  ///< the write end of its standard input (Start with pipeIn), until closed
    /// StartChild(args, pipeIn, logPath).
    bool Start(const std::vector<std::string>& args, bool pipeIn, const std::string& logPath, std::string* error) {
        return StartChild(args, pipeIn, logPath, &pid, &input, error);
    }
    /// WaitForFfmpeg on it (never waitpid(-1): "ffmpeg is not running" when there is none); it is gone after.
    bool Wait(double stallSeconds, const std::string& output, const std::string& logPath, std::string* error);
    /// KillChild; it is gone after.
    void Kill();
    /// Closes its standard input if open.
    void CloseInput();
};
