#include "frames/ffmpeg_video.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/display.h>
#include <libavutil/imgutils.h>
#include <libavutil/pixdesc.h>
#include <libswscale/swscale.h>
}

#include <opencv2/core.hpp>

#include "io/av_error.hpp"

namespace spt::video {

namespace {

using io::av_text;

// One opened file: the demuxer and its best video stream.
struct Demux {
    AVFormatContext* fmt = nullptr;
    int stream = -1;
    ~Demux() { avformat_close_input(&fmt); }
    AVStream* st() const { return fmt->streams[stream]; }
};

Status open_demux(const std::string& path, Demux& d) {
    // FFmpeg's own log lines would repeat what spt's errors and warnings say, without the
    // frame numbers; spt reports for it.
    av_log_set_level(AV_LOG_FATAL);
    // Packets without a presentation time (MPEG-PS gives one only every few frames) get one
    // from the packets after them: frame numbers and seeks are by presentation time.
    d.fmt = avformat_alloc_context();
    if (!d.fmt) return make_error(Code::IoError, path + ": out of memory opening the video");
    d.fmt->flags |= AVFMT_FLAG_GENPTS;
    if (int e = avformat_open_input(&d.fmt, path.c_str(), nullptr, nullptr); e < 0)
        return make_error(Code::IoError, path + ": cannot open this video file (" + av_text(e) + ")");
    if (int e = avformat_find_stream_info(d.fmt, nullptr); e < 0)
        return make_error(Code::Corrupt, path + ": cannot read the video file's streams (" + av_text(e) + ")");
    d.stream = av_find_best_stream(d.fmt, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
    if (d.stream < 0) return make_error(Code::Unsupported, path + ": holds no video stream FFmpeg can decode");
    return {};
}

int64_t packet_time(const AVPacket* p) { return p->pts; }

constexpr int kMaxSide = 32768;
constexpr int64_t kMaxPixels = int64_t(1) << 28;

}  // namespace

struct FfmpegVideo::Impl {
    std::string path;
    Demux dx;
    AVCodecContext* dec = nullptr;
    AVPacket* pkt = nullptr;
    AVFrame* frame = nullptr;
    SwsContext* sws = nullptr;
    int width = 0, height = 0, rotation = 0, depth = 8;
    bool alpha = false, deep = false;
    double fps = 0;
    uint64_t header_frames = 0;
    // The stream's packets: their presentation times in order (frame N is times[N]), and the
    // key frames' times in order. `timed`: every packet has a time and no two share one.
    std::vector<int64_t> times, keys;
    bool timed = true;
    long want = 0;        // frames before this are decoded and dropped (a seek's target)
    long last = -1;       // the number of the last frame decoded
    bool draining = false, ended = false;
    uint64_t decoded = 0;
    cv::Mat padded, converted, wide;

    ~Impl() {
        sws_freeContext(sws);
        av_frame_free(&frame);
        av_packet_free(&pkt);
        avcodec_free_context(&dec);
    }

    long number_of(int64_t t) const {
        if (!timed || t == AV_NOPTS_VALUE) return -1;
        auto it = std::lower_bound(times.begin(), times.end(), t);
        return it != times.end() && *it == t ? long(it - times.begin()) : -1;
    }

    Status scan() {
        Demux s;
        if (Status st = open_demux(path, s); !st) return st;
        AVPacket* p = av_packet_alloc();
        while (av_read_frame(s.fmt, p) >= 0) {
            if (p->stream_index == s.stream) {
                const int64_t t = packet_time(p);
                if (t == AV_NOPTS_VALUE) timed = false;
                times.push_back(t);
                if (p->flags & AV_PKT_FLAG_KEY) keys.push_back(t);
            }
            av_packet_unref(p);
        }
        av_packet_free(&p);
        std::sort(times.begin(), times.end());
        std::sort(keys.begin(), keys.end());
        timed = timed && std::adjacent_find(times.begin(), times.end()) == times.end();
        return {};
    }

