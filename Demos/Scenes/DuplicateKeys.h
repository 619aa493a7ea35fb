#pragma once
// A key given twice in one JSON object. nlohmann-json, like most parsers, keeps the last value silently; a scene
// file (docs/scenes.md, "Errors") refuses it instead, so an edit of a copied key never goes unnoticed. GL-free.

#include <cstddef>
#include <string>

/// Where a key is given twice.
struct DuplicateKey {
    std::string objectPath;  ///< the object's JSON path in the scene-file style ("world", "bodies[2]"; "" at the top)
    std::string key;         ///< the key, as written (escapes resolved)
    std::size_t offset = 0;  ///< 0-based byte offset of the opening quote of its second occurrence
};

/// Scans the JSON `text` for the first object (in document order) with a key given twice. True and *out filled if
/// there is one; false if every object's keys are unique or the text stops being JSON before one is found
/// (ParseSceneText reports syntax errors itself).
bool FindDuplicateKey(const std::string& text, DuplicateKey* out);
