#pragma once
// A demo's run-time parameters: the same table feeds the demo's ImGui panel, `--set key=value` on the
// command line, `--help`, tests and benchmarks. GL-free.

#include <functional>
#include <string>
#include <vector>

class ParameterSet {
public:
    enum class Kind { Int, Float, Bool, Choice, Action };

    struct Entry {
        std::string key;
        Kind kind = Kind::Int;
        std::string help;
        int* intValue = nullptr;      // Int, and Choice (index into choices)
        float* floatValue = nullptr;  // Float
        bool* boolValue = nullptr;    // Bool
        double min = 0.0, max = 0.0;  // Int and Float: inclusive range
        std::vector<std::string> choices;
        std::function<void()> onChange;  // runs after a successful Set (e.g. reset the scene); Action: the action
    };

    void AddInt(const std::string& key, int* value, int min, int max, const std::string& help,
                std::function<void()> onChange = {});
    void AddFloat(const std::string& key, float* value, float min, float max, const std::string& help,
                  std::function<void()> onChange = {});
    void AddBool(const std::string& key, bool* value, const std::string& help, std::function<void()> onChange = {});
    void AddChoice(const std::string& key, int* index, std::vector<std::string> choices, const std::string& help,
                   std::function<void()> onChange = {});
    /// An action such as "reset" or "step": `--set reset=1` runs it.
    void AddAction(const std::string& key, std::function<void()> action, const std::string& help);

    /// Parses and applies one value. On failure returns false and sets *error to a message that names the
    /// key and value and lists the valid keys (unknown key) or the valid range/choices (bad value).
    bool Set(const std::string& key, const std::string& value, std::string* error);
    /// The current value as text ("" for actions).
    std::string Get(const std::string& key) const;
    const Entry* Find(const std::string& key) const;
    const std::vector<Entry>& Entries() const { return entries; }
    /// One line per key: "key  range/choices  current  help".
    std::string Describe() const;
    std::string Keys() const;  ///< comma-separated

private:
    std::vector<Entry> entries;
};
