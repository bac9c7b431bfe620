// Streaming writer (SPEC.md 9.1): constant memory; keeps only the index entries and the live
// list length. Writes an AtomicFile (spt/atomic_file.hpp) linked into place in finish().
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "container.hpp"
#include "spt/atomic_file.hpp"
#include "frame_coding.hpp"
#include "spt/reader.hpp"
#include "spt/render.hpp"
#include "spt/utf8.hpp"
#include "spt/writer.hpp"
#include "validate.hpp"

namespace spt {

Writer::~Writer() = default;

namespace {

// SPEC.md 3.2-3.3: metadata keys and values and template names are UTF-8; a file never gets
// text that its readers (or a JSON export) cannot carry.
Status check_text(const StreamInfo& info, const std::string& path) {
    size_t at = 0;
    for (const auto& [k, v] : info.metadata) {
        if (!is_valid_utf8(k, &at))
            return make_error(Code::InvalidArgument, path + ": metadata key \"" + printable_text(k) +
                                                         "\" is not valid UTF-8 (byte " + std::to_string(at) + ")");
        if (!is_valid_utf8(v, &at))
            return make_error(Code::InvalidArgument, path + ": metadata key \"" + k + "\": the value is not valid UTF-8 (byte " +
                                                         std::to_string(at) + ")");
    }
    for (size_t i = 0; i < info.templates.size(); ++i)
        if (!is_valid_utf8(info.templates[i].name, &at))
            return make_error(Code::InvalidArgument, path + ": template " + std::to_string(i) + ": the name \"" +
                                                         printable_text(info.templates[i].name) + "\" is not valid UTF-8");
    return {};
}

using detail::ByteSink;

class FileWriter final : public Writer {
public:
    FileWriter(std::string path, const StreamInfo& info, const WriterOptions& opts)
        : path_(std::move(path)), out_path_(path_), header_(info.header),
          shape_(detail::StreamShape::of(info.header, info.templates.size())), opts_(opts) {
        // Frame coding 2 is format 1.1 (SPEC.md 7.7).
        if (opts_.coding == Coding::Replay && header_.version_minor < 1) header_.version_minor = 1;
    }
    ~FileWriter() override { if (!finished_) abort(); }

    Status open_and_write_start(const StreamInfo& info) {
        if (opts_.coding == Coding::Replay) {
            auto r = Renderer::create(info.header, info.templates);
            if (!r) return r.error();
            renderer_ = std::move(*r);
        }
        if (opts_.atomic_rename) {
            auto a = AtomicFile::create(path_);
            if (!a) return a.error();
            atomic_ = std::move(*a);
            file_ = atomic_.stream();
        } else {
            file_ = std::fopen(out_path_.c_str(), "wb");
            if (!file_) return make_error(Code::IoError, out_path_ + ": cannot create: " + std::strerror(errno));
        }
        ByteSink s;
        for (uint8_t b : detail::kSignature) s.u8(b);
        Header h = header_;
        h.frame_count = kUnknownFrameCount;  // patched in finish()
        detail::put_chunk(s, "HEAD", detail::encode_head(h));
        const Coding tc = opts_.coding != Coding::Stored ? opts_.template_coding : Coding::Stored;
        for (const auto& t : info.templates) {
            auto payload = detail::encode_tmpl(t, tc);
            if (!payload) return payload.error();
            detail::put_chunk(s, "TMPL", *payload);
        }
        if (!info.metadata.empty()) detail::put_chunk(s, "meta", detail::encode_meta(info.metadata));
        for (const auto& r : info.rois) rois_.push_back(r);
        stats_.header_bytes = s.size();
        return write(s.bytes());
    }

