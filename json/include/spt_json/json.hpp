// The JSON the importers and the converter read and write. Parsing is nlohmann-json's strict
// RFC 8259 SAX parser under spt's rules: limits are checked before anything is allocated for
// them, duplicate object keys are refused, errors say file:line:column; the result is a small
// tree that remembers the line of every value, so importers can name the line of a bad element.
// Writing: the one JSON string escaper (nlohmann-json's, invalid UTF-8 replaced by U+FFFD).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "spt/result.hpp"

namespace spt::json {

enum class Type : uint8_t { Null, Bool, Number, String, Array, Object };

struct Member;

struct Value {
    Type type = Type::Null;
    uint32_t line = 0;       // 1-based line where the value starts
    bool boolean = false;
    double number = 0;
    std::string text;        // String: decoded UTF-8; Number: the literal (integers: canonical decimal)
    std::vector<Value> items;                          // Array
    std::vector<Member> members;  // Object, in file order (a vector of an incomplete type is fine since C++17)

    bool is_number() const { return type == Type::Number; }
    bool is_string() const { return type == Type::String; }
    bool is_array() const { return type == Type::Array; }
    bool is_object() const { return type == Type::Object; }
    // Object member by key (first match), or nullptr.
    const Value* find(std::string_view key) const;
};

struct Member {
    std::string first;
    Value second;
    Member() = default;
    Member(std::string k, Value v) : first(std::move(k)), second(std::move(v)) {}
};

const char* type_name(Type t);

struct ParseLimits {
    size_t max_bytes = size_t(1) << 30;
    uint32_t max_depth = 64;
    size_t max_values = size_t(1) << 26;  // total values in the document
    // Count checks made while parsing, so that a list over its reader's limit is refused before
    // the parse tree holds it: an array that is the value of key `first` holds at most `second`
    // items, and an array inside an array (a tuple) at most `max_tuple_items` (0: no such cap).
    std::vector<std::pair<std::string, size_t>> max_items_by_key;
    size_t max_tuple_items = 0;
};

// Parses a whole document. Errors name `source` (the file name), the line and the column; the
// offset is the byte offset of the problem. Duplicate object keys are an error (they are
// ambiguous). A UTF-8 byte order mark is skipped; invalid UTF-8 in strings is an error.
Result<Value> parse(std::string_view text, const std::string& source, const ParseLimits& lim = {});

// `s` as a JSON string literal, quotes included: ", \ and control characters escaped, other
// bytes as they are, except that invalid UTF-8 becomes U+FFFD (the output is always valid JSON).
std::string quote(std::string_view s);
// Appends quote(s) to `out`.
void append_string(std::string& out, std::string_view s);

}  // namespace spt::json
