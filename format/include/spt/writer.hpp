// Streaming writer: append frames with constant memory; finish() writes the index and the end.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "spt/result.hpp"
#include "spt/types.hpp"

namespace spt {

enum class Coding : uint8_t {
    Stored = 0,   // fixed-size little-endian fields, no entropy coding (SPEC.md "Stored frames")
    Range = 1,    // context-adaptive binary range coding (SPEC.md "Range-coded frames")
    // Decoder-replayed candidates (SPEC.md 7.7): frames whose Frame::replay describes how their
    // stamps were drawn code accept gaps instead of positions, colours and orientations against
    // the canvas painted so far; any other frame falls back to coding 1.
    Replay = 2,
};

struct WriterOptions {
    Coding coding = Coding::Range;
    // Write an unnamed (or exclusively created) temporary linked at <path> in finish(), so that
    // the final name never holds a half-written file and no existing path is written through
    // (spt/atomic_file.hpp). abort() discards it. false: write <path> itself.
    bool atomic_rename = true;
    // Bitmap templates: Range codes their samples (TMPL coding 1) when `coding` is Range too;
    // Stored writes raw samples. Stored-coded files always get raw templates.
    Coding template_coding = Coding::Range;
};

// Where the bits of frame bodies go, per field (for `spt info` and benches). Stored coding
// counts exact bytes; range coding counts the information cost -log2(p) of every coded
// decision of the field, which sums to the stream size within a few bytes per frame.
enum class Field : uint8_t {
    Count = 0,    // frame-level counts and sizes (stroke/removal counts, stream lengths)
    Kind,         // stroke kind
    SetTemplate,  // stamp set, template of any stroke
    Orientation,  // stamp orientation
    Position,     // stamp/affine anchor, first curve point
    Color,        // R, G, B
    Alpha,        // A
    Geometry,     // affine matrix, curve point count, further curve points, widths
    Removal,      // removed stroke indices
    Motion,       // motion field
    Candidates,   // coding 2: accepted-candidate gaps, per-set counts, candidate regions, seed
};
constexpr size_t kFieldCount = 11;
const char* field_name(Field f);

struct FieldStats {
    double bits[kFieldCount] = {};
    double& operator[](Field f) { return bits[size_t(f)]; }
    double operator[](Field f) const { return bits[size_t(f)]; }
    double bytes(Field f) const { return bits[size_t(f)] / 8.0; }
    double total_bits() const { double t = 0; for (double b : bits) t += b; return t; }
    void add(const FieldStats& o) { for (size_t i = 0; i < kFieldCount; ++i) bits[i] += o.bits[i]; }
};

// Per-section byte counts, for `spt info` and benches.
struct WriteStats {
    uint64_t total_bytes = 0;
    uint64_t header_bytes = 0;     // signature, HEAD, TMPL, meta, rois
    uint64_t frame_bytes = 0;      // FRAM chunks including framing
    uint64_t stroke_bytes = 0;     // stroke payload inside FRAM chunks
    uint64_t motion_bytes = 0;     // motion and removal payload inside FRAM chunks
    uint64_t index_bytes = 0;
    uint64_t frames = 0, key_frames = 0, strokes = 0;
    FieldStats fields;             // summed over all frame bodies
};

class Writer {
public:
    // Validates `info` (sets, orientations, templates, sizes) and writes everything before the
    // first frame.
    static Result<std::unique_ptr<Writer>> create(const std::string& path, const StreamInfo& info,
                                                  const WriterOptions& opts = {});
    virtual ~Writer();
    // Frames must be appended with index 0, 1, 2, ...; the first must be a key frame.
    virtual Status append(const Frame& frame) = 0;
    // Adds a region-of-interest record (written before the index).
    virtual Status add_roi(const Roi& roi) = 0;
    // Writes the index and the end chunk, flushes, renames into place.
    virtual Status finish() = 0;
    // Gives up: removes the partial output.
    virtual void abort() = 0;
    virtual const WriteStats& stats() const = 0;
};

}  // namespace spt
