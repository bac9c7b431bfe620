// The player's side of the Reader: the live stroke list of a frame, kept between calls so that
// reading frame after frame is incremental, and render_frame, with its path for key frames of
// stamps in coding 0 (rendered from their records without a Stroke list).
#include <algorithm>
#include <cstring>

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
    // The renderer checks every stamp (ranges, footprint) and bounds the fill work of SPEC 10,
    // per frame and what is left of the file's budget (over it, the general path reports it).
    const uint64_t limit = std::min(opts_.limits.max_fill_work, fill_budget() - std::min(fill_budget(), spent_[kFillWork]));
    uint64_t work = 0;
    if (!detail::render_stamp_frame(*renderer_, canvas, stamps, threads, limit, &work)) return false;
    spent_[kFillWork] += work;  // the stamps' boxes unclipped: at least the work of SPEC 10
    paid_[pos] = true;
    return true;
}

uint64_t ReaderImpl::work_budget(int kind) const {
    // base + per_byte x size, saturating (both are caller-set).
    const Limits& l = opts_.limits;
    const uint64_t base = kind == kFillWork ? l.max_file_fill_work : kind == kPolygonWork ? l.max_file_polygon_work : l.max_file_curve_work;
    const uint64_t rate = kind == kFillWork      ? l.max_fill_work_per_byte
                          : kind == kPolygonWork ? l.max_polygon_work_per_byte
                                                 : l.max_curve_work_per_byte;
    const uint64_t size = file_size();
    if (rate && size > (UINT64_MAX - base) / rate) return UINT64_MAX;
    return base + rate * size;
}

Status ReaderImpl::pay_fill_work(size_t change, const std::vector<Stroke>& live) {
    if (paid_[change]) return {};  // this live list was paid for when first drawn
    // Each sum stays below 2^64: at most 2^24 strokes, each kind's work bounded per stroke.
    uint64_t work[3] = {0, 0, 0};
    for (const Stroke& s : live) {
        if (s.kind == StrokeKind::Polygon) work[kPolygonWork] += polygon_render_work(s.polygon, info_.header.height);
        else if (s.kind == StrokeKind::Curve) work[kCurveWork] += curve_render_work(s.curve, info_.header.width, info_.header.height);
        else work[kFillWork] += fill_render_work(s, info_.header, info_.templates);
    }
    static const char* const what[3] = {"stamps and affine strokes", "polygons", "curves"};
    static const char* const unit[3] = {"box pixels x samples", "edges x rows x samples", "segment box pixels"};
    for (int k = 0; k < 3; ++k) {
        const uint64_t budget = work_budget(k);
        if (work[k] <= budget && spent_[k] <= budget - work[k]) continue;
        const FrameEntry& e = frames_[change];
        return make_error(Code::LimitExceeded,
                          frame_where(e.index, e.offset) + ": rendering it would take the file's " + what[k] + " past " +
                              std::to_string(budget) + " units of rendering work (" + unit[k] + "; " +
                              std::to_string(spent_[k]) + " spent on the frames drawn before, " + std::to_string(work[k]) +
                              " for this one), the limit for a file of " + std::to_string(file_size()) + " bytes",
                          e.offset);
    }
    for (int k = 0; k < 3; ++k) spent_[k] += work[k];
    paid_[change] = true;
    return {};
}

namespace {

// A checksum of a canvas's bytes (64-bit multiply-xor over 8-byte words): tells whether the
// caller changed the canvas since render_frame drew it. Cheap beside a render (one pass).
uint64_t canvas_sum(const Canvas& c) {
    uint64_t h = 0x9E3779B97F4A7C15ull ^ (uint64_t(c.width) << 32 | c.height);
    auto mix = [&h](const void* data, size_t n) {
        const auto* p = static_cast<const uint8_t*>(data);
        size_t i = 0;
        for (; i + 8 <= n; i += 8) {
            uint64_t w;
            std::memcpy(&w, p + i, 8);
            h = (h ^ w) * 0xFF51AFD7ED558CCDull;
            h ^= h >> 32;
        }
        uint64_t w = n;
        for (; i < n; ++i) w = w << 8 | p[i];
        h = (h ^ w) * 0xC4CEB9FE1A85EC53ull;
        h ^= h >> 29;
    };
    mix(c.rgb.data(), c.rgb.size());
    mix(c.rgb16.data(), c.rgb16.size() * 2);
    mix(c.alpha.data(), c.alpha.size());
    return h;
}

}  // namespace

bool ReaderImpl::canvas_intact(const Canvas& canvas) const {
    return shown_canvas_ == &canvas && shown_sum_ == canvas_sum(canvas);
}

void ReaderImpl::shown(size_t pos, size_t change, const Canvas& canvas) {
    shown_pos_ = pos;
    shown_change_ = change;
    shown_canvas_ = &canvas;
    shown_sum_ = canvas_sum(canvas);
}

Status ReaderImpl::render_frame(size_t pos, Canvas& canvas, unsigned threads) {
    if (pos >= frames_.size())
        return make_error(Code::InvalidArgument, "frame " + std::to_string(pos) + " does not exist (" +
                                                     std::to_string(frames_.size()) + " frames)");
    // The same frame again, or a key frame whose still frames were drawn last: the canvas holds
    // its picture already.
    const bool key = frames_[pos].type == FrameType::Key;
    const bool intact = canvas_intact(canvas);
    if ((pos == shown_pos_ || (key && shown_change_ == pos)) && intact) {
        shown_pos_ = pos;
        return {};
    }
    // From here the canvas holds no known frame until a render ends (the record path draws
    // nothing when it declines, and strokes_at does not touch the canvas).
    shown_canvas_ = nullptr;
    if (render_stamp_frame(pos, canvas, threads)) {
        shown(pos, pos, canvas);  // a key frame is its own change frame
        return {};
    }
    auto live = strokes_at(pos);
    if (!live) return live.error();
    // A frame that left the live list as it was (an empty inter frame, or none since the frame
    // drawn last) has the picture that is on the canvas: rendering it again gives the same bytes.
    if (live_change_ == shown_change_ && shown_change_ != SIZE_MAX && intact) {
        shown_pos_ = pos;
        shown_canvas_ = &canvas;
        return {};
    }
    const FrameEntry& e = frames_[pos];
    SPT_TRY(ensure_renderer(frame_where(e.index, e.offset), e.offset));
    SPT_TRY(pay_fill_work(live_change_, **live));
    SPT_TRY(renderer_->render(canvas, **live, threads));
    shown(pos, live_change_, canvas);
    return {};
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
        if (auto st = decode(i, nullptr, scratch_frame_); !st) {
            live_pos_ = live_change_ = SIZE_MAX;
            live_.clear();
            return st.error();
        }
        if (auto st = apply_frame(live_, scratch_frame_, info_.header, opts_.limits, &info_.templates); !st) {
            live_pos_ = live_change_ = SIZE_MAX;
            live_.clear();
            const auto& e = frames_[i];
            return make_error(st.error().code, frame_where(e.index, e.offset) + ": " + st.error().message, e.offset);
        }
        const Frame& f = scratch_frame_;
        if (f.type == FrameType::Key || !f.removed.empty() || !f.motion.empty() || !f.added.empty()) live_change_ = i;
        live_pos_ = i;
    }
    return &live_;
}

}  // namespace spt::reader
