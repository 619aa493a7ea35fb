#include "Platform/GifJoin.h"

#include <algorithm>
#include <cstddef>
#include <string>

namespace {

constexpr std::size_t kHeaderSize = 13;  // "GIF87a" or "GIF89a" and the logical screen descriptor

/// Bytes of the colour table a packed field announces (bit 7: present; bits 0-2: 2^(n+1) entries of 3 bytes).
std::size_t ColourTableSize(std::uint8_t packed) { return (packed & 0x80) ? 3u * (2u << (packed & 7)) : 0u; }

/// One parsed part: where its blocks are.
struct Part {
    std::size_t tableEnd = 0;    // end of the header and the global colour table, where the blocks start
    std::uint8_t tableBits = 0;  // the global table's size field (bits 0-2 of the screen descriptor's packed byte)
    bool hasTable = false;
};

class Reader {
public:
    Reader(const std::vector<std::uint8_t>& bytes, std::size_t at) : b(bytes), i(at) {}
    bool Has(std::size_t n) const { return i <= b.size() && b.size() - i >= n; }
    std::size_t At() const { return i; }
    std::uint8_t Byte() { return b[i++]; }
    void Skip(std::size_t n) { i += n; }
    /// Skips sub-blocks up to and including the zero-length terminator; false if the data ends first.
    bool SkipSubBlocks() {
        for (;;) {
            if (!Has(1)) return false;
            const std::uint8_t n = Byte();
            if (n == 0) return true;
            if (!Has(n)) return false;
            Skip(n);
        }
    }

private:
    const std::vector<std::uint8_t>& b;
    std::size_t i;
};

bool ParseHeader(const std::vector<std::uint8_t>& b, Part* p) {
    if (b.size() < kHeaderSize || b[0] != 'G' || b[1] != 'I' || b[2] != 'F' || b[3] != '8' ||
        (b[4] != '7' && b[4] != '9') || b[5] != 'a')
        return false;
    const std::uint8_t packed = b[10];
    p->hasTable = (packed & 0x80) != 0;
    p->tableBits = packed & 7;
    p->tableEnd = kHeaderSize + ColourTableSize(packed);
    return b.size() >= p->tableEnd;
}

/// How one part's blocks are copied into the joined file.
struct PartCopy {
    const std::vector<std::uint8_t>& b;
    const Part& part;
    bool isFirst;
    bool sameTable;  // the part's global table equals the first part's
    std::string name;
    std::vector<std::uint8_t>* out;
    std::string* error;

    bool Fail(const char* what) const {
        *error = name + " " + what;
        return false;
    }
    void Copy(std::size_t from, std::size_t to) const {
        out->insert(out->end(), b.begin() + std::ptrdiff_t(from), b.begin() + std::ptrdiff_t(to));
    }

    /// An extension: label, then sub-blocks. Later parts' application extensions (the loop count) are dropped.
    bool Extension(Reader& r, std::size_t start) const {
        if (!r.Has(1)) return Fail("ends inside an extension");
        const std::uint8_t label = r.Byte();
        if (!r.SkipSubBlocks()) return Fail("ends inside an extension");
        if (isFirst || label != 0xFF) Copy(start, r.At());
        return true;
    }

    /// An image: descriptor, optional local table, LZW code size, sub-blocks.
    bool Image(Reader& r, std::size_t start) const {
        if (!r.Has(9)) return Fail("ends inside an image descriptor");
        r.Skip(8);
        const std::uint8_t packed = r.Byte();
        const std::size_t local = ColourTableSize(packed);
        if (!r.Has(local + 1)) return Fail("ends inside an image");
        r.Skip(local + 1);
        if (!r.SkipSubBlocks()) return Fail("ends inside an image");
        if (isFirst || local > 0 || sameTable || !part.hasTable) {
            Copy(start, r.At());
            return true;
        }
        // A later part's images need its own palette: the descriptor with a local table announced (bit 7, the
        // part's table size in bits 0-2; interlace, bit 6, kept), the part's global table, then the image data.
        Copy(start, start + 9);
        out->push_back(std::uint8_t((packed & 0x40) | 0x80 | part.tableBits));
        Copy(kHeaderSize, part.tableEnd);
        Copy(start + 10, r.At());
        return true;
    }

    /// Every block after the header up to the trailer.
    bool Blocks() const {
        Reader r(b, part.tableEnd);
        for (;;) {
            if (!r.Has(1)) return Fail("ends before its trailer");
            const std::size_t start = r.At();
            const std::uint8_t kind = r.Byte();
            if (kind == 0x3B) return true;
            const bool ok = kind == 0x21   ? Extension(r, start)
                            : kind == 0x2C ? Image(r, start)
                                           : UnknownBlock(kind, start);
            if (!ok) return false;
        }
    }

    bool UnknownBlock(std::uint8_t kind, std::size_t start) const {
        *error = name + " has an unknown block (byte " + std::to_string(int(kind)) + " at offset " +
                 std::to_string(start) + ")";
        return false;
    }
};

}  // namespace

bool JoinGifs(const std::vector<std::vector<std::uint8_t>>& parts, std::vector<std::uint8_t>* out, std::string* error) {
    out->clear();
    if (parts.empty()) {
        *error = "no GIF parts to join";
        return false;
    }
    Part first;
    for (std::size_t k = 0; k < parts.size(); ++k) {
        const std::vector<std::uint8_t>& b = parts[k];
        const std::string name = "GIF part " + std::to_string(k + 1) + " of " + std::to_string(parts.size());
        Part part;
        if (!ParseHeader(b, &part)) {
            *error = name + " is not a GIF file";
            return false;
        }
        if (k == 0) {
            first = part;
            out->insert(out->end(), b.begin(), b.begin() + std::ptrdiff_t(part.tableEnd));
        } else if (b[6] != parts[0][6] || b[7] != parts[0][7] || b[8] != parts[0][8] || b[9] != parts[0][9]) {
            *error = name + " has another screen size than the first";
            return false;
        }
        const bool sameTable = part.hasTable == first.hasTable && part.tableEnd == first.tableEnd &&
                               std::equal(b.begin() + kHeaderSize, b.begin() + std::ptrdiff_t(part.tableEnd),
                                          parts[0].begin() + kHeaderSize);
        const PartCopy copy{b, part, k == 0, sameTable, name, out, error};
        if (!copy.Blocks()) return false;
    }
    out->push_back(0x3B);
    return true;
}

bool ReplaceGlobalColourTable(std::vector<std::uint8_t>* gif, const std::vector<std::uint8_t>& table,
                              std::string* error) {
    Part part;
    if (!ParseHeader(*gif, &part)) {
        *error = "not a GIF file";
        return false;
    }
    int bits = 0;
    while (bits < 8 && 3u * (2u << bits) != table.size()) ++bits;
    if (bits == 8) {
        *error = "a colour table of " + std::to_string(table.size()) + " bytes (3 x 2 to 3 x 256, a power of two)";
        return false;
    }
    (*gif)[10] = std::uint8_t(((*gif)[10] & 0x78) | 0x80 | bits);  // keep colour resolution and sort bits
    gif->erase(gif->begin() + std::ptrdiff_t(kHeaderSize), gif->begin() + std::ptrdiff_t(part.tableEnd));
    gif->insert(gif->begin() + std::ptrdiff_t(kHeaderSize), table.begin(), table.end());
    return true;
}
