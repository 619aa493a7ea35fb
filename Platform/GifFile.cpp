#include "Platform/GifFile.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>

namespace {

/// Size of the signature, the screen descriptor and the global colour table, or 0 if `bytes` is too short.
std::size_t HeaderSize(const std::string& bytes) {
    if (bytes.size() < 13 || (bytes.compare(0, 6, "GIF89a") != 0 && bytes.compare(0, 6, "GIF87a") != 0)) return 0;
    const unsigned char packed = static_cast<unsigned char>(bytes[10]);
    std::size_t size = 13;
    if (packed & 0x80) size += 3u * (2u << (packed & 0x07));  // global colour table of 2^(n+1) RGB entries
    return size <= bytes.size() ? size : 0;
}

bool ReadFile(const std::string& path, std::string* bytes, std::string* error) {
    std::ifstream in(path, std::ios::binary);
    bytes->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (in.bad() || !in.is_open()) {
        *error = "cannot read " + path + ": " + std::strerror(errno);
        return false;
    }
    return true;
}

}  // namespace

bool GifFirstFrameOffset(const std::string& bytes, std::size_t* offset) {
    std::size_t i = HeaderSize(bytes);
    if (i == 0) return false;
    while (i < bytes.size()) {
        const unsigned char block = static_cast<unsigned char>(bytes[i]);
        if (block == 0x2C) {
            *offset = i;
            return true;
        }
        if (block != 0x21 || i + 1 >= bytes.size()) return false;  // a trailer or garbage before any frame
        if (static_cast<unsigned char>(bytes[i + 1]) == 0xF9) {
            *offset = i;
            return true;
        }
        // Another extension: its data sub-blocks (a length byte, then that many bytes) up to a zero length.
        std::size_t j = i + 2;
        while (j < bytes.size() && bytes[j] != 0) j += 1 + static_cast<unsigned char>(bytes[j]);
        if (j >= bytes.size()) return false;
        i = j + 1;
    }
    return false;
}

bool AppendGifFrames(const std::string& first, const std::string& second, std::string* error) {
    std::string a, b;
    if (!ReadFile(first, &a, error) || !ReadFile(second, &b, error)) return false;
    std::size_t frameA = 0, frameB = 0;
    if (!GifFirstFrameOffset(a, &frameA) || a.back() != 0x3B) {
        *error = "not a complete GIF: " + first;
        return false;
    }
    if (!GifFirstFrameOffset(b, &frameB)) {
        *error = "not a complete GIF: " + second;
        return false;
    }
    const std::size_t header = HeaderSize(a);
    if (HeaderSize(b) != header || a.compare(0, header, b, 0, header) != 0) {
        *error = first + " and " + second + " have different screens or colour tables";
        return false;
    }
    // Drop the first file's trailer, then append the second from its first frame (its trailer included).
    if (truncate(first.c_str(), static_cast<off_t>(a.size() - 1)) != 0) {
        *error = "cannot truncate " + first + ": " + std::strerror(errno);
        return false;
    }
    std::ofstream out(first, std::ios::binary | std::ios::app);
    out.write(b.data() + frameB, static_cast<std::streamsize>(b.size() - frameB));
    out.flush();
    if (!out) {
        *error = "cannot write " + first + ": " + std::strerror(errno);
        return false;
    }
    return true;
}
