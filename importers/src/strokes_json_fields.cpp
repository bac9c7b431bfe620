#include "strokes_json_fields.hpp"

#include "spt_import/shapes.hpp"
#include "spt/color.hpp"
#include "spt/display.hpp"

namespace spt::import::strokes_json {

// Colour encoding 1 (version 3): "color" [r, g, b(, a)] holds half codes 0..31743 (0x7BFF) and
// the 8-bit alpha; "linear" [r, g, b(, a)] gives linear values (the nearest code) instead; a
// "#rrggbb(aa)" string is sRGB, through the inverse sRGB curve.
namespace {

bool read_linear_color(const Ctx& c, const Value& obj, const std::string& where, Rgba8& out, Error& e) {
    const Value* col = obj.find("color");
    const Value* lin = obj.find("linear");
    if (col && lin) { e = c.err(*lin, where + ": give \"color\" (codes) or \"linear\" (values), not both"); return false; }
    if (!col && !lin) { e = c.err(obj, where + ": missing \"color\""); return false; }
    const Value& v = col ? *col : *lin;
    if (v.is_string()) {
        Rgb8 rgb;
        bool none = false;
        if (v.text.size() != 7 || !parse_color(v.text, rgb, none) || none) { e = c.err(v, where + ": bad colour \"" + v.text + "\""); return false; }
        out = Rgba8{};
        const uint8_t ch[3] = {rgb.r, rgb.g, rgb.b};
        for (int k = 0; k < 3; ++k) set_code16(out, k, float_to_half_code(srgb_decode(ch[k] / 255.f)));
    } else {
        const std::string n = where + (col ? ".color" : ".linear");
        if (!c.need(v, Type::Array, n, e)) return false;
        if (v.items.size() != 3 && v.items.size() != 4) { e = c.err(v, n + " must have 3 or 4 entries"); return false; }
        out = Rgba8{};
        for (size_t i = 0; i < 3; ++i) {
            const std::string ni = n + "[" + std::to_string(i) + "]";
            if (col) {
                int64_t code;
                if (!c.integer(v.items[i], ni, 0, kMaxHalfCode, code, e)) return false;
                set_code16(out, int(i), uint16_t(code));
            } else {
                double d;
                if (!c.num(v.items[i], ni, 0, 65504, d, e)) return false;
                set_code16(out, int(i), float_to_half_code(float(d)));
            }
        }
        if (v.items.size() == 4) {
            int64_t a;
            if (!c.integer(v.items[3], n + "[3]", 0, 255, a, e)) return false;
            out.a = uint8_t(a);
        }
    }
    if (const Value* op = obj.find("opacity")) {
        double o;
        if (!c.num(*op, where + ".opacity", 0, 1, o, e)) return false;
        out.a = uint8_t(std::nearbyint(out.a * o));
    }
    return true;
}

}  // namespace

bool read_color(const Ctx& c, const Value& obj, const std::string& where, Rgba8& out, Error& e) {
    if (c.linear) return read_linear_color(c, obj, where, out, e);
    const Value* col = obj.find("color");
    if (!col) { e = c.err(obj, where + ": missing \"color\""); return false; }
    if (col->is_string()) {
        std::string_view s = col->text;
        Rgb8 rgb;
        bool none = false;
        uint8_t alpha = 255;
        if (s.size() == 9 && s[0] == '#') {
            auto hv = [](char ch) { return ch >= '0' && ch <= '9' ? ch - '0' : ch >= 'a' && ch <= 'f' ? ch - 'a' + 10 : ch >= 'A' && ch <= 'F' ? ch - 'A' + 10 : -1; };
            int h1 = hv(s[7]), h2 = hv(s[8]);
            if (h1 < 0 || h2 < 0) { e = c.err(*col, where + ": bad colour \"" + col->text + "\""); return false; }
            alpha = uint8_t(h1 * 16 + h2);
            s = s.substr(0, 7);
        }
        if (!parse_color(s, rgb, none) || none) { e = c.err(*col, where + ": bad colour \"" + col->text + "\""); return false; }
        out = {rgb.r, rgb.g, rgb.b, alpha};
    } else {
        if (!c.need(*col, Type::Array, where + ".color", e)) return false;
        if (col->items.size() != 3 && col->items.size() != 4) { e = c.err(*col, where + ".color must have 3 or 4 entries"); return false; }
        int64_t v[4] = {0, 0, 0, 255};
        for (size_t i = 0; i < col->items.size(); ++i)
            if (!c.integer(col->items[i], where + ".color[" + std::to_string(i) + "]", 0, 255, v[i], e)) return false;
        out = {uint8_t(v[0]), uint8_t(v[1]), uint8_t(v[2]), uint8_t(v[3])};
    }
    if (const Value* op = obj.find("opacity")) {
        double o;
        if (!c.num(*op, where + ".opacity", 0, 1, o, e)) return false;
        out.a = uint8_t(std::nearbyint(out.a * o));
    }
    return true;
}

bool read_template_ref(const Ctx& c, const Value& obj, const std::string& where, const std::vector<Template>& T,
                       uint8_t& out, Error& e) {
    const Value* t = obj.find("template");
    if (!t) { e = c.err(obj, where + ": missing \"template\""); return false; }
    if (t->is_string()) {
        for (size_t i = 0; i < T.size(); ++i)
            if (T[i].name == t->text) { out = uint8_t(i); return true; }
        const char* kinds[] = {"bitmap", "ellipse", "rectangle", "triangle"};
        for (size_t i = 0; i < T.size(); ++i)
            if (t->text == kinds[size_t(T[i].kind)]) { out = uint8_t(i); return true; }
        e = c.err(*t, where + ": no template named \"" + t->text + "\"");
        return false;
    }
    int64_t id;
    if (!c.integer(*t, where + ".template", 0, int64_t(T.size()) - 1, id, e)) return false;
    out = uint8_t(id);
    return true;
}

bool read_point(const Ctx& c, const Value& v, const std::string& name, size_t n, double* out, Error& e) {
    if (!c.need(v, Type::Array, name, e)) return false;
    if (v.items.size() != n) { e = c.err(v, name + " must have " + std::to_string(n) + " numbers"); return false; }
    for (size_t i = 0; i < n; ++i)
        if (!c.num(v.items[i], name + "[" + std::to_string(i) + "]", -kPosPx, kPosPx, out[i], e)) return false;
    return true;
}

const Value* field(const Ctx& c, const Value& obj, const char* key, const std::string& where, Error& e) {
    const Value* v = obj.find(key);
    if (!v) e = c.err(obj, where + ": missing \"" + key + "\"");
    return v;
}

const Value* points_field(const Ctx& c, const Value& s, const std::string& where, size_t min, size_t max,
                          const char* noun, Error& e) {
    const Value* f = field(c, s, "points", where, e);
    if (!f || !c.need(*f, Type::Array, where + ".points", e)) return nullptr;
    if (f->items.size() < min || f->items.size() > max) {
        e = c.err(*f, where + ".points: " + std::to_string(min) + ".." + std::to_string(max) + " " + noun + " required");
        return nullptr;
    }
    return f;
}

bool read_supersample(const Ctx& c, const Value& s, const std::string& where, uint8_t& out, Error& e) {
    const Value* n = s.find("supersample");
    if (!n) return true;
    int64_t v;
    if (!c.integer(*n, where + ".supersample", 0, 16, v, e)) return false;
    if (v == 1) { e = c.err(*n, where + ".supersample must be 0 or 2..16"); return false; }
    out = uint8_t(v);
    return true;
}

bool list_of(const Ctx& c, const Value& v, const std::string& name, size_t max, Error& e) {
    if (!c.need(v, Type::Array, name, e)) return false;
    if (v.items.empty() || v.items.size() > max) {
        e = c.err(v, name + " must hold 1.." + std::to_string(max) + " entries");
        return false;
    }
    return true;
}

bool tuple_of(const Ctx& c, const Value& v, const std::string& name, size_t n, const char* shape, Error& e) {
    if (!c.need(v, Type::Array, name, e)) return false;
    if (v.items.size() != n) { e = c.err(v, name + " must be " + shape); return false; }
    return true;
}

}  // namespace spt::import::strokes_json
