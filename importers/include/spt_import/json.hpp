// A small, strict JSON reader (RFC 8259) that remembers the line of every value, so importers
// can name the line of a bad element; and helpers to write JSON. Standard library only.
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
    std::string text;        // String: decoded UTF-8; Number: the literal as written
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
};

// Parses a whole document. Errors name `source` (the file name) and the line; the offset is the
// byte offset of the problem. Duplicate object keys are an error (they are ambiguous).
Result<Value> parse(std::string_view text, const std::string& source, const ParseLimits& lim = {});

// Writing: appends an escaped JSON string literal (with quotes).
void append_string(std::string& out, std::string_view s);

}  // namespace spt::json
