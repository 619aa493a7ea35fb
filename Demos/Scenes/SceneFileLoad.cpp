// Reading a scene file from disk (SceneFile.h): the file checks before any byte is parsed, and line and column
// numbers for messages.
#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "Demos/Scenes/SceneFile.h"

void LineAndColumn(const std::string& text, std::size_t offset, int* line, int* column) {
    if (offset > text.size()) offset = text.size();
    int l = 1, c = 1;
    for (std::size_t i = 0; i < offset; ++i) {
        if (text[i] == '\n') {
            ++l;
            c = 1;
        } else {
            ++c;
        }
    }
    *line = l;
    *column = c;
}

bool LoadSceneFile(const std::string& fileName, SceneDescription* out, std::vector<std::string>* errors,
                   std::vector<std::string>* notes) {
    struct stat st {};
    // stat follows links: a dangling link or a loop gives the system's reason, as a missing file does.
    if (stat(fileName.c_str(), &st) != 0) {
        errors->push_back(fileName + ": cannot read: " + std::strerror(errno));
        return false;
    }
    if (!S_ISREG(st.st_mode)) {
        errors->push_back(fileName + ": cannot read: not a regular file");
        return false;
    }
    if (static_cast<std::size_t>(st.st_size) > SceneLimits::kMaxFileBytes) {
        errors->push_back(fileName + ": is larger than the limit of " + std::to_string(SceneLimits::kMaxFileBytes) +
                          " bytes (got " + std::to_string(st.st_size) + ")");
        return false;
    }
    std::ifstream in(fileName, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in.is_open() || (!in && !in.eof())) {
        errors->push_back(fileName + ": cannot read: " + std::strerror(errno));
        return false;
    }
    return ParseSceneText(text.str(), fileName, out, errors, notes);
}
