#include "Demos/Scenes/Parameters.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace {

bool ParseInt(const std::string& text, long* out) {
    if (text.empty()) return false;
    char* end = nullptr;
    errno = 0;
    const long v = std::strtol(text.c_str(), &end, 10);
    if (errno != 0 || end == text.c_str() || *end != '\0') return false;
    *out = v;
    return true;
}

bool ParseFloat(const std::string& text, double* out) {
    if (text.empty()) return false;
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(text.c_str(), &end);
    if (errno != 0 || end == text.c_str() || *end != '\0' || !std::isfinite(v)) return false;
    *out = v;
    return true;
}

bool ParseBool(const std::string& text, bool* out) {
    if (text == "1" || text == "true" || text == "on" || text == "yes") {
        *out = true;
        return true;
    }
    if (text == "0" || text == "false" || text == "off" || text == "no") {
        *out = false;
        return true;
    }
    return false;
}

std::string RangeText(const ParameterSet::Entry& e) {
    std::ostringstream s;
    switch (e.kind) {
        case ParameterSet::Kind::Int:
            s << "integer " << static_cast<long>(e.min) << ".." << static_cast<long>(e.max);
            break;
        case ParameterSet::Kind::Float:
            s << "number " << e.min << ".." << e.max;
            break;
        case ParameterSet::Kind::Bool:
            s << "0|1";
            break;
        case ParameterSet::Kind::Choice:
            for (size_t i = 0; i < e.choices.size(); ++i) s << (i ? "|" : "") << e.choices[i];
            break;
        case ParameterSet::Kind::Action:
            s << "1 (action)";
            break;
    }
    return s.str();
}

}  // namespace

void ParameterSet::AddInt(const std::string& key, int* value, int min, int max, const std::string& help,
                          std::function<void()> onChange) {
    Entry e;
    e.key = key, e.kind = Kind::Int, e.help = help, e.intValue = value, e.min = min, e.max = max;
    e.onChange = std::move(onChange);
    entries.push_back(std::move(e));
}
void ParameterSet::AddFloat(const std::string& key, float* value, float min, float max, const std::string& help,
                            std::function<void()> onChange) {
    Entry e;
    e.key = key, e.kind = Kind::Float, e.help = help, e.floatValue = value, e.min = min, e.max = max;
    e.onChange = std::move(onChange);
    entries.push_back(std::move(e));
}
void ParameterSet::AddBool(const std::string& key, bool* value, const std::string& help,
                           std::function<void()> onChange) {
    Entry e;
    e.key = key, e.kind = Kind::Bool, e.help = help, e.boolValue = value;
    e.onChange = std::move(onChange);
    entries.push_back(std::move(e));
}
void ParameterSet::AddChoice(const std::string& key, int* index, std::vector<std::string> choices,
                             const std::string& help, std::function<void()> onChange) {
    Entry e;
    e.key = key, e.kind = Kind::Choice, e.help = help, e.intValue = index, e.choices = std::move(choices);
    e.onChange = std::move(onChange);
    entries.push_back(std::move(e));
}
void ParameterSet::AddAction(const std::string& key, std::function<void()> action, const std::string& help) {
    Entry e;
    e.key = key, e.kind = Kind::Action, e.help = help, e.onChange = std::move(action);
    entries.push_back(std::move(e));
}

const ParameterSet::Entry* ParameterSet::Find(const std::string& key) const {
    for (const Entry& e : entries)
        if (e.key == key) return &e;
    return nullptr;
}

std::string ParameterSet::Keys() const {
    std::string keys;
    for (const Entry& e : entries) keys += (keys.empty() ? "" : ", ") + e.key;
    return keys;
}

bool ParameterSet::Set(const std::string& key, const std::string& value, std::string* error) {
    const Entry* e = Find(key);
    if (e == nullptr) {
        if (error) *error = "unknown parameter '" + key + "'; valid keys: " + (entries.empty() ? "(none)" : Keys());
        return false;
    }
    auto bad = [&]() {
        if (error) *error = "bad value '" + value + "' for '" + key + "': expected " + RangeText(*e);
        return false;
    };
    switch (e->kind) {
        case Kind::Int: {
            long v = 0;
            if (!ParseInt(value, &v) || v < e->min || v > e->max) return bad();
            *e->intValue = static_cast<int>(v);
            break;
        }
        case Kind::Float: {
            double v = 0;
            if (!ParseFloat(value, &v) || v < e->min || v > e->max) return bad();
            *e->floatValue = static_cast<float>(v);
            break;
        }
        case Kind::Bool: {
            bool v = false;
            if (!ParseBool(value, &v)) return bad();
            *e->boolValue = v;
            break;
        }
        case Kind::Choice: {
            int found = -1;
            for (size_t i = 0; i < e->choices.size(); ++i)
                if (e->choices[i] == value) found = static_cast<int>(i);
            if (found < 0) return bad();
            *e->intValue = found;
            break;
        }
        case Kind::Action: {
            bool v = false;
            if (!ParseBool(value, &v)) return bad();
            if (!v) return true;
            break;
        }
    }
    if (e->onChange) e->onChange();
    return true;
}

std::string ParameterSet::Get(const std::string& key) const {
    const Entry* e = Find(key);
    if (e == nullptr) return "";
    std::ostringstream s;
    switch (e->kind) {
        case Kind::Int:
            s << *e->intValue;
            break;
        case Kind::Float:
            s << *e->floatValue;
            break;
        case Kind::Bool:
            s << (*e->boolValue ? 1 : 0);
            break;
        case Kind::Choice:
            s << e->choices.at(static_cast<size_t>(*e->intValue));
            break;
        case Kind::Action:
            break;
    }
    return s.str();
}

std::string ParameterSet::Describe() const {
    std::ostringstream s;
    for (const Entry& e : entries)
        s << "  " << e.key << " = " << (e.kind == Kind::Action ? "-" : Get(e.key)) << "  [" << RangeText(e) << "]  "
          << e.help << "\n";
    return s.str();
}
