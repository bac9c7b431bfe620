// Strict recursive-descent JSON parser with line tracking and hard limits on depth and size.
#include "spt_import/json.hpp"

#include "text_cursor.hpp"

#include <charconv>
#include <cmath>

namespace spt::json {

const Value* Value::find(std::string_view key) const {
    for (const auto& m : members)
        if (m.first == key) return &m.second;
    return nullptr;
}

const char* type_name(Type t) {
    switch (t) {
        case Type::Null: return "null";
        case Type::Bool: return "boolean";
        case Type::Number: return "number";
        case Type::String: return "string";
        case Type::Array: return "array";
        case Type::Object: return "object";
    }
    return "?";
}

namespace {

class Parser : text::Cursor<ParseLimits> {
public:
    Parser(std::string_view t, const std::string& src, const ParseLimits& l) : Cursor(t, src, l) {}

    Result<Value> run() {
        if (s_.size() > lim_.max_bytes)
            return make_error(Code::LimitExceeded, src_ + ": JSON document larger than the limit");
        // A UTF-8 byte order mark is tolerated: some Windows tools write one.
        if (s_.size() >= 3 && (unsigned char)s_[0] == 0xEF && (unsigned char)s_[1] == 0xBB &&
            (unsigned char)s_[2] == 0xBF)
            pos_ = 3;
        Value v;
        if (!value(v, 0)) return err_;
        skip_ws();
        if (pos_ != s_.size()) {
            fail("unexpected text after the JSON value");
            return err_;
        }
        return v;
    }

private:
    void skip_ws() {
        while (pos_ < s_.size()) {
            char c = s_[pos_];
            if (c == '\n') { ++line_; ++pos_; }
            else if (c == ' ' || c == '\t' || c == '\r') ++pos_;
            else break;
        }
    }
    bool literal(std::string_view word) {
        if (s_.substr(pos_, word.size()) != word) return fail("invalid literal");
        pos_ += word.size();
        return true;
    }

    bool value(Value& v, uint32_t depth) {
        if (depth > lim_.max_depth) return fail("nesting deeper than " + std::to_string(lim_.max_depth));
        if (++count_ > lim_.max_values) return fail("too many JSON values", Code::LimitExceeded);
        skip_ws();
        if (pos_ >= s_.size()) return fail("unexpected end of document");
        v.line = line_;
        char c = s_[pos_];
        switch (c) {
            case '{': return object(v, depth);
            case '[': return array(v, depth);
            case '"': v.type = Type::String; return string(v.text);
            case 't': v.type = Type::Bool; v.boolean = true; return literal("true");
            case 'f': v.type = Type::Bool; v.boolean = false; return literal("false");
            case 'n': v.type = Type::Null; return literal("null");
            default:
                if (c == '-' || (c >= '0' && c <= '9')) return number(v);
                return fail(std::string("unexpected character '") + (c >= 32 && c < 127 ? std::string(1, c) : "?") + "'");
        }
    }

    bool object(Value& v, uint32_t depth) {
        v.type = Type::Object;
        ++pos_;
        skip_ws();
        if (pos_ < s_.size() && s_[pos_] == '}') { ++pos_; return true; }
        for (;;) {
            skip_ws();
            if (pos_ >= s_.size() || s_[pos_] != '"') return fail("expected a string key in object");
            std::string key;
            if (!string(key)) return false;
            for (const auto& m : v.members)
                if (m.first == key) return fail("duplicate key \"" + key + "\"");
            skip_ws();
            if (pos_ >= s_.size() || s_[pos_] != ':') return fail("expected ':' after key \"" + key + "\"");
            ++pos_;
            Value child;
            if (!value(child, depth + 1)) return false;
            v.members.emplace_back(std::move(key), std::move(child));
            skip_ws();
            if (pos_ >= s_.size()) return fail("unterminated object");
            if (s_[pos_] == ',') { ++pos_; continue; }
            if (s_[pos_] == '}') { ++pos_; return true; }
            return fail("expected ',' or '}' in object");
        }
    }

    bool array(Value& v, uint32_t depth) {
        v.type = Type::Array;
        ++pos_;
        skip_ws();
        if (pos_ < s_.size() && s_[pos_] == ']') { ++pos_; return true; }
        for (;;) {
            Value child;
            if (!value(child, depth + 1)) return false;
            v.items.push_back(std::move(child));
            skip_ws();
            if (pos_ >= s_.size()) return fail("unterminated array");
            if (s_[pos_] == ',') { ++pos_; continue; }
            if (s_[pos_] == ']') { ++pos_; return true; }
            return fail("expected ',' or ']' in array");
        }
    }

