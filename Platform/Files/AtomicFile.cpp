#include "Platform/Files/AtomicFile.h"

#include <fcntl.h>
#include <limits.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>

#include "Platform/Files/TempRegistry.h"

namespace {

constexpr std::size_t kBufferBytes = 64 * 1024;
constexpr std::size_t kNameMax = NAME_MAX;  // bytes in one path component (255 on Linux)

// Six characters that differ between processes (pid, clock) and between calls (a counter).
std::string UniqueSuffix() {
    static std::atomic<unsigned> counter{0};
    timespec now{};
    clock_gettime(CLOCK_REALTIME, &now);
    unsigned long long x = (unsigned long long)getpid() * 2654435761ull ^ (unsigned long long)now.tv_nsec ^
                           ((unsigned long long)counter.fetch_add(1) << 20);
    static const char kAlphabet[] = "abcdefghijklmnopqrstuvwxyz0123456789";
    std::string s(6, 'a');
    for (char& c : s) {
        c = kAlphabet[x % 36];
        x /= 36;
    }
    return s;
}

std::string SystemError(int err) { return std::strerror(err); }

}  // namespace

std::string TemporaryNameFor(const std::string& target, const std::string& suffix) {
    const std::size_t slash = target.find_last_of('/');
    const std::string dir = slash == std::string::npos ? std::string() : target.substr(0, slash + 1);
    std::string base = slash == std::string::npos ? target : target.substr(slash + 1);
    const std::size_t room = kNameMax - 2 - suffix.size();  // "." + base + "." + suffix
    if (base.size() > room) base.resize(room);
    return dir + "." + base + "." + suffix;
}

bool CheckWritableTarget(const std::string& path, std::string* error) {
    struct stat st;
    if (lstat(path.c_str(), &st) != 0) {
        if (errno == ENOENT) return true;
        *error = "cannot write " + path + ": " + SystemError(errno);
        return false;
    }
    if (S_ISREG(st.st_mode)) return true;
    const char* what = S_ISLNK(st.st_mode)    ? "a symbolic link"
                       : S_ISDIR(st.st_mode)  ? "a directory"
                       : S_ISFIFO(st.st_mode) ? "a FIFO"
                                              : "a device or special file";
    *error = "cannot write " + path + ": it exists and is " + what + ", not a regular file (refusing to replace it)";
    return false;
}

std::string CreateTemporaryBeside(const std::string& target, int* registryId, std::string* error) {
    for (int attempt = 0; attempt < 100; ++attempt) {
        const std::string temp = TemporaryNameFor(target, UniqueSuffix());
        *registryId = RegisterTemporary(temp);  // before it exists: a signal cannot leave it behind
        const int fd = open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            close(fd);
            return temp;
        }
        const int err = errno;
        UnregisterTemporary(*registryId);
        *registryId = -1;
        if (err != EEXIST) {
            *error = "cannot create a temporary beside " + target + ": " + SystemError(err);
            return "";
        }
    }
    *error = "cannot create a temporary beside " + target + ": no unused temporary name";
    return "";
}

AtomicFile::~AtomicFile() { Abandon(); }

bool AtomicFile::Open(const std::string& path, std::string* error) {
    Abandon();
    if (!CheckWritableTarget(path, error)) return false;
    target = path;
    for (int attempt = 0; attempt < 100; ++attempt) {
        temp = TemporaryNameFor(path, UniqueSuffix());
        // Registered before it exists, so a signal between open and register cannot leave it behind.
        registryId = RegisterTemporary(temp);
        fd = open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) break;
        const int err = errno;
        UnregisterTemporary(registryId);
        registryId = -1;
        if (err != EEXIST) {
            *error = "cannot write " + path + " (creating " + temp + "): " + SystemError(err);
            temp.clear();
            return false;
        }
    }
    if (fd < 0) {
        *error = "cannot write " + path + ": no unused temporary name";
        temp.clear();
        return false;
    }
    buffer.clear();
    buffer.reserve(kBufferBytes);
    return true;
}

bool AtomicFile::Fail(const char* what, std::string* error) {
    const int err = errno;
    *error = "cannot write " + target + " (" + what + " " + temp + "): " + SystemError(err);
    Abandon();
    return false;
}

bool AtomicFile::Flush(std::string* error) {
    const char* p = buffer.data();
    std::size_t left = buffer.size();
    while (left > 0) {
        const ssize_t n = write(fd, p, left);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            if (n == 0) errno = EIO;
            return Fail("writing", error);
        }
        p += n;
        left -= std::size_t(n);
    }
    buffer.clear();
    return true;
}

bool AtomicFile::Write(const void* data, std::size_t size, std::string* error) {
    if (fd < 0) {
        *error = "cannot write " + target + ": the file is not open";
        return false;
    }
    const char* bytes = static_cast<const char*>(data);
    buffer.insert(buffer.end(), bytes, bytes + size);
    return buffer.size() < kBufferBytes || Flush(error);
}

bool AtomicFile::Commit(std::string* error) {
    if (fd < 0) {
        *error = "cannot write " + target + ": the file is not open";
        return false;
    }
    if (!Flush(error)) return false;
    if (close(fd) != 0) {
        fd = -1;
        return Fail("closing", error);
    }
    fd = -1;
    if (rename(temp.c_str(), target.c_str()) != 0) return Fail("renaming", error);
    UnregisterTemporary(registryId);
    registryId = -1;
    temp.clear();
    return true;
}

void AtomicFile::Abandon() {
    if (fd >= 0) close(fd);
    fd = -1;
    if (!temp.empty()) unlink(temp.c_str());
    UnregisterTemporary(registryId);
    registryId = -1;
    temp.clear();
    buffer.clear();
}

bool WriteFileAtomic(const std::string& path, const std::vector<std::uint8_t>& bytes, std::string* error) {
    AtomicFile file;
    return file.Open(path, error) && file.Write(bytes.data(), bytes.size(), error) && file.Commit(error);
}

bool ReadRegularFile(const std::string& path, std::size_t maxBytes, std::vector<std::uint8_t>* bytes,
                     ReadFailure* failure, std::string* error) {
    const auto fail = [&](ReadFailure why, const std::string& text) {
        *failure = why;
        *error = path + ": " + text;
        return false;
    };
    // O_NONBLOCK: opening a FIFO with no writer returns at once instead of waiting for one.
    const int fd = open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) return fail(errno == ENOENT ? ReadFailure::Missing : ReadFailure::IoError, SystemError(errno));
    struct stat st;
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        close(fd);
        return fail(ReadFailure::NotRegular, "not a regular file");
    }
    if (std::size_t(st.st_size) > maxBytes) {
        close(fd);
        return fail(ReadFailure::TooLarge, "larger than " + std::to_string(maxBytes) + " bytes");
    }
    bytes->resize(std::size_t(st.st_size));
    std::size_t got = 0;
    for (;;) {
        // One byte beyond the size seen by fstat detects a file that grows while it is read.
        if (got == bytes->size()) bytes->resize(std::min(got + kBufferBytes, maxBytes + 1));
        const ssize_t n = read(fd, bytes->data() + got, bytes->size() - got);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            const int err = errno;
            close(fd);
            return fail(ReadFailure::IoError, SystemError(err));
        }
        if (n == 0) break;
        got += std::size_t(n);
        if (got > maxBytes) {
            close(fd);
            return fail(ReadFailure::TooLarge, "larger than " + std::to_string(maxBytes) + " bytes");
        }
    }
    close(fd);
    bytes->resize(got);
    *failure = ReadFailure::None;
    return true;
}
