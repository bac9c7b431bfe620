// Chunk-level rewriting of a written .spt (SPEC.md 2), for the golden variants the Writer does
// not produce: a file without its index, a file with an unknown ancillary chunk.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace spt::testing::golden {

struct RawChunk { std::string type; std::vector<uint8_t> payload; };

// The chunks after the signature, in file order.
std::vector<RawChunk> split_chunks(const std::vector<uint8_t>& b);
// Reassembles chunks, recomputing indx and IEND (or dropping the index).
std::vector<uint8_t> assemble(const std::vector<RawChunk>& chunks, bool with_index);

}  // namespace spt::testing::golden
