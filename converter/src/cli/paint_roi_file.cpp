// --roi-file: a small strict JSON reader for {"rois":[{"x":..,"y":..,"w":..,"h":..,
// "frames":[first,last] or "first-last"}]}. Only what the schema needs: objects, arrays, numbers, strings,
// true/false/null (skipped where not used). Errors name the file and the byte offset.
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

#include "cli/paint_options.hpp"

namespace spt::cli {

namespace {

constexpr size_t kMaxFileBytes = 16u << 20;
constexpr int kMaxDepth = 32;

struct JValue {
    enum Kind { Null, Bool, Number, String, Array, Object } kind = Null;
    double num = 0;
    std::string str;
    std::vector<JValue> items;
    std::vector<std::pair<std::string, JValue>> fields;
    const JValue* get(const std::string& k) const {
        for (const auto& f : fields)
            if (f.first == k) return &f.second;
        return nullptr;
    }
};

class Parser {
public:
    explicit Parser(const std::string& t) : t_(t) {}
    bool parse(JValue& v, std::string& err) {
        if (!value(v, 0)) { err = err_; return false; }
        ws();
        if (p_ != t_.size()) { err = fail("trailing characters after the JSON value"), err = err_; return false; }
        return true;
    }
private:
    std::string fail(const std::string& m) {
        err_ = "byte " + std::to_string(p_) + ": " + m;
        return err_;
    }
    void ws() { while (p_ < t_.size() && (t_[p_] == ' ' || t_[p_] == '\n' || t_[p_] == '\r' || t_[p_] == '\t')) ++p_; }
    bool lit(const char* s) {
        const std::string w(s);
        if (t_.compare(p_, w.size(), w) != 0) return false;
        p_ += w.size();
        return true;
    }
    bool string(std::string& out) {
        ++p_;  // opening quote
        while (p_ < t_.size() && t_[p_] != '"') {
            if (t_[p_] == '\\') {
                if (++p_ >= t_.size()) break;
                const char e = t_[p_];
                if (e == 'u') { p_ += 4; out += '?'; }  // names only; the schema has no escapes
                else out += e == 'n' ? '\n' : e == 't' ? '\t' : e;
                ++p_;
            } else out += t_[p_++];
        }
        if (p_ >= t_.size()) { fail("unterminated string"); return false; }
        ++p_;
        return true;
    }
    bool value(JValue& v, int depth) {
        if (depth > kMaxDepth) { fail("nesting too deep"); return false; }
        ws();
        if (p_ >= t_.size()) { fail("unexpected end of file"); return false; }
        const char c = t_[p_];
        if (c == '{') {
            v.kind = JValue::Object;
            ++p_;
            ws();
            if (p_ < t_.size() && t_[p_] == '}') { ++p_; return true; }
            for (;;) {
                ws();
                if (p_ >= t_.size() || t_[p_] != '"') { fail("expected a key string"); return false; }
                std::string k;
                if (!string(k)) return false;
                ws();
                if (p_ >= t_.size() || t_[p_] != ':') { fail("expected ':'"); return false; }
                ++p_;
                JValue x;
                if (!value(x, depth + 1)) return false;
                v.fields.emplace_back(std::move(k), std::move(x));
                ws();
                if (p_ < t_.size() && t_[p_] == ',') { ++p_; continue; }
                if (p_ < t_.size() && t_[p_] == '}') { ++p_; return true; }
                fail("expected ',' or '}'");
                return false;
            }
        }
        if (c == '[') {
            v.kind = JValue::Array;
            ++p_;
            ws();
            if (p_ < t_.size() && t_[p_] == ']') { ++p_; return true; }
            for (;;) {
                JValue x;
                if (!value(x, depth + 1)) return false;
                v.items.push_back(std::move(x));
                ws();
                if (p_ < t_.size() && t_[p_] == ',') { ++p_; continue; }
                if (p_ < t_.size() && t_[p_] == ']') { ++p_; return true; }
                fail("expected ',' or ']'");
                return false;
            }
        }
        if (c == '"') { v.kind = JValue::String; return string(v.str); }
        if (lit("true")) { v.kind = JValue::Bool; v.num = 1; return true; }
        if (lit("false")) { v.kind = JValue::Bool; return true; }
        if (lit("null")) { v.kind = JValue::Null; return true; }
        const char* b = t_.c_str() + p_;
        char* e = nullptr;
        const double d = std::strtod(b, &e);
        if (e == b || !std::isfinite(d)) { fail("expected a JSON value"); return false; }
        p_ += size_t(e - b);
        v.kind = JValue::Number;
        v.num = d;
        return true;
    }
    const std::string& t_;
    size_t p_ = 0;
    std::string err_;
};

bool get_uint(const JValue& o, const char* k, long lo, long hi, long& out) {
    const JValue* v = o.get(k);
    if (!v || v->kind != JValue::Number || v->num != std::floor(v->num) || v->num < lo || v->num > hi) return false;
    out = long(v->num);
    return true;
}

}  // namespace

Result<std::vector<RoiSpec>> load_roi_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return make_error(Code::IoError, "--roi-file " + path + ": cannot open");
    std::ostringstream ss;
    ss << in.rdbuf();
    const std::string text = ss.str();
    if (text.size() > kMaxFileBytes) return make_error(Code::LimitExceeded, "--roi-file " + path + ": larger than 16 MiB");
    JValue root;
    std::string err;
    if (!Parser(text).parse(root, err)) return make_error(Code::Corrupt, "--roi-file " + path + ": " + err);
    const JValue* rois = root.kind == JValue::Object ? root.get("rois") : nullptr;
    if (!rois || rois->kind != JValue::Array)
        return make_error(Code::InvalidArgument, "--roi-file " + path + ": expected an object with a \"rois\" array");
    std::vector<RoiSpec> out;
    for (size_t i = 0; i < rois->items.size(); ++i) {
        const JValue& r = rois->items[i];
        const std::string where = "--roi-file " + path + ": rois[" + std::to_string(i) + "]";
        long x, y, w, h;
        if (r.kind != JValue::Object || !get_uint(r, "x", 0, 1L << 24, x) || !get_uint(r, "y", 0, 1L << 24, y) ||
            !get_uint(r, "w", 1, 1L << 24, w) || !get_uint(r, "h", 1, 1L << 24, h))
            return make_error(Code::InvalidArgument, where + ": needs integer x, y >= 0 and w, h >= 1");
        RoiSpec s;
        s.rect = paint::Rect{int32_t(x), int32_t(y), int32_t(w), int32_t(h)};
        if (const JValue* f = r.get("frames"); f && f->kind == JValue::String) {
            // "A-B" or "A" (the video encoder's spelling).
            const std::string& t = f->str;
            char* e = nullptr;
            const unsigned long a = std::strtoul(t.c_str(), &e, 10);
            unsigned long b = a;
            if (e != t.c_str() && *e == '-') b = std::strtoul(e + 1, &e, 10);
            if (t.empty() || *e || b < a || b > 4294967294ul)
                return make_error(Code::InvalidArgument, where + ": \"frames\" must be \"A-B\" or [A, B] with A <= B");
            s.first_frame = uint32_t(a);
            s.last_frame = uint32_t(b);
        } else if (f) {
            if (f->kind != JValue::Array || f->items.size() != 2 || f->items[0].kind != JValue::Number ||
                f->items[1].kind != JValue::Number || f->items[0].num < 0 || f->items[1].num < f->items[0].num ||
                f->items[1].num > 4294967294.0)
                return make_error(Code::InvalidArgument, where + ": \"frames\" must be [first, last] with first <= last");
            s.first_frame = uint32_t(f->items[0].num);
            s.last_frame = uint32_t(f->items[1].num);
        }
        out.push_back(s);
    }
    return out;
}

}  // namespace spt::cli
