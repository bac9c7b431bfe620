// Internal: the Reader's implementation, shared by reader.cpp (opening a file: header chunks,
// index or scan; decoding one frame) and frame_player.cpp (the live list of a frame and
// render_frame, a player's path).
#pragma once

#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "byte_source.hpp"
#include "container.hpp"
#include "frame_coding.hpp"
#include "spt/reader.hpp"
#include "spt/render.hpp"

namespace spt::reader {

// Lends a reader's kept payload buffer to a Chunk for one decode and takes it back (with
// whatever capacity it grew to) when the decode ends.
struct SparePayload {
    SparePayload(std::vector<uint8_t>& chunk, std::vector<uint8_t>& spare) : chunk_(chunk), spare_(spare) { chunk_.swap(spare_); }
    ~SparePayload() { spare_.swap(chunk_); }
    SparePayload(const SparePayload&) = delete;
    SparePayload& operator=(const SparePayload&) = delete;

private:
    std::vector<uint8_t>& chunk_;
    std::vector<uint8_t>& spare_;
};

struct Chunk {
    uint64_t offset = 0;  // of the length field
    uint32_t length = 0;
    uint8_t type[4] = {};
    std::vector<uint8_t> payload;
    uint64_t payload_offset() const { return offset + 8; }
    uint64_t end() const { return offset + detail::kChunkOverhead + length; }
};

inline std::string at(uint64_t off) { return " at byte offset " + std::to_string(off); }

class ReaderImpl final : public Reader {
public:
    ReaderImpl(std::unique_ptr<detail::ByteSource> src, const ReaderOptions& opts) : src_(std::move(src)), opts_(opts) {}

    Status open();

    const StreamInfo& info() const override { return info_; }
    const std::vector<FrameEntry>& frames() const override { return frames_; }
    bool has_index() const override { return has_index_; }
    bool complete() const override { return complete_; }
    const std::vector<Error>& warnings() const override { return warnings_; }
    uint64_t file_size() const override { return src_->size(); }

    Result<Frame> read_frame(size_t pos) override {
        Frame f;
        SPT_TRY(decode(pos, nullptr, f));
        return f;
    }
    Status read_frame(size_t pos, Frame& out) override { return decode(pos, nullptr, out); }
    Result<const std::vector<Stroke>*> strokes_at(size_t pos) override;
    Status render_frame(size_t pos, Canvas& canvas, unsigned threads) override;
    Result<FieldStats> field_stats(size_t pos) override {
        FieldStats fs;
        Frame f;
        SPT_TRY(decode(pos, &fs, f));
        return fs;
    }

private:
    // Reads a chunk's header; with `whole`, also its payload and (if enabled) checks its CRC.
    Status read_chunk(uint64_t off, Chunk& c, bool whole);
    Status read_header_chunks();
    Status try_index();
    Status scan_frames();
    Status add_frame(const Chunk& c, const uint8_t* first8, uint64_t body_size, const detail::BodyPeek& peek);
    void read_ancillary(const Chunk& c);
    std::string frame_where(uint32_t index, uint64_t off) const {
        return "frame " + std::to_string(index) + " (FRAM chunk" + at(off) + ")";
    }
    // The reader's Renderer (coding 2 frames and render_frame), made on first use.
    Status ensure_renderer(const std::string& where, uint64_t off);
    // render_frame's fast path: true when frame `pos` is a sound key frame of stamp records in
    // coding 0 and has been rendered from them; false (nothing reported) otherwise.
    bool render_stamp_frame(size_t pos, Canvas& canvas, unsigned threads);
    // True when `canvas` is the one render_frame last drew into and still holds those bytes.
    bool canvas_intact(const Canvas& canvas) const;
    void shown(size_t pos, size_t change, const Canvas& canvas);
    // The file's fill-work budget (Limits::max_file_fill_work + max_fill_work_per_byte per byte
    // of the file), and its charge for drawing the live list of change frame `change`: each
    // distinct live list is paid for once, however often it is drawn.
    // Polygons and curves likewise, each kind against its own budget (Limits).
    enum WorkKind { kFillWork = 0, kPolygonWork = 1, kCurveWork = 2 };
    uint64_t work_budget(int kind) const;
    uint64_t fill_budget() const { return work_budget(kFillWork); }
    Status pay_fill_work(size_t change, const std::vector<Stroke>& live);
    // Decodes frame `pos` into f, reusing f's memory (and the reader's chunk buffer).
    Status decode(size_t pos, FieldStats* stats, Frame& f);
    void warn(Error e) { warnings_.push_back(std::move(e)); }

    std::unique_ptr<detail::ByteSource> src_;
    ReaderOptions opts_;
    StreamInfo info_;
    detail::StreamShape shape_;
    std::vector<FrameEntry> frames_;
    std::vector<Error> warnings_;
    bool has_index_ = false, complete_ = false;
    bool complete_damaged_ = false;  // a chunk was skipped: never report the file complete
    uint64_t first_frame_offset_ = 0;  // where the chunks after the header chunks start
    // strokes_at cache
    std::vector<Stroke> live_;
    size_t live_pos_ = SIZE_MAX;
    // The last frame at or before live_pos_ that changed the live list (its key frame, or an
    // inter frame with a removal, motion or an added stroke): frames with the same one have
    // the same live list, hence the same picture.
    size_t live_change_ = SIZE_MAX;
    // What render_frame last drew: the frame, its change frame (as live_change_), the canvas
    // and a checksum of its bytes, so that a frame whose live list is unchanged reuses the
    // picture instead of rendering it again (still stretches cost no rendering).
    size_t shown_pos_ = SIZE_MAX, shown_change_ = SIZE_MAX;
    const Canvas* shown_canvas_ = nullptr;
    uint64_t shown_sum_ = 0;
    // The fill work of the live lists drawn so far, and which change frames they were.
    uint64_t spent_[3] = {0, 0, 0};  // by WorkKind
    std::vector<bool> paid_;
    std::unique_ptr<Renderer> renderer_;  // coding 2 frames render while they decode
    // A frame chunk's payload buffer kept between decodes, so that reading frame after frame
    // does not allocate (and fault in) a fresh buffer each time. decode() borrows it (a nested
    // decode, via strokes_at for coding 2, finds it empty and allocates its own).
    std::vector<uint8_t> spare_payload_;
    Frame scratch_frame_;  // strokes_at's decoded frame, reused the same way
};

}  // namespace spt::reader
