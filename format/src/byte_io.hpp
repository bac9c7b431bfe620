// Internal: little-endian byte output, bounds-checked byte input, CRC-32 (SPEC.md sections 1-2).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "spt/result.hpp"

namespace spt::detail {

// CRC-32/ISO-HDLC (zlib, PNG). Pass the previous return value to continue a running CRC.
uint32_t crc32(const uint8_t* data, size_t size, uint32_t crc = 0);
// The same through tables only (the path of hosts without carry-less multiplication); for tests.
uint32_t crc32_portable(const uint8_t* data, size_t size, uint32_t crc = 0);

// Appends little-endian fields to a growing buffer.
class ByteSink {
public:
    std::vector<uint8_t>& bytes() { return buf_; }
    const std::vector<uint8_t>& bytes() const { return buf_; }
    size_t size() const { return buf_.size(); }
    void u8(uint8_t v) { buf_.push_back(v); }
    void u16(uint16_t v) { u8(uint8_t(v)); u8(uint8_t(v >> 8)); }
    void u32(uint32_t v) { u16(uint16_t(v)); u16(uint16_t(v >> 16)); }
    void u64(uint64_t v) { u32(uint32_t(v)); u32(uint32_t(v >> 32)); }
    void i16(int16_t v) { u16(uint16_t(v)); }
    void i32(int32_t v) { u32(uint32_t(v)); }
    void raw(const void* p, size_t n) {
        const auto* b = static_cast<const uint8_t*>(p);
        buf_.insert(buf_.end(), b, b + n);
    }
    // ULEB128, minimal length (SPEC.md 7.1).
    void varint(uint32_t v) {
        while (v >= 0x80) { u8(uint8_t(v | 0x80)); v >>= 7; }
        u8(uint8_t(v));
    }
private:
    std::vector<uint8_t> buf_;
};

inline uint16_t load_u16(const uint8_t* p) { return uint16_t(p[0] | (p[1] << 8)); }
inline uint32_t load_u32(const uint8_t* p) {
    return uint32_t(p[0]) | (uint32_t(p[1]) << 8) | (uint32_t(p[2]) << 16) | (uint32_t(p[3]) << 24);
}
inline uint64_t load_u64(const uint8_t* p) { return load_u32(p) | (uint64_t(load_u32(p + 4)) << 32); }
inline void store_u32(uint8_t* p, uint32_t v) {
    p[0] = uint8_t(v); p[1] = uint8_t(v >> 8); p[2] = uint8_t(v >> 16); p[3] = uint8_t(v >> 24);
}

// Reads little-endian fields from a byte range. Every read is bounds-checked; a failed read
// returns an error naming `what` and the absolute file offset (base + position).
class ByteCursor {
public:
    ByteCursor(const uint8_t* data, size_t size, uint64_t base, std::string what)
        : p_(data), n_(size), base_(base), what_(std::move(what)) {}
    size_t pos() const { return pos_; }
    size_t left() const { return n_ - pos_; }
    uint64_t offset() const { return base_ + pos_; }
    const uint8_t* here() const { return p_ + pos_; }
    const std::string& what() const { return what_; }

    Error error(Code c, const std::string& msg) const {
        return make_error(c, what_ + ": " + msg + " at byte offset " + std::to_string(offset()), offset());
    }
    Status need(size_t k, const char* field) const {
        if (left() < k)
            return error(Code::Truncated, std::string(field) + " needs " + std::to_string(k) +
                                              " bytes, " + std::to_string(left()) + " left");
        return {};
    }
    Status u8(uint8_t& v, const char* f) { if (auto s = need(1, f); !s) return s; v = p_[pos_++]; return {}; }
    Status u16(uint16_t& v, const char* f) { if (auto s = need(2, f); !s) return s; v = load_u16(p_ + pos_); pos_ += 2; return {}; }
    Status u32(uint32_t& v, const char* f) { if (auto s = need(4, f); !s) return s; v = load_u32(p_ + pos_); pos_ += 4; return {}; }
    Status u64(uint64_t& v, const char* f) { if (auto s = need(8, f); !s) return s; v = load_u64(p_ + pos_); pos_ += 8; return {}; }
    Status i16(int16_t& v, const char* f) { uint16_t u = 0; auto s = u16(u, f); v = int16_t(u); return s; }
    Status i32(int32_t& v, const char* f) { uint32_t u = 0; auto s = u32(u, f); v = int32_t(u); return s; }
    // Moves past k bytes the caller has checked are there (k <= left()).
    void advance(size_t k) { pos_ += k; }
    Status skip(size_t k, const char* f) { if (auto s = need(k, f); !s) return s; pos_ += k; return {}; }
    // ULEB128 of at most 5 bytes holding a u32, in its minimal form.
    Status varint(uint32_t& v, const char* f) {
        uint64_t acc = 0;
        for (int i = 0; i < 5; ++i) {
            uint8_t b;
            if (auto s = u8(b, f); !s) return s;
            acc |= uint64_t(b & 0x7F) << (7 * i);
            if (!(b & 0x80)) {
                if (acc > 0xFFFFFFFFull) return error(Code::Corrupt, std::string(f) + " exceeds 32 bits");
                if (i > 0 && b == 0) return error(Code::Corrupt, std::string(f) + " is not in minimal form");
                v = uint32_t(acc);
                return {};
            }
        }
        return error(Code::Corrupt, std::string(f) + " is longer than 5 bytes");
    }
private:
    const uint8_t* p_;
    size_t n_;
    size_t pos_ = 0;
    uint64_t base_;
    std::string what_;
};

}  // namespace spt::detail

#define SPT_TRY(expr)                         \
    do {                                      \
        if (auto _st = (expr); !_st.ok())     \
            return _st.error();               \
    } while (0)
