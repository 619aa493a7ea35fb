#pragma once
// One table of an enum's stable ids (the words the command line, scene files and CSVs use) and the three things
// read from it: an id for a value, a value for an id, and the list of ids for an error message. ContactSolver,
// Integrator, ParticleContact and BudgetQuantity each keep one such table in their .cpp.

#include <cstddef>
#include <string>

template <class Enum>
struct EnumId {
    Enum value;
    const char* id;
};

/// The id of `value` in `table`; "unknown" for a value the table lacks.
template <class Enum, std::size_t N>
const char* IdOf(const EnumId<Enum> (&table)[N], Enum value) {
    for (const EnumId<Enum>& e : table)
        if (e.value == value) return e.id;
    return "unknown";
}

/// The value whose id is `text`: true and *out set (when out is given), else false and *out untouched.
template <class Enum, std::size_t N>
bool ParseId(const EnumId<Enum> (&table)[N], const std::string& text, Enum* out) {
    for (const EnumId<Enum>& e : table)
        if (text == e.id) {
            if (out != nullptr) *out = e.value;
            return true;
        }
    return false;
}

/// Every id of `table` in its order, comma-separated.
template <class Enum, std::size_t N>
std::string JoinIds(const EnumId<Enum> (&table)[N]) {
    std::string ids;
    for (const EnumId<Enum>& e : table) {
        if (!ids.empty()) ids += ", ";
        ids += e.id;
    }
    return ids;
}
