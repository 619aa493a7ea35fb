#include "Demos/Scenes/JsonNesting.h"

JsonNesting MeasureNesting(const std::string& text, std::size_t limit) {
    JsonNesting deepest;
    std::size_t depth = 0;
    bool inString = false, escaped = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            if (escaped)
                escaped = false;
            else if (c == '\\')
                escaped = true;
            else if (c == '"')
                inString = false;
            continue;
        }
        if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth <= deepest.depth) continue;
            deepest.depth = depth;
            if (depth == limit + 1) deepest.over = true, deepest.offset = i;
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return deepest;
}