    Status open_decoder() {
        const AVCodecParameters* par = dx.st()->codecpar;
        const AVCodec* codec = nullptr;
        // FFmpeg's own VP8/VP9 decoders drop a WebM file's alpha (side data of each block);
        // libvpx's decode it.
        const AVDictionaryEntry* am = av_dict_get(dx.st()->metadata, "alpha_mode", nullptr, 0);
        const bool webm_alpha = am && std::strcmp(am->value, "1") == 0 &&
                                (par->codec_id == AV_CODEC_ID_VP9 || par->codec_id == AV_CODEC_ID_VP8);
        if (webm_alpha) codec = avcodec_find_decoder_by_name(par->codec_id == AV_CODEC_ID_VP9 ? "libvpx-vp9" : "libvpx");
        if (!codec) codec = avcodec_find_decoder(par->codec_id);
        if (!codec)
            return make_error(Code::Unsupported, path + ": no decoder for its video codec (" +
                                                     std::string(avcodec_get_name(par->codec_id)) + ")");
        dec = avcodec_alloc_context3(codec);
        if (!dec || avcodec_parameters_to_context(dec, par) < 0)
            return make_error(Code::IoError, path + ": cannot set up the video decoder");
        dec->thread_count = 0;  // as many as the decoder likes; frames come out the same
        if (int e = avcodec_open2(dec, codec, nullptr); e < 0)
            return make_error(Code::Unsupported, path + ": cannot open the " + codec->name + " decoder (" + av_text(e) + ")");
        const AVPixFmtDescriptor* pd = av_pix_fmt_desc_get(AVPixelFormat(par->format));
        if (pd) {
            alpha = (pd->flags & AV_PIX_FMT_FLAG_ALPHA) && !(pd->flags & AV_PIX_FMT_FLAG_PAL);
            depth = pd->comp[0].depth;
        }
        alpha = alpha || webm_alpha;
        deep = alpha || depth > 8;
        return {};
    }

    Status open(const std::string& p, bool index) {
        path = p;
        if (Status st = open_demux(path, dx); !st) return st;
        if (Status st = open_decoder(); !st) return st;
        if (!index) timed = false;
        else if (Status st = scan(); !st) return st;
        pkt = av_packet_alloc();
        frame = av_frame_alloc();
        if (!pkt || !frame) return make_error(Code::IoError, path + ": out of memory opening the video");
        const AVStream* st = dx.st();
        // The header figures as OpenCV's FFmpeg backend read them (the painter stored its fps).
        fps = av_q2d(st->avg_frame_rate);
        if (!(fps > 1e-6)) fps = av_q2d(st->r_frame_rate);
        if (!(fps > 1e-6) && st->time_base.num > 0) fps = 1.0 / av_q2d(st->time_base);
        int64_t n = st->nb_frames;
        if (n <= 0) {
            double sec = dx.fmt->duration != AV_NOPTS_VALUE ? double(dx.fmt->duration) / AV_TIME_BASE : 0;
            if (sec < 1e-6 && st->duration != AV_NOPTS_VALUE) sec = double(st->duration) * av_q2d(st->time_base);
            n = int64_t(std::floor(sec * fps + 0.5));
        }
        header_frames = n > 0 && n < int64_t(1e9) ? uint64_t(n) : 0;
        if (const uint8_t* m = av_stream_get_side_data(st, AV_PKT_DATA_DISPLAYMATRIX, nullptr)) {
            const double ccw = av_display_rotation_get(reinterpret_cast<const int32_t*>(m));
            if (std::isfinite(ccw)) rotation = ((int(std::lround(-ccw / 90.0)) % 4 + 4) % 4) * 90;
        }
        width = st->codecpar->width;
        height = st->codecpar->height;
        if (Status sz = check_size(width, height); !sz) return sz;
        if (rotation == 90 || rotation == 270) std::swap(width, height);
        return {};
    }

    // Back to the start of the file by opening it again (a seek to 0 is not exact in every
    // container).
    Status rewind() {
        Demux fresh;
        if (Status st = open_demux(path, fresh); !st) return st;
        std::swap(dx.fmt, fresh.fmt);
        avcodec_flush_buffers(dec);
        last = -1;
        draining = ended = false;
        return {};
    }

