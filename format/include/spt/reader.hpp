// Reader: header, frame count, seek to any frame (through the index, or by scanning when the
// index is missing), and the live stroke list of each frame.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "spt/coding.hpp"
#include "spt/limits.hpp"
#include "spt/render.hpp"
#include "spt/result.hpp"
#include "spt/types.hpp"

namespace spt {

struct FrameEntry {
    uint32_t index = 0;
    FrameType type = FrameType::Key;
    Coding coding = Coding::Stored;
    uint64_t offset = 0;        // of the FRAM chunk
    uint64_t chunk_bytes = 0;   // whole chunk including framing
    uint64_t stroke_bytes = 0;  // payload bytes coding added strokes
    uint64_t motion_bytes = 0;  // payload bytes coding removals and motion
    uint32_t added = 0, removed = 0;
};

struct ReaderOptions {
    Limits limits;
    bool verify_checksums = true;
};

class Reader {
public:
    static Result<std::unique_ptr<Reader>> open(const std::string& path, const ReaderOptions& opts = {});
    // Reads from memory (fuzzing, tests). The buffer is copied.
    static Result<std::unique_ptr<Reader>> open_memory(const uint8_t* data, size_t size,
                                                       const ReaderOptions& opts = {});
    virtual ~Reader();

    virtual const StreamInfo& info() const = 0;
    // Every complete frame found (from the index, or by scanning a file without one).
    virtual const std::vector<FrameEntry>& frames() const = 0;
    virtual bool has_index() const = 0;
    // True when the end chunk was found and everything before it is sound.
    virtual bool complete() const = 0;
    // Problems found while opening that did not stop it (a truncated tail, a bad index).
    virtual const std::vector<Error>& warnings() const = 0;

    // Decodes one frame's stored record (no state applied).
    virtual Result<Frame> read_frame(size_t frame_pos) = 0;
    // The same into `out`, reusing its memory: a player reading frame after frame allocates
    // nothing once its Frame has grown. On error `out` holds no complete frame.
    virtual Status read_frame(size_t frame_pos, Frame& out) = 0;
    // The live stroke list after applying frames up to `frame_pos`, decoding from the nearest
    // key frame at or before it. Sequential calls are incremental.
    virtual Result<const std::vector<Stroke>*> strokes_at(size_t frame_pos) = 0;
    // Renders frame `frame_pos` onto `canvas`: exactly Renderer::render of strokes_at(frame_pos)
    // with a Renderer of this file's header and templates (the reader keeps one), with `threads`
    // threads (0: one per hardware thread). A player's call: a key frame of stamps in coding 0
    // is rendered straight from its records, without building its stroke list; other frames go
    // through strokes_at (and move its incremental state). Errors are those strokes_at reports.
    // A frame whose live list is the one last drawn (an inter frame with no removal, motion or
    // added stroke, or the same frame again) is not rendered again when `canvas` is the canvas
    // drawn last and still holds its bytes (a checksum says so): the bytes are the same.
    virtual Status render_frame(size_t frame_pos, Canvas& canvas, unsigned threads = 1) = 0;
    // Decodes one frame and reports where its body's bits go, per field.
    virtual Result<FieldStats> field_stats(size_t frame_pos) = 0;
    // Size of the file or buffer in bytes.
    virtual uint64_t file_size() const = 0;
};

// Applies one frame to a live stroke list (the normative state update of SPEC.md), and checks
// the rendering work of the resulting list against `limits` (SPEC.md 10; stamps and affine
// strokes only when `templates` is given).
Status apply_frame(std::vector<Stroke>& live, const Frame& frame, const Header& header,
                   const Limits& limits = {}, const std::vector<Template>* templates = nullptr);

}  // namespace spt