    Status append(const Frame& frame) override {
        if (auto st = usable(); !st) return st;
        const std::string where = "frame " + std::to_string(frame.index);
        if (frame.index != next_index_)
            return make_error(Code::InvalidArgument, where + ": expected frame index " + std::to_string(next_index_));
        if (next_index_ == 0 && frame.type != FrameType::Key)
            return make_error(Code::InvalidArgument, where + ": the first frame must be a key frame");
        if (next_index_ == 0xFFFFFFFEu) return make_error(Code::InvalidArgument, where + ": too many frames");
        Limits lim;
        lim.max_curve_points = 0xFFFFFFFFu;  // writers follow the format, not a reader's limits
        lim.max_polygon_vertices = 0xFFFFFFFFu;
        lim.max_polygon_work = lim.max_curve_work = ~uint64_t(0);
        lim.max_strokes_per_frame = lim.max_live_strokes = 0xFFFFFFFFu;
        if (auto st = detail::check_frame(frame, shape_, lim, live_, Code::InvalidArgument, where, pos_); !st) return st;
        if (auto st = polygon_version(frame, where); !st) return st;
        ByteSink chunk_payload;
        detail::BodySplit split;
        // Coding 2 when the frame's strokes replay from its generator, else coding 1 (SPEC.md 7.7).
        Coding coding = opts_.coding == Coding::Replay ? Coding::Range : opts_.coding;
        std::vector<uint8_t> body;
        FieldStats fields;
        detail::encode_frame_body(frame, coding, shape_, body, &split, &fields);
        if (opts_.coding == Coding::Replay && frame.replay.present) {
            detail::ReplayEnv env{&header_, renderer_.get(), shape_, &live_strokes_};
            // Lead strokes and one region for all sets need 1.5; raising the version in place
            // keeps earlier frames' values unless a coding-1 frame of a pre-1.2 file held a curve
            // (as for polygons).
            env.allow_lead = header_.version_minor >= detail::kPolygonMinorVersion || !range_curves_;
            bool needs_1_5 = false;
            std::vector<uint8_t> replayed;
            detail::BodySplit replayed_split;
            FieldStats replayed_fields;
            // Coding 2 where it is smaller: a frame of a few stamps codes them in fewer bytes
            // than its seed and candidate regions take.
            if (detail::encode_replay_body(frame, env, replayed, &replayed_split, &replayed_fields, &needs_1_5) &&
                replayed.size() < body.size()) {
                coding = Coding::Replay;
                body = std::move(replayed);
                split = replayed_split;
                fields = replayed_fields;
                if (needs_1_5 && header_.version_minor < kLeadMinorVersion)
                    if (auto st = raise_version(kLeadMinorVersion); !st) return st;
            }
        }
        stats_.fields.add(fields);
        detail::encode_frame_header(chunk_payload, {frame.index, uint8_t(frame.type), uint8_t(coding)});
        chunk_payload.raw(body.data(), body.size());
        if (chunk_payload.size() > 0xFFFFFFFFull)
            return fail(make_error(Code::InvalidArgument, where + ": frame body exceeds 4 GiB"));
        ByteSink chunk;
        detail::put_chunk(chunk, "FRAM", chunk_payload.bytes());
        const uint64_t offset = pos_;
        if (auto st = write(chunk.bytes()); !st) return st;
        index_.push_back({frame.index, uint8_t(frame.type), offset});
        ++next_index_;
        live_ = frame.type == FrameType::Key ? frame.added.size() : live_ - frame.removed.size() + frame.added.size();
        if (opts_.coding == Coding::Replay) {
            // Coding 2 predicts from the canvas, so this writer keeps the live list.
            Limits unlimited;
            unlimited.max_live_strokes = 0xFFFFFFFFu;
            unlimited.max_polygon_work = unlimited.max_curve_work = ~uint64_t(0);
            if (auto st = apply_frame(live_strokes_, frame, header_, unlimited); !st) return fail(st.error());
        }
        stats_.frame_bytes += chunk.size();
        stats_.stroke_bytes += split.stroke_bytes;
        stats_.motion_bytes += split.motion_bytes;
        ++stats_.frames;
        if (frame.type == FrameType::Key) ++stats_.key_frames;
        stats_.strokes += frame.added.size();
        if (coding == Coding::Range)
            for (const Stroke& s : frame.added) range_curves_ = range_curves_ || s.kind == StrokeKind::Curve;
        return {};
    }

