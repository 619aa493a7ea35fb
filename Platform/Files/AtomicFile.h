#pragma once
// Whole-or-nothing file output and bounded file input (docs/app.md, "Files"). A file is written to a unique
// temporary in its own directory (".NAME.XXXXXX", NAME shortened so the temporary stays within NAME_MAX) and
// renamed over the target when complete, so a reader sees the old file or the new one, never a mix, and two
// processes writing the same target never share a temporary. An existing target that is not a regular file
// (a symbolic link, a device, a FIFO, a directory) is refused, never replaced.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

class AtomicFile {
public:
    AtomicFile() = default;
    ~AtomicFile();  ///< Abandons an uncommitted file.
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    /// Creates the temporary for path. False with *error naming path and the reason (the target exists and is
    /// not a regular file; the directory is missing or unwritable).
    bool Open(const std::string& path, std::string* error);
    /// Appends bytes (buffered). False with *error naming the path and the system error (ENOSPC, EFBIG, ...).
    bool Write(const void* data, std::size_t size, std::string* error);
    /// Flushes, closes and renames the temporary over the target. False with *error; the temporary is removed.
    bool Commit(std::string* error);
    /// Closes and removes the temporary; the target is untouched. Safe to call at any time.
    void Abandon();
    bool IsOpen() const { return fd >= 0; }
    const std::string& TemporaryPath() const { return temp; }

private:
    bool Flush(std::string* error);
    bool Fail(const char* what, std::string* error);

    int fd = -1;
    int registryId = -1;
    std::string target;
    std::string temp;
    std::vector<char> buffer;
};

/// Creates an empty temporary file beside target (".NAME.XXXXXX", mode 0666 less the umask, as AtomicFile's),
/// registered for removal on SIGINT/SIGTERM (TempRegistry.h). Returns its path and sets *registryId (for
/// UnregisterTemporary once it is renamed or removed); "" with *error naming the directory on failure.
std::string CreateTemporaryBeside(const std::string& target, int* registryId, std::string* error);

/// Writes bytes to path whole or not at all (AtomicFile). On failure *error names the path and the reason.
bool WriteFileAtomic(const std::string& path, const std::vector<std::uint8_t>& bytes, std::string* error);
/// Checks that path can be the target of an AtomicFile: it does not exist, or it is a regular file (lstat: a
/// symbolic link is refused even when it points at a regular file). False with *error.
bool CheckWritableTarget(const std::string& path, std::string* error);

/// Why ReadRegularFile failed.
enum class ReadFailure { None, Missing, NotRegular, TooLarge, IoError };

/// Reads the whole of path into *bytes if it is a regular file of at most maxBytes bytes. Never blocks on a
/// FIFO and never reads a device. False with *failure and *error (naming the path) otherwise.
bool ReadRegularFile(const std::string& path, std::size_t maxBytes, std::vector<std::uint8_t>* bytes,
                     ReadFailure* failure, std::string* error);
/// The temporary name used for target: same directory, "." + base name (shortened to stay within NAME_MAX
/// with the suffix) + "." + suffix.
std::string TemporaryNameFor(const std::string& target, const std::string& suffix);
