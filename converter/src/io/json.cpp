// Minimal JSON writer (see json.hpp); strings are escaped by the shared JSON layer (json/).
#include "io/json.hpp"

#include "spt_json/json.hpp"

#include <cmath>
#include <cstdio>

namespace spt::io {

std::string json_quote(std::string_view s) { return json::quote(s); }

std::string json_number(double v) {
    if (!std::isfinite(v)) return "null";
    char b[32];
    if (v == std::floor(v) && std::fabs(v) < 9.0e15)
        std::snprintf(b, sizeof b, "%.0f", v);
    else
        std::snprintf(b, sizeof b, "%.6g", v);
    return b;
}

void JsonWriter::newline() {
    if (!pretty_) return;
    out_ += '\n';
    out_.append(stack_.size() * 2, ' ');
}

void JsonWriter::before_value() {
    if (after_key_) {
        after_key_ = false;
        return;
    }
    if (!stack_.empty()) {
        if (!stack_.back().first) out_ += ',';
        stack_.back().first = false;
        newline();
    }
}

JsonWriter& JsonWriter::obj() {
    before_value();
    out_ += '{';
    stack_.push_back({true, true});
    return *this;
}

JsonWriter& JsonWriter::arr() {
    before_value();
    out_ += '[';
    stack_.push_back({false, true});
    return *this;
}

JsonWriter& JsonWriter::end() {
    if (stack_.empty()) return *this;
    const bool obj = stack_.back().object, empty = stack_.back().first;
    stack_.pop_back();
    if (!empty) newline();
    out_ += obj ? '}' : ']';
    return *this;
}

JsonWriter& JsonWriter::key(std::string_view k) {
    before_value();
    out_ += json_quote(k);
    out_ += pretty_ ? ": " : ":";
    after_key_ = true;
    return *this;
}

JsonWriter& JsonWriter::str(std::string_view v) { before_value(); out_ += json_quote(v); return *this; }
JsonWriter& JsonWriter::num(double v) { before_value(); out_ += json_number(v); return *this; }
JsonWriter& JsonWriter::integer(int64_t v) { before_value(); out_ += std::to_string(v); return *this; }
JsonWriter& JsonWriter::uinteger(uint64_t v) { before_value(); out_ += std::to_string(v); return *this; }
JsonWriter& JsonWriter::boolean(bool v) { before_value(); out_ += v ? "true" : "false"; return *this; }
JsonWriter& JsonWriter::null() { before_value(); out_ += "null"; return *this; }

}  // namespace spt::io
