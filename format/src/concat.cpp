// spt::concatenate (SPEC.md 9.6). Each part is opened with the Reader (which checks its
// framing, index and end), then its FRAM chunks are copied through the container layer: the
// chunk is read whole, its CRC checked, its frame_index rewritten and its CRC recomputed. No
// frame body is decoded. The output's chunk order is the Writer's, so that a join of shots
// gives the bytes one Writer would have written for the same frames.
#include "spt/concat.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>

#include "byte_source.hpp"
#include "container.hpp"
#include "validate.hpp"
#include "spt/atomic_file.hpp"

namespace spt {

namespace {

bool parse_u32(const std::string& s, uint32_t& v) {
    if (s.empty() || s.size() > 10) return false;
    uint64_t x = 0;
    for (char c : s) {
        if (c < '0' || c > '9') return false;
        x = x * 10 + uint64_t(c - '0');
    }
    if (x > 0xFFFFFFFFull) return false;
    v = uint32_t(x);
    return true;
}

const std::string* find_meta(const StreamInfo& info, const std::string& key) {
    for (const auto& [k, v] : info.metadata)
        if (k == key) return &v;
    return nullptr;
}

std::string rational(const Rational& r) { return std::to_string(r.num) + "/" + std::to_string(r.den); }

std::string sets_text(const std::vector<StrokeSet>& s) {
    std::string t;
    for (size_t i = 0; i < s.size(); ++i) t += (i ? "," : "") + std::to_string(s[i].width) + "x" + std::to_string(s[i].height);
    return t;
}

// The header fields that must agree (SPEC.md 9.6), first difference named.
Status same_canvas(const Header& a, const Header& b, const std::string& name, const std::string& first) {
    auto differ = [&](const std::string& what, const std::string& va, const std::string& vb) {
        return make_error(Code::InvalidArgument, name + ": cannot be joined to " + first + ": " + what + " is " + vb +
                                                     ", " + first + " has " + va);
    };
    if (a.version_major != b.version_major)
        return differ("format major version", std::to_string(a.version_major), std::to_string(b.version_major));
    if (a.width != b.width || a.height != b.height)
        return differ("the canvas", std::to_string(a.width) + "x" + std::to_string(a.height),
                      std::to_string(b.width) + "x" + std::to_string(b.height));
    if (!(a.fps == b.fps)) return differ("the frame rate", rational(a.fps), rational(b.fps));
    if (a.color != b.color)
        return differ("the colour encoding", std::to_string(int(a.color)), std::to_string(int(b.color)));
    if (a.alpha != b.alpha)
        return differ("the alpha channel", a.alpha ? "alpha" : "no alpha", b.alpha ? "alpha" : "no alpha");
    if (a.curve_grid != b.curve_grid)  // a curve's record and stream have a grid exactly with the flag
        return differ("the curve_grid flag (anti-aliased curves)", a.curve_grid ? "set" : "not set",
                      b.curve_grid ? "set" : "not set");
    auto rgb = [](const Rgb8& c) { return std::to_string(c.r) + "," + std::to_string(c.g) + "," + std::to_string(c.b); };
    if (!(a.background == b.background)) return differ("the background", rgb(a.background), rgb(b.background));
    if (!(a.background_lo == b.background_lo))
        return differ("the background's low bytes", rgb(a.background_lo), rgb(b.background_lo));
    if (a.sets != b.sets) return differ("the stroke sets", sets_text(a.sets), sets_text(b.sets));
    if (a.orientations != b.orientations)
        return differ("the orientation table", std::to_string(a.orientations.size()) + " entries",
                      std::to_string(b.orientations.size()) + " entries" +
                          (a.orientations.size() == b.orientations.size() ? " with other values" : ""));
    return {};
}

// One part as the first pass saw it.
struct Part {
    std::string path;
    StreamInfo info;
    std::vector<FrameEntry> frames;
    bool range_coded = false;  // holds a coding-1 frame
};

Result<Part> open_part(const std::string& path, const ReaderOptions& ro) {
    Result<std::unique_ptr<Reader>> r = Reader::open(path, ro);
    if (!r) {
        Error e = r.error();
        if (e.message.rfind(path, 0) != 0) e.message = path + ": " + e.message;
        return e;
    }
    Reader& rd = **r;
    if (!rd.complete())
        return make_error(Code::Truncated, path + ": incomplete file (no sound end chunk): finish or repair it "
                                                  "before joining");
    if (!rd.warnings().empty()) return make_error(Code::Corrupt, path + ": damaged: " + rd.warnings().front().message);
    if (rd.frames().empty()) return make_error(Code::InvalidArgument, path + ": holds no frames");
    if (rd.frames().front().type != FrameType::Key)
        return make_error(Code::InvalidArgument, path + ": does not start with a key frame; a part must");
    Part p;
    p.path = path;
    p.info = rd.info();
    p.frames = rd.frames();
    for (size_t i = 0; i < p.frames.size(); ++i) {
        if (p.frames[i].index != i)
            return make_error(Code::Corrupt, path + ": frame " + std::to_string(i) + " is numbered " +
                                                 std::to_string(p.frames[i].index));
        p.range_coded = p.range_coded || p.frames[i].coding == Coding::Range;
    }
    return p;
}

class Output {
public:
    ~Output() {
        if (f_ && !atomic_) std::fclose(f_);
        if (!done_ && !atomic_ && !path_.empty()) std::remove(path_.c_str());
    }
    // `atomic`: through an AtomicFile, linked into place by finish() (never half-written, no
    // temporary name a symlink could redirect); else straight to `path`.
    Status open(const std::string& path, bool atomic) {
        path_ = path;
        atomic_ = atomic;
        if (atomic) {
            auto a = AtomicFile::create(path);
            if (!a) return a.error();
            file_ = std::move(*a);
            f_ = file_.stream();
            return {};
        }
        f_ = std::fopen(path.c_str(), "wb");
        if (!f_) return make_error(Code::IoError, path + ": cannot create: " + std::strerror(errno));
        return {};
    }
    Status write(const uint8_t* p, size_t n) {
        if (n && std::fwrite(p, 1, n, f_) != n)
            return make_error(Code::IoError, path_ + ": write failed at byte offset " + std::to_string(pos_) + ": " +
                                                 std::strerror(errno));
        pos_ += n;
        return {};
    }
    Status write(const std::vector<uint8_t>& b) { return write(b.data(), b.size()); }
    Status finish() {
        if (atomic_) {
            f_ = nullptr;
            if (Status st = file_.commit(); !st) return st;
            done_ = true;
            return {};
        }
        const bool flushed = std::fflush(f_) == 0;
        const bool closed = std::fclose(f_) == 0;
        f_ = nullptr;
        if (!flushed || !closed) return make_error(Code::IoError, path_ + ": cannot close: " + std::strerror(errno));
        done_ = true;
        return {};
    }
    uint64_t pos() const { return pos_; }

private:
    std::string path_;
    bool atomic_ = true;
    AtomicFile file_;  // discarded unless finish() commits it
    std::FILE* f_ = nullptr;
    uint64_t pos_ = 0;
    bool done_ = false;
};

// The chunks between HEAD and the first frame that are copied as they are: the templates
// (their samples keep the coding the part's writer chose).
Status template_chunks(detail::ByteSource& src, const Part& p, std::vector<uint8_t>& out) {
    uint64_t off = 8;
    const uint64_t end = p.frames.front().offset;
    while (off < end) {
        uint8_t h[8];
        if (!src.read(off, 8, h)) return make_error(Code::IoError, p.path + ": cannot read the chunk at byte offset " + std::to_string(off));
        const uint64_t n = detail::kChunkOverhead + uint64_t(detail::load_u32(h));
        if (n > end - off) return make_error(Code::Corrupt, p.path + ": chunk at byte offset " + std::to_string(off) + " runs into the first frame");
        if (detail::is_type(h + 4, "TMPL")) {
            const size_t at = out.size();
            out.resize(at + size_t(n));
            if (!src.read(off, size_t(n), out.data() + at))
                return make_error(Code::IoError, p.path + ": cannot read the template at byte offset " + std::to_string(off));
        }
        off += n;
    }
    return {};
}

}  // namespace

bool has_first_frame_number(const StreamInfo& info) {
    uint32_t v = 0;
    const std::string* s = find_meta(info, kFirstFrameKey);
    return s && parse_u32(*s, v);
}

uint32_t first_frame_number(const StreamInfo& info) {
    uint32_t v = 0;
    const std::string* s = find_meta(info, kFirstFrameKey);
    return s && parse_u32(*s, v) ? v : 0;
}

Result<StreamInfo> join_info(const std::vector<StreamInfo>& parts, const std::vector<uint64_t>& frame_counts,
                             const std::vector<std::string>& names, std::vector<std::string>* warnings) {
    if (parts.empty()) return make_error(Code::InvalidArgument, "nothing to join");
    if (frame_counts.size() != parts.size() || names.size() != parts.size())
        return make_error(Code::InvalidArgument, "join_info: one frame count and one name per part");
    auto warn = [&](std::string w) { if (warnings) warnings->push_back(std::move(w)); };
    const StreamInfo& first = parts.front();
    StreamInfo out;
    out.header = first.header;
    out.templates = first.templates;
    uint64_t total = 0;
    for (size_t i = 0; i < parts.size(); ++i) {
        if (i > 0) {
            if (auto st = same_canvas(first.header, parts[i].header, names[i], names[0]); !st) return st.error();
            if (parts[i].templates != first.templates)
                return make_error(Code::InvalidArgument,
                                  names[i] + ": cannot be joined to " + names[0] + ": the stroke templates differ (" +
                                      std::to_string(parts[i].templates.size()) + " against " +
                                      std::to_string(first.templates.size()) + ")");
        }
        out.header.version_minor = std::max(out.header.version_minor, parts[i].header.version_minor);
        for (Roi r : parts[i].rois) {
            if (uint64_t(r.last_frame) + total > 0xFFFFFFFEull)
                return make_error(Code::InvalidArgument, names[i] + ": a region of interest lies past frame 2^32 - 2 of the join");
            r.first_frame += uint32_t(total);
            r.last_frame += uint32_t(total);
            out.rois.push_back(r);
        }
        total += frame_counts[i];
        if (total > 0xFFFFFFFEull) return make_error(Code::InvalidArgument, names[i] + ": the join would hold more than 2^32 - 2 frames");
    }
    out.header.frame_count = uint32_t(total);

    // Metadata: the first part's entries that every part shares; `part.` keys never; the
    // frame numbering when the parts' numbers follow on.
    bool numbers_follow = true;
    uint64_t expect = first_frame_number(first);
    for (size_t i = 0; i < parts.size(); ++i) {
        if (first_frame_number(parts[i]) != expect) numbers_follow = false;
        expect = uint64_t(first_frame_number(parts[i])) + frame_counts[i];
    }
    std::map<std::string, bool> seen;
    for (const auto& [k, v] : first.metadata) {
        if (seen[k]) continue;  // the first entry of a key speaks for it
        seen[k] = true;
        if (k.rfind(kPartKeyPrefix, 0) == 0) continue;
        if (k == kFirstFrameKey) {
            if (numbers_follow) out.metadata.emplace_back(k, v);
            continue;
        }
        bool shared = true;
        for (size_t i = 1; i < parts.size() && shared; ++i) {
            const std::string* o = find_meta(parts[i], k);
            shared = o && *o == v;
        }
        if (shared) out.metadata.emplace_back(k, v);
        else warn("metadata '" + k + "' differs between the parts: not kept");
    }
    if (!numbers_follow)
        warn("the parts' source frame numbers do not follow on: the joined file numbers its frames from " +
             std::string(has_first_frame_number(first) ? "the first part's first frame" : "0"));
    return out;
}

Result<ConcatReport> concatenate(const std::vector<std::string>& paths, const std::string& output,
                                 const ConcatOptions& opts) {
    if (paths.empty()) return make_error(Code::InvalidArgument, "nothing to join");
    std::vector<Part> parts;
    std::vector<StreamInfo> infos;
    std::vector<uint64_t> counts;
    for (size_t i = 0; i < paths.size(); ++i) {
        Result<Part> p = open_part(paths[i], opts.reader);
        if (!p) return p.error();
        if (opts.check_part)
            if (auto st = opts.check_part(i, paths[i], p->info, p->frames.size()); !st) return st.error();
        infos.push_back(p->info);
        counts.push_back(p->frames.size());
        parts.push_back(std::move(*p));
    }
    ConcatReport rep;
    Result<StreamInfo> joined = join_info(infos, counts, paths, &rep.warnings);
    if (!joined) return joined.error();
    StreamInfo& info = *joined;
    // A coding-1 frame of format 1.0/1.1 decodes differently under 1.2 when it holds a curve
    // (SPEC.md 7.4): such a part cannot be raised to 1.2 without re-coding.
    if (info.header.version_minor >= detail::kPolygonMinorVersion)
        for (const Part& p : parts)
            if (p.info.header.version_minor < detail::kPolygonMinorVersion && p.range_coded)
                return make_error(Code::InvalidArgument,
                                  p.path + ": format 1." + std::to_string(p.info.header.version_minor) +
                                      " with range-coded frames cannot be joined to format 1.2 parts (its curves "
                                      "would decode differently); re-code it first (spt pack)");

    Output out;
    if (auto st = out.open(output, opts.atomic_rename); !st) return st.error();
    detail::ByteSink start;
    for (uint8_t b : detail::kSignature) start.u8(b);
    detail::put_chunk(start, "HEAD", detail::encode_head(info.header));
    {
        std::unique_ptr<detail::FileSource> src = detail::FileSource::open(parts[0].path);
        if (!src) return make_error(Code::IoError, parts[0].path + ": cannot open: " + std::strerror(errno));
        if (auto st = template_chunks(*src, parts[0], start.bytes()); !st) return st.error();
    }
    if (!info.metadata.empty()) detail::put_chunk(start, "meta", detail::encode_meta(info.metadata));
    if (auto st = out.write(start.bytes()); !st) return st.error();

    std::vector<detail::IndexEntry> index;
    index.reserve(size_t(info.header.frame_count));
    std::vector<uint8_t> chunk;
    uint32_t next = 0;
    for (const Part& p : parts) {
        std::unique_ptr<detail::FileSource> src = detail::FileSource::open(p.path);
        if (!src) return make_error(Code::IoError, p.path + ": cannot open: " + std::strerror(errno));
        for (size_t i = 0; i < p.frames.size(); ++i) {
            const FrameEntry& e = p.frames[i];
            const std::string where = p.path + ": frame " + std::to_string(i) + " (FRAM chunk at byte offset " +
                                      std::to_string(e.offset) + ")";
            if (e.chunk_bytes < detail::kChunkOverhead + detail::kFrameHeaderBytes || e.chunk_bytes > (uint64_t(1) << 32) + 12)
                return make_error(Code::Corrupt, where + ": bad chunk size");
            chunk.resize(size_t(e.chunk_bytes));
            if (!src->read(e.offset, chunk.size(), chunk.data()))
                return make_error(Code::IoError, where + ": cannot read");
            const uint32_t len = detail::load_u32(chunk.data());
            const size_t crc_at = chunk.size() - 4;
            if (uint64_t(len) + detail::kChunkOverhead != e.chunk_bytes || !detail::is_type(chunk.data() + 4, "FRAM"))
                return make_error(Code::Corrupt, where + ": not the FRAM chunk the index names");
            if (detail::crc32(chunk.data() + 4, crc_at - 4) != detail::load_u32(chunk.data() + crc_at))
                return make_error(Code::Corrupt, where + ": fails its CRC");
            detail::FrameHeader fh;
            if (auto st = detail::decode_frame_header(chunk.data() + 8, len, e.offset + 8, fh); !st) {
                Error err = st.error();
                err.message = where + ": " + err.message;
                return err;
            }
            if (fh.index != i) return make_error(Code::Corrupt, where + ": numbered " + std::to_string(fh.index));
            detail::store_u32(chunk.data() + 8, next);
            detail::store_u32(chunk.data() + crc_at, detail::crc32(chunk.data() + 4, crc_at - 4));
            index.push_back({next, fh.type, out.pos()});
            if (auto st = out.write(chunk); !st) return st.error();
            ++next;
        }
    }

    detail::ByteSink tail;
    if (!info.rois.empty()) detail::put_chunk(tail, "rois", detail::encode_rois(info.rois));
    const uint64_t index_offset = out.pos() + tail.size();
    detail::put_chunk(tail, "indx", detail::encode_indx(index));
    detail::put_chunk(tail, "IEND", detail::encode_iend(next, index_offset));
    if (auto st = out.write(tail.bytes()); !st) return st.error();
    if (auto st = out.finish(); !st) return st.error();
    rep.parts = parts.size();
    rep.frames = next;
    rep.bytes = out.pos();
    return rep;
}

}  // namespace spt
