#include "Demos/Scenes/DuplicateKeys.h"

#include <iterator>
#include <nlohmann/json.hpp>
#include <set>
#include <vector>

using Json = nlohmann::json;

namespace {

/// A char iterator that counts the characters the parser has consumed, so the SAX handler knows where it is.
class CountingIterator {
public:
    using iterator_category = std::input_iterator_tag;
    using value_type = char;
    using difference_type = std::ptrdiff_t;
    using pointer = const char*;
    using reference = const char&;

    CountingIterator(const char* at, std::size_t* consumed) : p(at), count(consumed) {}
    reference operator*() const { return *p; }
    CountingIterator& operator++() {
        ++p;
        ++*count;
        return *this;
    }
    bool operator==(const CountingIterator& other) const { return p == other.p; }
    bool operator!=(const CountingIterator& other) const { return p != other.p; }

private:
    const char* p;
    std::size_t* count;
};

/// SAX handler keeping, per open object, the keys seen; stops at the first repeated one.
class KeyChecker {
public:
    KeyChecker(const std::string& text, const std::size_t* consumed) : source(text), position(consumed) {}

    bool null() { return Value(); }
    bool boolean(bool) { return Value(); }
    bool number_integer(Json::number_integer_t) { return Value(); }
    bool number_unsigned(Json::number_unsigned_t) { return Value(); }
    bool number_float(Json::number_float_t, const std::string&) { return Value(); }
    bool string(std::string&) { return Value(); }
    bool binary(Json::binary_t&) { return Value(); }
    bool start_object(std::size_t) { return Open(false); }
    bool start_array(std::size_t) { return Open(true); }
    bool end_object() { return Close(); }
    bool end_array() { return Close(); }
    bool key(std::string& name) {
        Container& object = open.back();
        if (!object.keys.insert(name).second) {
            found.objectPath = PathOfInnermost();
            found.key = name;
            found.offset = OpeningQuote();
            duplicate = true;
            return false;  // stop: one report is enough
        }
        object.key = name;
        return true;
    }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) { return false; }

    bool Found() const { return duplicate; }
    const DuplicateKey& Result() const { return found; }

private:
    /// One open array or object. No path is kept: the innermost object's path is built from the open containers
    /// only when a duplicate is reported, so memory stays linear in the text (a path per level would be quadratic
    /// in the depth).
    struct Container {
        bool array = false;
        std::size_t next = 0;     // array: index of the next element
        std::size_t current = 0;  // array: index of the element being read
        std::string key;          // object: the key of the value being read
        std::set<std::string> keys;
    };

    /// A scalar value: only an array's element count moves.
    bool Value() {
        if (!open.empty() && open.back().array) ++open.back().next;
        return true;
    }
    bool Open(bool array) {
        if (!open.empty() && open.back().array) open.back().current = open.back().next++;
        Container c;
        c.array = array;
        open.push_back(std::move(c));
        return true;
    }
    bool Close() {
        open.pop_back();
        return true;
    }
    /// Path of the innermost open container, in the scene-file style (Join and Index in SceneFile.cpp).
    std::string PathOfInnermost() const {
        std::string path;
        for (std::size_t level = 0; level + 1 < open.size(); ++level) {
            const Container& c = open[level];
            if (c.array)
                path += "[" + std::to_string(c.current) + "]";
            else
                path += (path.empty() ? "" : ".") + c.key;
        }
        return path;
    }
    /// The parser has just read the key's closing quote: back from it to the unescaped opening quote.
    std::size_t OpeningQuote() const {
        std::size_t at = *position > 0 ? *position - 1 : 0;
        while (at > 0) {
            --at;
            if (source[at] != '"') continue;
            std::size_t backslashes = 0;
            while (at > backslashes && source[at - 1 - backslashes] == '\\') ++backslashes;
            if (backslashes % 2 == 0) break;
        }
        return at;
    }

    const std::string& source;
    const std::size_t* position;
    std::vector<Container> open;
    DuplicateKey found;
    bool duplicate = false;
};

}  // namespace

bool FindDuplicateKey(const std::string& text, DuplicateKey* out) {
    std::size_t consumed = 0;
    KeyChecker checker(text, &consumed);
    const char* begin = text.data();
    Json::sax_parse(CountingIterator(begin, &consumed), CountingIterator(begin + text.size(), &consumed), &checker);
    if (!checker.Found()) return false;
    *out = checker.Result();
    return true;
}
