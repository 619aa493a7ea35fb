#pragma once
// The temporaries a process has open, so a signal can remove them before the process ends (docs/app.md,
// "Signals and temporary files"). The registry is process-wide by necessity: a signal handler has no other
// way to find them. Every function here is thread-safe; the handler uses only async-signal-safe calls.

#include <string>

/// Records a temporary file path (relative paths are taken against the working directory, which the programs
/// never change). Returns a slot id for UnregisterTemporary, or -1 when the path is too long or the registry is
/// full (the file is then simply not removed on a signal).
int RegisterTemporary(const std::string& path);
/// Forgets slot id (after the temporary was renamed or removed). -1 is ignored.
void UnregisterTemporary(int id);
/// Records a child process (an encoder writing into a registered temporary): on SIGINT/SIGTERM it is killed
/// and reaped before the temporaries are removed, so it cannot write them again. Up to 8; false when full.
bool RegisterChildProcess(int pid);
/// Forgets a child recorded by RegisterChildProcess (after it was waited for). Unknown pids are ignored.
void UnregisterChildProcess(int pid);
/// Installs the process's signal policy: SIGINT and SIGTERM remove every registered temporary, print one line
/// "<program>: interrupted by SIGINT; temporary files removed, completed files kept" on stderr and exit with
/// 128 + the signal number (130, 143); SIGXFSZ is ignored, so a write beyond the file-size limit fails with
/// EFBIG and is reported like any other write error. program must outlive the process (a string literal).
void InstallTemporaryCleanupOnSignals(const char* program);
