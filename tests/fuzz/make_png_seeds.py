#!/usr/bin/env python3
"""Writes the png_fuzz seed corpus (tests/fuzz/corpus/png_fuzz/) and the known-failing PNG inputs
(tests/fuzz/regressions/png_fuzz/): tiny PNGs of every colour type and bit depth, interlaced, with ancillary
chunks, and broken ones (truncated, bad CRC, no IEND, zero and huge sizes). Deterministic; re-run after
changing it and commit the files. Usage: make_png_seeds.py (from anywhere). docs/testing.md "Fuzzing"."""
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
SIGNATURE = b"\x89PNG\r\n\x1a\n"


def chunk(kind, data, crc=None):
    if crc is None:
        crc = zlib.crc32(kind + data)
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", crc & 0xFFFFFFFF)


def ihdr(w, h, depth, colour, interlace=0):
    return chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, depth, colour, 0, 0, interlace))


def pack_row(samples, depth):
    """Packs sample values (one per channel per pixel) of the given bit depth into a row of bytes."""
    if depth == 16:
        return b"".join(struct.pack(">H", s) for s in samples)
    if depth == 8:
        return bytes(samples)
    out, acc, bits = bytearray(), 0, 0
    for s in samples:
        acc = (acc << depth) | s
        bits += depth
        if bits == 8:
            out.append(acc)
            acc, bits = 0, 0
    if bits:
        out.append(acc << (8 - bits))
    return bytes(out)


def image(w, h, depth, colour, pixel, extra=b"", interlace=0):
    """A whole PNG; pixel(x, y) returns the samples of one pixel. Interlaced images use Adam7 passes."""
    if interlace:
        passes = [(0, 0, 8, 8), (4, 0, 8, 8), (0, 4, 4, 8), (2, 0, 4, 4), (0, 2, 2, 4), (1, 0, 2, 2), (0, 1, 1, 2)]
        raw = b""
        for x0, y0, dx, dy in passes:
            xs, ys = range(x0, w, dx), range(y0, h, dy)
            if len(xs) and len(ys):
                for y in ys:
                    raw += b"\0" + pack_row([s for x in xs for s in pixel(x, y)], depth)
    else:
        raw = b"".join(b"\0" + pack_row([s for x in range(w) for s in pixel(x, y)], depth) for y in range(h))
    return (SIGNATURE + ihdr(w, h, depth, colour, interlace) + extra + chunk(b"IDAT", zlib.compress(raw, 9)) +
            chunk(b"IEND", b""))


def golden(x, y):  # the fixed 4x4 frame of png_fuzz.cpp
    return (60 * x, 60 * y, 128)


def seeds():
    s = {}
    s["rgb8-golden.png"] = image(4, 4, 8, 2, golden)
    s["rgb8-off-by-20.png"] = image(4, 4, 8, 2, lambda x, y: tuple(min(255, c + (20 if x == y else 3))
                                                                   for c in golden(x, y)))
    s["rgb8-5x3.png"] = image(5, 3, 8, 2, lambda x, y: (x * 50, y * 80, 7))
    s["rgba8.png"] = image(4, 4, 8, 6, lambda x, y: golden(x, y) + (x * 80,))
    for depth in (1, 2, 4, 8):
        s["grey%d.png" % depth] = image(4, 4, depth, 0, lambda x, y, d=depth: ((x + y) % (1 << d),))
    s["grey-alpha8.png"] = image(4, 4, 8, 4, lambda x, y: (x * 60, 255 - y * 60))
    palette = chunk(b"PLTE", bytes([0, 0, 0, 255, 0, 0, 0, 255, 0, 0, 0, 255]))
    s["palette2-trns.png"] = image(4, 4, 2, 3, lambda x, y: ((x + y) % 4,), palette + chunk(b"tRNS", b"\x00\x80"))
    s["palette8.png"] = image(4, 4, 8, 3, lambda x, y: ((x * y) % 4,), palette)
    s["palette-index-out-of-range.png"] = image(4, 4, 8, 3, lambda x, y: (x * 60,), palette)
    s["rgb16.png"] = image(4, 4, 16, 2, lambda x, y: tuple(c * 257 for c in golden(x, y)))
    s["grey16.png"] = image(4, 4, 16, 0, lambda x, y: (x * 16384 + y,))
    s["rgba16.png"] = image(2, 2, 16, 6, lambda x, y: (65535, x * 65535, y * 30000, 40000))
    s["rgb8-adam7-9x9.png"] = image(9, 9, 8, 2, lambda x, y: (x * 28, y * 28, (x ^ y) * 16), interlace=1)
    ancillary = (chunk(b"gAMA", struct.pack(">I", 45455)) + chunk(b"sRGB", b"\x00") +
                 chunk(b"tEXt", b"Comment\x00fuzz seed") + chunk(b"pHYs", struct.pack(">IIB", 2835, 2835, 1)))
    s["rgb8-ancillary.png"] = image(4, 4, 8, 2, golden, ancillary)
    whole = s["rgb8-golden.png"]
    s["truncated-in-idat.png"] = whole[:len(whole) - 20]
    s["truncated-after-ihdr.png"] = whole[:33]
    s["signature-only.png"] = SIGNATURE
    s["no-iend.png"] = whole[:-12]
    s["bad-ihdr-crc.png"] = SIGNATURE + chunk(b"IHDR", struct.pack(">IIBBBBB", 4, 4, 8, 2, 0, 0, 0), crc=1) + whole[33:]
    s["zero-width.png"] = SIGNATURE + ihdr(0, 4, 8, 2) + whole[33:]
    s["bad-depth.png"] = SIGNATURE + ihdr(4, 4, 3, 2) + whole[33:]
    # The widest image libpng accepts by default (1,000,000 pixels), one row, its data cut short.
    s["width-1000000-truncated.png"] = (SIGNATURE + ihdr(1000000, 1, 8, 2) +
                                        chunk(b"IDAT", zlib.compress(b"\0" * 600, 9)) + chunk(b"IEND", b""))
    s["empty.png"] = b""
    s["text.png"] = b"not a png at all\n"
    return s


def regressions():
    # A header claiming 1,000,000 x 1,000,000 pixels (libpng's default limits): DecodePng allocates 3e12 bytes
    # before reading any pixel (std::bad_alloc, or an out-of-memory report under the fuzzer).
    return {"huge-1000000x1000000.png": SIGNATURE + ihdr(1000000, 1000000, 8, 2) +
            chunk(b"IDAT", zlib.compress(b"\0" * 16, 9)) + chunk(b"IEND", b"")}


def write(folder, files):
    os.makedirs(folder, exist_ok=True)
    for name, data in sorted(files.items()):
        with open(os.path.join(folder, name), "wb") as f:
            f.write(data)


if __name__ == "__main__":
    write(os.path.join(HERE, "corpus", "png_fuzz"), seeds())
    write(os.path.join(HERE, "regressions", "png_fuzz"), regressions())
