// What the hand-written text parsers (json.cpp, xml.cpp) share: the text, the file name that
// messages name, the position and line, the limits, a value counter and the first error.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "spt/result.hpp"

namespace spt::text {

template <class Limits>
class Cursor {
protected:
    Cursor(std::string_view t, const std::string& src, const Limits& l) : s_(t), src_(src), lim_(l) {}

    std::string_view s_;
    const std::string& src_;
    Limits lim_;
    size_t pos_ = 0;
    uint32_t line_ = 1;
    size_t count_ = 0;
    Error err_;

    // Records "file:line: what" at the current offset; returns false so callers can
    // `return fail(...)`.
    bool fail(const std::string& what, Code code = Code::Corrupt) {
        err_ = make_error(code, src_ + ":" + std::to_string(line_) + ": " + what, pos_);
        return false;
    }
};

}  // namespace spt::text
