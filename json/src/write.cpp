// Printing JSON documents (write.hpp): nlohmann-json's serializer for every scalar, plus spt's
// number form and terminal-safe escaping.
#include "spt_json/write.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace spt::json {

namespace {

// DEL and the C1 controls (U+0080..U+009F, which a terminal may act on as on ESC) as \u escapes:
// the same string to a parser. They can only occur inside strings (the rest of a JSON text is
// ASCII), so the whole text is filtered at once.
std::string escape_controls(const std::string& q) {
    std::string out;
    out.reserve(q.size());
    for (size_t i = 0; i < q.size(); ++i) {
        const uint8_t c = uint8_t(q[i]);
        const bool c1 = c == 0xC2 && i + 1 < q.size() && uint8_t(q[i + 1]) <= 0x9F;
        if (c != 0x7F && !c1) {
            out += q[i];
            continue;
        }
        const uint8_t code = c1 ? uint8_t(q[++i]) : c;
        static const char* hex = "0123456789abcdef";
        out += "\\u00";
        out += hex[code >> 4];
        out += hex[code & 15];
    }
    return out;
}

std::string raw(const Doc& d) { return d.dump(-1, ' ', false, Doc::error_handler_t::replace); }

void layout(std::string& out, const Doc& d, std::string_view key, int depth, int level,
            const std::function<bool(const Doc&, std::string_view, int)>& broken) {
    if (!d.is_structured()) {
        out += raw(d);
        return;
    }
    const bool obj = d.is_object();
    const bool brk = broken(d, key, depth);
    out += obj ? '{' : '[';
    const std::string inner = brk ? "\n" + std::string(size_t(level + 1) * 2, ' ') : std::string();
    bool first = true;
    for (auto it = d.begin(); it != d.end(); ++it) {
        if (!first) out += brk ? "," : ", ";
        first = false;
        out += inner;
        if (obj) {
            out += raw(Doc(it.key()));
            out += ": ";
        }
        layout(out, *it, obj ? std::string_view(it.key()) : std::string_view(), depth + 1, level + (brk ? 1 : 0), broken);
    }
    if (brk) out += "\n" + std::string(size_t(level) * 2, ' ');
    out += obj ? '}' : ']';
}

}  // namespace

Doc number(double v) {
    if (!std::isfinite(v)) return nullptr;
    if (v == std::floor(v) && std::fabs(v) < 9.0e15) return int64_t(v);
    char b[32];
    std::snprintf(b, sizeof b, "%.6g", v);
    const double r = std::strtod(b, nullptr);
    // Rounded to a whole number (999999.7 -> 1e+06): written as one.
    if (r == std::floor(r) && std::fabs(r) < 9.0e15) return int64_t(r);
    return r;
}

std::string dump(const Doc& d, int indent) {
    return escape_controls(d.dump(indent, ' ', false, Doc::error_handler_t::replace));
}

std::string dump_layout(const Doc& d, const std::function<bool(const Doc&, std::string_view, int)>& broken) {
    std::string out;
    layout(out, d, {}, 0, 0, broken);
    return escape_controls(out);
}

}  // namespace spt::json
