// Minimal JSON writer (see json.hpp).
#include "io/json.hpp"

#include <cmath>
#include <cstdio>

namespace spt::io {

namespace {

// Length of the valid UTF-8 sequence starting at s[i], or 0 when it is invalid.
size_t utf8_len(std::string_view s, size_t i) {
    const auto c = uint8_t(s[i]);
    size_t n = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
    if (n == 0 || i + n > s.size()) return 0;
    for (size_t k = 1; k < n; ++k)
        if ((uint8_t(s[i + k]) & 0xC0) != 0x80) return 0;
    return n;
}

}  // namespace

std::string json_quote(std::string_view s) {
    std::string o;
    o.reserve(s.size() + 2);
    o += '"';
    for (size_t i = 0; i < s.size();) {
        const auto c = uint8_t(s[i]);
        if (c == '"' || c == '\\') {
            o += '\\';
            o += char(c);
        } else if (c == '\n') {
            o += "\\n";
        } else if (c == '\t') {
            o += "\\t";
        } else if (c == '\r') {
            o += "\\r";
        } else if (c < 0x20 || c == 0x7F) {
            char b[8];
            std::snprintf(b, sizeof b, "\\u%04x", c);
            o += b;
        } else if (c >= 0x80) {
            size_t n = utf8_len(s, i);
            if (n == 0) {
                o += "\xEF\xBF\xBD";
                ++i;
                continue;
            }
            o.append(s.substr(i, n));
            i += n;
            continue;
        } else {
            o += char(c);
        }
        ++i;
    }
    o += '"';
    return o;
}

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