    // Towards the key frame at or before time `t`; true when the demuxer's next key packet of
    // the stream is no later than `limit` (that packet is left in `pkt`, to be sent first, and
    // its time in `landed`).
    bool seek_to(int64_t t, int64_t limit, int64_t& landed) {
        if (av_seek_frame(dx.fmt, dx.stream, t, AVSEEK_FLAG_BACKWARD) < 0) return false;
        avcodec_flush_buffers(dec);
        draining = ended = false;
        while (av_read_frame(dx.fmt, pkt) >= 0) {
            if (pkt->stream_index == dx.stream && (pkt->flags & AV_PKT_FLAG_KEY)) {
                const int64_t pt = packet_time(pkt);
                if (pt != AV_NOPTS_VALUE && pt <= limit) {
                    landed = pt;
                    have_pending = true;
                    return true;
                }
                av_packet_unref(pkt);
                return false;
            }
            av_packet_unref(pkt);
        }
        return false;
    }
    bool have_pending = false;

    Status seek(long n) {
        want = std::max(0L, n);
        // Without times (or past the last packet): decode forward to it, from the start if need be.
        if (!timed || size_t(want) >= times.size()) return last >= want ? rewind() : Status{};
        auto k = std::upper_bound(keys.begin(), keys.end(), times[size_t(want)]);
        if (k == keys.begin()) return rewind();
        // Already before the target with no key frame between: decoding on is cheapest.
        const long key_number = number_of(*(k - 1));
        if (key_number >= 0 && last < want && last + 1 >= key_number && !ended) return {};
        // Some containers land after the time asked for (MPEG-PS: on the next key frame, found
        // by scanning): then ask for earlier key frames.
        const int64_t limit = *(k - 1);
        for (int tries = 0; tries < 3 && k != keys.begin(); ++tries, --k) {
            int64_t landed = 0;
            if (seek_to(*(k - 1), limit, landed)) {
                last = number_of(landed) - 1;
                return {};
            }
        }
        return rewind();
    }

    // The next decoded frame into `frame`; false at the end of the stream.
    bool decode() {
        for (;;) {
            int r = avcodec_receive_frame(dec, frame);
            if (r == 0) {
                ++decoded;
                return true;
            }
            if (r == AVERROR_EOF || ended) {
                ended = true;
                return false;
            }
            if (r != AVERROR(EAGAIN)) {  // a broken stream: as OpenCV did, it ends here
                ended = true;
                return false;
            }
            if (draining) {
                ended = true;
                return false;
            }
            if (!have_pending) {
                bool got = false;
                while (av_read_frame(dx.fmt, pkt) >= 0) {
                    if (pkt->stream_index == dx.stream) {
                        got = true;
                        break;
                    }
                    av_packet_unref(pkt);
                }
                if (!got) {
                    draining = true;
                    avcodec_send_packet(dec, nullptr);
                    continue;
                }
            }
            have_pending = false;
            // Frames shown before the one wanted that nothing refers to need not be decoded.
            const int64_t t = packet_time(pkt);
            const bool before = timed && size_t(want) < times.size() && t != AV_NOPTS_VALUE && t < times[size_t(want)];
            dec->skip_frame = before ? AVDISCARD_NONREF : AVDISCARD_DEFAULT;
            avcodec_send_packet(dec, pkt);  // a packet that does not decode is skipped
            av_packet_unref(pkt);
        }
    }

    // Checked before any picture is allocated: a header that lies about its size must not make
    // spt ask for gigabytes (the image readers' limits, io/scene_image.hpp).
    Status check_size(int w, int h) const {
        if (w <= 0 || h <= 0) return make_error(Code::Corrupt, path + ": the video stream has no picture size");
        if (w > kMaxSide || h > kMaxSide || int64_t(w) * h > kMaxPixels)
            return make_error(Code::LimitExceeded, path + ": the video is " + std::to_string(w) + "x" + std::to_string(h) +
                                                       ", over the size limit (" + std::to_string(kMaxSide) +
                                                       " per side, " + std::to_string(kMaxPixels) + " pixels)");
        return {};
    }

