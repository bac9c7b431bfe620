// A minimal JSON writer for machine-readable output (spt info --json, progress lines, compare).
// Builds one document into a string; no parsing.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace spt::io {

// `s` as a JSON string literal, quotes included (spt::json::quote: invalid UTF-8 becomes U+FFFD).
std::string json_quote(std::string_view s);
// A JSON number: integers exactly, others with up to 6 significant decimals; NaN/inf -> null.
std::string json_number(double v);

// Streaming writer: obj()/arr() open a container, end() closes the innermost one; key() names
// the next value inside an object. Commas are inserted automatically.
class JsonWriter {
public:
    explicit JsonWriter(bool pretty = false) : pretty_(pretty) {}
    JsonWriter& obj();
    JsonWriter& arr();
    JsonWriter& end();
    JsonWriter& key(std::string_view k);
    JsonWriter& str(std::string_view v);
    JsonWriter& num(double v);
    JsonWriter& integer(int64_t v);
    JsonWriter& uinteger(uint64_t v);
    JsonWriter& boolean(bool v);
    JsonWriter& null();
    // Shorthands for key(k).value(v).
    JsonWriter& kv(std::string_view k, std::string_view v) { return key(k).str(v); }
    JsonWriter& kv(std::string_view k, const char* v) { return key(k).str(v); }
    JsonWriter& kv(std::string_view k, double v) { return key(k).num(v); }
    JsonWriter& kv(std::string_view k, int v) { return key(k).integer(v); }
    JsonWriter& kv(std::string_view k, int64_t v) { return key(k).integer(v); }
    JsonWriter& kv(std::string_view k, uint32_t v) { return key(k).uinteger(v); }
    JsonWriter& kv(std::string_view k, uint64_t v) { return key(k).uinteger(v); }
    JsonWriter& kv(std::string_view k, bool v) { return key(k).boolean(v); }
    const std::string& text() const { return out_; }
private:
    void before_value();
    void newline();
    std::string out_;
    struct Level { bool object; bool first; };
    std::vector<Level> stack_;
    bool after_key_ = false;
    bool pretty_;
};

}  // namespace spt::io
