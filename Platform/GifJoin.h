#pragma once
// Joins GIF files made one after another into one animation, each part keeping its own palette. The video
// recorder (Platform/VideoEncoder.h) encodes a GIF in parts, each with a palette generated from its own frames,
// so that the parts are mapped while later frames still render; this puts them back together. docs/app.md,
// "Video".
//
// The format (GIF89a): a 13-byte header and logical screen descriptor, an optional global colour table, then
// blocks: extensions (0x21, a label, sub-blocks ending in a zero length), images (0x2C, a 9-byte descriptor,
// an optional local colour table, the LZW minimum code size and sub-blocks) and the trailer (0x3B).

#include <cstdint>
#include <string>
#include <vector>

/// Joins parts (each a whole GIF file's bytes, all of the same logical screen size) into *out: the first
/// part's header, global colour table and extensions stand for the whole; every later part's images are
/// copied in order, each given that part's global colour table as its local one (unless it has its own or
/// the tables are equal), and later parts' application extensions (the loop count) are dropped. False, with
/// *error naming the part and what is wrong, if a part is not a well-formed GIF or the sizes differ.
bool JoinGifs(const std::vector<std::vector<std::uint8_t>>& parts, std::vector<std::uint8_t>* out, std::string* error);

/// Gives a GIF file (its whole bytes) the global colour table `table` (3 bytes an entry, 2 to 256 entries, a
/// power of two) in place of its own, and sets the screen descriptor's table size to match. The images keep their
/// indices, so the table must give them the colours they mean. False, with *error, if gif is not a GIF or the
/// table's size is not one a GIF can have.
bool ReplaceGlobalColourTable(std::vector<std::uint8_t>* gif, const std::vector<std::uint8_t>& table,
                              std::string* error);
