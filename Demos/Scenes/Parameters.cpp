#include "Demos/Scenes/Parameters.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "Demos/Scenes/StepValue.h"

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
            s << (e.step ? "step in s (decimal or n/d, whole microseconds) " : "number ") << e.min << ".." << e.max;
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
        case ParameterSet::Kind::Text:
            s << "(panel text)";
            break;
    }
    return s.str();
}

/// What the panel calls the entry: its label, or for a hidden "##id" label the caption before it; "" if none.
std::string PanelName(const ParameterSet::Entry& e) {
    const ParameterSet::Widget& w = e.widget;
    if (w.type == ParameterSet::Widget::Type::None) return "";
    if (!w.label.empty() && w.label.compare(0, 2, "##") != 0) return w.label;
    return w.caption;
}

}  // namespace

using Widget = ParameterSet::Widget;

Widget Widget::Slider(const std::string& label) {
    Widget w;
    w.type = Type::Slider, w.label = label;
    return w;
}
Widget Widget::InputInt(const std::string& label) {
    Widget w;
    w.type = Type::InputInt, w.label = label;
    return w;
}
Widget Widget::Checkbox(const std::string& label) {
    Widget w;
    w.type = Type::Checkbox, w.label = label;
    return w;
}
Widget Widget::RadioButtons(std::vector<std::string> labels) {
    Widget w;
    w.type = Type::RadioButtons, w.choiceLabels = std::move(labels);
    return w;
}
Widget Widget::Button(const std::string& label) {
    Widget w;
    w.type = Type::Button, w.label = label;
    return w;
}
Widget Widget::Text() {
    Widget w;
    w.type = Type::Text;
    return w;
}
Widget& Widget::Width(float pixels) {
    itemWidth = pixels;
    return *this;
}
Widget& Widget::SameLine() {
    sameLine = true;
    return *this;
}
Widget& Widget::Caption(const std::string& text) {
    caption = text;
    return *this;
}
Widget& Widget::Format(const std::string& printfFormat) {
    format = printfFormat;
    return *this;
}
Widget& Widget::AppliesAtOnce() {
    appliesAtOnce = true;
    return *this;
}

ParameterSet::Entry& ParameterSet::Entry::Alias(const std::string& alias) {
    aliases.push_back(alias);
    return *this;
}
ParameterSet::Entry& ParameterSet::Entry::DeprecatedAlias(const std::string& alias) {
    deprecated.push_back(alias);
    return *this;
}
ParameterSet::Entry& ParameterSet::Entry::OnPanel(const Widget& w) {
    widget = w;
    return *this;
}
ParameterSet::Entry& ParameterSet::Entry::Step() {
    step = true;
    return *this;
}

ParameterSet::Entry& ParameterSet::Add(Entry e) {
    entries.push_back(std::move(e));
    return entries.back();
}

ParameterSet::Entry& ParameterSet::AddInt(const std::string& key, int* value, int min, int max, const std::string& help,
                                          std::function<void()> onChange) {
    Entry e;
    e.key = key, e.kind = Kind::Int, e.help = help, e.intValue = value, e.min = min, e.max = max;
    e.onChange = std::move(onChange);
    return Add(std::move(e));
}
ParameterSet::Entry& ParameterSet::AddFloat(const std::string& key, float* value, float min, float max,
                                            const std::string& help, std::function<void()> onChange) {
    Entry e;
    e.key = key, e.kind = Kind::Float, e.help = help, e.floatValue = value, e.min = min, e.max = max;
    e.onChange = std::move(onChange);
    return Add(std::move(e));
}
ParameterSet::Entry& ParameterSet::AddBool(const std::string& key, bool* value, const std::string& help,
                                           std::function<void()> onChange) {
    Entry e;
    e.key = key, e.kind = Kind::Bool, e.help = help, e.boolValue = value;
    e.onChange = std::move(onChange);
    return Add(std::move(e));
}
ParameterSet::Entry& ParameterSet::AddChoice(const std::string& key, int* index, std::vector<std::string> choices,
                                             const std::string& help, std::function<void()> onChange) {
    Entry e;
    e.key = key, e.kind = Kind::Choice, e.help = help, e.intValue = index, e.choices = std::move(choices);
    e.onChange = std::move(onChange);
    return Add(std::move(e));
}
ParameterSet::Entry& ParameterSet::AddAction(const std::string& key, std::function<void()> action,
                                             const std::string& help) {
    Entry e;
    e.key = key, e.kind = Kind::Action, e.help = help, e.onChange = std::move(action);
    return Add(std::move(e));
}
ParameterSet::Entry& ParameterSet::AddPanelButton(const Widget& button, std::function<void()> action) {
    Entry e;
    e.kind = Kind::Action, e.onChange = std::move(action), e.widget = button;
    return Add(std::move(e));
}
ParameterSet::Entry& ParameterSet::AddPanelText(std::function<std::string()> text) {
    Entry e;
    e.kind = Kind::Text, e.text = std::move(text), e.widget = Widget::Text();
    return Add(std::move(e));
}

