#pragma once
// How deeply arrays and objects nest in a JSON text, found by one pass over its bytes before any parser sees it.
// A scene file (docs/scenes.md, "Limits") nests at most SceneLimits::kMaxNesting levels; deeper text is refused
// up front, so neither the parser nor the checks after it pay for the depth. GL-free.

#include <cstddef>
#include <string>

/// The deepest nesting of a JSON text.
struct JsonNesting {
    std::size_t depth = 0;   ///< deepest level of '[' and '{' outside strings (0: a bare scalar)
    bool over = false;       ///< depth > the limit asked for
    std::size_t offset = 0;  ///< when over: 0-based byte offset of the first bracket past the limit
};

/// Scans `text` once (linear time, constant memory), skipping string contents and their escapes, for its deepest
/// level and the first bracket nested deeper than `limit`. Unbalanced or otherwise malformed JSON is measured as
/// written; the parser reports its syntax errors.
JsonNesting MeasureNesting(const std::string& text, std::size_t limit);
