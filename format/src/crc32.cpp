// CRC-32/ISO-HDLC (reflected polynomial 0xEDB88320), as in zlib and PNG. Every chunk a reader
// decodes is checked, so this runs over every byte of a file.
//
// Portable path: eight bytes a step through eight tables ("slicing by 8": table k maps a byte
// to its CRC after k further zero bytes), about 5x faster than a byte a step.
//
// x86 with PCLMULQDQ: carry-less multiplication folds the message 64 bytes a step, about 10x
// faster again; with VPCLMULQDQ (AVX-512) 256 bytes a step. The message is the polynomial M(x) (first byte's lowest bit = highest power);
// the CRC is M(x)·x^32 mod P with the running value XORed into the first four bytes. A 16-byte
// block A at some position can be replaced by a block B D bits further on when
// B ≡ A·x^D (mod P). With A = A_hi·x^64 + A_lo (the register's low quadword holds A_hi, its
// bits in reflected order):
//     B = A_hi·(x^(64+D) mod P) + A_lo·(x^D mod P),
// each product below 2^95, so B fits 128 bits and is XORed onto the data block D bits on.
// A reflected 64 x 64 product lands one bit lower than the block layout, so the constants are
// those of D - 1 (x^(63+D) and x^(D-1) mod P), stored with x^i at bit 63 - i. Four lanes fold
// 512 bits a step; they are folded into one, and the last 16 bytes of state and the tail go
// through the table: the folded state is a message with the same CRC as what it replaced.
// The constants are computed, not copied; tests/format/crc32_test.cpp checks both paths
// against a bitwise CRC on every length and alignment up to 300 bytes and on long buffers.
#include <array>
#include <cstring>

#include "byte_io.hpp"

#if defined(__x86_64__) || defined(_M_X64)
#include <immintrin.h>
#define SPT_CRC_CLMUL 1
#endif

