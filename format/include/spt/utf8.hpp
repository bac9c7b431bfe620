// UTF-8 validation for the text the format carries (metadata keys and values, template names:
// SPEC.md 3.2-3.3 require UTF-8). Writers and importers reject invalid text with these.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace spt {

// True when `s` is well-formed UTF-8 (RFC 3629: no overlong forms, no surrogates, nothing above
// U+10FFFF). Otherwise false, with the offset of the first byte of the bad sequence in *bad_at.
bool is_valid_utf8(std::string_view s, size_t* bad_at = nullptr);

// `s` for a message or a terminal: printable ASCII and valid UTF-8 as they are, C1 controls
// as \u0080..\u009f, other bytes (control characters, ESC, DEL, invalid UTF-8) as \xNN, so no
// file-supplied text reaches a terminal as an escape sequence.
std::string printable_text(std::string_view s);

}  // namespace spt
