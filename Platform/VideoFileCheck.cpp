#include "Platform/VideoFileCheck.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <sstream>
#include <vector>

#include "Platform/FfmpegProcess.h"
#include "Platform/Files/AtomicFile.h"

namespace {

std::uint64_t BigEndian(const std::uint8_t* p, int n) {
    std::uint64_t v = 0;
    for (int i = 0; i < n; ++i) v = v << 8 | p[i];
    return v;
}

/// An EBML variable-length integer at offset (Matroska's element sizes): its value, its length in bytes, and
/// whether all its value bits are 1 ("unknown size"). False if it cannot be read or its first byte is 0.
bool ReadVint(const ReadAt& read, std::uint64_t offset, std::uint64_t* value, int* length, bool* unknown) {
    std::uint8_t bytes[8];
    if (!read(offset, bytes, 1) || bytes[0] == 0) return false;
    int n = 1;
    while (!(bytes[0] & (0x80 >> (n - 1)))) ++n;
    if (n > 1 && !read(offset + 1, bytes + 1, std::size_t(n - 1))) return false;
    std::uint64_t v = bytes[0] & (0xFFu >> n);
    bool allOnes = v == (0xFFu >> n);
    for (int i = 1; i < n; ++i) {
        v = v << 8 | bytes[i];
        allOnes = allOnes && bytes[i] == 0xFF;
    }
    *value = v;
    *length = n;
    *unknown = allOnes;
    return true;
}

/// The text of a small file ("" if unreadable).
std::string SmallFileText(const std::string& path) {
    std::vector<std::uint8_t> bytes;
    ReadFailure failure = ReadFailure::None;
    std::string ignored;
    if (!ReadRegularFile(path, 1 << 16, &bytes, &failure, &ignored)) return "";
    return std::string(bytes.begin(), bytes.end());
}

/// ffprobe's count of the video packets in path; false with *error (ffprobe's own message) if it fails.
bool ProbePackets(const std::string& path, const std::string& scratchPath, double stallSeconds, long long* packets,
                  std::string* error) {
    if (truncate(scratchPath.c_str(), 0) != 0) {
        *error = "cannot reuse " + scratchPath + ": " + std::strerror(errno);
        return false;
    }
    pid_t pid = -1;
    int unusedFd = -1;
    if (!StartChild({"ffprobe", "-v", "error", "-select_streams", "v:0", "-count_packets", "-show_entries",
                     "stream=nb_read_packets", "-of", "csv=p=0", path},
                    false, scratchPath, &pid, &unusedFd, error))
        return false;
    int code = -1;
    const ChildEnd end = WaitForChild(pid, stallSeconds, "", &code);
    std::istringstream lines(SmallFileText(scratchPath));
    std::string line, count, complaint;
    while (std::getline(lines, line)) {
        if (line.empty()) continue;
        if (line.find_first_not_of("0123456789") == std::string::npos && count.empty())
            count = line;
        else if (complaint.empty())
            complaint = line;
    }
    if (end != ChildEnd::Exited || code != 0 || !complaint.empty() || count.empty()) {
        std::ostringstream text;
        text << "ffprobe cannot read it";
        if (end == ChildEnd::Stalled) text << " (no answer within " << stallSeconds << " s)";
        if (!complaint.empty()) text << ": " << complaint;
        *error = text.str();
        return false;
    }
    *packets = std::stoll(count.substr(0, 18));
    return true;
}

}  // namespace