    Status add_roi(const Roi& roi) override {
        if (auto st = usable(); !st) return st;
        if (roi.last_frame < roi.first_frame) return make_error(Code::InvalidArgument, "roi: last_frame before first_frame");
        rois_.push_back(roi);
        return {};
    }

    Status finish() override {
        if (auto st = usable(); !st) return st;
        if (next_index_ == 0) return make_error(Code::InvalidArgument, path_ + ": a file needs at least one frame");
        ByteSink s;
        if (!rois_.empty()) detail::put_chunk(s, "rois", detail::encode_rois(rois_));
        stats_.header_bytes += s.size();
        const uint64_t index_offset = pos_ + s.size();
        const size_t before = s.size();
        detail::put_chunk(s, "indx", detail::encode_indx(index_));
        stats_.index_bytes = s.size() - before;
        detail::put_chunk(s, "IEND", detail::encode_iend(next_index_, index_offset));
        if (auto st = write(s.bytes()); !st) return st;
        // The frame count is known now: patch HEAD (same length) so readers see it up front.
        Header h = header_;
        h.frame_count = next_index_;
        ByteSink head;
        detail::put_chunk(head, "HEAD", detail::encode_head(h));
        if (std::fseek(file_, 8, SEEK_SET) != 0 || std::fwrite(head.bytes().data(), 1, head.size(), file_) != head.size())
            return fail(make_error(Code::IoError, out_path_ + ": cannot update HEAD: " + std::strerror(errno)));
        if (opts_.atomic_rename) {
            file_ = nullptr;
            if (auto st = atomic_.commit(); !st) return fail(st.error());
        } else {
            if (std::fflush(file_) != 0)
                return fail(make_error(Code::IoError, out_path_ + ": cannot flush: " + std::strerror(errno)));
            const int rc = std::fclose(file_);
            file_ = nullptr;
            if (rc != 0) return fail(make_error(Code::IoError, out_path_ + ": cannot close: " + std::strerror(errno)));
        }
        stats_.total_bytes = pos_;
        finished_ = true;
        return {};
    }

    void abort() override {
        if (opts_.atomic_rename) {
            file_ = nullptr;
            atomic_.discard();
        } else {
            if (file_) { std::fclose(file_); file_ = nullptr; }
            if (!finished_ && !removed_) { std::remove(out_path_.c_str()); removed_ = true; }
        }
        failed_ = true;
    }

    const WriteStats& stats() const override { return stats_; }

private:
    // Polygon strokes are format 1.2 (SPEC.md 11). A file without them keeps the caller's
    // version, so that its bytes do not change; the first frame with a polygon raises HEAD's
    // version_minor to 2 (rewritten in place) when every frame written so far decodes the same
    // under 1.2: stored frames always do, range-coded ones unless they hold a curve (1.2 codes
    // one more kind flag after it). Otherwise the caller must ask for 1.2 when creating.
    Status polygon_version(const Frame& frame, const std::string& where) {
        if (header_.version_minor >= detail::kPolygonMinorVersion) return {};
        bool any = false;
        for (const Stroke& s : frame.added) any = any || s.kind == StrokeKind::Polygon;
        if (!any) return {};
        if (range_curves_)
            return make_error(Code::InvalidArgument, where + ": polygon strokes need format 1.2, and earlier frames were "
                                                              "range-coded as 1." + std::to_string(header_.version_minor) +
                                                              " with curves: create the writer with header.version_minor = 2");
        return raise_version(detail::kPolygonMinorVersion);
    }
    // Rewrites HEAD in place with a newer version_minor (every frame so far decodes the same).
    Status raise_version(uint16_t minor) {
        header_.version_minor = minor;
        shape_.version_minor = header_.version_minor;
        Header h = header_;
        h.frame_count = kUnknownFrameCount;
        ByteSink head;
        detail::put_chunk(head, "HEAD", detail::encode_head(h));
        if (std::fseek(file_, 8, SEEK_SET) != 0 || std::fwrite(head.bytes().data(), 1, head.size(), file_) != head.size() ||
            std::fseek(file_, 0, SEEK_END) != 0)
            return fail(make_error(Code::IoError, out_path_ + ": cannot update HEAD: " + std::strerror(errno)));
        return {};
    }
    Status usable() const {
        if (finished_) return make_error(Code::BadState, path_ + ": writer already finished");
        if (failed_) return make_error(Code::BadState, path_ + ": writer failed earlier or was aborted");
        return {};
    }
    Error fail(Error e) {
        abort();
        return e;
    }
    Status write(const std::vector<uint8_t>& b) {
        if (!b.empty() && std::fwrite(b.data(), 1, b.size(), file_) != b.size())
            return fail(make_error(Code::IoError, out_path_ + ": write failed at byte offset " + std::to_string(pos_) + ": " +
                                                      std::strerror(errno), pos_));
        pos_ += b.size();
        stats_.total_bytes = pos_;
        return {};
    }

