// The player's side of the Reader: the live stroke list of a frame, kept between calls so that
// reading frame after frame is incremental, and render_frame, with its path for key frames of
// stamps in coding 0 (rendered from their records without a Stroke list).
#include "reader_impl.hpp"
#include "stamp_frame.hpp"

namespace spt::reader {

Status ReaderImpl::ensure_renderer(const std::string& where, uint64_t off) {
    if (renderer_) return {};
    auto r = Renderer::create(info_.header, info_.templates);
    if (!r) return make_error(r.error().code, where + ": " + r.error().message, off);
    renderer_ = std::move(*r);
    return {};
}

bool ReaderImpl::render_stamp_frame(size_t pos, Canvas& canvas, unsigned threads) {
    const FrameEntry& e = frames_[pos];
    if (e.type != FrameType::Key || e.coding != Coding::Stored || !info_.header.plain_color()) return false;
    Chunk c;
    const SparePayload spare(c.payload, spare_payload_);
    // The checks of decode() and decode_stored_body(); anything unusual takes the general path,
    // which reports it.
    detail::FrameHeader fh;
    if (!read_chunk(e.offset, c, true) || !detail::is_type(c.type, "FRAM") || c.length < 8 ||
        !detail::decode_frame_header(c.payload.data(), 8, c.payload_offset(), fh) || fh.index != e.index ||
        fh.type != uint8_t(FrameType::Key) || fh.coding != uint8_t(Coding::Stored))
        return false;
    detail::StampSource stamps;
    if (!detail::stored_key_stamps(c.payload.data() + 8, c.length - 8, opts_.limits, stamps)) return false;
    if (!ensure_renderer("", 0)) return false;
    // The renderer checks every stamp (ranges, footprint) and bounds the fill work of SPEC 10.
    return detail::render_stamp_frame(*renderer_, canvas, stamps, threads, opts_.limits.max_fill_work);
}

Status ReaderImpl::render_frame(size_t pos, Canvas& canvas, unsigned threads) {
    if (pos >= frames_.size())
        return make_error(Code::InvalidArgument, "frame " + std::to_string(pos) + " does not exist (" +
                                                     std::to_string(frames_.size()) + " frames)");
    if (render_stamp_frame(pos, canvas, threads)) return {};
    auto live = strokes_at(pos);
    if (!live) return live.error();
    const FrameEntry& e = frames_[pos];
    SPT_TRY(ensure_renderer(frame_where(e.index, e.offset), e.offset));
    return renderer_->render(canvas, **live, threads);
}

Result<const std::vector<Stroke>*> ReaderImpl::strokes_at(size_t pos) {
    if (pos >= frames_.size())
        return make_error(Code::InvalidArgument, "frame " + std::to_string(pos) + " does not exist (" +
                                                     std::to_string(frames_.size()) + " frames)");
    if (live_pos_ == pos) return &live_;
    size_t start = pos;
    while (frames_[start].type != FrameType::Key) --start;  // frame 0 is always a key frame
    if (live_pos_ != SIZE_MAX && live_pos_ >= start && live_pos_ < pos) start = live_pos_ + 1;
    else live_pos_ = SIZE_MAX;
    for (size_t i = start; i <= pos; ++i) {
        // Not re-entered: frame i's base (for coding 2) is the live list of frame i - 1.
        if (auto st = decode(i, nullptr, scratch_frame_); !st) { live_pos_ = SIZE_MAX; live_.clear(); return st.error(); }
        if (auto st = apply_frame(live_, scratch_frame_, info_.header, opts_.limits, &info_.templates); !st) {
            live_pos_ = SIZE_MAX;
            live_.clear();
            const auto& e = frames_[i];
            return make_error(st.error().code, frame_where(e.index, e.offset) + ": " + st.error().message, e.offset);
        }
        live_pos_ = i;
    }
    return &live_;
}

}  // namespace spt::reader
