// The C API the browser player calls: libspt's Reader over a file held in memory, rendering a
// frame into RGBA. Compiled with emcc together with format/src (the same sources as the native
// library): the browser decodes with libspt itself, with its limits and its error messages.
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "spt/display.hpp"
#include "spt/reader.hpp"

#if defined(__EMSCRIPTEN__)
#include <emscripten/emscripten.h>
#define SPT_EXPORT extern "C" EMSCRIPTEN_KEEPALIVE
#else
#define SPT_EXPORT extern "C"
#endif

namespace {

struct Player {
    std::unique_ptr<spt::Reader> reader;
    spt::Canvas canvas;
    // width * height * 4, straight sRGB (spt/display.hpp to_rgba8): alpha 255 on plain
    // canvases; alpha canvases keep theirs, scene-linear ones go through the sRGB curve.
    std::vector<uint8_t> rgba;
};

// The last failure's message and code, for spt_error_message() / spt_error_code().
std::string g_message;
int g_code = 0;

void set_error(const spt::Error& e) {
    g_code = int(e.code);
    g_message = e.message;
    if (e.offset != 0 && g_message.find(std::to_string(e.offset)) == std::string::npos)
        g_message += " (byte offset " + std::to_string(e.offset) + ")";
}

}  // namespace

// Opens a .spt file from `size` bytes at `data` (copied: the caller may free them). Returns
// null on failure (see spt_error_message). The reader's default limits apply, as natively.
SPT_EXPORT Player* spt_open(const uint8_t* data, size_t size) {
    auto r = spt::Reader::open_memory(data, size);
    if (!r) {
        set_error(r.error());
        return nullptr;
    }
    auto p = std::make_unique<Player>();
    p->reader = std::move(*r);
    const auto& h = p->reader->info().header;
    if (p->reader->frames().empty()) {
        set_error(spt::make_error(spt::Code::Corrupt, "the file holds no complete frame"));
        return nullptr;
    }
    p->canvas = spt::Canvas(h);
    p->rgba.assign(size_t(h.width) * h.height * 4, 255);
    return p.release();
}

SPT_EXPORT void spt_close(Player* p) { delete p; }

SPT_EXPORT uint32_t spt_frame_count(const Player* p) { return uint32_t(p->reader->frames().size()); }
SPT_EXPORT uint32_t spt_width(const Player* p) { return p->reader->info().header.width; }
SPT_EXPORT uint32_t spt_height(const Player* p) { return p->reader->info().header.height; }
SPT_EXPORT uint32_t spt_fps_num(const Player* p) { return p->reader->info().header.fps.num; }
SPT_EXPORT uint32_t spt_fps_den(const Player* p) { return p->reader->info().header.fps.den; }
// The frame number the file gives frame position `pos` (positions count the frames found).
SPT_EXPORT uint32_t spt_frame_index(const Player* p, uint32_t pos) { return p->reader->frames()[pos].index; }
SPT_EXPORT uint32_t spt_is_key(const Player* p, uint32_t pos) {
    return p->reader->frames()[pos].type == spt::FrameType::Key;
}
// 1 when the canvas has an alpha channel (format 1.3): the page shows through where it is
// transparent, over spt_background().
SPT_EXPORT uint32_t spt_has_alpha(const Player* p) { return p->reader->info().header.alpha ? 1 : 0; }
// The header's background as sRGB 0xRRGGBB (scene-linear through the sRGB curve).
SPT_EXPORT uint32_t spt_background(const Player* p) {
    const auto& h = p->reader->info().header;
    uint32_t v = 0;
    for (int k = 0; k < 3; ++k) v = v << 8 | spt::unit_to_u8(spt::srgb_encode(spt::background_linear(h, k)));
    if (h.color == spt::ColorEncoding::Srgb8) v = uint32_t(h.background.r) << 16 | uint32_t(h.background.g) << 8 | h.background.b;
    return v;
}
SPT_EXPORT uint32_t spt_warning_count(const Player* p) { return uint32_t(p->reader->warnings().size()); }
SPT_EXPORT const char* spt_warning(const Player* p, uint32_t i) { return p->reader->warnings()[i].message.c_str(); }

// Decodes and renders frame position `pos` (Reader::render_frame, one thread) and converts it
// to RGBA at spt_pixels(). 0 on success, else the error code (see spt_error_message).
SPT_EXPORT int spt_render(Player* p, uint32_t pos) {
    if (pos >= p->reader->frames().size()) {
        set_error(spt::make_error(spt::Code::InvalidArgument,
                                  "frame position " + std::to_string(pos) + " is past the last frame (" +
                                      std::to_string(p->reader->frames().size()) + " frames)"));
        return g_code;
    }
    if (spt::Status s = p->reader->render_frame(pos, p->canvas, 1); !s) {
        set_error(s.error());
        return g_code;
    }
    const auto& h = p->reader->info().header;
    if (!h.plain_color()) {
        spt::to_rgba8(p->canvas, h, p->rgba);
        return 0;
    }
    const uint8_t* src = p->canvas.rgb.data();
    uint8_t* dst = p->rgba.data();
    const size_t n = size_t(p->canvas.width) * p->canvas.height;
    for (size_t i = 0; i < n; ++i, src += 3, dst += 4) {
        dst[0] = src[0];
        dst[1] = src[1];
        dst[2] = src[2];
    }
    return 0;
}

SPT_EXPORT const uint8_t* spt_pixels(const Player* p) { return p->rgba.data(); }

SPT_EXPORT const char* spt_error_message() { return g_message.c_str(); }
SPT_EXPORT int spt_error_code() { return g_code; }
SPT_EXPORT const char* spt_code_name(int code) { return spt::code_name(spt::Code(code)); }

// For JavaScript to pass file bytes in.
SPT_EXPORT void* spt_alloc(size_t n) { return std::malloc(n ? n : 1); }
SPT_EXPORT void spt_free(void* q) { std::free(q); }
