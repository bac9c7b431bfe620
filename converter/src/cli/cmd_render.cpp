// spt render: a .spt file to an image, an image sequence or a preview video.
#include <cstdio>
#include <filesystem>
#include <system_error>


#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "io/canvas_image.hpp"
#include "io/image_io.hpp"
#include "io/private_output.hpp"
#include "io/progress.hpp"
#include "io/sequence.hpp"
#include "io/spt_file.hpp"
#include "spt/concat.hpp"
#include "spt_import/shapes.hpp"
#include "spt/spt.hpp"
#include "io/ffmpeg_writer.hpp"

namespace spt::cli {

namespace fs = std::filesystem;

namespace {

int fail(const std::string& msg) { return command_failed("render", msg); }

// --background: "R,G,B" (0..255, as spt paint's), a hex colour "RRGGBB" / "#RRGGBB" (as spt
// import's) or an SVG colour name ("white", "black", ...: the SVG importer's parser).
bool parse_colour(std::string s, Rgb8& c) {
    bool none = false;
    if (s.find(',') == std::string::npos && s.size() != 6 && import::parse_color(s, c, none) && !none) return true;
    if (!s.empty() && s[0] == '#') s.erase(0, 1);
    if (s.size() == 6 && s.find_first_not_of("0123456789abcdefABCDEF") == std::string::npos) {
        const unsigned long v = std::stoul(s, nullptr, 16);
        c = {uint8_t(v >> 16), uint8_t(v >> 8), uint8_t(v)};
        return true;
    }
    int v[3], used = 0;
    if (std::sscanf(s.c_str(), "%d,%d,%d%n", &v[0], &v[1], &v[2], &used) != 3 || used != int(s.size())) return false;
    for (int k : v)
        if (k < 0 || k > 255) return false;
    c = {uint8_t(v[0]), uint8_t(v[1]), uint8_t(v[2])};
    return true;
}

std::string lower_ext(const std::string& p) {
    std::string e = fs::path(p).extension().string();
    for (auto& c : e) c = char(std::tolower(static_cast<unsigned char>(c)));
    return e;
}

// A preview video through FFmpeg (io/ffmpeg_writer.hpp), written inside a private folder
// (io/private_output.hpp) and moved into place when complete.
class VideoOut {
public:
    bool open(const std::string& path, double fps, uint32_t w, uint32_t h, std::string& err) {
        auto p = io::PrivateOutput::create(path);
        if (!p) {
            err = p.error().message;
            return false;
        }
        out_ = std::move(*p);  // the container is named by the extension, kept by file()
        if (Status s = writer_.open(out_.file(), lower_ext(path), path, fps > 0 ? fps : 24.0, w, h); !s) {
            // A full disk is the commonest reason, and named as such.
            const Status space = out_.check_space();
            err = space ? s.error().message : space.error().message;
            discard();
            return false;
        }
        return true;
    }
    bool write(const Canvas& c, const Header& h, const io::CanvasImageOptions& o, std::string& err) {
        // A plain canvas as it is; others flattened and viewed as a JPEG would be.
        if (!h.plain_color() || o.view) flat_ = io::canvas_rgb8(c, h, o);
        Status s = writer_.write_rgb(h.plain_color() && !o.view ? c.rgb.data() : flat_.data());
        if (!s) err = s.error().message;
        return s.ok();
    }
    bool finish(std::string& err) {
        if (Status s = writer_.finish(); !s) {
            // A full disk is the commonest reason: said as the other outputs say it.
            const Status space = out_.check_space();
            err = space ? s.error().message : space.error().message + " (the video was not finished; nothing was written)";
            discard();
            return false;
        }
        // A full disk is found here too, whatever the encoder said.
        if (Status s = out_.check_space(); !s) {
            err = s.error().message + " (the video was not finished; nothing was written)";
            out_.discard();
            return false;
        }
        if (Status s = out_.commit(); !s) {
            err = s.error().message;
            return false;
        }
        return true;
    }
    void discard() { out_.discard(); }
private:
    video::VideoFileWriter writer_;
    io::PrivateOutput out_;
    std::vector<uint8_t> flat_;
};

}  // namespace

int cmd_render(int argc, char** argv) {
    Args args("render", "render a .spt file to images (PNG, EXR, TIFF, JPEG), a sequence or a video",
              "spt render FILE.spt -o OUT [--frames RANGE | --frame N] [--start N] [--background C] [...]");
    args.positional("FILE.spt", "the file to render")
        .option("output", "OUT",
                "an image (.png .exr .tif .jpg ...: one frame), a sequence pattern (out.####.png, "
                "out.%04d.exr, out.@@@.tif) or a video (.mp4 .mov .mkv .avi: a quick preview at the "
                "file's fps)", 'o')
        .option("frames", "RANGE", "frames to render, by frame number: \"A-B\", \"A\", \"1-10,20\", \"0-100x5\" "
                                   "(default: all). Numbers are the source's (a file painted from shot.1001.exr... "
                                   "starts at 1001; spt info shows them), else 0-based")
        .option("frame", "N", "the frame of a single-image output, by frame number (default: the first)")
        .option("start", "N", "number the output files from N: the file's i-th frame is written as i + N "
                              "(default: the frame numbers, so shot.1001.exr... renders to out.1001.png...)")
        .option("background", "COLOUR", "flatten an alpha canvas over this sRGB colour: R,G,B (0..255), RRGGBB or a name, "
                                         "for any output (default: PNG, TIFF and EXR keep the alpha; JPEG and videos "
                                         "flatten over the file's background)")
        .option("depth", "BITS", "8 or 16: bits per channel of PNG and TIFF output (default 8)", 0, "8")
        .option("view", "VIEW", "PNG/TIFF/JPEG/video: show the scene-linear values through this OCIO view (of "
                                "--display) instead of the sRGB curve; needs --ocio FILE or $OCIO")
        .option("display", "DISPLAY", "the OCIO display of --view (default: the config's default display)")
        .option("ocio", "FILE", "the OCIO config of --view (default: $OCIO)")
        .option("progress", "MODE", io::kProgressHelp, 0, "auto")
        .epilog("Frames are reached through the index: rendering frames 500-510 decodes from the "
                "key frame at or before 500 only. PNG, TIFF and JPEG are written 8-bit sRGB; EXR "
                "half float scene-linear (the inverse of the sRGB curve). Every file is written "
                "without a name until complete (a video: in a private folder) and then moved into place.\n\n"
                "Alpha and scene-linear files (format 1.3): EXR gets half-float RGBA, premultiplied as OpenEXR "
                "stores it (A = a/255); a scene-linear file's colours are its half floats exactly, values above "
                "1 kept. PNG and TIFF get straight alpha: c = (255p + a/2)/a for 8-bit values (0 where a = 0); "
                "scene-linear values are divided by the alpha and shown through the sRGB curve (no tone "
                "mapping: above 1 clips), or through --view. JPEG has no alpha: it is flattened over the "
                "file's background (a note says so) unless --background names another colour. Files "
                "without alpha in 8-bit sRGB render as before 1.3.");
    if (int rc = args.parse(argc, argv); rc >= 0) return rc;
    io::ProgressMode mode;
    if (!args.get_progress(mode)) return 2;
    const std::string path = args.pos("FILE.spt");
    const std::string out = args.get("output");
    if (out.empty()) return args.usage_error("missing -o OUT");
    long start = -1, single = -1;
    if (!args.get_long("start", start, 0, 999999999) || !args.get_long("frame", single, 0, 0x1FFFFFFFDL)) return 2;
    if (args.has("frame") && args.has("frames")) return args.usage_error("give --frame or --frames, not both");
    io::CanvasImageOptions img;
    if (args.has("background")) {
        Rgb8 bg;
        if (!parse_colour(args.get("background"), bg))
            return args.usage_error("--background: expected R,G,B (0..255), RRGGBB or a colour name, got '" + args.get("background") + "'");
        img.background = bg;
    }
    long depth = 8;
    if (!args.get_long("depth", depth, 8, 16)) return 2;
    if (depth != 8 && depth != 16) return args.usage_error("--depth: 8 or 16, got " + args.get("depth"));
    img.depth = int(depth);
    if ((args.has("display") || args.has("ocio")) && !args.has("view"))
        return args.usage_error("--display and --ocio choose the OCIO view of --view: give --view VIEW");
    auto range = io::parse_frame_range(args.has("frame") ? args.get("frame") : args.get("frames"));
    if (!range) return args.usage_error(range.error().message);

    const bool video = io::is_video_file(out);
    const bool sequence = !video && io::is_sequence_pattern(out);
    if (!video && !io::is_writable_image_name(sequence ? io::format_frame(out, 0) : out))
        return args.usage_error("-o " + out + ": unknown image extension (use .png, .exr, .tif, .jpg or a video extension)");
    if (!sequence && !video && args.has("start")) return args.usage_error("--start needs a sequence pattern in -o");
    const std::string fmt = video ? "" : io::image_format_name(sequence ? io::format_frame(out, 0) : out);
    if (fmt == "openexr" && args.has("view"))
        return args.usage_error("--view applies to PNG, TIFF, JPEG and video output: EXR is written scene-linear");
    if (depth == 16 && (video || (fmt != "png" && fmt != "tiff")))
        return args.usage_error("--depth 16 applies to PNG and TIFF output");
    std::unique_ptr<io::ViewTransform> view;
    if (args.has("view")) {
        auto v = io::ViewTransform::open({args.get("view"), args.get("display"), args.get("ocio")});
        if (!v) return fail(v.error().message);
        view = std::move(*v);
        img.view = view.get();
    }

    auto opened = io::open_spt(path);
    if (!opened) return fail(opened.error().message);
    Reader& r = **opened;
    const auto& frames = r.frames();
    const Header& h = r.info().header;
    if (frames.empty()) return fail(path + ": the file holds no frames");
    // Frame numbers (SPEC.md 3.3 source.first_frame): frame i is number first + i.
    const long first = long(first_frame_number(r.info()));
    const long last = first + long(frames.size()) - 1;
    const std::string have = path + ": has frames " + std::to_string(first) + "-" + std::to_string(last);
    if (start < 0) start = first;

    std::vector<long> todo;
    if (!sequence && !video && !args.has("frames")) {
        todo.push_back(single < 0 ? first : single);
        if (todo.front() < first) return fail(have + "; there is no frame " + std::to_string(todo.front()));
    } else {
        todo = range->frames_within(first, last);
    }
    if (!sequence && !video && todo.size() > 1)
        return args.usage_error("--frames names " + std::to_string(todo.size()) +
                                " frames but -o " + out + " has no frame placeholder (####, %04d, @)");
    // A damaged file: the reader kept the frames before the damage. They are rendered, and the
    // run still fails, naming the first frame it could not reach and where the damage is.
    const bool frames_lost = !r.complete() && (h.frame_count == kUnknownFrameCount || h.frame_count > frames.size());
    std::string lost;
    if (frames_lost) {
        const Error* w = r.warnings().empty() ? nullptr : &r.warnings().back();  // where the scan stopped
        const uint64_t at = w && w->offset ? w->offset : r.file_size();
        std::string why = w ? io::describe_error(path, *w) : std::string("the file ends early");
        if (why.rfind(path + ": ", 0) == 0) why.erase(0, path.size() + 2);
        lost = path + ": frame " + std::to_string(last + 1) + " (byte offset " + std::to_string(at) +
               ") could not be rendered: " + why;
    }
    long beyond = -1;  // the first frame asked for past the last one found
    for (const auto& [a, b] : range->spans) {
        if (a < first) return fail(have + "; the range asks for frame " + std::to_string(a));
        if (b > last && beyond < 0) beyond = b;
    }
    if (single > last) beyond = single;
    if (beyond >= 0 && !frames_lost)
        return fail(have + (single > last ? "; there is no frame " : "; the range asks for frame ") + std::to_string(beyond));
    // Lost frames were asked for: named past the last one found, or "every frame" (a sequence or
    // a video without --frames; a single image without --frame is the first frame only).
    const bool all_asked = (sequence || video) && !args.has("frames");
    const bool fail_after = frames_lost && (beyond >= 0 || all_asked || todo.empty());
    if (todo.empty() || todo.front() > last) {
        if (fail_after) return fail(lost + "; nothing written");
        return fail(have + "; nothing to render in that range");
    }
    for (long& f : todo) f -= first;  // file frame positions from here on

    if (auto rc = Renderer::create(h, r.info().templates); !rc) return fail(io::describe_error(path, rc.error()));
    Canvas canvas(h);

    VideoOut vout;
    std::string err;
    if (video && !vout.open(out, h.fps.den ? double(h.fps.num) / h.fps.den : 24.0, h.width, h.height, err))
        return fail(err);

    io::Progress progress(mode, "render", double(todo.size()));
    size_t done = 0;
    std::string first_bad;  // the first frame that did not decode; later ones are still tried
    for (long f : todo) {
        // Decode and render in one: a key frame of stamps in coding 0 renders straight from its
        // records; other frames through the reader's live list.
        if (Status s = r.render_frame(size_t(f), canvas); !s) {
            if (first_bad.empty()) first_bad = io::frame_error(r, size_t(f), path, s.error()) + " (not rendered)";
            if (video) break;  // a video cannot skip a frame: keep the frames before it
            continue;
        }
        if (video) {
            if (!vout.write(canvas, h, img, err)) {
                vout.discard();
                return fail(err);
            }
        } else {
            const std::string name = sequence ? io::format_frame(out, f + start) : out;
            std::string note;
            Status w = io::write_canvas(name, canvas, h, img, done == 0 ? &note : nullptr);
            if (!w) return fail(w.error().message);
            if (!note.empty()) std::fprintf(stderr, "spt render: note: %s\n", note.c_str());
        }
        progress.update(double(++done), "frame " + std::to_string(f + first));
    }
    if (video && done == 0) vout.discard();
    else if (video && !vout.finish(err)) return fail(err);
    // Of the frames asked for: where frames were lost and the header gives the count, the
    // request counted against what the file should hold.
    size_t asked = todo.size();
    if (frames_lost && h.frame_count != kUnknownFrameCount && (sequence || video))
        asked = range->frames_within(first, first + long(h.frame_count) - 1).size();
    const std::string summary = "wrote " + std::to_string(done) + " of " + std::to_string(asked) + " frames";
    if (!first_bad.empty() || fail_after) {
        progress.finish(false, summary);
        return fail((first_bad.empty() ? lost : first_bad) + "; " + summary);
    }
    if (!r.complete())  // damaged, but every frame asked for was rendered
        for (const auto& w : r.warnings()) std::fprintf(stderr, "spt render: warning: %s\n", io::describe_error(path, w).c_str());
    progress.finish(true, std::to_string(done) + " frames");
    return 0;
}

}  // namespace spt::cli
