// Chunk framing and the HEAD, TMPL, meta, rois, indx, IEND chunks (SPEC.md 2-3).
#include "container.hpp"

#include "validate.hpp"

namespace spt::detail {
namespace {
bool is_letter(uint8_t c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
}  // namespace

bool valid_type(const uint8_t* t) {
    if (!is_letter(t[0])) return false;
    for (int i = 1; i < 4; ++i)
        if (!is_letter(t[i]) && t[i] != ' ') return false;
    return true;
}

std::string type_name(const uint8_t* t) {
    std::string s;
    for (int i = 0; i < 4; ++i) {
        if (t[i] >= 0x20 && t[i] < 0x7F) s += char(t[i]);
        else { static const char* hex = "0123456789ABCDEF"; s += "\\x"; s += hex[t[i] >> 4]; s += hex[t[i] & 15]; }
    }
    return "'" + s + "'";
}

void put_chunk(ByteSink& out, const char* type, const uint8_t* payload, size_t n) {
    out.u32(uint32_t(n));
    out.raw(type, 4);
    out.raw(payload, n);
    uint32_t crc = crc32(reinterpret_cast<const uint8_t*>(type), 4);
    crc = crc32(payload, n, crc);
    out.u32(crc);
}

// ---- HEAD ----
std::vector<uint8_t> encode_head(const Header& h) {
    ByteSink s;
    s.u16(h.version_major);
    s.u16(h.version_minor);
    s.u32((h.alpha ? kHeadFlagAlpha : 0) | (h.curve_grid ? kHeadFlagCurveGrid : 0));
    s.u32(h.width);
    s.u32(h.height);
    s.u32(h.fps.num);
    s.u32(h.fps.den);
    s.u32(h.frame_count);
    s.u8(uint8_t(h.color));
    s.u8(h.background.r); s.u8(h.background.g); s.u8(h.background.b);
    s.u8(uint8_t(h.sets.size()));
    s.u8(uint8_t(h.orientations.size()));
    s.u16(0);
    for (const auto& st : h.sets) { s.u16(st.width); s.u16(st.height); }
    for (const auto& o : h.orientations) { s.i16(o.cos_q14); s.i16(o.sin_q14); }
    if (h.color == ColorEncoding::LinearHalf) {
        s.u8(h.background_lo.r); s.u8(h.background_lo.g); s.u8(h.background_lo.b);
        s.u8(0);
    }
    return std::move(s.bytes());
}

Status decode_head(const uint8_t* p, size_t n, uint64_t off, const Limits& lim, Header& h) {
    ByteCursor c(p, n, off, "HEAD");
    uint32_t flags, color;
    uint8_t u8v, nsets, norient;
    uint16_t reserved;
    SPT_TRY(c.u16(h.version_major, "version_major"));
    SPT_TRY(c.u16(h.version_minor, "version_minor"));
    if (h.version_major != 1)
        return c.error(Code::Unsupported, "format major version " + std::to_string(h.version_major) + " is not 1");
    SPT_TRY(c.u32(flags, "flags"));
    if (flags & ~(kHeadFlagAlpha | kHeadFlagCurveGrid)) return c.error(Code::Unsupported, "reserved flags are not 0");
    h.alpha = (flags & kHeadFlagAlpha) != 0;
    h.curve_grid = (flags & kHeadFlagCurveGrid) != 0;
    SPT_TRY(c.u32(h.width, "width"));
    SPT_TRY(c.u32(h.height, "height"));
    SPT_TRY(c.u32(h.fps.num, "fps_num"));
    SPT_TRY(c.u32(h.fps.den, "fps_den"));
    SPT_TRY(c.u32(h.frame_count, "frame_count"));
    SPT_TRY(c.u8(u8v, "color_encoding"));
    color = u8v;
    if (color > 1) return c.error(Code::Unsupported, "colour encoding " + std::to_string(color) + " is reserved");
    h.color = ColorEncoding(color);
    SPT_TRY(c.u8(h.background.r, "background"));
    SPT_TRY(c.u8(h.background.g, "background"));
    SPT_TRY(c.u8(h.background.b, "background"));
    SPT_TRY(c.u8(nsets, "set_count"));
    SPT_TRY(c.u8(norient, "orientation_count"));
    SPT_TRY(c.u16(reserved, "reserved"));
    if (reserved) return c.error(Code::Unsupported, "reserved field is not 0");
    if (nsets < 1 || nsets > kMaxSets) return c.error(Code::Corrupt, "set count " + std::to_string(nsets) + " is not 1..16");
    if (norient < 1 || norient > kMaxOrientations)
        return c.error(Code::Corrupt, "orientation count " + std::to_string(norient) + " is not 1..64");
    SPT_TRY(c.need(size_t(nsets) * 4 + size_t(norient) * 4, "set and orientation tables"));
    h.sets.resize(nsets);
    for (auto& s : h.sets) { SPT_TRY(c.u16(s.width, "set width")); SPT_TRY(c.u16(s.height, "set height")); }
    h.orientations.resize(norient);
    for (auto& o : h.orientations) { SPT_TRY(c.i16(o.cos_q14, "cos")); SPT_TRY(c.i16(o.sin_q14, "sin")); }
    h.background_lo = Rgb8{0, 0, 0};
    if (h.color == ColorEncoding::LinearHalf) {
        SPT_TRY(c.u8(h.background_lo.r, "background_lo"));
        SPT_TRY(c.u8(h.background_lo.g, "background_lo"));
        SPT_TRY(c.u8(h.background_lo.b, "background_lo"));
        SPT_TRY(c.u8(u8v, "reserved"));
        if (u8v) return c.error(Code::Unsupported, "reserved byte after background_lo is not 0");
    }
    if (c.left()) return c.error(Code::Corrupt, std::to_string(c.left()) + " bytes follow the orientation table");
    return check_header(h, lim, Code::Corrupt, "HEAD", off);
}

// ---- TMPL ----
Result<std::vector<uint8_t>> encode_tmpl(const Template& t, Coding coding) {
    ByteSink s;
    const bool bitmap = t.kind == TemplateKind::Bitmap;
    const bool ranged = bitmap && coding == Coding::Range;
    s.u8(uint8_t(t.kind));
    s.u8(bitmap ? (ranged ? 1 : 0) : t.supersample);  // analytic kinds: the supersampling grid (3.2)
    s.u16(bitmap ? t.width : 0);
    s.u16(bitmap ? t.height : 0);
    s.u8(uint8_t(t.name.size()));
    s.raw(t.name.data(), t.name.size());
    if (bitmap) {
        if (ranged) encode_template_samples(t, s.bytes());
        else s.raw(t.pixels.data(), t.pixels.size());
    }
    return std::move(s.bytes());
}

Status decode_tmpl(const uint8_t* p, size_t n, uint64_t off, const Limits& lim, Template& t) {
    ByteCursor c(p, n, off, "TMPL");
    uint8_t kind, coding, name_len;
    SPT_TRY(c.u8(kind, "kind"));
    if (kind > 3) return c.error(Code::Unsupported, "template kind " + std::to_string(kind) + " is reserved");
    t.kind = TemplateKind(kind);
    SPT_TRY(c.u8(coding, "coding"));
    SPT_TRY(c.u16(t.width, "width"));
    SPT_TRY(c.u16(t.height, "height"));
    SPT_TRY(c.u8(name_len, "name_length"));
    SPT_TRY(c.need(name_len, "name"));
    t.name.assign(reinterpret_cast<const char*>(c.here()), name_len);
    SPT_TRY(c.skip(name_len, "name"));
    if (t.kind != TemplateKind::Bitmap) {
        // The coding byte of an analytic template is its supersampling grid N: 0 or 2..16.
        if (coding == 1 || coding > 16)
            return c.error(Code::Unsupported, "analytic template supersampling " + std::to_string(coding) + " is reserved");
        t.supersample = coding;
        if (t.width || t.height) return c.error(Code::Corrupt, "analytic template has a size");
        if (c.left()) return c.error(Code::Corrupt, "analytic template has samples");
        return {};
    }
    if (t.width < 1 || t.height < 1 || t.width > kMaxTemplateSide || t.height > kMaxTemplateSide)
        return c.error(Code::Corrupt, "bitmap template size " + std::to_string(t.width) + "x" + std::to_string(t.height) + " is not 1..1024");
    if (t.width > lim.max_template_side || t.height > lim.max_template_side)
        return c.error(Code::LimitExceeded, "bitmap template size exceeds the limits");
    if (coding == 0) {
        const size_t count = size_t(t.width) * t.height;
        if (c.left() != count)
            return c.error(Code::Corrupt, "template has " + std::to_string(c.left()) + " sample bytes, not " + std::to_string(count));
        t.pixels.assign(c.here(), c.here() + count);
        return {};
    }
    if (coding == 1) return decode_template_samples(c.here(), c.left(), c.offset(), t);
    return c.error(Code::Unsupported, "template coding " + std::to_string(coding) + " is reserved");
}

// ---- meta ----
std::vector<uint8_t> encode_meta(const std::vector<std::pair<std::string, std::string>>& kv) {
    ByteSink s;
    s.u32(uint32_t(kv.size()));
    for (const auto& [k, v] : kv) {
        s.u32(uint32_t(k.size())); s.raw(k.data(), k.size());
        s.u32(uint32_t(v.size())); s.raw(v.data(), v.size());
    }
    return std::move(s.bytes());
}

Status decode_meta(const uint8_t* p, size_t n, uint64_t off, const Limits& lim,
                   std::vector<std::pair<std::string, std::string>>& out) {
    ByteCursor c(p, n, off, "meta");
    if (n > lim.max_metadata_bytes) return c.error(Code::LimitExceeded, "metadata exceeds the limits");
    uint32_t count;
    SPT_TRY(c.u32(count, "count"));
    if (uint64_t(count) * 8 > c.left()) return c.error(Code::Corrupt, "entry count " + std::to_string(count) + " does not fit the chunk");
    out.clear();
    for (uint32_t i = 0; i < count; ++i) {
        uint32_t kl, vl;
        SPT_TRY(c.u32(kl, "key_length"));
        SPT_TRY(c.need(kl, "key"));
        std::string k(reinterpret_cast<const char*>(c.here()), kl);
        SPT_TRY(c.skip(kl, "key"));
        SPT_TRY(c.u32(vl, "value_length"));
        SPT_TRY(c.need(vl, "value"));
        std::string v(reinterpret_cast<const char*>(c.here()), vl);
        SPT_TRY(c.skip(vl, "value"));
        out.emplace_back(std::move(k), std::move(v));
    }
    if (c.left()) return c.error(Code::Corrupt, "bytes follow the last entry");
    return {};
}

// ---- rois ----
std::vector<uint8_t> encode_rois(const std::vector<Roi>& rois) {
    ByteSink s;
    s.u32(uint32_t(rois.size()));
    for (const auto& r : rois) { s.u32(r.first_frame); s.u32(r.last_frame); s.u32(r.x); s.u32(r.y); s.u32(r.w); s.u32(r.h); }
    return std::move(s.bytes());
}

Status decode_rois(const uint8_t* p, size_t n, uint64_t off, std::vector<Roi>& out) {
    ByteCursor c(p, n, off, "rois");
    uint32_t count;
    SPT_TRY(c.u32(count, "count"));
    if (uint64_t(count) * 24 != c.left())
        return c.error(Code::Corrupt, "record count " + std::to_string(count) + " does not match the chunk length");
    for (uint32_t i = 0; i < count; ++i) {
        Roi r;
        SPT_TRY(c.u32(r.first_frame, "first_frame")); SPT_TRY(c.u32(r.last_frame, "last_frame"));
        SPT_TRY(c.u32(r.x, "x")); SPT_TRY(c.u32(r.y, "y")); SPT_TRY(c.u32(r.w, "w")); SPT_TRY(c.u32(r.h, "h"));
        out.push_back(r);
    }
    return {};
}

// ---- indx ----
std::vector<uint8_t> encode_indx(const std::vector<IndexEntry>& e) {
    ByteSink s;
    s.u32(uint32_t(e.size()));
    for (const auto& x : e) { s.u32(x.frame_index); s.u8(x.frame_type); s.u8(0); s.u16(0); s.u64(x.offset); }
    return std::move(s.bytes());
}

Status decode_indx(const uint8_t* p, size_t n, uint64_t off, const Limits& lim, std::vector<IndexEntry>& out) {
    ByteCursor c(p, n, off, "indx");
    uint32_t count;
    SPT_TRY(c.u32(count, "count"));
    if (uint64_t(count) * kIndexEntryBytes != c.left())
        return c.error(Code::Corrupt, "entry count " + std::to_string(count) + " does not match the chunk length");
    if (count > lim.max_frames) return c.error(Code::LimitExceeded, "frame count exceeds the limits");
    out.resize(count);
    for (uint32_t i = 0; i < count; ++i) {
        uint8_t r8; uint16_t r16;
        auto& e = out[i];
        SPT_TRY(c.u32(e.frame_index, "frame_index"));
        SPT_TRY(c.u8(e.frame_type, "frame_type"));
        SPT_TRY(c.u8(r8, "reserved"));
        SPT_TRY(c.u16(r16, "reserved"));
        SPT_TRY(c.u64(e.offset, "offset"));
        if (r8 || r16) return c.error(Code::Unsupported, "index entry " + std::to_string(i) + " has reserved bits set");
        if (e.frame_index != i) return c.error(Code::Corrupt, "index entry " + std::to_string(i) + " names frame " + std::to_string(e.frame_index));
        if (e.frame_type > 1) return c.error(Code::Corrupt, "index entry " + std::to_string(i) + " has frame type " + std::to_string(e.frame_type));
        if (i && e.offset <= out[i - 1].offset) return c.error(Code::Corrupt, "index offsets are not increasing at entry " + std::to_string(i));
    }
    return {};
}

// ---- IEND ----
std::vector<uint8_t> encode_iend(uint32_t frame_count, uint64_t index_offset) {
    ByteSink s;
    s.u32(frame_count);
    s.u64(index_offset);
    return std::move(s.bytes());
}

Status decode_iend(const uint8_t* p, size_t n, uint64_t off, uint32_t& frame_count, uint64_t& index_offset) {
    ByteCursor c(p, n, off, "IEND");
    if (n != kIendPayload) return c.error(Code::Corrupt, "payload is " + std::to_string(n) + " bytes, not 12");
    SPT_TRY(c.u32(frame_count, "frame_count"));
    SPT_TRY(c.u64(index_offset, "index_offset"));
    return {};
}

// ---- FRAM header ----
void encode_frame_header(ByteSink& out, const FrameHeader& fh) {
    out.u32(fh.index);
    out.u8(fh.type);
    out.u8(fh.coding);
    out.u16(0);
}

Status decode_frame_header(const uint8_t* p, size_t n, uint64_t off, FrameHeader& fh) {
    ByteCursor c(p, n, off, "FRAM");
    uint16_t reserved;
    SPT_TRY(c.u32(fh.index, "frame_index"));
    SPT_TRY(c.u8(fh.type, "frame_type"));
    SPT_TRY(c.u8(fh.coding, "coding"));
    SPT_TRY(c.u16(reserved, "reserved"));
    if (fh.type > 1) return c.error(Code::Unsupported, "frame " + std::to_string(fh.index) + " has reserved frame type " + std::to_string(fh.type));
    if (fh.coding > 2) return c.error(Code::Unsupported, "frame " + std::to_string(fh.index) + " has reserved coding " + std::to_string(fh.coding));
    if (reserved) return c.error(Code::Unsupported, "frame " + std::to_string(fh.index) + " has reserved bits set");
    return {};
}

}  // namespace spt::detail
