// docs/scenes.md states the soft solver's defaults in a table; the engine's SoftSolverSettings is the one source.
// This reads the table and checks every row against a default-constructed SoftSolverSettings.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "Physics/ContactSolver.h"

namespace {

/// The `soft` table of docs/scenes.md: key -> the default column, as written.
std::map<std::string, std::string> SoftDefaultsTable() {
    std::ifstream in(std::string(PSB_SOURCE_DIR) + "/docs/scenes.md");
    std::map<std::string, std::string> rows;
    std::string line;
    bool inTable = false;
    while (std::getline(in, line)) {
        if (line.find("| key | unit, range | default |") != std::string::npos) inTable = true;
        if (!inTable) continue;
        if (line.find('|') == std::string::npos) break;
        std::vector<std::string> cells;
        std::stringstream ss(line);
        std::string cell;
        while (std::getline(ss, cell, '|')) cells.push_back(cell);
        if (cells.size() < 4 || cells[1].find('`') == std::string::npos) continue;
        const std::size_t a = cells[1].find('`'), b = cells[1].rfind('`');
        std::string value = cells[3];
        value.erase(0, value.find_first_not_of(' '));
        value.erase(value.find_last_not_of(' ') + 1);
        rows[cells[1].substr(a + 1, b - a - 1)] = value;
    }
    return rows;
}

}  // namespace

TEST(SceneDocs, TheSoftDefaultsTableIsTheEngines) {
    const std::map<std::string, std::string> table = SoftDefaultsTable();
    const SoftSolverSettings engine;
    const std::map<std::string, double> expected = {
        {"substeps", engine.substeps},
        {"iterations", engine.iterations},
        {"relaxIterations", engine.relaxIterations},
        {"contactHertz", engine.contactHertz},
        {"contactDampingRatio", engine.contactDampingRatio},
        {"maxPushoutSpeed", engine.maxPushoutSpeed},
        {"speculativeMargin", engine.speculativeMargin},
        {"linearSlop", engine.linearSlop},
        {"restitutionThreshold", engine.restitutionThreshold},
        {"warmStartFactor", engine.warmStartFactor},
    };
    ASSERT_EQ(table.size(), expected.size()) << "the table's rows and SoftSolverSettings' fields differ in number";
    for (const auto& [key, value] : expected) {
        const auto row = table.find(key);
        ASSERT_NE(row, table.end()) << key << " is missing from docs/scenes.md's soft table";
        EXPECT_NEAR(std::atof(row->second.c_str()), value, 1e-6 * (1.0 + value))
            << key << ": docs/scenes.md says " << row->second << ", the engine " << value;
    }
}