const ParameterSet::Entry* ParameterSet::Find(const std::string& key) const {
    if (key.empty()) return nullptr;
    for (const Entry& e : entries) {
        if (e.key == key) return &e;
        for (const std::string& alias : e.aliases)
            if (alias == key) return &e;
        for (const std::string& alias : e.deprecated)
            if (alias == key) return &e;
    }
    return nullptr;
}

std::string ParameterSet::Keys() const {
    std::string keys;
    for (const Entry& e : entries)
        if (!e.key.empty()) keys += (keys.empty() ? "" : ", ") + e.key;
    return keys;
}

bool ParameterSet::Set(const std::string& key, const std::string& value, std::string* error, std::string* note) {
    const Entry* e = Find(key);
    if (e == nullptr) {
        if (error) *error = "unknown parameter '" + key + "'; valid keys: " + (Keys().empty() ? "(none)" : Keys());
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
            // Compared as the float that is stored: "0.1" must meet the bound 0.1f, which as a double is
            // 0.10000000149 (an inclusive range written in decimal).
            double parsed = 0;
            if (!(e->step ? ParseStepSeconds(value, &parsed) : ParseFloat(value, &parsed))) return bad();
            const float v = static_cast<float>(parsed);
            if (!std::isfinite(v) || v < static_cast<float>(e->min) || v > static_cast<float>(e->max)) return bad();
            if (e->step) {
                // Stored as given: the host runs whole microseconds of it (docs/app.md, "Steps"), and says so.
                bool exact = true;
                const long long micros = StepMicros(parsed, &exact);
                if (parsed > 0.0 && micros == 0) return bad();
                if (!exact && note != nullptr)
                    *note = "--set " + key + "=" + value + ": " + StepRoundedNote(value, micros);
            }
            *e->floatValue = v;
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
        case Kind::Text:
            return bad();
    }
    if (note != nullptr && key != e->key &&
        std::find(e->deprecated.begin(), e->deprecated.end(), key) != e->deprecated.end()) {
        *note = "--set " + key + "=" + value + ": '" + key + "' is deprecated; use '" + e->key + "'";
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
        case Kind::Text:
            break;
    }
    return s.str();
}

std::string ParameterSet::Describe() const {
    std::ostringstream s;
    for (const Entry& e : entries) {
        if (e.key.empty()) continue;
        s << "  " << e.key << " = " << (e.kind == Kind::Action ? "-" : Get(e.key)) << "  [" << RangeText(e) << "]  "
          << e.help;
        std::string notes;
        for (size_t i = 0; i < e.aliases.size(); ++i) notes += (i ? ", " : "also: ") + e.aliases[i];
        if (!PanelName(e).empty()) notes += (notes.empty() ? "" : "; ") + std::string("panel \"") + PanelName(e) + "\"";
        s << (notes.empty() ? "" : " (" + notes + ")") << "\n";
    }
    return s.str();
}
