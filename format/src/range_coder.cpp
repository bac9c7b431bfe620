// The range encoder's byte output and termination (SPEC.md 7.2).
#include <cmath>

#include "range_coder.hpp"

namespace spt::detail {

double bit_cost(uint32_t p) {
    // Probabilities stay within 31..2017 of 2048, so a table of all 2049 values suffices.
    static const std::vector<double> table = [] {
        std::vector<double> t(2049);
        for (size_t i = 0; i < t.size(); ++i) t[i] = -std::log2(double(i ? i : 1) / 2048.0);
        return t;
    }();
    return table[p > 2048 ? 2048 : p];
}

// Moves the top byte of `low` out. A byte is held back in `cache` (with a run of 0xFF bytes
// after it) until it is known that no carry can reach it any more.
void RangeEncoder::shift_low() {
    if (uint32_t(low_) < 0xFF000000u || (low_ >> 32) != 0) {
        const uint8_t carry = uint8_t(low_ >> 32);
        uint8_t temp = cache_;
        do {
            emit(uint8_t(temp + carry));
            temp = 0xFF;
        } while (--cache_size_ != 0);
        cache_ = uint8_t(low_ >> 24);
    }
    ++cache_size_;
    low_ = (low_ & 0x00FFFFFFu) << 8;
}

void RangeEncoder::finish() {
    // Pick the value in [low, low + range) with the most trailing zero bytes; only its
    // leading bytes need to be written, because a decoder reads missing bytes as 0.
    int k = 4;
    for (int bytes = 0; bytes < 4; ++bytes) {
        const uint64_t mask = (uint64_t(1) << (32 - 8 * bytes)) - 1;
        const uint64_t v = (low_ + mask) & ~mask;
        if (v >= low_ && v - low_ < range_) {
            low_ = v;
            k = bytes;
            break;
        }
    }
    for (int i = 0; i < k + 1; ++i) shift_low();
    // Trailing zero bytes carry no information for the same reason.
    while (out_.size() > start_ && out_.back() == 0) out_.pop_back();
}

}  // namespace spt::detail
