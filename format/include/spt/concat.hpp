// Joining .spt files without re-coding (SPEC.md 9.6): the frames of every part are copied
// chunk by chunk (only the frame number and the CRC of each FRAM chunk change), and a new
// header, metadata, ROI list, index and end are written. Shots painted apart (on a farm) join
// into the file one process would have written.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "spt/reader.hpp"
#include "spt/result.hpp"
#include "spt/types.hpp"

namespace spt {

// SPEC.md 3.3: the source's frame number of frame 0 (`source.first_frame`); frame i is
// number first + i. Absent or malformed: 0 (files number from 0).
inline constexpr const char* kFirstFrameKey = "source.first_frame";
// SPEC.md 3.3: keys starting with "part." describe one part of a join only; a join drops them.
inline constexpr const char* kPartKeyPrefix = "part.";
uint32_t first_frame_number(const StreamInfo& info);
// True when `info` holds a well-formed `source.first_frame` entry.
bool has_first_frame_number(const StreamInfo& info);

// What the parts must share and how the rest combines (SPEC.md 9.6). `frame_counts[i]` is the
// number of frames of part i. Fails, naming `names[i]`, when part i cannot follow part 0;
// `warnings` gets one line per metadata entry the join drops.
Result<StreamInfo> join_info(const std::vector<StreamInfo>& parts, const std::vector<uint64_t>& frame_counts,
                             const std::vector<std::string>& names, std::vector<std::string>* warnings = nullptr);

struct ConcatOptions {
    // Write through an spt::AtomicFile, linked into place when complete (never half-written, no
    // temporary name); false writes straight to the output.
    bool atomic_rename = true;
    ReaderOptions reader;
    // Called for every part once its header has been read and before anything is written:
    // the caller's own refusals (a farm plan's missing or extra shots).
    std::function<Status(size_t part, const std::string& path, const StreamInfo& info, uint64_t frames)> check_part;
};

struct ConcatReport {
    uint64_t parts = 0, frames = 0, bytes = 0;
    std::vector<std::string> warnings;
};

// Joins `parts` (in order) into `output`. Refuses, naming the file, a part that is incomplete
// or damaged, does not start with a key frame, or differs from the first part in anything
// SPEC.md 9.6 says must agree. On failure nothing is left under `output`.
Result<ConcatReport> concatenate(const std::vector<std::string>& parts, const std::string& output,
                                 const ConcatOptions& opts = {});

}  // namespace spt
