// Streaming writer: append frames with constant memory; finish() writes the index and the end.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "spt/coding.hpp"
#include "spt/result.hpp"
#include "spt/types.hpp"

namespace spt {

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
