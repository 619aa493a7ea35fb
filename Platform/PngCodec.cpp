#include "Platform/PngCodec.h"

#include <png.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace {

struct WriteTarget {
    std::vector<std::uint8_t>* out;
};

void AppendBytes(png_structp png, png_bytep data, png_size_t length) {
    auto* target = static_cast<WriteTarget*>(png_get_io_ptr(png));
    target->out->insert(target->out->end(), data, data + length);
}

void NoFlush(png_structp) {}

// libpng reports errors by longjmp; keep the message for the caller.
void OnPngError(png_structp png, png_const_charp message) {
    auto* text = static_cast<char*>(png_get_error_ptr(png));
    std::snprintf(text, 256, "%s", message);
    png_longjmp(png, 1);
}

void OnPngWarning(png_structp, png_const_charp) {}

// Everything between setjmp and the end is C state only, so the longjmp skips no destructor.
bool EncodeRows(const Image& img, const PngOptions& options, WriteTarget* target, char* message) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, message, OnPngError, OnPngWarning);
    if (!png) return false;
    png_infop info = png_create_info_struct(png);
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, info ? &info : nullptr);
        return false;
    }
    png_set_write_fn(png, target, AppendBytes, NoFlush);
    png_set_compression_level(png, options.level);
    static const int kFilters[] = {PNG_FILTER_NONE, PNG_FILTER_SUB, PNG_FILTER_UP, PNG_ALL_FILTERS};
    png_set_filter(png, PNG_FILTER_TYPE_BASE, kFilters[int(options.filter)]);
    png_set_IHDR(png, info, png_uint_32(img.width), png_uint_32(img.height), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
    png_write_info(png, info);
    for (int y = 0; y < img.height; ++y)
        png_write_row(png, const_cast<png_bytep>(img.rgb.data() + std::size_t(y) * std::size_t(img.width) * 3));
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return true;
}

}  // namespace

bool EncodePng(const Image& img, const PngOptions& options, std::vector<std::uint8_t>* out, std::string* error) {
    if (img.width <= 0 || img.height <= 0 || img.rgb.size() != std::size_t(img.width) * img.height * 3) {
        *error = "cannot encode a " + std::to_string(img.width) + "x" + std::to_string(img.height) + " image";
        return false;
    }
    out->clear();
    out->reserve(img.rgb.size() / 4);
    WriteTarget target{out};
    char message[256] = "libpng could not allocate its state";
    if (!EncodeRows(img, options, &target, message)) {
        *error = std::string("PNG encode failed: ") + message;
        return false;
    }
    return true;
}

bool DecodePng(const std::vector<std::uint8_t>& bytes, Image* img, std::string* error) {
    png_image image;
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&image, bytes.data(), bytes.size())) {
        *error = std::string("not a PNG: ") + image.message;
        return false;
    }
    image.format = PNG_FORMAT_RGB;
    Image result(int(image.width), int(image.height));
    if (!png_image_finish_read(&image, nullptr, result.rgb.data(), 0, nullptr)) {
        *error = std::string("PNG decode failed: ") + image.message;
        png_image_free(&image);
        return false;
    }
    *img = std::move(result);
    return true;
}

bool ReadFileBytes(const std::string& path, std::vector<std::uint8_t>* bytes, std::string* error) {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) {
        *error = "cannot read " + path + ": " + std::strerror(errno);
        return false;
    }
    bytes->clear();
    std::uint8_t buffer[65536];
    std::size_t n = 0;
    while ((n = std::fread(buffer, 1, sizeof buffer, f)) > 0) bytes->insert(bytes->end(), buffer, buffer + n);
    const bool ok = !std::ferror(f);
    std::fclose(f);
    if (!ok) *error = "read error on " + path;
    return ok;
}

bool ReadPngFile(const std::string& path, Image* img, std::string* error) {
    std::vector<std::uint8_t> bytes;
    if (!ReadFileBytes(path, &bytes, error)) return false;
    if (!DecodePng(bytes, img, error)) {
        *error = path + ": " + *error;
        return false;
    }
    return true;
}

bool WriteFileAtomic(const std::string& path, const std::vector<std::uint8_t>& bytes, std::string* error) {
    // The temporary sits beside the target (same file system, so rename is atomic) and is hidden.
    const std::size_t slash = path.find_last_of('/');
    const std::string dir = slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
    const std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
    const std::string temp = dir + "." + base + ".tmp";
    const auto fail = [&](const char* what) {
        *error = "cannot write " + path + " (" + what + " " + temp + "): " + std::strerror(errno);
        std::remove(temp.c_str());
        return false;
    };
    std::FILE* f = std::fopen(temp.c_str(), "wb");
    if (!f) {
        *error = "cannot write " + path + " (creating " + temp + "): " + std::strerror(errno);
        return false;
    }
    const bool written = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
    const bool closed = std::fclose(f) == 0;
    if (!written || !closed) return fail("writing");
    if (std::rename(temp.c_str(), path.c_str()) != 0) return fail("renaming");
    return true;
}
