// A strict, small JSON parser for tests: checks that tool output is valid JSON and lets tests
// look values up. Not for production use (recursion depth is bounded, numbers are doubles).
#pragma once

#include <cctype>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace spt_test {

struct Json {
    enum Type { Null, Bool, Number, String, Array, Object } type = Null;
    bool b = false;
    double num = 0;
    std::string str;
    std::vector<Json> arr;
    std::map<std::string, Json> obj;

    bool has(const std::string& k) const { return type == Object && obj.count(k) > 0; }
    const Json& operator[](const std::string& k) const {
        static const Json null_value;
        auto it = obj.find(k);
        return it == obj.end() ? null_value : it->second;
    }
    const Json& operator[](size_t i) const { return arr.at(i); }
};

class JsonParser {
public:
    // Parses the whole text; false (with `error` set) when it is not exactly one JSON value.
    static bool parse(const std::string& text, Json& out, std::string* error = nullptr) {
        JsonParser p(text);
        bool ok = p.value(out, 0);
        p.ws();
        if (ok && p.i_ != text.size()) ok = p.fail("trailing characters");
        if (!ok && error) *error = p.err_;
        return ok;
    }

private:
    explicit JsonParser(const std::string& t) : t_(t) {}
    const std::string& t_;
    size_t i_ = 0;
    std::string err_;

    bool fail(const std::string& m) {
        if (err_.empty()) err_ = m + " at offset " + std::to_string(i_);
        return false;
    }
    void ws() {
        while (i_ < t_.size() && (t_[i_] == ' ' || t_[i_] == '\n' || t_[i_] == '\r' || t_[i_] == '\t')) ++i_;
    }
    bool lit(const char* s) {
        size_t n = std::char_traits<char>::length(s);
        if (t_.compare(i_, n, s) != 0) return fail("bad literal");
        i_ += n;
        return true;
    }
    bool string(std::string& out) {
        if (i_ >= t_.size() || t_[i_] != '"') return fail("expected string");
        ++i_;
        while (i_ < t_.size() && t_[i_] != '"') {
            char c = t_[i_++];
            if (uint8_t(c) < 0x20) return fail("control character in string");
            if (c == '\\') {
                if (i_ >= t_.size()) return fail("bad escape");
                char e = t_[i_++];
                switch (e) {
                    case '"': out += '"'; break;
                    case '\\': out += '\\'; break;
                    case '/': out += '/'; break;
                    case 'b': out += '\b'; break;
                    case 'f': out += '\f'; break;
                    case 'n': out += '\n'; break;
                    case 'r': out += '\r'; break;
                    case 't': out += '\t'; break;
                    case 'u':
                        if (i_ + 4 > t_.size()) return fail("bad \\u escape");
                        for (int k = 0; k < 4; ++k)
                            if (!std::isxdigit(uint8_t(t_[i_ + k]))) return fail("bad \\u escape");
                        out += '?';
                        i_ += 4;
                        break;
                    default: return fail("bad escape");
                }
            } else {
                out += c;
            }
        }
        if (i_ >= t_.size()) return fail("unterminated string");
        ++i_;
        return true;
    }
    bool number(double& out) {
        size_t s = i_;
        if (i_ < t_.size() && t_[i_] == '-') ++i_;
        if (i_ >= t_.size() || !std::isdigit(uint8_t(t_[i_]))) return fail("bad number");
        if (t_[i_] == '0') ++i_;
        else while (i_ < t_.size() && std::isdigit(uint8_t(t_[i_]))) ++i_;
        if (i_ < t_.size() && t_[i_] == '.') {
            ++i_;
            if (i_ >= t_.size() || !std::isdigit(uint8_t(t_[i_]))) return fail("bad fraction");
            while (i_ < t_.size() && std::isdigit(uint8_t(t_[i_]))) ++i_;
        }
        if (i_ < t_.size() && (t_[i_] == 'e' || t_[i_] == 'E')) {
            ++i_;
            if (i_ < t_.size() && (t_[i_] == '+' || t_[i_] == '-')) ++i_;
            if (i_ >= t_.size() || !std::isdigit(uint8_t(t_[i_]))) return fail("bad exponent");
            while (i_ < t_.size() && std::isdigit(uint8_t(t_[i_]))) ++i_;
        }
        out = std::strtod(t_.substr(s, i_ - s).c_str(), nullptr);
        return true;
    }
    bool value(Json& v, int depth) {
        if (depth > 64) return fail("too deep");
        ws();
        if (i_ >= t_.size()) return fail("unexpected end");
        char c = t_[i_];
        if (c == '{') {
            v.type = Json::Object;
            ++i_;
            ws();
            if (i_ < t_.size() && t_[i_] == '}') { ++i_; return true; }
            for (;;) {
                ws();
                std::string k;
                if (!string(k)) return false;
                ws();
                if (i_ >= t_.size() || t_[i_] != ':') return fail("expected ':'");
                ++i_;
                Json child;
                if (!value(child, depth + 1)) return false;
                if (v.obj.count(k)) return fail("duplicate key " + k);
                v.obj.emplace(k, std::move(child));
                ws();
                if (i_ < t_.size() && t_[i_] == ',') { ++i_; continue; }
                if (i_ < t_.size() && t_[i_] == '}') { ++i_; return true; }
                return fail("expected ',' or '}'");
            }
        }
        if (c == '[') {
            v.type = Json::Array;
            ++i_;
            ws();
            if (i_ < t_.size() && t_[i_] == ']') { ++i_; return true; }
            for (;;) {
                Json child;
                if (!value(child, depth + 1)) return false;
                v.arr.push_back(std::move(child));
                ws();
                if (i_ < t_.size() && t_[i_] == ',') { ++i_; continue; }
                if (i_ < t_.size() && t_[i_] == ']') { ++i_; return true; }
                return fail("expected ',' or ']'");
            }
        }
        if (c == '"') { v.type = Json::String; return string(v.str); }
        if (c == 't') { v.type = Json::Bool; v.b = true; return lit("true"); }
        if (c == 'f') { v.type = Json::Bool; v.b = false; return lit("false"); }
        if (c == 'n') { v.type = Json::Null; return lit("null"); }
        v.type = Json::Number;
        return number(v.num);
    }
};

}  // namespace spt_test
