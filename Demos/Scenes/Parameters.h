#pragma once
// A demo's run-time parameters: ONE table per demo. Each entry is a `--set key=value` key with its inclusive
// range (and the older or book keys it also answers to), a line of `--params`, and, if it has a widget, one
// widget of the demo's ImGui panel, drawn in table order by Demos/ParameterPanel.cpp. Ranges, defaults and
// panel labels are written here once. Panel-only entries (text rows, the Show Help button) have no key.
// GL-free: the widgets are plain data.

#include <functional>
#include <string>
#include <vector>

class ParameterSet {
public:
    /// What the entry's value is.
    enum class Kind { Int, Float, Bool, Choice, Action, Text };

    /// How an entry shows on the demo panel (docs/book-reference.md §1.7). Type None: `--set` only.
    struct Widget {
        enum class Type { None, Slider, InputInt, Checkbox, RadioButtons, Button, Text };
        Type type = Type::None;
        std::string label;                      ///< the book's label ("Porjection" [sic]); "##id" where it is ""
        std::string caption;                    ///< text drawn before the widget on its line ("Particle count")
        std::vector<std::string> choiceLabels;  ///< RadioButtons: one label per choice, in choice order
        float itemWidth = 0.0f;                 ///< px (PushItemWidth); 0: ImGui's default width
        bool sameLine = false;                  ///< continues the line of the widget before it
        std::string format;                     ///< slider number format; "": ImGui's ("%.3f", "%d")
        bool appliesAtOnce = false;  ///< a panel edit runs onChange at once (the book's Spheres, Drop); else on Reset

        static Widget Slider(const std::string& label);
        static Widget InputInt(const std::string& label);
        static Widget Checkbox(const std::string& label);
        static Widget RadioButtons(std::vector<std::string> labels);
        static Widget Button(const std::string& label);
        static Widget Text();
        Widget& Width(float pixels);
        Widget& SameLine();
        Widget& Caption(const std::string& text);
        Widget& Format(const std::string& printfFormat);
        Widget& AppliesAtOnce();
    };

    struct Entry {
        std::string key;                      ///< the `--set` key; "" for a panel-only entry
        std::vector<std::string> aliases;     ///< other keys `--set` accepts for it (the book's or older names)
        std::vector<std::string> deprecated;  ///< older keys still accepted, each with a note that it is deprecated
        Kind kind = Kind::Int;
        std::string help;
        int* intValue = nullptr;      // Int, and Choice (index into choices)
        float* floatValue = nullptr;  // Float
        bool* boolValue = nullptr;    // Bool
        double min = 0.0, max = 0.0;  // Int and Float: inclusive range (Float: the float bounds, exactly)
        std::vector<std::string> choices;
        std::function<void()> onChange;     // runs after a successful Set (e.g. reset the scene); Action: the action
        std::function<std::string()> text;  // Text: the row, evaluated each frame; "" draws no row
        Widget widget;
        /// Float only: a physics step in s (StepValue.h, docs/app.md "Steps"): a decimal or a fraction n/d; one
        /// that is not a whole number of microseconds gets a note (the host runs it rounded), and a positive one
        /// that rounds to 0 is refused.
        bool step = false;

        /// Adds a key `--set` also accepts; `--params` lists it after the help.
        Entry& Alias(const std::string& key);
        /// An older key `--set` still accepts; Set's note then says it is deprecated and names this entry's key.
        Entry& DeprecatedAlias(const std::string& key);
        /// Puts the entry on the panel as `w`.
        Entry& OnPanel(const Widget& w);
        /// Marks a Float entry as a physics step (`step` above).
        Entry& Step();
    };

    // Each Add returns the new entry, valid until the next Add (for chaining Alias and OnPanel).
    Entry& AddInt(const std::string& key, int* value, int min, int max, const std::string& help,
                  std::function<void()> onChange = {});
    Entry& AddFloat(const std::string& key, float* value, float min, float max, const std::string& help,
                    std::function<void()> onChange = {});
    Entry& AddBool(const std::string& key, bool* value, const std::string& help, std::function<void()> onChange = {});
    Entry& AddChoice(const std::string& key, int* index, std::vector<std::string> choices, const std::string& help,
                     std::function<void()> onChange = {});
    /// An action such as "reset" or "step": `--set reset=1` runs it.
    Entry& AddAction(const std::string& key, std::function<void()> action, const std::string& help);
    /// A panel-only button (no `--set` key), such as the book's "Show Help"; `button` is a Widget::Button.
    Entry& AddPanelButton(const Widget& button, std::function<void()> action);
    /// A panel-only text row; text() is its contents each frame ("" hides the row).
    Entry& AddPanelText(std::function<std::string()> text);

    /// Parses and applies one value. The range is inclusive and checked in the entry's own type, so the
    /// documented bounds (`0.1`, `0.0005`) are accepted. On failure returns false and sets *error to a message
    /// that names the key and value and lists the valid keys (unknown key) or the valid range/choices (bad value).
    /// For a step entry whose value is not a whole number of microseconds, *note (if given) is set to a one-line
    /// note for stderr; otherwise it is left as it is.
    bool Set(const std::string& key, const std::string& value, std::string* error, std::string* note = nullptr);
    /// The current value as text ("" for actions and unknown keys).
    std::string Get(const std::string& key) const;
    /// The entry with this key or alias; nullptr if none (always for "").
    const Entry* Find(const std::string& key) const;
    /// Every entry in table (= panel) order, panel-only ones included.
    const std::vector<Entry>& Entries() const { return entries; }
    /// One line per key: `key = current  [range/choices]  help (also: aliases; panel "label")`.
    std::string Describe() const;
    std::string Keys() const;  ///< comma-separated `--set` keys

private:
    Entry& Add(Entry e);
    std::vector<Entry> entries;
};