namespace spt::detail {
namespace {
using Tables = std::array<std::array<uint32_t, 256>, 8>;
constexpr Tables make_tables() {
    Tables t{};
    for (uint32_t n = 0; n < 256; ++n) {
        uint32_t c = n;
        for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
        t[0][n] = c;
    }
    for (size_t k = 1; k < 8; ++k)
        for (uint32_t n = 0; n < 256; ++n) t[k][n] = (t[k - 1][n] >> 8) ^ t[0][t[k - 1][n] & 0xFF];
    return t;
}
constexpr Tables kTables = make_tables();

// The raw CRC update (no inversions) of `size` bytes through the tables.
uint32_t crc_tables(const uint8_t* data, size_t size, uint32_t crc) {
    const auto& t = kTables;
    size_t i = 0;
    for (; i + 8 <= size; i += 8) {
        // Little-endian byte order is spelled out so that big-endian hosts agree.
        const uint32_t lo = crc ^ (uint32_t(data[i]) | uint32_t(data[i + 1]) << 8 | uint32_t(data[i + 2]) << 16 |
                                   uint32_t(data[i + 3]) << 24);
        crc = t[7][lo & 0xFF] ^ t[6][(lo >> 8) & 0xFF] ^ t[5][(lo >> 16) & 0xFF] ^ t[4][lo >> 24] ^
              t[3][data[i + 4]] ^ t[2][data[i + 5]] ^ t[1][data[i + 6]] ^ t[0][data[i + 7]];
    }
    for (; i < size; ++i) crc = t[0][(crc ^ data[i]) & 0xFF] ^ (crc >> 8);
    return crc;
}

#ifdef SPT_CRC_CLMUL
// x^n mod P (P = 0x104C11DB7, normal bit order) as a folding constant: x^i at bit 63 - i.
constexpr uint64_t fold_constant(unsigned n) {
    uint64_t r = 1;
    for (unsigned k = 0; k < n; ++k) {
        r <<= 1;
        if (r & (uint64_t(1) << 32)) r ^= 0x104C11DB7u;
    }
    uint64_t out = 0;
    for (unsigned i = 0; i < 32; ++i)
        if (r >> i & 1) out |= uint64_t(1) << (63 - i);
    return out;
}
// {x^(63+D), x^(D-1)} for D = 512 (four lanes) and D = 128 (one lane).
constexpr uint64_t kFold512Hi = fold_constant(63 + 512), kFold512Lo = fold_constant(512 - 1);
constexpr uint64_t kFold128Hi = fold_constant(63 + 128), kFold128Lo = fold_constant(128 - 1);

__attribute__((target("pclmul,sse2"))) inline __m128i fold(__m128i a, __m128i k, __m128i next) {
    return _mm_xor_si128(_mm_xor_si128(_mm_clmulepi64_si128(a, k, 0x00), _mm_clmulepi64_si128(a, k, 0x11)), next);
}

// The four lanes a0..a3 hold the state of the 64 bytes before data + i: folds the rest of the
// message on (64, then 16 bytes a step, then the table) and returns the raw CRC.
__attribute__((target("pclmul,sse2"))) uint32_t crc_clmul_from(__m128i a0, __m128i a1, __m128i a2, __m128i a3,
                                                              const uint8_t* data, size_t i, size_t size) {
    auto load = [](const uint8_t* p) { return _mm_loadu_si128(reinterpret_cast<const __m128i*>(p)); };
    const __m128i k512 = _mm_set_epi64x(int64_t(kFold512Lo), int64_t(kFold512Hi));
    for (; i + 64 <= size; i += 64) {
        a0 = fold(a0, k512, load(data + i));
        a1 = fold(a1, k512, load(data + i + 16));
        a2 = fold(a2, k512, load(data + i + 32));
        a3 = fold(a3, k512, load(data + i + 48));
    }
    const __m128i k128 = _mm_set_epi64x(int64_t(kFold128Lo), int64_t(kFold128Hi));
    __m128i a = fold(fold(fold(a0, k128, a1), k128, a2), k128, a3);
    for (; i + 16 <= size; i += 16) a = fold(a, k128, load(data + i));
    alignas(16) uint8_t state[16];
    _mm_store_si128(reinterpret_cast<__m128i*>(state), a);
    return crc_tables(data + i, size - i, crc_tables(state, 16, 0));
}

__attribute__((target("pclmul,sse2"))) uint32_t crc_clmul(const uint8_t* data, size_t size, uint32_t crc) {
    // size >= 64
    auto load = [](const uint8_t* p) { return _mm_loadu_si128(reinterpret_cast<const __m128i*>(p)); };
    const __m128i a0 = _mm_xor_si128(load(data), _mm_cvtsi32_si128(int(crc)));
    return crc_clmul_from(a0, load(data + 16), load(data + 32), load(data + 48), data, 64, size);
}

// GCC 12 warns that the _mm512_undefined_epi32() inside several AVX-512 intrinsics "is used
// uninitialized"; it is the intrinsics' own don't-care operand.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
// With VPCLMULQDQ: the same folding on 512-bit registers, each four 128-bit lanes (one
// register is what crc_clmul keeps in a0..a3), four registers folding 256 bytes a step; they
// are then folded into one (512 bits apart) and handed to crc_clmul_from.
constexpr uint64_t kFold2048Hi = fold_constant(63 + 2048), kFold2048Lo = fold_constant(2048 - 1);

__attribute__((target("vpclmulqdq,avx512f,pclmul,sse2"))) inline __m512i fold4(__m512i a, __m512i k, __m512i next) {
    return _mm512_xor_si512(_mm512_xor_si512(_mm512_clmulepi64_epi128(a, k, 0x00), _mm512_clmulepi64_epi128(a, k, 0x11)),
                            next);
}

__attribute__((target("vpclmulqdq,avx512f,pclmul,sse2"))) uint32_t crc_vpclmul(const uint8_t* data, size_t size,
                                                                               uint32_t crc) {
    // size >= 256
    __m512i x0 = _mm512_xor_si512(_mm512_loadu_si512(data), _mm512_zextsi128_si512(_mm_cvtsi32_si128(int(crc))));
    __m512i x1 = _mm512_loadu_si512(data + 64), x2 = _mm512_loadu_si512(data + 128), x3 = _mm512_loadu_si512(data + 192);
    size_t i = 256;
    const __m512i k2048 = _mm512_broadcast_i32x4(_mm_set_epi64x(int64_t(kFold2048Lo), int64_t(kFold2048Hi)));
    for (; i + 256 <= size; i += 256) {
        x0 = fold4(x0, k2048, _mm512_loadu_si512(data + i));
        x1 = fold4(x1, k2048, _mm512_loadu_si512(data + i + 64));
        x2 = fold4(x2, k2048, _mm512_loadu_si512(data + i + 128));
        x3 = fold4(x3, k2048, _mm512_loadu_si512(data + i + 192));
    }
    const __m512i k512 = _mm512_broadcast_i32x4(_mm_set_epi64x(int64_t(kFold512Lo), int64_t(kFold512Hi)));
    const __m512i x = fold4(fold4(fold4(x0, k512, x1), k512, x2), k512, x3);
    return crc_clmul_from(_mm512_extracti32x4_epi32(x, 0), _mm512_extracti32x4_epi32(x, 1),
                          _mm512_extracti32x4_epi32(x, 2), _mm512_extracti32x4_epi32(x, 3), data, i, size);
}
#pragma GCC diagnostic pop

bool have_clmul() {
    static const bool yes = __builtin_cpu_supports("pclmul") && __builtin_cpu_supports("sse2");
    return yes;
}
bool have_vpclmul() {
    static const bool yes = have_clmul() && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("vpclmulqdq");
    return yes;
}
#endif
}  // namespace

uint32_t crc32_portable(const uint8_t* data, size_t size, uint32_t crc) { return ~crc_tables(data, size, ~crc); }

uint32_t crc32(const uint8_t* data, size_t size, uint32_t crc) {
#ifdef SPT_CRC_CLMUL
    if (size >= 256 && have_vpclmul()) return ~crc_vpclmul(data, size, ~crc);
    if (size >= 64 && have_clmul()) return ~crc_clmul(data, size, ~crc);
#endif
    return crc32_portable(data, size, crc);
}

}  // namespace spt::detail