    static void put_utf8(std::string& out, uint32_t cp) {
        if (cp < 0x80) out += char(cp);
        else if (cp < 0x800) { out += char(0xC0 | (cp >> 6)); out += char(0x80 | (cp & 63)); }
        else if (cp < 0x10000) {
            out += char(0xE0 | (cp >> 12)); out += char(0x80 | ((cp >> 6) & 63)); out += char(0x80 | (cp & 63));
        } else {
            out += char(0xF0 | (cp >> 18)); out += char(0x80 | ((cp >> 12) & 63));
            out += char(0x80 | ((cp >> 6) & 63)); out += char(0x80 | (cp & 63));
        }
    }
    bool hex4(uint32_t& cp) {
        if (pos_ + 4 > s_.size()) return fail("truncated \\u escape");
        cp = 0;
        for (int i = 0; i < 4; ++i) {
            char c = s_[pos_++];
            cp <<= 4;
            if (c >= '0' && c <= '9') cp |= uint32_t(c - '0');
            else if (c >= 'a' && c <= 'f') cp |= uint32_t(c - 'a' + 10);
            else if (c >= 'A' && c <= 'F') cp |= uint32_t(c - 'A' + 10);
            else return fail("bad hex digit in \\u escape");
        }
        return true;
    }
    bool string(std::string& out) {
        ++pos_;  // opening quote
        for (;;) {
            if (pos_ >= s_.size()) return fail("unterminated string");
            unsigned char c = (unsigned char)s_[pos_];
            if (c == '"') { ++pos_; return true; }
            if (c < 0x20) return fail("control character in string");
            if (c != '\\') { out += char(c); ++pos_; continue; }
            if (++pos_ >= s_.size()) return fail("unterminated string");
            char e = s_[pos_++];
            switch (e) {
                case '"': out += '"'; break;
                case '\\': out += '\\'; break;
                case '/': out += '/'; break;
                case 'b': out += '\b'; break;
                case 'f': out += '\f'; break;
                case 'n': out += '\n'; break;
                case 'r': out += '\r'; break;
                case 't': out += '\t'; break;
                case 'u': {
                    uint32_t cp = 0;
                    if (!hex4(cp)) return false;
                    if (cp >= 0xD800 && cp < 0xDC00) {
                        uint32_t lo = 0;
                        if (pos_ + 2 > s_.size() || s_[pos_] != '\\' || s_[pos_ + 1] != 'u')
                            return fail("unpaired surrogate in \\u escape");
                        pos_ += 2;
                        if (!hex4(lo)) return false;
                        if (lo < 0xDC00 || lo > 0xDFFF) return fail("unpaired surrogate in \\u escape");
                        cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
                    } else if (cp >= 0xDC00 && cp <= 0xDFFF) {
                        return fail("unpaired surrogate in \\u escape");
                    }
                    put_utf8(out, cp);
                    break;
                }
                default: return fail("invalid escape in string");
            }
        }
    }

    bool number(Value& v) {
        // Validate the RFC 8259 grammar first: from_chars alone accepts forms JSON forbids.
        const size_t start = pos_;
        if (s_[pos_] == '-') ++pos_;
        auto digits = [&] { size_t b = pos_; while (pos_ < s_.size() && s_[pos_] >= '0' && s_[pos_] <= '9') ++pos_; return pos_ - b; };
        if (pos_ >= s_.size()) return fail("bad number");
        if (s_[pos_] == '0') ++pos_;
        else if (digits() == 0) return fail("bad number");
        if (pos_ < s_.size() && s_[pos_] == '.') { ++pos_; if (digits() == 0) return fail("bad number: digits expected after '.'"); }
        if (pos_ < s_.size() && (s_[pos_] == 'e' || s_[pos_] == 'E')) {
            ++pos_;
            if (pos_ < s_.size() && (s_[pos_] == '+' || s_[pos_] == '-')) ++pos_;
            if (digits() == 0) return fail("bad number: digits expected in exponent");
        }
        v.type = Type::Number;
        v.text.assign(s_.substr(start, pos_ - start));
        auto r = std::from_chars(v.text.data(), v.text.data() + v.text.size(), v.number);
        if (r.ec != std::errc() || !std::isfinite(v.number)) return fail("number out of range: " + v.text);
        return true;
    }
};

}  // namespace

Result<Value> parse(std::string_view text, const std::string& source, const ParseLimits& lim) {
    Parser p(text, source, lim);
    return p.run();
}

void append_string(std::string& out, std::string_view s) {
    static const char* hex = "0123456789abcdef";
    out += '"';
    for (unsigned char c : s) {
        switch (c) {
            case '"': out += "\\\""; break;
            case '\\': out += "\\\\"; break;
            case '\n': out += "\\n"; break;
            case '\r': out += "\\r"; break;
            case '\t': out += "\\t"; break;
            default:
                if (c < 0x20) { out += "\\u00"; out += hex[c >> 4]; out += hex[c & 15]; }
                else out += char(c);
        }
    }
    out += '"';
}

}  // namespace spt::json