    std::string path_, out_path_;
    Header header_;
    detail::StreamShape shape_;
    WriterOptions opts_;
    AtomicFile atomic_;           // opts_.atomic_rename: owns file_
    std::FILE* file_ = nullptr;
    uint64_t pos_ = 0;
    uint32_t next_index_ = 0;
    uint64_t live_ = 0;
    std::vector<detail::IndexEntry> index_;
    std::vector<Roi> rois_;
    WriteStats stats_;
    std::unique_ptr<Renderer> renderer_;      // coding 2 only
    std::vector<Stroke> live_strokes_;        // coding 2 only
    bool range_curves_ = false;               // a coding-1 frame with a curve was written
    bool finished_ = false, failed_ = false, removed_ = false;
};

}  // namespace

Result<std::unique_ptr<Writer>> Writer::create(const std::string& path, const StreamInfo& info,
                                               const WriterOptions& opts) {
    Limits lim;  // the format's own bounds, not a reader's
    lim.max_width = lim.max_height = 0xFFFFFFFFu;
    lim.max_pixels = ~uint64_t(0);
    lim.max_template_side = detail::kMaxTemplateSide;
    // An alpha canvas or colour encoding 1 is format 1.3, anti-aliased curves 1.4: the writer
    // says so itself, as it does for coding 2 and polygons.
    StreamInfo checked_info = info;
    Header& hd = checked_info.header;
    if (!hd.plain_color() && hd.version_minor < kAlphaLinearMinorVersion) hd.version_minor = kAlphaLinearMinorVersion;
    if (hd.curve_grid && hd.version_minor < kCurveGridMinorVersion) hd.version_minor = kCurveGridMinorVersion;
    if (auto st = detail::check_header(hd, lim, Code::InvalidArgument, path + ": header", 0); !st) return st.error();
    if (info.templates.size() > 255)
        return make_error(Code::InvalidArgument, path + ": " + std::to_string(info.templates.size()) + " templates, at most 255");
    for (size_t i = 0; i < info.templates.size(); ++i)
        if (auto st = detail::check_template(info.templates[i], lim, Code::InvalidArgument, path + ": template " + std::to_string(i), 0); !st)
            return st.error();
    if (auto st = check_text(info, path); !st) return st.error();
    if (opts.coding != Coding::Stored && opts.coding != Coding::Range && opts.coding != Coding::Replay)
        return make_error(Code::InvalidArgument, path + ": unknown frame coding");
    WriterOptions o = opts;
    if (!hd.plain_color() && o.coding == Coding::Replay) o.coding = Coding::Range;  // 7.7: plain canvases only
    auto w = std::make_unique<FileWriter>(path, checked_info, o);
    if (auto st = w->open_and_write_start(checked_info); !st) return st.error();
    return std::unique_ptr<Writer>(std::move(w));
}

}  // namespace spt
