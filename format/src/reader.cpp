// Reader (SPEC.md 9.3): opens through IEND -> indx when they are sound, otherwise scans the
// chunks and keeps every complete, CRC-valid frame. Limits are checked before allocation.
// The live list of a frame and render_frame (a player's calls) are in frame_player.cpp.
#include <algorithm>

#include "reader_impl.hpp"
#include "validate.hpp"

namespace spt {

Reader::~Reader() = default;

namespace reader {

Status ReaderImpl::read_chunk(uint64_t off, Chunk& c, bool whole) {
    uint8_t h[8];
    const uint64_t size = src_->size();
    if (off > size || size - off < 8 || !src_->read(off, 8, h))
        return make_error(Code::Truncated, "chunk header" + at(off) + " is cut off by the end of the data", off);
    c.offset = off;
    c.length = detail::load_u32(h);
    std::memcpy(c.type, h + 4, 4);
    if (!detail::valid_type(c.type))
        return make_error(Code::Corrupt, "chunk type " + detail::type_name(c.type) + at(off) + " is not four letters", off);
    if (c.length > opts_.limits.max_chunk_bytes)
        return make_error(Code::LimitExceeded, "chunk " + detail::type_name(c.type) + at(off) + " claims " +
                                                   std::to_string(c.length) + " bytes, above the chunk limit", off);
    if (uint64_t(c.length) + 4 > size - off - 8)
        return make_error(Code::Truncated, "chunk " + detail::type_name(c.type) + at(off) + " claims " +
                                               std::to_string(c.length) + " bytes; the data ends before it does", off);
    if (!whole) return {};
    c.payload.resize(size_t(c.length) + 4);
    if (!src_->read(off + 8, c.payload.size(), c.payload.data()))
        return make_error(Code::IoError, "cannot read chunk" + at(off), off);
    const uint32_t stored = detail::load_u32(c.payload.data() + c.length);
    c.payload.resize(c.length);
    if (opts_.verify_checksums) {
        uint32_t crc = detail::crc32(c.type, 4);
        crc = detail::crc32(c.payload.data(), c.payload.size(), crc);
        if (crc != stored)
            return make_error(Code::Corrupt, "chunk " + detail::type_name(c.type) + at(off) + " fails its CRC", off);
    }
    return {};
}

void ReaderImpl::read_ancillary(const Chunk& c) {
    Status st;
    if (detail::is_type(c.type, "meta")) {
        std::vector<std::pair<std::string, std::string>> kv;
        st = detail::decode_meta(c.payload.data(), c.payload.size(), c.payload_offset(), opts_.limits, kv);
        if (st) info_.metadata.insert(info_.metadata.end(), kv.begin(), kv.end());
    } else if (detail::is_type(c.type, "rois")) {
        std::vector<Roi> r;
        st = detail::decode_rois(c.payload.data(), c.payload.size(), c.payload_offset(), r);
        if (st) info_.rois.insert(info_.rois.end(), r.begin(), r.end());
    }
    if (!st) {
        warn(st.error());
        complete_damaged_ = true;
    }
}

Status ReaderImpl::read_header_chunks() {
    uint64_t off = 8;
    bool have_head = false;
    while (true) {
        Chunk c;
        if (!have_head) {
            SPT_TRY(read_chunk(off, c, true));
            if (!detail::is_type(c.type, "HEAD"))
                return make_error(Code::Corrupt, "first chunk is " + detail::type_name(c.type) + ", not HEAD" + at(off), off);
            SPT_TRY(detail::decode_head(c.payload.data(), c.length, c.payload_offset(), opts_.limits, info_.header));
            have_head = true;
            off = c.end();
            continue;
        }
        if (off == src_->size()) break;  // nothing after the header chunks: incomplete
        SPT_TRY(read_chunk(off, c, false));
        if (detail::is_type(c.type, "FRAM") || detail::is_type(c.type, "IEND")) break;
        if (auto st = read_chunk(off, c, true); !st) {
            // A damaged ancillary chunk loses only itself; its length was checked above.
            if (detail::is_critical(c.type) || st.error().code != Code::Corrupt) return st;
            warn(st.error());
            complete_damaged_ = true;
            off = c.end();
            continue;
        }
        if (detail::is_type(c.type, "TMPL")) {
            if (info_.templates.size() >= opts_.limits.max_templates)
                return make_error(Code::LimitExceeded, "more TMPL chunks than the template limit" + at(off), off);
            Template t;
            SPT_TRY(detail::decode_tmpl(c.payload.data(), c.length, c.payload_offset(), opts_.limits, t));
            info_.templates.push_back(std::move(t));
        } else if (detail::is_type(c.type, "HEAD")) {
            return make_error(Code::Corrupt, "second HEAD chunk" + at(off), off);
        } else if (detail::is_critical(c.type)) {
            return make_error(Code::Unsupported, "unknown critical chunk " + detail::type_name(c.type) + at(off), off);
        } else {
            read_ancillary(c);
        }
        off = c.end();
    }
    first_frame_offset_ = off;
    shape_ = detail::StreamShape::of(info_.header, info_.templates.size());
    return {};
}

Status ReaderImpl::add_frame(const Chunk& c, const uint8_t* first8, uint64_t body_size, const detail::BodyPeek& peek) {
    detail::FrameHeader fh;
    SPT_TRY(detail::decode_frame_header(first8, 8, c.payload_offset(), fh));
    const std::string where = frame_where(fh.index, c.offset);
    if (fh.index != frames_.size())
        return make_error(Code::Corrupt, where + ": expected frame index " + std::to_string(frames_.size()), c.offset);
    if (frames_.empty() && fh.type != 0)
        return make_error(Code::Corrupt, where + ": the first frame is not a key frame", c.offset);
    if (frames_.size() >= opts_.limits.max_frames)
        return make_error(Code::LimitExceeded, where + ": more frames than the limit", c.offset);
    detail::DecodeContext ctx;
    ctx.offset = c.payload_offset() + 8;
    ctx.where = where;
    detail::BodySplit split;
    SPT_TRY(detail::measure_frame_body(FrameType(fh.type), Coding(fh.coding), body_size, peek, ctx, split));
    FrameEntry e;
    e.index = fh.index;
    e.type = FrameType(fh.type);
    e.coding = Coding(fh.coding);
    e.offset = c.offset;
    e.chunk_bytes = c.end() - c.offset;
    e.stroke_bytes = split.stroke_bytes;
    e.motion_bytes = split.motion_bytes;
    e.added = split.added;
    e.removed = split.removed;
    frames_.push_back(e);
    return {};
}

Status ReaderImpl::try_index() {
    const uint64_t size = src_->size();
    if (size < first_frame_offset_ + 24) return make_error(Code::Truncated, "no room for an IEND chunk");
    Chunk iend;
    const uint64_t iend_off = size - 24;
    SPT_TRY(read_chunk(iend_off, iend, true));
    if (!detail::is_type(iend.type, "IEND")) return make_error(Code::Corrupt, "the last 24 bytes are not an IEND chunk", iend_off);
    uint32_t count;
    uint64_t index_off;
    SPT_TRY(detail::decode_iend(iend.payload.data(), iend.length, iend.payload_offset(), count, index_off));
    if (index_off == 0) return make_error(Code::Corrupt, "the file has no index");
    if (index_off < first_frame_offset_ || index_off >= iend_off)
        return make_error(Code::Corrupt, "IEND names an index" + at(index_off) + " outside the frame area", iend_off);
    Chunk ix;
    SPT_TRY(read_chunk(index_off, ix, true));
    if (!detail::is_type(ix.type, "indx")) return make_error(Code::Corrupt, "IEND names " + detail::type_name(ix.type) + at(index_off) + ", not indx", index_off);
    std::vector<detail::IndexEntry> entries;
    SPT_TRY(detail::decode_indx(ix.payload.data(), ix.length, ix.payload_offset(), opts_.limits, entries));
    if (entries.size() != count)
        return make_error(Code::Corrupt, "index lists " + std::to_string(entries.size()) + " frames, IEND " + std::to_string(count), index_off);
    if (!entries.empty() && entries[0].offset != first_frame_offset_)
        return make_error(Code::Corrupt, "index does not start at the first frame", index_off);
    frames_.reserve(entries.size());
    uint64_t end = first_frame_offset_;
    for (size_t i = 0; i < entries.size(); ++i) {
        Chunk c;
        const uint64_t off = entries[i].offset;
        if (off < end) return make_error(Code::Corrupt, "index entry " + std::to_string(i) + " overlaps the previous frame", off);
        SPT_TRY(read_chunk(off, c, false));
        if (!detail::is_type(c.type, "FRAM") || c.length < 8 || c.end() > index_off)
            return make_error(Code::Corrupt, "index entry " + std::to_string(i) + " does not point at a FRAM chunk", off);
        uint8_t first8[8];
        if (!src_->read(off + 8, 8, first8)) return make_error(Code::IoError, "cannot read frame" + at(off), off);
        if (first8[4] != entries[i].frame_type)
            return make_error(Code::Corrupt, "index entry " + std::to_string(i) + " has the wrong frame type", off);
        const uint64_t body_off = off + 16;
        const uint64_t body_size = c.length - 8;
        auto peek = [&](uint64_t rel, size_t n, uint8_t* dst) {
            return rel <= body_size && n <= body_size - rel && src_->read(body_off + rel, n, dst);
        };
        SPT_TRY(add_frame(c, first8, body_size, peek));
        end = c.end();
    }
    // Ancillary chunks after the last frame (rois, meta) up to the index.
    while (end < index_off) {
        Chunk c;
        SPT_TRY(read_chunk(end, c, true));
        if (detail::is_critical(c.type))
            return make_error(Code::Corrupt, "critical chunk " + detail::type_name(c.type) + at(end) + " between the frames and the index", end);
        read_ancillary(c);
        end = c.end();
    }
    if (end != index_off || ix.end() != iend_off)
        return make_error(Code::Corrupt, "chunks do not line up with the index", end);
    has_index_ = true;
    complete_ = !complete_damaged_;
    return {};
}

Status ReaderImpl::scan_frames() {
    uint64_t off = first_frame_offset_;
    const uint64_t size = src_->size();
    while (true) {
        if (off == size) {
            warn(make_error(Code::Truncated, "the data ends" + at(off) + " without an IEND chunk; the file is incomplete", off));
            return {};
        }
        Chunk c;
        if (auto st = read_chunk(off, c, true); !st) {
            Error e = st.error();
            if (!frames_.empty() || true)
                e.message += "; kept the " + std::to_string(frames_.size()) + " frames before it";
            warn(e);
            return {};
        }
        if (detail::is_type(c.type, "FRAM")) {
            if (c.length < 8) {
                warn(make_error(Code::Corrupt, frame_where(uint32_t(frames_.size()), off) + " is shorter than its header", off));
                return {};
            }
            const uint8_t* body = c.payload.data() + 8;
            const uint64_t body_size = c.length - 8;
            auto peek = [&](uint64_t rel, size_t n, uint8_t* dst) {
                if (rel > body_size || n > body_size - rel) return false;
                std::memcpy(dst, body + rel, n);
                return true;
            };
            if (auto st = add_frame(c, c.payload.data(), body_size, peek); !st) {
                if (st.error().code == Code::Unsupported) return st;
                warn(st.error());
                return {};
            }
        } else if (detail::is_type(c.type, "IEND")) {
            uint32_t count;
            uint64_t index_off;
            if (auto st = detail::decode_iend(c.payload.data(), c.length, c.payload_offset(), count, index_off); !st) {
                warn(st.error());
                return {};
            }
            if (count != frames_.size()) {
                warn(make_error(Code::Corrupt, "IEND counts " + std::to_string(count) + " frames, the file holds " +
                                                   std::to_string(frames_.size()), off));
                return {};
            }
            if (c.end() != size) {
                warn(make_error(Code::Corrupt, std::to_string(size - c.end()) + " bytes follow IEND" + at(c.end()), c.end()));
                return {};
            }
            complete_ = warnings_.empty() && !complete_damaged_;
            return {};
        } else if (detail::is_type(c.type, "HEAD") || detail::is_type(c.type, "TMPL")) {
            warn(make_error(Code::Corrupt, detail::type_name(c.type) + " chunk after the first frame" + at(off), off));
            return {};
        } else if (detail::is_critical(c.type)) {
            return make_error(Code::Unsupported, "unknown critical chunk " + detail::type_name(c.type) + at(off), off);
        } else if (!detail::is_type(c.type, "indx")) {
            read_ancillary(c);
        }
        off = c.end();
    }
}

Status ReaderImpl::open() {
    uint8_t sig[8];
    if (src_->size() < 8 || !src_->read(0, 8, sig) || std::memcmp(sig, detail::kSignature, 8) != 0)
        return make_error(Code::NotSpt, "the data does not start with the .spt signature");
    SPT_TRY(read_header_chunks());
    const auto meta_size = info_.metadata.size();
    const auto rois_size = info_.rois.size();
    if (auto st = try_index(); !st) {
        // Start over by scanning; say why unless the file simply has no index.
        if (st.error().message != "the file has no index")
            warn(make_error(st.error().code, "index not used: " + st.error().message + "; scanning the frames", st.error().offset));
        frames_.clear();
        info_.metadata.resize(meta_size);
        info_.rois.resize(rois_size);
        has_index_ = false;
        complete_ = false;
        SPT_TRY(scan_frames());
    }
    paid_.assign(frames_.size(), false);  // render_frame's per-file fill budget
    return {};
}

Status ReaderImpl::decode(size_t pos, FieldStats* stats, Frame& f) {
    if (pos >= frames_.size())
        return make_error(Code::InvalidArgument, "frame " + std::to_string(pos) + " does not exist (" +
                                                     std::to_string(frames_.size()) + " frames)");
    const FrameEntry& e = frames_[pos];
    const std::string where = frame_where(e.index, e.offset);
    Chunk c;
    const SparePayload spare(c.payload, spare_payload_);
    if (auto st = read_chunk(e.offset, c, true); !st)
        return make_error(st.error().code, where + ": " + st.error().message, st.error().offset);
    if (!detail::is_type(c.type, "FRAM") || c.length < 8)
        return make_error(Code::Corrupt, where + ": not a FRAM chunk", e.offset);
    detail::FrameHeader fh;
    SPT_TRY(detail::decode_frame_header(c.payload.data(), 8, c.payload_offset(), fh));
    if (fh.index != e.index || fh.type != uint8_t(e.type))
        return make_error(Code::Corrupt, where + ": frame header does not match the frame table", e.offset);
    detail::DecodeContext ctx;
    ctx.shape = shape_;
    ctx.limits = opts_.limits;
    // The live length is known when the previous frame is the cached state; otherwise
    // removals are range-checked later by apply_frame.
    ctx.prev_live = (live_pos_ != SIZE_MAX && live_pos_ + 1 == pos) ? live_.size() : detail::kUnknownLive;
    ctx.offset = c.payload_offset() + 8;
    ctx.where = where;
    ctx.stats = stats;
    if (fh.coding == uint8_t(Coding::Replay)) {
        // Coding 2 renders while it decodes (SPEC.md 7.7): an inter frame needs the live list
        // before it, which strokes_at() keeps.
        SPT_TRY(ensure_renderer(where, e.offset));
        ctx.header = &info_.header;
        ctx.renderer = renderer_.get();
        if (fh.type == uint8_t(FrameType::Inter)) {
            if (live_pos_ == SIZE_MAX || live_pos_ + 1 != pos) {
                auto prev = strokes_at(pos - 1);
                if (!prev) return prev.error();
            }
            ctx.base = &live_;
            ctx.prev_live = live_.size();
        }
    }
    f.index = fh.index;
    f.replay = ReplayInfo();
    SPT_TRY(detail::decode_frame_body(FrameType(fh.type), Coding(fh.coding), c.payload.data() + 8, c.length - 8, ctx, f, nullptr));
    f.index = fh.index;
    return {};
}

}  // namespace reader

Result<std::unique_ptr<Reader>> Reader::open(const std::string& path, const ReaderOptions& opts) {
    auto src = detail::FileSource::open(path);
    if (!src) return make_error(Code::IoError, path + ": cannot open for reading");
    auto r = std::make_unique<reader::ReaderImpl>(std::move(src), opts);
    if (auto st = r->open(); !st) {
        Error e = st.error();
        e.message = path + ": " + e.message;
        return e;
    }
    return std::unique_ptr<Reader>(std::move(r));
}

Result<std::unique_ptr<Reader>> Reader::open_memory(const uint8_t* data, size_t size, const ReaderOptions& opts) {
    auto r = std::make_unique<reader::ReaderImpl>(std::make_unique<detail::MemorySource>(data, size), opts);
    if (auto st = r->open(); !st) return st.error();
    return std::unique_ptr<Reader>(std::move(r));
}

}  // namespace spt
