// The typed reading of spt JSON stroke lists (importers/README.md): each field checked for its
// type and range, with errors that name the file, the line and the element. Shared by the
// document reader (import_strokes_json.cpp) and the stroke reader (strokes_json_stroke.cpp).
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "spt_import/codec.hpp"
#include "spt_import/importer.hpp"
#include "spt_json/json.hpp"
#include "spt/utf8.hpp"

namespace spt::import::strokes_json {

using json::Type;
using json::Value;

// Reads typed fields with errors that name the file, the line and the element.
class Ctx {
public:
    Ctx(const std::string& src, const Limits& lim) : src_(src), lim_(lim) {}
    const Limits& lim() const { return lim_; }
    // The document's version: 2 adds polygon strokes (`polygon` is then stored as one).
    int64_t version = 1;
    // Version 3: canvas.color_encoding "linear-half" (colours are 16-bit half codes).
    bool linear = false;
    Error err(const Value& v, const std::string& what) const {
        return make_error(Code::Corrupt, src_ + ":" + std::to_string(v.line) + ": " + what);
    }
    // SPEC.md 3.2-3.3: the text a file carries is UTF-8; the JSON parser passes raw bytes through.
    bool utf8(const Value& v, const std::string& name, Error& e) const {
        size_t at = 0;
        if (is_valid_utf8(v.text, &at)) return true;
        e = err(v, name + " is not valid UTF-8 (byte " + std::to_string(at) + " of the string)");
        return false;
    }
    bool need(const Value& v, Type t, const std::string& name, Error& e) const {
        if (v.type == t) return true;
        e = err(v, name + " must be a" + (t == Type::Array || t == Type::Object ? "n " : " ") + json::type_name(t) +
                       ", not a " + json::type_name(v.type));
        return false;
    }
    bool num(const Value& v, const std::string& name, double lo, double hi, double& out, Error& e) const {
        if (!need(v, Type::Number, name, e)) return false;
        if (!(v.number >= lo && v.number <= hi)) {
            e = err(v, name + " = " + v.text + " is outside " + fmt(lo) + ".." + fmt(hi));
            return false;
        }
        out = v.number;
        return true;
    }
    bool integer(const Value& v, const std::string& name, int64_t lo, int64_t hi, int64_t& out, Error& e) const {
        double d;
        if (!num(v, name, double(lo), double(hi), d, e)) return false;
        if (d != std::floor(d)) { e = err(v, name + " must be an integer"); return false; }
        out = int64_t(d);
        return true;
    }
    // Pixels to Q4, rounding; the range is the spec's position range.
    bool q4(const Value& v, const std::string& name, double max_px, int32_t& out, Error& e) const {
        double d;
        if (!num(v, name, -max_px, max_px, d, e)) return false;
        out = int32_t(std::nearbyint(d * 16));
        return true;
    }
    static std::string fmt(double d) {
        if (d == std::floor(d) && std::fabs(d) < 1e15) return std::to_string(int64_t(d));
        return std::to_string(d);
    }
private:
    const std::string& src_;
    const Limits& lim_;
};

constexpr double kPosPx = double(1 << 20);   // 2^24 Q4
constexpr double kAxisPx = double(1 << 12);  // 2^16 Q4

// A stroke's (or the background's) "color" and "opacity": [r, g, b(, a)] or "#rrggbb(aa)"; in a
// linear document (version 3) half codes, or "linear" values.
bool read_color(const Ctx& c, const Value& obj, const std::string& where, Rgba8& out, Error& e);
// "template": a template's name, its kind's name, or its index.
bool read_template_ref(const Ctx& c, const Value& obj, const std::string& where, const std::vector<Template>& T,
                       uint8_t& out, Error& e);
// `v`, named `name`: an array of `n` numbers within the position range, in pixels.
bool read_point(const Ctx& c, const Value& v, const std::string& name, size_t n, double* out, Error& e);
// obj[key], or null with an error naming `where` and the key.
const Value* field(const Ctx& c, const Value& obj, const char* key, const std::string& where, Error& e);
// The "points" array of a polygon or curve stroke, of min..max items (`noun` in the error).
const Value* points_field(const Ctx& c, const Value& s, const std::string& where, size_t min, size_t max,
                          const char* noun, Error& e);
// A polygon's or curve's optional "supersample" grid: 0 (absent) or 2..16 (SPEC.md 8.5, 8.8).
bool read_supersample(const Ctx& c, const Value& s, const std::string& where, uint8_t& out, Error& e);
// `v`, named `name`: an array of 1..`max` entries.
bool list_of(const Ctx& c, const Value& v, const std::string& name, size_t max, Error& e);
// `v`, named `name`: an array of `n` values, written `shape` in the error ("[x, y]", ...).
bool tuple_of(const Ctx& c, const Value& v, const std::string& name, size_t n, const char* shape, Error& e);

// One entry of a frame's "strokes" (stamp, affine, shape, polygon, curve), appended to `out`.
bool read_stroke(const Ctx& c, const Value& s, const std::string& where, const StreamInfo& info,
                 std::vector<Stroke>& out, ImportReport& rep, Error& e);

}  // namespace spt::import::strokes_json
