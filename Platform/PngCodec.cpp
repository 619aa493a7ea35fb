#include "Platform/PngCodec.h"

#include <png.h>

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

// Reading from memory: libpng asks for n bytes at a time; running out is an error, never a read past the end.
struct ReadSource {
    const std::uint8_t* data;
    std::size_t size;
    std::size_t pos;
};

void ReadBytes(png_structp png, png_bytep out, png_size_t n) {
    auto* source = static_cast<ReadSource*>(png_get_io_ptr(png));
    if (n > source->size - source->pos) png_error(png, "truncated PNG");
    std::memcpy(out, source->data + source->pos, n);
    source->pos += n;
}

// The libpng read state; the functions that call libpng below keep only C state between setjmp and return.
struct PngReader {
    png_structp png = nullptr;
    png_infop info = nullptr;
    ReadSource source;
    char message[256] = "libpng could not allocate its state";
    explicit PngReader(const std::vector<std::uint8_t>& bytes) : source{bytes.data(), bytes.size(), 0} {
        png = png_create_read_struct(PNG_LIBPNG_VER_STRING, message, OnPngError, OnPngWarning);
        if (png) info = png_create_info_struct(png);
    }
    ~PngReader() {
        if (png) png_destroy_read_struct(&png, info ? &info : nullptr, nullptr);
    }
    PngReader(const PngReader&) = delete;
    PngReader& operator=(const PngReader&) = delete;
};

bool ReadInfo(PngReader* r, png_uint_32* width, png_uint_32* height) {
    if (!r->png || !r->info) return false;
    if (setjmp(png_jmpbuf(r->png))) return false;
    // The header's own size is reported as it is; the decode is refused by the caller, before any allocation.
    png_set_user_limits(r->png, 0x7fffffffu, 0x7fffffffu);
    png_set_read_fn(r->png, &r->source, ReadBytes);
    png_read_info(r->png, r->info);
    *width = png_get_image_width(r->png, r->info);
    *height = png_get_image_height(r->png, r->info);
    return true;
}

// Any colour type and depth to 8-bit RGBA: palette and low-depth grey expanded, tRNS to alpha, 16-bit
// channels to their high byte (v16 = 257 * v8 gives back v8; no gamma is applied), grey to RGB, opaque
// alpha added where there is none.
bool ReadRgbaRows(PngReader* r, png_uint_32 width, png_bytepp rows) {
    if (setjmp(png_jmpbuf(r->png))) return false;
    png_set_expand(r->png);
    png_set_strip_16(r->png);
    png_set_gray_to_rgb(r->png);
    png_set_add_alpha(r->png, 0xff, PNG_FILLER_AFTER);
    png_set_interlace_handling(r->png);
    png_read_update_info(r->png, r->info);
    if (png_get_rowbytes(r->png, r->info) != png_size_t(width) * 4) png_error(r->png, "unexpected row layout");
    png_read_image(r->png, rows);
    return true;
}

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

bool ReadPngHeader(const std::vector<std::uint8_t>& bytes, int* width, int* height, std::string* error) {
    PngReader reader(bytes);
    png_uint_32 w = 0, h = 0;
    if (!ReadInfo(&reader, &w, &h)) {
        *error = std::string("not a PNG: ") + reader.message;
        return false;
    }
    *width = int(w);
    *height = int(h);
    return true;
}

bool DecodePng(const std::vector<std::uint8_t>& bytes, Image* img, std::string* error) {
    PngReader reader(bytes);
    png_uint_32 w = 0, h = 0;
    if (!ReadInfo(&reader, &w, &h)) {
        *error = std::string("not a PNG: ") + reader.message;
        return false;
    }
    if (w > png_uint_32(kMaxPngSide) || h > png_uint_32(kMaxPngSide)) {
        *error = "PNG of " + std::to_string(w) + "x" + std::to_string(h) + " is larger than " +
                 std::to_string(kMaxPngSide) + "x" + std::to_string(kMaxPngSide);
        return false;
    }
    std::vector<std::uint8_t> rgba(std::size_t(w) * h * 4);
    std::vector<png_bytep> rows(h);
    for (png_uint_32 y = 0; y < h; ++y) rows[y] = rgba.data() + std::size_t(y) * w * 4;
    if (!ReadRgbaRows(&reader, w, rows.data())) {
        *error = std::string("PNG decode failed: ") + reader.message;
        return false;
    }
    Image result(static_cast<int>(w), static_cast<int>(h));
    for (std::size_t p = 0, n = std::size_t(w) * h; p < n; ++p)
        std::memcpy(&result.rgb[p * 3], &rgba[p * 4], 3);  // alpha dropped: frames are opaque
    *img = std::move(result);
    return true;
}

bool ReadFileBytes(const std::string& path, std::vector<std::uint8_t>* bytes, std::string* error) {
    ReadFailure failure = ReadFailure::None;
    return ReadRegularFile(path, kMaxPngFileBytes, bytes, &failure, error);
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
