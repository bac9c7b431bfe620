// Internal: chunk framing and the non-frame chunks of SPEC.md sections 2-3.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "byte_io.hpp"
#include "spt/limits.hpp"
#include "spt/types.hpp"
#include "spt/coding.hpp"

namespace spt::detail {

inline constexpr uint8_t kSignature[8] = {0x89, 'S', 'P', 'T', 0x0D, 0x0A, 0x1A, 0x0A};
constexpr size_t kChunkOverhead = 12;   // length, type, crc
constexpr size_t kFrameHeaderBytes = 8; // FRAM: frame_index, frame_type, coding, reserved
constexpr size_t kIendPayload = 12;
constexpr size_t kIndexEntryBytes = 16;
constexpr uint32_t kHeadFlagAlpha = 1;  // HEAD flags bit 0: the canvas has alpha (format 1.3)
constexpr uint32_t kHeadFlagCurveGrid = 2;  // HEAD flags bit 1: curves carry a grid (format 1.4)

inline bool is_type(const uint8_t* t, const char* s) {
    return t[0] == uint8_t(s[0]) && t[1] == uint8_t(s[1]) && t[2] == uint8_t(s[2]) && t[3] == uint8_t(s[3]);
}
// SPEC.md 2: letters only (a space allowed after the first); first letter's case = criticality.
bool valid_type(const uint8_t* t);
inline bool is_critical(const uint8_t* t) { return t[0] >= 'A' && t[0] <= 'Z'; }
std::string type_name(const uint8_t* t);

// Appends length, type, payload and CRC.
void put_chunk(ByteSink& out, const char* type, const uint8_t* payload, size_t n);
inline void put_chunk(ByteSink& out, const char* type, const std::vector<uint8_t>& p) {
    put_chunk(out, type, p.data(), p.size());
}

std::vector<uint8_t> encode_head(const Header& h);
// `off` is the payload's file offset, for messages.
Status decode_head(const uint8_t* p, size_t n, uint64_t off, const Limits& lim, Header& out);

Result<std::vector<uint8_t>> encode_tmpl(const Template& t, Coding coding);
Status decode_tmpl(const uint8_t* p, size_t n, uint64_t off, const Limits& lim, Template& out);
// TMPL coding 1 sample stream (SPEC.md 7.6).
void encode_template_samples(const Template& t, std::vector<uint8_t>& out);
Status decode_template_samples(const uint8_t* p, size_t n, uint64_t off, Template& t);

std::vector<uint8_t> encode_meta(const std::vector<std::pair<std::string, std::string>>& kv);
Status decode_meta(const uint8_t* p, size_t n, uint64_t off, const Limits& lim,
                   std::vector<std::pair<std::string, std::string>>& out);

std::vector<uint8_t> encode_rois(const std::vector<Roi>& rois);
Status decode_rois(const uint8_t* p, size_t n, uint64_t off, std::vector<Roi>& out);

struct IndexEntry {
    uint32_t frame_index = 0;
    uint8_t frame_type = 0;
    uint64_t offset = 0;
};
std::vector<uint8_t> encode_indx(const std::vector<IndexEntry>& e);
Status decode_indx(const uint8_t* p, size_t n, uint64_t off, const Limits& lim, std::vector<IndexEntry>& out);

std::vector<uint8_t> encode_iend(uint32_t frame_count, uint64_t index_offset);
Status decode_iend(const uint8_t* p, size_t n, uint64_t off, uint32_t& frame_count, uint64_t& index_offset);

// The first 8 bytes of a FRAM payload.
struct FrameHeader {
    uint32_t index = 0;
    uint8_t type = 0;
    uint8_t coding = 0;
};
void encode_frame_header(ByteSink& out, const FrameHeader& fh);
Status decode_frame_header(const uint8_t* p, size_t n, uint64_t off, FrameHeader& out);

}  // namespace spt::detail
