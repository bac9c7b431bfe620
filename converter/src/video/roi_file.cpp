#include "video/roi_file.hpp"

#include <cctype>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

namespace spt::video {

namespace {

// Just enough JSON for the ROI schema: objects, arrays, strings (simple escapes), numbers,
// true/false/null. Errors name the byte offset.
struct Value {
    enum Kind { Null, Bool, Number, String, Array, Object } kind = Null;
    double number = 0;
    std::string str;
    std::vector<Value> items;
    std::map<std::string, Value> fields;
};

class Parser {
public:
    Parser(const std::string& t, const std::string& name) : t_(t), name_(name) {}

    Result<Value> parse() {
        Value v;
        if (!value(v, 0)) return err_;
        ws();
        if (p_ != t_.size()) return fail("unexpected text after the JSON value");
        return v;
    }

private:
    const std::string& t_;
    const std::string& name_;
    size_t p_ = 0;
    Error err_;

    Error fail(const std::string& what) {
        err_ = make_error(Code::InvalidArgument, name_ + ": " + what + " at byte " + std::to_string(p_), p_);
        return err_;
    }
    void ws() {
        while (p_ < t_.size() && std::isspace(static_cast<unsigned char>(t_[p_]))) ++p_;
    }
    bool lit(const char* s) {
        const size_t n = std::char_traits<char>::length(s);
        if (t_.compare(p_, n, s) != 0) return false;
        p_ += n;
        return true;
    }
    bool value(Value& v, int depth) {
        if (depth > 32) return fail("nesting too deep"), false;
        ws();
        if (p_ >= t_.size()) return fail("unexpected end"), false;
        const char c = t_[p_];
        if (c == '{') return object(v, depth);
        if (c == '[') return array(v, depth);
        if (c == '"') { v.kind = Value::String; return string(v.str); }
        if (lit("true")) { v.kind = Value::Bool; v.number = 1; return true; }
        if (lit("false")) { v.kind = Value::Bool; return true; }
        if (lit("null")) return true;
        const char* begin = t_.c_str() + p_;
        char* end = nullptr;
        v.number = std::strtod(begin, &end);
        if (end == begin) return fail("expected a value"), false;
        v.kind = Value::Number;
        p_ += size_t(end - begin);
        return true;
    }
    bool string(std::string& out) {
        ++p_;  // opening quote
        while (p_ < t_.size() && t_[p_] != '"') {
            if (t_[p_] == '\\') {
                if (++p_ >= t_.size()) break;
                const char e = t_[p_];
                out += e == 'n' ? '\n' : e == 't' ? '\t' : e;  // \uXXXX is not needed here
            } else {
                out += t_[p_];
            }
            ++p_;
        }
        if (p_ >= t_.size()) return fail("unterminated string"), false;
        ++p_;
        return true;
    }
    bool array(Value& v, int depth) {
        v.kind = Value::Array;
        ++p_;
        ws();
        if (p_ < t_.size() && t_[p_] == ']') { ++p_; return true; }
        for (;;) {
            v.items.emplace_back();
            if (!value(v.items.back(), depth + 1)) return false;
            ws();
            if (p_ < t_.size() && t_[p_] == ',') { ++p_; continue; }
            if (p_ < t_.size() && t_[p_] == ']') { ++p_; return true; }
            return fail("expected ',' or ']'"), false;
        }
    }
    bool object(Value& v, int depth) {
        v.kind = Value::Object;
        ++p_;
        ws();
        if (p_ < t_.size() && t_[p_] == '}') { ++p_; return true; }
        for (;;) {
            ws();
            std::string key;
            if (p_ >= t_.size() || t_[p_] != '"') return fail("expected a key"), false;
            if (!string(key)) return false;
            ws();
            if (p_ >= t_.size() || t_[p_] != ':') return fail("expected ':'"), false;
            ++p_;
            if (!value(v.fields[key], depth + 1)) return false;
            ws();
            if (p_ < t_.size() && t_[p_] == ',') { ++p_; continue; }
            if (p_ < t_.size() && t_[p_] == '}') { ++p_; return true; }
            return fail("expected ',' or '}'"), false;
        }
    }
};

bool parse_range(const std::string& s, long& a, long& b) {
    char* end = nullptr;
    a = std::strtol(s.c_str(), &end, 10);
    if (end == s.c_str()) return false;
    if (*end == '\0') { b = a; return true; }
    if (*end != '-') return false;
    const char* rest = end + 1;
    b = std::strtol(rest, &end, 10);
    return end != rest && *end == '\0' && b >= a;
}

}  // namespace

Result<std::vector<RoiSpec>> parse_roi_json(const std::string& text, const std::string& name) {
    Parser parser(text, name);
    Result<Value> root = parser.parse();
    if (!root) return root.error();
    auto bad = [&](size_t i, const std::string& what) {
        return make_error(Code::InvalidArgument, name + ": rois[" + std::to_string(i) + "]: " + what);
    };
    if (root->kind != Value::Object || !root->fields.count("rois") ||
        root->fields.at("rois").kind != Value::Array)
        return make_error(Code::InvalidArgument, name + ": expected an object with a \"rois\" array");
    std::vector<RoiSpec> out;
    const auto& items = root->fields.at("rois").items;
    for (size_t i = 0; i < items.size(); ++i) {
        const Value& r = items[i];
        if (r.kind != Value::Object) return bad(i, "not an object");
        RoiSpec s;
        auto it = r.fields.find("frames");
        if (it == r.fields.end()) return bad(i, "no \"frames\"");
        if (it->second.kind == Value::Number) {
            s.first = s.last = long(it->second.number);
        } else if (it->second.kind != Value::String || !parse_range(it->second.str, s.first, s.last)) {
            return bad(i, "\"frames\" must be \"A-B\", \"A\" or a number");
        }
        int* dst[] = {&s.x, &s.y, &s.w, &s.h};
        const char* keys[] = {"x", "y", "w", "h"};
        for (int k = 0; k < 4; ++k) {
            auto f = r.fields.find(keys[k]);
            if (f == r.fields.end() || f->second.kind != Value::Number)
                return bad(i, std::string("\"") + keys[k] + "\" missing or not a number");
            const double v = f->second.number;
            if (v < 0 || v > 1e6) return bad(i, std::string("\"") + keys[k] + "\" out of range");
            *dst[k] = int(v);
        }
        if (s.w <= 0 || s.h <= 0) return bad(i, "empty rectangle");
        out.push_back(s);
    }
    return out;
}

Result<std::vector<RoiSpec>> read_roi_file(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    if (!f) return make_error(Code::IoError, path + ": cannot open the ROI file");
    std::ostringstream ss;
    ss << f.rdbuf();
    if (ss.str().size() > (1u << 24)) return make_error(Code::LimitExceeded, path + ": ROI file over 16 MiB");
    return parse_roi_json(ss.str(), path);
}

}  // namespace spt::video
