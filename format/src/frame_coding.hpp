// Internal: frame body coders (SPEC.md 6 and 7). Also the entry points of the fuzz targets.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "spt/coding.hpp"
#include "spt/limits.hpp"
#include "spt/reader.hpp"
#include "spt/render.hpp"
#include "spt/types.hpp"
#include "validate.hpp"

namespace spt::detail {

// How a body splits into stroke bytes and edit (removal + motion) bytes.
struct BodySplit {
    uint64_t stroke_bytes = 0;
    uint64_t motion_bytes = 0;
    uint32_t added = 0, removed = 0;
    // A body of `body_bytes` bytes whose first `motion_bytes` code the removals and motion.
    static BodySplit of(uint64_t body_bytes, uint64_t motion_bytes, uint32_t added, uint32_t removed) {
        BodySplit s;
        s.stroke_bytes = body_bytes - motion_bytes;
        s.motion_bytes = motion_bytes;
        s.added = added;
        s.removed = removed;
        return s;
    }
};

struct DecodeContext {
    StreamShape shape;
    Limits limits;
    uint64_t prev_live = 0;   // live list length before an inter frame
    uint64_t offset = 0;      // file offset of the body, for messages
    std::string where = "frame";  // e.g. "frame 12 (FRAM at byte offset 3456)"
    FieldStats* stats = nullptr;
    // Coding 2 only (SPEC.md 7.7): the decoder renders while it decodes.
    const Header* header = nullptr;
    const Renderer* renderer = nullptr;
    const std::vector<Stroke>* base = nullptr;  // inter frames: the live list before the frame
};

// An error in a frame body: `msg` with where the body is, `rel` bytes into it.
Error body_error(const DecodeContext& ctx, Code code, const std::string& msg, uint64_t rel = 0);

// Encodes a validated frame's body. `stats` (optional) receives per-field accounting.
void encode_frame_body(const Frame& f, Coding coding, const StreamShape& shape,
                       std::vector<uint8_t>& out, BodySplit* split, FieldStats* stats);
// Decodes and validates a body. The frame's index and type are set by the caller.
Status decode_frame_body(FrameType type, Coding coding, const uint8_t* p, size_t n,
                         const DecodeContext& ctx, Frame& out, BodySplit* split);

// Reads `n` bytes at `rel` bytes into a body; false when they are not there.
using BodyPeek = std::function<bool(uint64_t rel, size_t n, uint8_t* dst)>;
// Splits a body into stroke and edit bytes by reading only its counts (for frame tables).
Status measure_frame_body(FrameType type, Coding coding, uint64_t body_size, const BodyPeek& peek,
                          const DecodeContext& ctx, BodySplit& split);

// Coding 0.
void encode_stored_body(const Frame& f, const StreamShape& shape, std::vector<uint8_t>& out, BodySplit* split,
                        FieldStats* stats);
// Reuses the Strokes already in out.added (a player decodes frame after frame into one
// Frame); sets *checked to the number of leading strokes it found valid (check_frame need
// not check those again).
Status decode_stored_body(FrameType type, const uint8_t* p, size_t n, const DecodeContext& ctx, Frame& out,
                          BodySplit* split, size_t* checked = nullptr);
Status measure_stored_body(FrameType type, uint64_t body_size, const BodyPeek& peek, const DecodeContext& ctx,
                           BodySplit& split);

// Coding 1.
void encode_range_body(const Frame& f, const StreamShape& shape, std::vector<uint8_t>& out, BodySplit* split,
                       FieldStats* stats);
Status decode_range_body(FrameType type, const uint8_t* p, size_t n, const DecodeContext& ctx, Frame& out,
                         BodySplit* split);
// The two range-coded streams of a coding-1 body on their own (fuzz targets, tests).
Status decode_stroke_stream(const uint8_t* p, size_t n, uint32_t count, const DecodeContext& ctx,
                            std::vector<Stroke>& out);
Status decode_edit_stream(const uint8_t* p, size_t n, uint32_t removed_count, bool motion, uint16_t block_size,
                          const DecodeContext& ctx, Frame& out);

// The counts and the edit stream that open every coding-1 and coding-2 body (SPEC.md 7.1;
// body_prefix.cpp).
class ByteCursor;
class ByteSink;
struct BodyPrefix {
    uint32_t removed = 0, added = 0;
    size_t motion_bytes = 0;  // the prefix's length for inter frames, 0 for key frames
};
// Reads the counts and the edit stream from `c`, decodes the removals and motion into `out`,
// and leaves `c` at the stroke stream.
Status decode_body_prefix(FrameType type, ByteCursor& c, const DecodeContext& ctx, Frame& out, BodyPrefix& pre);
// The encoder's side: writes f's counts and edit stream into `head`. The edit stream's bits go
// to `stats` per field, the rest as Field::Count. Returns the prefix length that counts as
// motion bytes (0 for key frames).
size_t encode_body_prefix(const Frame& f, ByteSink& head, FieldStats* stats);
// The frame table's view: the split of a coding-1 or coding-2 body from its counts alone.
Status measure_body_prefix(FrameType type, uint64_t body_size, const BodyPeek& peek, const DecodeContext& ctx,
                           BodySplit& split);

// Coding 2 (SPEC.md 7.7). What the encoder needs besides the frame.
struct ReplayEnv {
    const Header* header = nullptr;
    const Renderer* renderer = nullptr;
    StreamShape shape;
    const std::vector<Stroke>* live = nullptr;  // the live list before the frame (inter frames)
    // Format 1.5: the strokes before the first stamp may be coded as lead strokes (SPEC.md 7.7.5).
    bool allow_lead = false;
};
// Codes `f` with coding 2 when its strokes are the accepted candidates its ReplayInfo
// describes, after lead strokes of other kinds when env.allow_lead; returns false (and leaves
// `out` unchanged) when they are not, so that the caller falls back to coding 1. With
// env.allow_lead, sets drawing from one region code it once (format 1.5 files only).
// *needs_lead_version says whether the body uses a 1.5 feature (lead strokes, one region).
bool encode_replay_body(const Frame& f, const ReplayEnv& env, std::vector<uint8_t>& out, BodySplit* split,
                        FieldStats* stats, bool* needs_lead_version = nullptr);
Status decode_replay_body(FrameType type, const uint8_t* p, size_t n, const DecodeContext& ctx, Frame& out,
                          BodySplit* split);

}  // namespace spt::detail
