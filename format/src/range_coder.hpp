// Internal: the binary adaptive range coder of SPEC.md 7.2 and the integer models built on it
// (7.3). The syntax code is written once as templates over a "coder" that either encodes the
// value it is given or decodes one and ignores it, so that encoder and decoder cannot drift.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "spt/coding.hpp"
#include "spt/result.hpp"

// The model functions below are forced inline so that a decoder's state stays in registers
// across a whole stroke instead of going through memory on every bit (a store-to-load
// round trip on the critical path of each decision).
#if defined(__GNUC__) || defined(__clang__)
#define SPT_CODER_INLINE __attribute__((always_inline)) inline
#else
#define SPT_CODER_INLINE inline
#endif

namespace spt::detail {

constexpr uint16_t kProbInit = 1024;  // P(bit = 0) in units of 1/2048
constexpr int kProbBits = 11;
constexpr int kAdaptShift = 5;
constexpr uint32_t kTop = 1u << 24;

// -log2 of a probability in units of 1/2048, for field accounting only.
double bit_cost(uint32_t p_of_symbol);

class RangeEncoder {
public:
    static constexpr bool kDecoding = false;
    explicit RangeEncoder(std::vector<uint8_t>& out, FieldStats* stats = nullptr)
        : out_(out), start_(out.size()), stats_(stats) {}
    void set_field(Field f) { field_ = f; }
    // Codes bit `b` with adaptive probability `p`, then adapts `p`. Returns b.
    int bit(uint16_t& p, int b) {
        if (stats_) account(b ? 2048u - p : p);
        const uint32_t bound = (range_ >> kProbBits) * p;
        if (!b) {
            range_ = bound;
            p = uint16_t(p + ((2048u - p) >> kAdaptShift));
        } else {
            low_ += bound;
            range_ -= bound;
            p = uint16_t(p - (p >> kAdaptShift));
        }
        normalize();
        return b;
    }
    // An equiprobable bit: probability 1024, never adapted.
    int direct(int b) {
        if (stats_) (*stats_)[field_] += 1.0;
        const uint32_t bound = (range_ >> kProbBits) << 10;
        if (!b) range_ = bound; else { low_ += bound; range_ -= bound; }
        normalize();
        return b;
    }
    // Terminates the stream (SPEC.md 7.2.4): the shortest byte string that decodes correctly.
    void finish();
    bool failed() const { return false; }

private:
    void account(uint32_t p) { (*stats_)[field_] += bit_cost(p); }
    void normalize() {
        while (range_ < kTop) { range_ <<= 8; shift_low(); }
    }
    void shift_low();
    void emit(uint8_t b) {
        if (drop_first_) { drop_first_ = false; return; }  // always 0 (SPEC.md 7.2.3)
        out_.push_back(b);
    }
    std::vector<uint8_t>& out_;
    size_t start_;
    FieldStats* stats_;
    Field field_ = Field::Count;
    uint64_t low_ = 0;
    uint32_t range_ = 0xFFFFFFFFu;
    uint8_t cache_ = 0;
    uint64_t cache_size_ = 1;
    bool drop_first_ = true;
};

// The decoder of SPEC.md 7.2, written without data-dependent branches: positions and colour
// residuals are close to random bits, and a mispredicted branch per bit cost more than the
// bit's arithmetic (bench/decode_bench). The selects below compile to conditional moves.
class RangeDecoder {
public:
    static constexpr bool kDecoding = true;
    RangeDecoder(const uint8_t* data, size_t size, FieldStats* stats = nullptr)
        : p_(size ? data : kZero), last_(size ? size - 1 : 0), n_(size), stats_(stats) {
        for (int i = 0; i < 4; ++i) code_ = (code_ << 8) | next();
    }
    void set_field(Field f) { field_ = f; }
    SPT_CODER_INLINE int bit(uint16_t& p, int /*ignored*/ = 0) {
        const uint32_t pv = p;
        const uint32_t bound = (range_ >> kProbBits) * pv;
        const uint32_t keep = split(bound);  // all ones for a 0 bit
        if (stats_) account(pv ^ ((pv ^ (2048u - pv)) & ~keep));
        // 0: p + ((2048 - p) >> 5); 1: p - (p >> 5); both are p - floor((p - t) / 32) with
        // t = 2017 or 0 (arithmetic shift).
        p = uint16_t(int32_t(pv) - ((int32_t(pv) - int32_t(2017u & keep)) >> kAdaptShift));
        normalize();
        return int(keep + 1);
    }
    SPT_CODER_INLINE int direct(int /*ignored*/ = 0) {
        if (stats_) (*stats_)[field_] += 1.0;
        const uint32_t keep = split((range_ >> kProbBits) << 10);
        normalize();
        return int(keep + 1);
    }
    // True when the decoder read every byte of the stream (bytes past its end read as 0).
    bool consumed_all() const { return pos_ >= n_; }
    bool failed() const { return false; }

private:
    static constexpr uint8_t kZero[1] = {0};
    // Narrows to [0, bound) (returns all ones: bit 0) or [bound, range) (returns 0: bit 1) with
    // arithmetic on a mask instead of a branch.
    SPT_CODER_INLINE uint32_t split(uint32_t bound) {
        const uint32_t keep = uint32_t(uint64_t(int64_t(code_) - int64_t(bound)) >> 32);  // code < bound
        const uint32_t hi = range_ - bound;
        code_ -= bound & ~keep;
        range_ = hi ^ ((hi ^ bound) & keep);
        return keep;
    }
    void account(uint32_t p) { (*stats_)[field_] += bit_cost(p); }
    uint8_t next() { uint8_t b = pos_ < n_ ? p_[pos_] : 0; ++pos_; return b; }
    // One bit leaves range >= 2^13 * 31 (p stays in 31..2017), so one byte always restores
    // range >= 2^24. Past the end the byte is 0: read the last byte and mask it.
    SPT_CODER_INLINE void normalize() {
        if (range_ < kTop) {
            const uint32_t in = pos_ < n_ ? 0xFFu : 0u;
            const uint32_t byte = p_[pos_ < n_ ? pos_ : last_] & in;
            range_ <<= 8;
            code_ = (code_ << 8) | byte;
            ++pos_;
        }
    }
    const uint8_t* p_;
    size_t last_;
    size_t n_;
    size_t pos_ = 0;
    FieldStats* stats_;
    Field field_ = Field::Count;
    uint32_t range_ = 0xFFFFFFFFu;
    uint32_t code_ = 0;
};

// ---- models (SPEC.md 7.3) ----

inline int bit_length(uint64_t v) { int n = 0; while (v) { ++n; v >>= 1; } return n; }

// A bit-tree over `nbits` bits: 2^nbits probabilities, node 1 is the root.
struct BitTree {
    std::vector<uint16_t> p;
    int nbits = 0;
    void reset(int bits) { nbits = bits; p.assign(size_t(1) << bits, kProbInit); }
};

template <class C>
SPT_CODER_INLINE uint32_t code_tree(C& c, uint16_t* probs, int nbits, uint32_t v) {
    uint32_t m = 1;
    for (int i = nbits - 1; i >= 0; --i) m = (m << 1) | uint32_t(c.bit(probs[m], int((v >> i) & 1)));
    return m - (1u << nbits);
}
template <class C>
SPT_CODER_INLINE uint32_t code_tree(C& c, BitTree& t, uint32_t v) { return code_tree(c, t.p.data(), t.nbits, v); }

// Adaptive Exp-Golomb for 0 .. 2^32-1: the bit length of u+1 in unary with adaptive
// contexts, then its bits below the leading one, equiprobable.
struct UIntModel {
    uint16_t prefix[32];
    UIntModel() { reset(); }
    void reset() { for (auto& q : prefix) q = kProbInit; }
};

template <class C>
SPT_CODER_INLINE uint64_t code_uint(C& c, UIntModel& m, uint64_t u) {
    const uint64_t v = u + 1;
    const int k = bit_length(v) - 1;
    int kk = 0;
    while (kk < 32 && c.bit(m.prefix[kk], kk < k ? 1 : 0)) ++kk;
    uint64_t r = 1;
    for (int i = kk - 1; i >= 0; --i) r = (r << 1) | uint64_t(c.direct(int((v >> i) & 1)));
    return r - 1;
}

// Signed integers: a zero flag, a sign, the magnitude minus one as UInt.
struct SIntModel {
    uint16_t zero = kProbInit, sign = kProbInit;
    UIntModel mag;
};

template <class C>
SPT_CODER_INLINE int64_t code_sint(C& c, SIntModel& m, int64_t v) {
    if (!c.bit(m.zero, v != 0 ? 1 : 0)) return 0;
    const int neg = c.bit(m.sign, v < 0 ? 1 : 0);
    const uint64_t a = v < 0 ? uint64_t(-v) : uint64_t(v);
    const int64_t mag = int64_t(code_uint(c, m.mag, a - 1)) + 1;
    return neg ? -mag : mag;
}

// Residuals of 8-bit samples, -128..127: zero flag, sign, class k = floor(log2 |v|) as a
// 3-bit tree, then the k bits below the leading one, equiprobable.
struct Res8Model {
    uint16_t zero = kProbInit, sign = kProbInit;
    uint16_t cls[8];
    Res8Model() { for (auto& q : cls) q = kProbInit; }
};

template <class C>
SPT_CODER_INLINE int code_res8(C& c, Res8Model& m, int v) {
    if (!c.bit(m.zero, v != 0 ? 1 : 0)) return 0;
    const int neg = c.bit(m.sign, v < 0 ? 1 : 0);
    const uint32_t a = uint32_t(v < 0 ? -v : v);
    const int k = int(code_tree(c, m.cls, 3, uint32_t(bit_length(a) - 1)));
    uint32_t r = 1;
    for (int i = k - 1; i >= 0; --i) r = (r << 1) | uint32_t(c.direct(int((a >> i) & 1)));
    return neg ? -int(r) : int(r);
}

// Wraps an 8-bit difference into -128..127.
inline int wrap8(int d) { return ((d + 128) & 255) - 128; }

// A coded value that the decoder found invalid: its message (the caller adds where).
struct SyntaxError {
    bool bad = false;
    std::string msg;
    Code code = Code::Corrupt;  // LimitExceeded where a valid value passes the decoder's limits
    void set(std::string m) { if (!bad) { bad = true; msg = std::move(m); } }
};

}  // namespace spt::detail