    Status convert(cv::Mat& out) {
        const int w = frame->width, h = frame->height;
        if (Status sz = check_size(w, h); !sz) return sz;
        const AVPixFmtDescriptor* pd = av_pix_fmt_desc_get(AVPixelFormat(frame->format));
        const bool rgb = pd && (pd->flags & AV_PIX_FMT_FLAG_RGB);
        // 8-bit RGB with alpha (PNG in MOV) converts to RGBA as it is, then widens exactly (x 257):
        // swscale's path to 16 bits rounds it.
        const bool rgba8 = deep && rgb && pd->comp[0].depth <= 8;
        const AVPixelFormat to = rgba8 ? AV_PIX_FMT_RGBA : deep ? AV_PIX_FMT_RGBA64 : AV_PIX_FMT_BGR24;
        // SWS_BICUBIC and no colour details for 8-bit sources: OpenCV's call, so its bytes.
        sws = sws_getCachedContext(sws, w, h, AVPixelFormat(frame->format), w, h, to, SWS_BICUBIC, nullptr, nullptr,
                                   nullptr);
        if (!sws) return make_error(Code::Unsupported, path + ": cannot convert its pixel format (" +
                                                           std::string(av_get_pix_fmt_name(AVPixelFormat(frame->format))) + ")");
        if (deep && !rgb) {
            // Deep YUV sources are new to spt: read them with their own matrix and range.
            const int cs = frame->colorspace == AVCOL_SPC_UNSPECIFIED ? SWS_CS_DEFAULT : int(frame->colorspace);
            const int full = frame->color_range == AVCOL_RANGE_JPEG ? 1 : 0;
            sws_setColorspaceDetails(sws, sws_getCoefficients(cs), full, sws_getCoefficients(SWS_CS_DEFAULT), 1, 0,
                                     1 << 16, 1 << 16);
        }
        // swscale's SIMD writes up to a few bytes past a row's end: rows to spare below.
        padded.create(h + 2, w, rgba8 ? CV_8UC4 : deep ? CV_16UC4 : CV_8UC3);
        converted = padded.rowRange(0, h);
        uint8_t* dst[4] = {converted.data, nullptr, nullptr, nullptr};
        int stride[4] = {int(converted.step[0]), 0, 0, 0};
        sws_scale(sws, frame->data, frame->linesize, 0, h, dst, stride);
        if (rgba8) {
            converted.convertTo(wide, CV_16U, 257.0);
            converted = wide;
        }
        if (rotation == 0) {
            converted.copyTo(out);
        } else {
            const int code = rotation == 90 ? cv::ROTATE_90_CLOCKWISE
                             : rotation == 180 ? cv::ROTATE_180 : cv::ROTATE_90_COUNTERCLOCKWISE;
            cv::rotate(converted, out, code);
        }
        return {};
    }

    Result<bool> next(long& number, cv::Mat& out) {
        for (;;) {
            if (!decode()) return false;
            long n = number_of(frame->best_effort_timestamp);
            if (n >= 0 && n <= last) {  // shown before the key frame a seek went to
                av_frame_unref(frame);
                continue;
            }
            if (n < 0) n = last + 1;  // a frame without a time of the index counts on
            last = n;
            if (n < want) {
                av_frame_unref(frame);
                continue;
            }
            Status st = convert(out);
            av_frame_unref(frame);
            if (!st) return st.error();
            number = n;
            return true;
        }
    }
};

FfmpegVideo::FfmpegVideo() : d_(std::make_unique<Impl>()) {}
FfmpegVideo::~FfmpegVideo() = default;
Status FfmpegVideo::open(const std::string& path, bool index) { return d_->open(path, index); }
int FfmpegVideo::width() const { return d_->width; }
int FfmpegVideo::height() const { return d_->height; }
double FfmpegVideo::fps() const { return d_->fps; }
uint64_t FfmpegVideo::header_frames() const { return d_->header_frames; }
uint64_t FfmpegVideo::packet_frames() const { return d_->times.size(); }
bool FfmpegVideo::deep() const { return d_->deep; }
bool FfmpegVideo::has_alpha() const { return d_->alpha; }
int FfmpegVideo::bit_depth() const { return d_->depth; }
int FfmpegVideo::rotation() const { return d_->rotation; }
Status FfmpegVideo::seek(long n) { return d_->seek(n); }
Result<bool> FfmpegVideo::next(long& number, cv::Mat& out) { return d_->next(number, out); }
uint64_t FfmpegVideo::decoded_frames() const { return d_->decoded; }
long FfmpegVideo::position() const { return d_->last + 1; }

Result<uint64_t> count_video_packets(const std::string& path) {
    Demux d;
    if (Status st = open_demux(path, d); !st) return st.error();
    AVPacket* p = av_packet_alloc();
    uint64_t n = 0;
    while (av_read_frame(d.fmt, p) >= 0) {
        if (p->stream_index == d.stream) ++n;
        av_packet_unref(p);
    }
    av_packet_free(&p);
    return n;
}

}  // namespace spt::video
