// Internal: the binary adaptive range coder of SPEC.md 7.2 and the integer models built on it
// (7.3). The syntax code is written once as templates over a "coder" that either encodes the
// value it is given or decodes one and ignores it, so that encoder and decoder cannot drift.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "spt/writer.hpp"

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

class RangeDecoder {
public:
    static constexpr bool kDecoding = true;
    RangeDecoder(const uint8_t* data, size_t size, FieldStats* stats = nullptr)
        : p_(data), n_(size), stats_(stats) {
        for (int i = 0; i < 4; ++i) code_ = (code_ << 8) | next();
    }
    void set_field(Field f) { field_ = f; }
    int bit(uint16_t& p, int /*ignored*/ = 0) {
        const uint32_t bound = (range_ >> kProbBits) * p;
        int b;
        if (code_ < bound) {
            if (stats_) account(p);
            range_ = bound;
            p = uint16_t(p + ((2048u - p) >> kAdaptShift));
            b = 0;
        } else {
            if (stats_) account(2048u - p);
            code_ -= bound;
            range_ -= bound;
            p = uint16_t(p - (p >> kAdaptShift));
            b = 1;
        }
        normalize();
        return b;
    }
    int direct(int /*ignored*/ = 0) {
        if (stats_) (*stats_)[field_] += 1.0;
        const uint32_t bound = (range_ >> kProbBits) << 10;
        int b = 0;
        if (code_ >= bound) { code_ -= bound; range_ -= bound; b = 1; } else range_ = bound;
        normalize();
        return b;
    }
    // True when the decoder read every byte of the stream (bytes past its end read as 0).
    bool consumed_all() const { return pos_ >= n_; }
    bool failed() const { return false; }

private:
    void account(uint32_t p) { (*stats_)[field_] += bit_cost(p); }
    uint8_t next() { uint8_t b = pos_ < n_ ? p_[pos_] : 0; ++pos_; return b; }
    void normalize() {
        while (range_ < kTop) { range_ <<= 8; code_ = (code_ << 8) | next(); }
    }
    const uint8_t* p_;
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
uint32_t code_tree(C& c, uint16_t* probs, int nbits, uint32_t v) {
    uint32_t m = 1;
    for (int i = nbits - 1; i >= 0; --i) m = (m << 1) | uint32_t(c.bit(probs[m], int((v >> i) & 1)));
    return m - (1u << nbits);
}
template <class C>
uint32_t code_tree(C& c, BitTree& t, uint32_t v) { return code_tree(c, t.p.data(), t.nbits, v); }

// Adaptive Exp-Golomb for 0 .. 2^32-1: the bit length of u+1 in unary with adaptive
// contexts, then its bits below the leading one, equiprobable.
struct UIntModel {
    uint16_t prefix[32];
    UIntModel() { reset(); }
    void reset() { for (auto& q : prefix) q = kProbInit; }
};

template <class C>
uint64_t code_uint(C& c, UIntModel& m, uint64_t u) {
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
int64_t code_sint(C& c, SIntModel& m, int64_t v) {
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
int code_res8(C& c, Res8Model& m, int v) {
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

}  // namespace spt::detail
