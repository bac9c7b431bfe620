#include "format/golden_chunks.hpp"

#include "format/golden_canonical.hpp"

namespace spt::testing::golden {
namespace {

uint32_t crc32(const uint8_t* p, size_t n, uint32_t crc) {
    crc = ~crc;
    for (size_t i = 0; i < n; ++i) {
        crc ^= p[i];
        for (int k = 0; k < 8; ++k) crc = (crc & 1) ? 0xEDB88320u ^ (crc >> 1) : crc >> 1;
    }
    return ~crc;
}

void put_chunk(std::vector<uint8_t>& out, const std::string& type, const std::vector<uint8_t>& payload) {
    put32(out, uint32_t(payload.size()));
    out.insert(out.end(), type.begin(), type.end());
    out.insert(out.end(), payload.begin(), payload.end());
    uint32_t crc = crc32(reinterpret_cast<const uint8_t*>(type.data()), 4, 0);
    crc = crc32(payload.data(), payload.size(), crc);
    put32(out, crc);
}

}  // namespace

std::vector<RawChunk> split_chunks(const std::vector<uint8_t>& b) {
    std::vector<RawChunk> out;
    size_t p = 8;
    while (p + 12 <= b.size()) {
        const uint32_t n = uint32_t(b[p]) | uint32_t(b[p + 1]) << 8 | uint32_t(b[p + 2]) << 16 | uint32_t(b[p + 3]) << 24;
        out.push_back({std::string(reinterpret_cast<const char*>(&b[p + 4]), 4), {b.begin() + p + 8, b.begin() + p + 8 + n}});
        p += 12 + n;
    }
    return out;
}

std::vector<uint8_t> assemble(const std::vector<RawChunk>& chunks, bool with_index) {
    static const uint8_t sig[8] = {0x89, 'S', 'P', 'T', 0x0D, 0x0A, 0x1A, 0x0A};
    std::vector<uint8_t> out(sig, sig + 8);
    std::vector<uint8_t> index;
    uint32_t frames = 0;
    for (const auto& c : chunks) {
        if (c.type == "indx" || c.type == "IEND") continue;
        if (c.type == "FRAM") {
            put32(index, uint32_t(c.payload[0]) | uint32_t(c.payload[1]) << 8 | uint32_t(c.payload[2]) << 16 | uint32_t(c.payload[3]) << 24);
            index.push_back(c.payload[4]); index.push_back(0); index.push_back(0); index.push_back(0);
            const uint64_t off = out.size();
            put32(index, uint32_t(off)); put32(index, uint32_t(off >> 32));
            ++frames;
        }
        put_chunk(out, c.type, c.payload);
    }
    uint64_t index_offset = 0;
    if (with_index) {
        std::vector<uint8_t> p;
        put32(p, frames);
        p.insert(p.end(), index.begin(), index.end());
        index_offset = out.size();
        put_chunk(out, "indx", p);
    }
    std::vector<uint8_t> iend;
    put32(iend, frames); put32(iend, uint32_t(index_offset)); put32(iend, uint32_t(index_offset >> 32));
    put_chunk(out, "IEND", iend);
    return out;
}

}  // namespace spt::testing::golden
