// The chunk checksum (format/src/crc32.cpp): the table path and the carry-less-multiplication
// path against a bit-at-a-time CRC-32 written from the definition, on every length and
// alignment that crosses the paths' thresholds, on chained updates and on a long buffer.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "../format/src/byte_io.hpp"

namespace {

uint32_t crc_bitwise(const uint8_t* p, size_t n, uint32_t crc = 0) {
    crc = ~crc;
    for (size_t i = 0; i < n; ++i) {
        crc ^= p[i];
        for (int k = 0; k < 8; ++k) crc = (crc & 1) ? (crc >> 1) ^ 0xEDB88320u : crc >> 1;
    }
    return ~crc;
}

std::vector<uint8_t> random_bytes(size_t n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::vector<uint8_t> v(n);
    for (auto& b : v) b = uint8_t(rng());
    return v;
}

TEST(Crc32, CheckValue) {
    const uint8_t msg[] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
    EXPECT_EQ(spt::detail::crc32(msg, 9), 0xCBF43926u);
    EXPECT_EQ(spt::detail::crc32_portable(msg, 9), 0xCBF43926u);
}

TEST(Crc32, EveryLengthAndAlignmentMatchesBitwise) {
    const auto buf = random_bytes(300 + 16, 1);
    for (size_t align = 0; align < 16; ++align)
        for (size_t n = 0; n <= 300; ++n) {
            const uint8_t* p = buf.data() + align;
            const uint32_t want = crc_bitwise(p, n);
            ASSERT_EQ(spt::detail::crc32(p, n), want) << "length " << n << " alignment " << align;
            ASSERT_EQ(spt::detail::crc32_portable(p, n), want) << "length " << n << " alignment " << align;
        }
}

TEST(Crc32, ChainedUpdatesAndLongBuffers) {
    const auto buf = random_bytes((1 << 20) + 7, 2);
    const uint32_t want = crc_bitwise(buf.data(), buf.size());
    EXPECT_EQ(spt::detail::crc32(buf.data(), buf.size()), want);
    // The reader checks a chunk's type, then its payload, as one running CRC.
    for (size_t cut : {size_t(0), size_t(4), size_t(63), size_t(64), size_t(1000), buf.size() - 65}) {
        const uint32_t head = spt::detail::crc32(buf.data(), cut);
        EXPECT_EQ(spt::detail::crc32(buf.data() + cut, buf.size() - cut, head), want) << "cut at " << cut;
    }
    // All ones and all zeros stress the reductions' carries.
    for (uint8_t fill : {uint8_t(0), uint8_t(0xFF)}) {
        const std::vector<uint8_t> v(4099, fill);
        EXPECT_EQ(spt::detail::crc32(v.data(), v.size()), crc_bitwise(v.data(), v.size())) << int(fill);
    }
}

}  // namespace