bool CheckMp4Layout(std::uint64_t fileSize, const ReadAt& read, std::string* error) {
    bool ftyp = false, moov = false, mdat = false;
    std::uint64_t offset = 0;
    while (offset < fileSize) {
        std::uint8_t head[16];
        if (fileSize - offset < 8 || !read(offset, head, 8)) {
            *error = "a truncated box at byte " + std::to_string(offset);
            return false;
        }
        const std::string type(reinterpret_cast<const char*>(head + 4), 4);
        for (const char c : type)
            if (c < 0x20 || c > 0x7E) {
                *error = "no MP4 box at byte " + std::to_string(offset);
                return false;
            }
        std::uint64_t size = BigEndian(head, 4), header = 8;
        if (size == 1) {  // a 64-bit size follows the type
            if (fileSize - offset < 16 || !read(offset + 8, head + 8, 8)) {
                *error = "a truncated box '" + type + "' at byte " + std::to_string(offset);
                return false;
            }
            size = BigEndian(head + 8, 8);
            header = 16;
        } else if (size == 0) {
            size = fileSize - offset;  // the last box, to the end of the file
        }
        if (size < header || size > fileSize - offset) {
            *error = "box '" + type + "' at byte " + std::to_string(offset) + " claims " + std::to_string(size) +
                     " bytes, " + std::to_string(fileSize - offset) + " are left (a truncated file)";
            return false;
        }
        if (offset == 0 && type != "ftyp") {
            *error = "it does not start with an 'ftyp' box";
            return false;
        }
        ftyp = ftyp || type == "ftyp";
        moov = moov || type == "moov";
        mdat = mdat || type == "mdat";
        offset += size;
    }
    if (ftyp && moov && mdat) return true;
    *error = std::string("no '") + (!ftyp ? "ftyp" : !moov ? "moov" : "mdat") + "' box (an unfinished file)";
    return false;
}

bool CheckWebmLayout(std::uint64_t fileSize, const ReadAt& read, std::string* error) {
    static const std::uint8_t kEbml[4] = {0x1A, 0x45, 0xDF, 0xA3}, kSegment[4] = {0x18, 0x53, 0x80, 0x67};
    std::uint8_t id[4];
    std::uint64_t size = 0;
    int length = 0;
    bool unknown = false;
    if (!read(0, id, 4) || std::memcmp(id, kEbml, 4) != 0 || !ReadVint(read, 4, &size, &length, &unknown) || unknown) {
        *error = "it does not start with an EBML header";
        return false;
    }
    const std::uint64_t segment = 4 + std::uint64_t(length) + size;
    if (segment < size || !read(segment, id, 4) || std::memcmp(id, kSegment, 4) != 0 ||
        !ReadVint(read, segment + 4, &size, &length, &unknown)) {
        *error = "no Segment after the EBML header";
        return false;
    }
    if (unknown) {
        *error = "the Segment's size was never written (an unfinished file)";
        return false;
    }
    const std::uint64_t data = segment + 4 + std::uint64_t(length);
    if (size > fileSize || data != fileSize - size) {
        *error = "the Segment claims " + std::to_string(size) + " bytes from byte " + std::to_string(data) +
                 ", the file has " + std::to_string(fileSize) + " (a truncated file)";
        return false;
    }
    return true;
}

bool CheckVideoFile(const std::string& path, VideoContainer container, int frames, const std::string& scratchPath,
                    double stallSeconds, std::string* error) {
    const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
    struct stat st {};
    if (fd < 0 || fstat(fd, &st) != 0) {
        *error = "cannot read the encoder's output: " + std::string(std::strerror(errno));
        if (fd >= 0) close(fd);
        return false;
    }
    const ReadAt read = [fd](std::uint64_t offset, std::uint8_t* buf, std::size_t n) {
        return pread(fd, buf, n, off_t(offset)) == ssize_t(n);
    };
    std::string why;
    bool ok = st.st_size > 0;
    if (!ok)
        why = "the encoder wrote nothing";
    else if (container == VideoContainer::Mp4)
        ok = CheckMp4Layout(std::uint64_t(st.st_size), read, &why);
    else
        ok = CheckWebmLayout(std::uint64_t(st.st_size), read, &why);
    close(fd);
    long long packets = 0;
    if (ok && ProgramOnPath("ffprobe")) {
        ok = ProbePackets(path, scratchPath, stallSeconds, &packets, &why);
        if (ok && packets != frames) {
            ok = false;
            why = "it holds " + std::to_string(packets) + " of the " + std::to_string(frames) + " frames sent";
        }
    }
    if (!ok) *error = "the encoder's output is not a whole video: " + why;
    return ok;
}
