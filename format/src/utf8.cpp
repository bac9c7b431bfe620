// UTF-8 validation (RFC 3629, table 3-7 of the Unicode standard).
#include "spt/utf8.hpp"

#include <cstdint>

namespace spt {

namespace {

// Length of the well-formed sequence starting at s[i], or 0.
size_t sequence_length(std::string_view s, size_t i) {
    const auto b = [&](size_t k) { return uint8_t(s[i + k]); };
    const uint8_t c = b(0);
    if (c < 0x80) return 1;
    size_t n;
    uint8_t lo = 0x80, hi = 0xBF;  // the second byte's range
    if (c >= 0xC2 && c <= 0xDF) n = 2;
    else if (c >= 0xE0 && c <= 0xEF) { n = 3; if (c == 0xE0) lo = 0xA0; if (c == 0xED) hi = 0x9F; }
    else if (c >= 0xF0 && c <= 0xF4) { n = 4; if (c == 0xF0) lo = 0x90; if (c == 0xF4) hi = 0x8F; }
    else return 0;
    if (s.size() - i < n) return 0;
    if (b(1) < lo || b(1) > hi) return 0;
    for (size_t k = 2; k < n; ++k)
        if (b(k) < 0x80 || b(k) > 0xBF) return 0;
    return n;
}

}  // namespace

bool is_valid_utf8(std::string_view s, size_t* bad_at) {
    for (size_t i = 0; i < s.size();) {
        const size_t n = sequence_length(s, i);
        if (n == 0) {
            if (bad_at) *bad_at = i;
            return false;
        }
        i += n;
    }
    return true;
}

std::string printable_text(std::string_view s) {
    static const char* hex = "0123456789abcdef";
    std::string out;
    for (size_t i = 0; i < s.size();) {
        const size_t n = sequence_length(s, i);
        const uint8_t c = uint8_t(s[i]);
        // C1 controls (U+0080..U+009F) are valid UTF-8, but a terminal may act on them as it
        // does on ESC: U+009B starts a control sequence.
        if (n == 2 && c == 0xC2 && uint8_t(s[i + 1]) <= 0x9F) {
            out += "\\u00";
            out += hex[uint8_t(s[i + 1]) >> 4];
            out += hex[uint8_t(s[i + 1]) & 15];
            i += 2;
        } else if (n > 1 || (n == 1 && c >= 0x20 && c != 0x7F)) {
            out.append(s.substr(i, n));
            i += n;
        } else {
            out += "\\x";
            out += hex[c >> 4];
            out += hex[c & 15];
            ++i;
        }
    }
    return out;
}

}  // namespace spt
